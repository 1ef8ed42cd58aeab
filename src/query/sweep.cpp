// Exact clearance of a pure translation in one traversal of the two trees (sweep_translation,
// motion.h). The positions of a convex piece of B along a straight translation fill its
// Minkowski sum with the segment: for a node, the zonotope of its rectangle and the segment
// grown by its radius; for a triangle, a prism. So a node pair is bounded once for the whole
// motion and a leaf pair is decided exactly, instead of bounding the distance at poses along it
// as the certificate does. Straight pulls of mounted parts (src/assembly/pulls.cpp) are exactly
// this motion, and their sliding mates, which a certificate must revisit at every pose it asks,
// are visited once.
#include "swept/query/motion.h"

#include "swept/geometry/distance.h"
#include "traversal.h"

namespace swept {

SweepResult sweep_translation(const Bvh& a, const Pose& pose_a, const Bvh& b, const Pose& pose_b,
                              const SweepRequest& request) {
  SweepResult out;
  if (a.empty() || b.empty()) return out;
  const detail::Relative rel(pose_a, pose_b);
  // The translation in A's model frame.
  const Vec3 sweep = pose_a.rotation.transpose() * request.translation;
  const double margin = std::max(request.margin, 0.0);
  auto near = [&](std::int32_t ia, std::int32_t ib, const Rss& na, detail::PlacedRss& pb) {
    ++out.stats.bv_tests;
    const double radii = na.radius + pb.rss.radius;
    const RectanglePair pair = detail::node_pair(na, pb.rss, pb);
    if (swept_rectangle_lower_bound(pair, na.axes.transpose() * sweep, margin + radii) - radii > margin) return false;
    return !(request.exclude_nodes_if && (*request.exclude_nodes_if)(ia, ib));
  };
  auto leaves = [&](const Node& na, const Node& nb) {
    for (std::int32_t j = nb.first; j < nb.first + nb.count; ++j) {
      const Triangle tb = rel.apply(b.triangles[j]);
      for (std::int32_t i = na.first; i < na.first + na.count; ++i) {
        ++out.stats.triangle_tests;
        if (!triangle_sweep_within(a.triangles[i], tb, sweep, margin)) continue;
        if (request.exclude_if && (*request.exclude_if)(a.triangle_ids[i], b.triangle_ids[j])) continue;
        out.clear = false;
        out.triangle_a = a.triangle_ids[i];
        out.triangle_b = b.triangle_ids[j];
        return false;
      }
    }
    return true;
  };
  detail::for_each_leaf_pair(a, b, rel, near, leaves);
  return out;
}

}  // namespace swept
