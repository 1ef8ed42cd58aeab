#pragma once
/// Internal to swept_scenes: small OpenCASCADE modelling helpers (tubes, bent pipes, rounded
/// boxes, plates with holes, booleans) and the tessellation of a B-rep into a triangle soup.
/// Including this header needs the OpenCASCADE include directory (swept_scenes has it
/// privately); the public scene API is `swept/scenes/scenes.h`.
///
/// Units: millimetres. Every helper is deterministic: booleans run serially, BRepMesh runs
/// serially, and faces are visited in topological-explorer order.
#include "swept/geometry/pose.h"
#include "swept/geometry/types.h"

#include <TopoDS_Shape.hxx>

#include <string>
#include <vector>

namespace swept::scenes::detail {

/// Axis-aligned box [min, max].
TopoDS_Shape box(const Vec3& min, const Vec3& max);

/// Axis-aligned box with every edge rounded by `radius` (0: sharp).
TopoDS_Shape rounded_box(const Vec3& min, const Vec3& max, double radius);

/// Axis-aligned box with every edge chamfered by `distance`.
TopoDS_Shape chamfered_box(const Vec3& min, const Vec3& max, double distance);

/// Solid cylinder with its base centre at `base`, axis `direction` (any length > 0).
TopoDS_Shape cylinder(const Vec3& base, const Vec3& direction, double radius, double height);

/// Sphere.
TopoDS_Shape sphere(const Vec3& centre, double radius);

/// Straight round tube from `a` to `b`; hollow when `inner_radius` > 0.
TopoDS_Shape tube(const Vec3& a, const Vec3& b, double outer_radius, double inner_radius);

/// A round tube swept along the polyline `points`, every interior corner replaced by a circular
/// bend of radius `bend_radius` (tori between cylinders, as a tube bender makes them).
/// `closed`: the polyline is a loop (the last point connects back to the first, with a bend).
/// Hollow when `inner_radius` > 0.
TopoDS_Shape bent_tube(const std::vector<Vec3>& points, double bend_radius, double outer_radius,
                       double inner_radius, bool closed = false);

/// Rotates `profile` (a closed polyline in the x–z half plane x ≥ 0, as (x, 0, z) points) about
/// the z axis through `base`: turned parts such as knobs, bellows, canister lids.
TopoDS_Shape revolved(const std::vector<Vec3>& profile, const Vec3& base);

/// Union of shapes (serial boolean). One shape is returned unchanged.
TopoDS_Shape fuse(const std::vector<TopoDS_Shape>& shapes);

/// `base` minus all `tools` (one serial boolean with many tools).
TopoDS_Shape cut(const TopoDS_Shape& base, const std::vector<TopoDS_Shape>& tools);

/// Rounds the edges of `shape` whose both vertices satisfy lo ≤ v ≤ hi (component-wise).
TopoDS_Shape fillet_edges_in(const TopoDS_Shape& shape, const Vec3& lo, const Vec3& hi, double radius);

/// Chamfers the edges of `shape` whose both vertices satisfy lo ≤ v ≤ hi (component-wise).
TopoDS_Shape chamfer_edges_in(const TopoDS_Shape& shape, const Vec3& lo, const Vec3& hi, double distance);

/// The shape moved rigidly by `pose`.
TopoDS_Shape placed(const TopoDS_Shape& shape, const Pose& pose);

/// Several shapes as one compound (no boolean).
TopoDS_Shape compound(const std::vector<TopoDS_Shape>& shapes);

/// Removes any triangulation and meshes `shape` with BRepMesh (serial), linear deflection in mm,
/// angular deflection in radians. Returns the number of triangles produced.
std::size_t mesh(const TopoDS_Shape& shape, double linear_deflection, double angular_deflection);

/// The triangles of an already meshed shape (face orientation respected: outward normals).
TriangleSoup triangles_of(const TopoDS_Shape& shape, const std::string& name);

}  // namespace swept::scenes::detail
