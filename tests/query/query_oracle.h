#pragma once
// Brute-force oracles over all triangle pairs, computed in A's frame exactly as the queries
// place B (so contact sets compare bit for bit).
#include "swept/bvh/bvh.h"
#include "swept/geometry/distance.h"
#include "swept/geometry/pose.h"
#include "swept/query/query.h"

#include <algorithm>
#include <limits>
#include <utility>
#include <vector>

namespace swept::test {

/// B's triangles in A's frame, indexed by input id.
inline std::vector<Triangle> b_in_a(const std::vector<Triangle>& b, const Pose& pose_a, const Pose& pose_b) {
  const Pose r = relative(pose_a, pose_b);
  std::vector<Triangle> out;
  out.reserve(b.size());
  for (const Triangle& t : b)
    out.push_back({r.rotation * t.p + r.translation, r.rotation * t.q + r.translation,
                   r.rotation * t.r + r.translation});
  return out;
}

struct BruteDistance {
  double distance = std::numeric_limits<double>::infinity();
  std::uint32_t a = 0, b = 0;
};

inline BruteDistance brute_distance(const std::vector<Triangle>& a, const std::vector<Triangle>& b,
                                    const Pose& pose_a, const Pose& pose_b) {
  const std::vector<Triangle> bb = b_in_a(b, pose_a, pose_b);
  BruteDistance best;
  for (std::uint32_t i = 0; i < a.size(); ++i)
    for (std::uint32_t j = 0; j < bb.size(); ++j) {
      const double d = triangle_distance(a[i], bb[j]).distance;
      if (d < best.distance) best = {d, i, j};
    }
  return best;
}

inline std::vector<std::pair<std::uint32_t, std::uint32_t>> brute_contacts(
    const std::vector<Triangle>& a, const std::vector<Triangle>& b, const Pose& pose_a,
    const Pose& pose_b) {
  const std::vector<Triangle> bb = b_in_a(b, pose_a, pose_b);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
  for (std::uint32_t i = 0; i < a.size(); ++i)
    for (std::uint32_t j = 0; j < bb.size(); ++j)
      if (triangles_intersect(a[i], bb[j])) out.emplace_back(i, j);
  return out;
}

}  // namespace swept::test
