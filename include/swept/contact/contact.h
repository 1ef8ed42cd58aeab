#pragma once
/// The contact layer (docs/planner.md, "The contact model"): rigid bodies as the mate rule sees
/// them (mate_rule.h) and the one certificate of a straight pull in contact, used by the planner's
/// escape and approach, `check_path` (`swept check`) and the assembly's pulls. Every motion that
/// starts or ends within the clearance is certified here and nowhere else.
#include "swept/contact/mate_rule.h"
#include "swept/bvh/bvh.h"
#include "swept/geometry/pose.h"
#include "swept/query/query.h"

#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace swept::contact {

/// A subtree of a body's tree whose triangles lie in one plane, to the mate rule's use: every
/// triangle's outward normal n has |n − normal| ≤ spread, and every vertex v has
/// lo ≤ normal·v ≤ hi. (`flat` false: the subtree holds triangles of other directions.)
struct FlatNode {
  bool flat = false;
  Vec3 normal = Vec3::Zero();
  double spread = 0.0;
  double lo = 0.0, hi = 0.0;
  bool two_sided = false;  ///< every triangle of the subtree is a sheet's (TrianglePlane::two_sided)
};

/// A cylindrical CAD face of a body (TriangleSoup::cylinders), with what the mate rule's case 4
/// needs of it (contact.h).
struct BodyCylinder {
  CadCylinder surface;
  /// Which side the solid is on, from its triangles' outward normals: inside the cylinder (a
  /// shaft) or outside (a bore). `known` false when the normals do not tell (the face is then
  /// left to the triangle rules).
  bool known = false;
  bool material_inside = false;
  /// The face's boundary edges (an edge of exactly one of its triangles), each as its two
  /// vertices' coordinates in increasing order, sorted: the chords of its rims.
  std::vector<std::array<double, 6>> boundary;
};

/// A rigid body at one pose: a part, a subassembly, a planner's obstacles or its moving body.
/// Everything but the tree is in the world frame at that pose; the tree may be shared (the
/// planner's) and is placed by `pose`.
struct Body {
  std::vector<Triangle> triangles;     ///< world frame, input order (ids of the tree)
  std::vector<TrianglePlane> planes;   ///< part_planes of the triangles (world frame)
  std::shared_ptr<const Bvh> tree;     ///< over the same triangles in its own frame
  Pose pose;                           ///< the tree's frame → world
  std::vector<FlatNode> flat;          ///< per node of `tree` (world frame)
  Aabb box;                            ///< world frame
  /// CAD parts: per triangle the index into `cylinders` of the cylindrical face it lies on, or −1;
  /// empty when none of the body's parts has CAD faces.
  std::vector<std::int32_t> cylinder_of;
  std::vector<BodyCylinder> cylinders;
};

/// A coaxial cylinder mate of a moving body with an obstacle for one pull (contact.h, case 4):
/// the axis of the face with the solid outside it (the bore), whose body is `outer`.
struct CylinderMate {
  Vec3 origin = Vec3::Zero();
  Vec3 axis = Vec3::UnitZ();
  bool moving_is_outer = false;  ///< the moving body holds the bore (a sleeve or a nut on a fixed shaft)
  double drift = 0.0;            ///< length · |d × axis|: how far the pull moves a point off its radius
};

/// The cylinder mates of `moving` with `obstacle` for a pull of `length` along the unit `direction`:
/// a shaft face and a bore face, one in each body, with parallel axes (|a × b| ≤ 1e-9), the
/// shaft's axis within `tolerance` of the bore's, the shaft's radius at most the bore's +
/// `tolerance`, and drift ≤ `tolerance`. One per bore face, in face order; none for meshes.
std::vector<CylinderMate> cylinder_mates(const Body& obstacle, const Body& moving, const Vec3& direction,
                                         double length, double tolerance);

/// Case 4 of the mate rule (contact.h) for obstacle triangle `a` and moving triangle `b`: under
/// one of `mates`, the inner triangle's largest distance from the axis exceeds the outer
/// triangle's smallest (taken at the CAD surface where it lies on a coaxial bore or at its rim)
/// by at most `tolerance` − drift.
bool cylinder_mate_allows(const std::vector<CylinderMate>& mates, const Body& obstacle, std::uint32_t a,
                          const Body& moving, std::uint32_t b, double tolerance);

/// The CAD cylinders of the given soups (merged in the given order, already in the world frame) into `body`.
void add_cylinders(Body& body, const std::vector<const TriangleSoup*>& parts);

/// Does the mate rule hold for every triangle pair under node `ia` of `obstacle` and node `ib` of
/// `moving`, by its first case along a flat node's normal (a face sliding along or leaving a
/// face), for a pull of `length` along the unit `direction`? Conservative: false when unsure.
bool nodes_mate(const Body& obstacle, std::int32_t ia, const Body& moving, std::int32_t ib, const Vec3& direction,
                double length, double tolerance);

/// The body of the given soups (world frame; merged in the given order), with its own tree.
/// Creases are found soup by soup (parts of a group do not share edges).
Body make_body(const std::vector<const TriangleSoup*>& parts, const BuildConfig& config);
/// The body of `soup` (its tree's frame, as `tree` was built over soup.triangles) placed at
/// `pose`: the tree is shared, not rebuilt.
Body place_body(const TriangleSoup& soup, std::shared_ptr<const Bvh> tree, const Pose& pose);

/// The same body moved by the translation `t` (world frame): its tree is shared.
Body translated(const Body& body, const Vec3& t);

/// What a pull is checked with: every pair keeps more than `clearance` along the whole pull,
/// except the mates of the mate rule at the pull's start, which reach at most `tolerance` into
/// each other.
struct PullSettings {
  double clearance = 0.0;
  double tolerance = 0.0;
};

/// Is the straight pull of `moving` by `length` along the unit `direction` clear of the
/// `obstacles`, with the mate rule of contact.h (the only pairs allowed within the clearance)?
/// Exact: one `sweep_translation` per obstacle the swept box comes near, counted into `queries`.
/// When it is blocked and `blocker` is given, the first of those obstacles that blocks it: it
/// blocks this pull on its own.
bool pull_is_clear(const Body& moving, const std::vector<const Body*>& obstacles, const Vec3& direction,
                   double length, const PullSettings& settings, std::atomic<std::uint64_t>& queries,
                   const Body** blocker = nullptr);

/// How far `moving` must go along `direction` for its box to leave the box of `obstacles`
/// (grown by `margin`): 0 when there are none.
double exit_length(const Body& moving, const std::vector<const Body*>& obstacles, const Vec3& direction, double margin);

/// A triangle of a contact between an obstacle and the moving body: its index in the obstacle's
/// or (`moving`) in the moving body's triangles.
struct ContactFacet {
  std::uint32_t triangle = 0;
  bool moving = false;
};
/// The triangles of the contact of `moving` with `obstacle` at their poses: every triangle of
/// either closer than `threshold` to a triangle of the other (proximity_triangles), each once,
/// the obstacle's in index order, then the moving body's.
std::vector<ContactFacet> touching_facets(const Body& obstacle, const Body& moving, double threshold);

/// Gap between two boxes (0 when they overlap).
double box_gap(const Aabb& a, const Aabb& b);

/// The directions to try, in order: +z, −z, +x, −x, +y, −y, then the outward normals of the
/// obstacle triangles the body touches (within `threshold`) and the reversed normals of its own
/// touching triangles, by contact area (at most 8), then the cross products of pairs of them
/// (cylinder axes, both signs, at most 8 axes); each direction once.
/// `contacts`, when given, returns the touching_facets of an obstacle with `moving` (at
/// `threshold`) when they are known, else null.
std::vector<Vec3> pull_directions(
    const Body& moving, const std::vector<const Body*>& obstacles, double threshold,
    const std::function<const std::vector<ContactFacet>*(const Body& obstacle)>& contacts = nullptr);

}  // namespace swept::contact
