// Distance bounds against the obstacles and the certificate of a straight motion, for the
// planner's phases and the final certification (checker.h).
#include "checker.h"

namespace swept::detail {

double Checker::clearance(const Pose& pose, double enough, bool relaxed) const {
  ++distance_queries_;
  const DistanceRequest request{.enough = enough, .exclude = relaxed ? &exempt_ : nullptr};
  return distance(scene_.obstacle_tree, Pose{}, scene_.body_tree, pose, request).distance;
}

DistanceResult Checker::nearest(const Pose& pose, double enough) const {
  ++distance_queries_;
  return distance(scene_.obstacle_tree, Pose{}, scene_.body_tree, pose, {.enough = enough});
}

double Checker::below(const Pose& pose, double bound, bool relaxed) const {
  ++distance_queries_;
  const DistanceRequest request{.enough = bound, .exclude = relaxed ? &exempt_ : nullptr};
  const DistanceResult d = distance(scene_.obstacle_tree, Pose{}, scene_.body_tree, pose, request);
  return d.exact ? d.distance : std::numeric_limits<double>::infinity();
}

Certificate Checker::certify(const Pose& a, double da, const Pose& b, double db, bool relaxed) const {
  // Coherence: each query of the certificate starts from the previous one's closest pair.
  DistanceHint hint;
  auto bound = [&](const Pose& pose, double enough) {
    ++distance_queries_;
    const DistanceRequest request{.enough = enough, .exclude = relaxed ? &exempt_ : nullptr, .hint = hint};
    const DistanceResult d = distance(scene_.obstacle_tree, Pose{}, scene_.body_tree, pose, request);
    if (d.hint.valid()) hint = d.hint;
    return d.distance;
  };
  const Certificate c = certify_motion(motion(a, b), bound,
                                       {.margin = margin_, .deadline = deadline_, .from_bound = da, .to_bound = db});
  if (c.status == MotionStatus::refused_cap) ++cap_refusals_;
  return c;
}

}  // namespace swept::detail
