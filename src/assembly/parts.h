#pragma once
// Internal to swept_assembly: the parts as the sequence sees them (a tree, the triangles' planes,
// the box) and the straight pull certified against the parts still in place (pulls.cpp).
#include "swept/assembly/contact.h"
#include "swept/assembly/disassemble.h"
#include "swept/query/query.h"

#include <atomic>
#include <cstdint>
#include <vector>

namespace swept::assembly_detail {

/// A rigid body of the sequence: one part or a subassembly, world frame at the mounted pose.
struct Body {
  std::vector<Triangle> triangles;     ///< input order (ids of the tree)
  std::vector<TrianglePlane> planes;   ///< plane_of(triangles[i])
  Bvh tree;
  Aabb box;
};

/// The body of the given parts (merged in the given order).
Body make_body(const Assembly& assembly, const std::vector<std::size_t>& parts, const BuildConfig& config);

/// What the sequence needs to know of a pull.
struct PullSettings {
  double clearance = 0.0;
  double tolerance = 0.0;
};

/// Certifies the straight pull of `moving` by `length` along the unit `direction` against the
/// `obstacles`, with the mate rule of contact.h (the only pairs allowed within the clearance).
/// Counts distance queries into `queries`. When it is blocked (a pose at or below the clearance
/// found) and `blocker` is given, the obstacle nearest at that pose: it blocks this pull on its own.
bool pull_is_clear(const Body& moving, const std::vector<const Body*>& obstacles, const Vec3& direction,
                   double length, const PullSettings& settings, std::atomic<std::uint64_t>& queries,
                   const Body** blocker = nullptr);

/// How far `moving` must go along `direction` for its box to leave the box of `obstacles`
/// (grown by `margin`): 0 when there are none.
double exit_length(const Body& moving, const std::vector<const Body*>& obstacles, const Vec3& direction, double margin);

/// The directions to try, in order: +z, −z, +x, −x, +y, −y, then the outward normals of the
/// obstacle triangles the body touches (within `threshold`) and the reversed normals of its own
/// touching triangles, by contact area (at most 8), then the cross products of pairs of them
/// (cylinder axes, both signs, at most 8 axes); each direction once.
std::vector<Vec3> pull_directions(const Body& moving, const std::vector<const Body*>& obstacles, double threshold);

}  // namespace swept::assembly_detail
