// Distance bounds against the obstacles and the certificate of a straight motion, for the
// planner's phases and the final certification (checker.h).
#include "checker.h"

#include <array>
#include <cmath>
#include <limits>

namespace swept::detail {

DistanceResult Checker::query(const Pose& pose, double enough, DistanceHint hint, bool decide,
                              std::span<const DistanceHint> suspects) const {
  ++distance_queries_;
  const DistanceRequest request{.enough = enough, .hint = hint,
                                .stop_below = decide && decide_blocked_ ? margin_ : -std::numeric_limits<double>::infinity(),
                                .suspects = suspects};
  return distance(scene_.obstacle_tree, Pose{}, scene_.body_tree, pose, request);
}

DistanceResult Checker::measure(const Pose& pose, double enough, Suspects* suspects) const {
  if (!suspects) return query(pose, enough);
  const DistanceResult r = query(pose, enough, {}, true, suspects->pairs);
  suspects->add(r.hint);
  return r;
}

double Checker::clearance(const Pose& pose, double enough) const {
  return query(pose, enough).distance;
}

bool Checker::free(const Pose& pose) const {
  // Exact below the next double above the margin, a lower bound at or above it otherwise: either
  // way "above the margin" is decided.
  const double above = std::nextafter(margin_, std::numeric_limits<double>::infinity());
  return query(pose, above).distance > margin_;
}

bool Checker::blocked_at_samples(const Pose& a, const Pose& b) const {
  const Motion m = motion(a, b);
  for (const double t : {0.5, 0.25, 0.75, 0.125, 0.375, 0.625, 0.875})
    if (!free(m.at(t))) return true;
  return false;
}

DistanceResult Checker::nearest(const Pose& pose, double enough) const {
  return query(pose, enough, {}, false);
}

double Checker::below(const Pose& pose, double bound) const {
  const DistanceResult d = query(pose, bound, {}, false);
  return d.exact ? d.distance : std::numeric_limits<double>::infinity();
}

Certificate Checker::certify(const Pose& a, double da, const Pose& b, double db, int max_queries, Pieces pieces, std::array<const std::atomic<bool>*, 2> cancel) const {
  // Coherence: each query of the certificate starts from the previous one's closest pair on
  // its lane.
  std::array<DistanceHint, 2> hints;
  auto bound = [&](const Pose& pose, double enough, int lane) {
    const DistanceResult d = query(pose, enough, hints[lane]);
    if (d.hint.valid()) hints[lane] = d.hint;
    return d.distance;
  };
  CertificateOptions options{.margin = margin_, .max_queries = max_queries, .deadline = deadline_, .cancel = cancel,
                             .from_bound = da, .to_bound = db,
                             .from_both_ends = pieces == Pieces::earliest_and_latest};
  // A translation that grazes the margin: the certificate's pieces shrink with the gap (a face
  // sliding along another at a hair above the margin needs thousands of them), while the sweep
  // bounds each node pair once for the whole motion. Short of that, the certificate is cheaper
  // (it stops at a blocked end or decides a free motion in a few queries), and a blocked
  // translation goes on with it, for where it is blocked. A motion that turns by a hair (its
  // ends' rotations differ by rounding) is swept with the margin raised by how far the turn
  // strays (`as_translation`).
  const Motion m = motion(a, b);
  if (max_queries > kSweepAfter) {
    options.decide_after = kSweepAfter;
    options.decide = [&](double smallest) {
      const std::optional<SweepResult> s =
          sweep_as_translation(scene_.obstacle_tree, Pose{}, scene_.body_tree, m, margin_, smallest);
      if (!s) return false;  // turns too far to be swept
      ++sweeps_;
      return s->clear;
    };
  }
  auto one_lane = [&](const Pose& pose, double enough) { return bound(pose, enough, 0); };
  const Certificate c = pieces == Pieces::one ? certify_motion(m, one_lane, options)
                                              : certify_motion_paired(m, bound, options);
  if (c.status == MotionStatus::refused_cap && max_queries == kMaxCertificateQueries) ++cap_refusals_;
  return c;
}

}  // namespace swept::detail
