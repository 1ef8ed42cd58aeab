#pragma once
/// Basic math and mesh value types shared by every layer of swept.
///
/// All coordinates are double precision, in the model's length unit (millimetres unless the
/// importer was told otherwise). Eigen types are used at the API, as FCL, Coal and OMPL do.
#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace swept {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Quat = Eigen::Quaterniond;

/// A triangle given by its three vertices, in the frame of the mesh that holds it.
/// Degenerate triangles (zero area, repeated vertices) are legal everywhere in swept.
struct Triangle {
  Vec3 p = Vec3::Zero();
  Vec3 q = Vec3::Zero();
  Vec3 r = Vec3::Zero();

  const Vec3& operator[](int i) const { return i == 0 ? p : (i == 1 ? q : r); }
  Vec3& operator[](int i) { return i == 0 ? p : (i == 1 ? q : r); }
};

/// Area of a triangle: ½‖(p − q) × (p − r)‖. Zero for degenerate triangles.
double area(const Triangle& t);

/// Centroid (p + q + r) / 3.
Vec3 centroid(const Triangle& t);

/// Twice the area divided by the squared longest edge: 0 for degenerate triangles,
/// √3/2 for an equilateral one. Used to count degenerate triangles.
double shape_quality(const Triangle& t);

/// Aspect ratio: longest edge over the triangle's smallest height (∞ for zero area).
double aspect_ratio(const Triangle& t);

/// A cylindrical B-rep face, as the CAD reader (OpenCASCADE) gives it: the surface its triangles
/// approximate. The contact model of assemblies slides mated cylinders along their axis by the
/// surfaces, not by their facets (docs/planner.md, "The contact model").
struct CadCylinder {
  Vec3 origin = Vec3::Zero();  ///< a point of the axis, in the soup's frame and unit
  Vec3 axis = Vec3::UnitZ();   ///< unit direction of the axis (either sign)
  double radius = 0.0;
  /// How far the face may lie from this cylinder: 0 for an analytic cylinder; for a free-form
  /// (B-spline) face the reader fitted it to, the largest distance from it of its samples and of
  /// its mesh nodes.
  double deviation = 0.0;
};

/// A triangle soup: triangles in one frame, no connectivity required. One soup per part.
struct TriangleSoup {
  std::string name;                 ///< part name (from the file, or the file's stem)
  std::vector<Triangle> triangles;  ///< in the part's frame, in the model's length unit
  /// CAD parts only (empty for meshes): per triangle, the index into `cylinders` of the
  /// cylindrical face it lies on, or −1 (another kind of face).
  std::vector<std::int32_t> cylinder_of;
  std::vector<CadCylinder> cylinders;  ///< the part's cylindrical faces, one per B-rep face
};

/// Are the soup's CAD cylinders (if any) what the contact model can trust: one index per
/// triangle, each −1 or a cylinder's, every cylinder finite with a unit axis, a positive radius
/// and a deviation ≥ 0? (The cylinders only add mates: a soup whose are not goes without them.)
bool cylinders_usable(const TriangleSoup& soup);

/// Axis-aligned bounding box.
struct Aabb {
  Vec3 min = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 max = Vec3::Constant(-std::numeric_limits<double>::infinity());

  bool empty() const { return (min.array() > max.array()).any(); }
  void extend(const Vec3& v) {
    min = min.cwiseMin(v);
    max = max.cwiseMax(v);
  }
  void extend(const Aabb& b) {
    min = min.cwiseMin(b.min);
    max = max.cwiseMax(b.max);
  }
  Vec3 center() const { return 0.5 * (min + max); }
  Vec3 size() const { return empty() ? Vec3::Zero() : Vec3(max - min); }
  /// Length of the diagonal (0 for an empty box).
  double extent() const { return empty() ? 0.0 : (max - min).norm(); }
};

/// Bounding box of a set of triangles.
Aabb bounds(const std::vector<Triangle>& triangles);

}  // namespace swept
