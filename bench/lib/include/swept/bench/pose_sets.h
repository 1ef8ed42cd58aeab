#pragma once
/// The seeded pose sets every query benchmark times (`swept bench paper`, `swept bench queries`,
/// bench_queries): one generator, so that every engine and every program measures the same kind
/// of poses, and the same poses for a given seed on every platform (SeededRng, no
/// std::*_distribution).
#include "swept/bvh/bvh.h"
#include "swept/geometry/pose.h"

#include <cstdint>
#include <string>
#include <vector>

namespace swept::bench {

/// Poses of model B against model A, which stays at the identity.
struct PoseSet {
  std::string name;  ///< "overlapping", "near" or "far"
  std::vector<Pose> poses;
};

struct PoseSetRequest {
  int count = 5;            ///< poses wanted per set
  std::uint64_t seed = 1;   ///< SeededRng seed
  /// Near contact means 0 < distance ≤ near_fraction · B's extent (the diagonal of its box).
  double near_fraction = 0.01;
};

/// Three sets of poses of B against A, in this order:
/// - "overlapping": B rotated uniformly, its box centre uniform in A's bounding box, kept when the
///   two collide (at most 400·count attempts);
/// - "near": from an overlapping pose, B moved along a random direction, bisecting the distance
///   until 0 < distance ≤ the near limit (at most 4·count attempts);
/// - "far": B's box centre at 1.1–2× the sum of both bounding-sphere radii from A's centre, so
///   that the bounding spheres are apart.
/// A set may hold fewer than `count` poses when the attempts run out (e.g. no overlapping pose
/// exists for models far smaller than each other's gaps); the callers say so.
std::vector<PoseSet> make_pose_sets(const Bvh& a, const Bvh& b, const PoseSetRequest& request = {});

}  // namespace swept::bench
