// The final certification of a path (the planner's last phase, and `swept check`): every
// segment certified with the planner's certificate (checker.h, over the query layer's
// `certify_motion`), or, with an end in contact, by the contact layer's pull certificate
// (contact_moves.h), and the smallest exact distance found along it (docs/planner.md).
#include "swept/plan/check.h"

#include "checker.h"
#include "contact_moves.h"

#include <tbb/parallel_for.h>

#include <mutex>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace swept {
namespace {

using detail::Checker;

struct Minimum {
  double value = std::numeric_limits<double>::infinity();
  double t = 0.0;
};

// The smallest exact distance along a segment (pose_at(t), t in [0, 1]) with exact end values
// `d0`, `d1`: 15 samples in between, then a golden-section search around the smallest. A sample
// only matters when it is below the smallest so far, so its query stops as soon as it proves it
// is not (`below` gives +∞ then).
template <class PoseAt>
Minimum sampled_minimum(const Checker& check, const PoseAt& pose_at, double d0, double d1) {
  constexpr int kSamples = 16;
  int best = 0;
  Minimum m{d0, 0.0};
  for (int k = 1; k < kSamples; ++k) {
    const double t = static_cast<double>(k) / kSamples;
    const double d = check.below(pose_at(t), m.value);
    if (d < m.value) m = {d, t}, best = k;
  }
  if (d1 < m.value) m = {d1, 1.0}, best = kSamples;
  // Golden section: each new point is compared with the interior point kept from the last step
  // (exact), so its query may stop once it proves it is not below (+∞: the new point is dropped
  // at the next step, and the kept interior value is always exact).
  double lo = std::max(0.0, (best - 1.0) / kSamples), hi = std::min(1.0, (best + 1.0) / kSamples);
  const double g = (std::sqrt(5.0) - 1.0) / 2.0;
  double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
  double f1 = check.exact(pose_at(x1)), f2 = check.below(pose_at(x2), f1);
  for (int it = 0; it < 24; ++it) {
    if (f1 < f2) hi = x2, x2 = x1, f2 = f1, x1 = hi - g * (hi - lo), f1 = check.below(pose_at(x1), f2);
    else lo = x1, x1 = x2, f1 = f2, x2 = lo + g * (hi - lo), f2 = check.below(pose_at(x2), f1);
  }
  if (f1 < m.value) m = {f1, x1};
  if (f2 < m.value) m = {f2, x2};
  return m;
}

}  // namespace

PathCheckResult check_path(const Problem& problem, const PlanScene& scene, const Path& path,
                           const PathCheckOptions& options) {
  PathCheckResult out;
  const double margin = options.clearance.value_or(problem.clearance);
  out.clearance = margin;
  const Vec3 reference = options.reference_point.value_or(scene.reference);
  Checker check(scene, margin, reference);
  const std::vector<Pose>& poses = path.poses;
  if (poses.empty()) {
    out.message = "the path has no poses";
    return out;
  }
  auto pose_on = [&](std::size_t i, double t) {
    return t <= 0.0 ? poses[i] : (t >= 1.0 ? poses[i + 1] : interpolate(poses[i], poses[i + 1], t, reference));
  };

  std::vector<double> at_waypoint(poses.size());
  tbb::parallel_for(std::size_t{0}, poses.size(), [&](std::size_t w) { at_waypoint[w] = check.exact(poses[w]); });
  // A segment with an end in contact is a pull, certified by the contact model from that end
  // (docs/planner.md, "The contact model").
  const std::size_t segments = poses.size() - 1;
  const bool contact_allowed = problem.contact_tolerance > 0.0;
  std::optional<detail::ContactMoves> contact;
  for (std::size_t i = 0; i < segments && contact_allowed && !contact; ++i)
    if (at_waypoint[i] <= margin || at_waypoint[i + 1] <= margin) contact.emplace(scene, margin, problem.contact_tolerance);

  out.segments.resize(segments);
  std::mutex progress_mutex;
  std::size_t segments_done = 0;
  tbb::parallel_for(std::size_t{0}, segments, [&](std::size_t i) {
    struct Report {  // on every way out of the segment's check
      const PathCheckOptions& options;
      std::mutex& mutex;
      std::size_t& done;
      std::size_t total;
      ~Report() {
        if (!options.progress) return;
        const std::lock_guard lock(mutex);
        options.progress(++done, total);
      }
    } report{options, progress_mutex, segments_done, segments};
    SegmentCheck& sc = out.segments[i];
    auto pose_at = [&](double t) { return pose_on(i, t); };
    // Where the certificate stopped: the parameter and the distance found there (≤ the
    // margin), or t = −1 when it gave up (query cap, parameter resolution).
    double t_blocked = -1.0, distance_at_block = 0.0;
    if (contact && (at_waypoint[i] <= margin || at_waypoint[i + 1] <= margin)) {
      sc.in_contact = true;
      const bool translation = rotation_angle(poses[i].rotation, poses[i + 1].rotation) <= 1e-12;
      const bool from_start = at_waypoint[i] <= margin;
      const Pose& at = from_start ? poses[i] : poses[i + 1];
      const Vec3 move = (from_start ? 1.0 : -1.0) * (poses[i + 1].translation - poses[i].translation);
      const double length = move.norm();
      sc.certified = translation && (length == 0.0 || contact->pull_clear(contact->body_at(at), move / length, length));
      if (!sc.certified) t_blocked = from_start ? 0.0 : 1.0, distance_at_block = from_start ? at_waypoint[i] : at_waypoint[i + 1];
    } else {
      // The waypoints' exact distances are the certificate's end bounds.
      const Certificate c = check.certify(poses[i], at_waypoint[i], poses[i + 1], at_waypoint[i + 1], kMaxCertificateQueries,
                                          detail::Pieces::two_earliest);
      if (c.status == MotionStatus::blocked) t_blocked = c.t_blocked, distance_at_block = c.distance_at_block;
      sc.certified = c.clear();
    }
    // The smallest distance along the segment, reported beside the certificate's verdict.
    const Minimum m = sampled_minimum(check, pose_at, at_waypoint[i], at_waypoint[i + 1]);
    sc.min_distance = m.value;
    sc.t_min = m.t;
    if (!sc.certified) {
      sc.t_blocked = t_blocked;
      sc.distance_at_block = distance_at_block;
    }
  });

  // Solids overlapping with their surfaces apart (a body inside a closed part): decided at the
  // first waypoint whose surfaces do not touch; the certified motions never cross a surface, so
  // that answer holds for the whole path.
  std::optional<std::string> inside;
  for (std::size_t w = 0; w < poses.size() && !inside; ++w)
    if (at_waypoint[w] > 0.0) {
      inside = enclosure_at(scene, poses[w]);
      if (inside) *inside = "at waypoint " + std::to_string(w) + " " + *inside;
      break;
    }

  // Results read in order: the same at any thread count.
  out.min_clearance = at_waypoint[0];
  out.min_pose = poses[0];
  for (std::size_t i = 0; i < segments; ++i) {
    const SegmentCheck& sc = out.segments[i];
    if (sc.min_distance < out.min_clearance) {
      out.min_clearance = sc.min_distance;
      out.min_segment = i;
      out.min_t = sc.t_min;
      out.min_pose = pose_on(i, sc.t_min);
    }
    if (sc.in_contact) ++out.contact_segments;
    if (!sc.certified && !out.first_bad_segment) {
      out.first_bad_segment = i;
      const double t = std::max(sc.t_blocked, 0.0);
      out.first_bad_pose = pose_on(i, t);
      out.first_bad_distance = sc.t_blocked >= 0.0 ? sc.distance_at_block : check.exact(out.first_bad_pose);
    }
  }
  out.distance_queries = check.distance_queries();
  out.sweeps = check.sweeps() + (contact ? contact->sweeps() : 0);
  std::ostringstream os;
  if (inside) {
    out.valid = false;
    out.min_clearance = 0.0;
    out.min_segment = 0;
    out.min_t = 0.0;
    out.min_pose = poses[0];
    out.first_bad_segment = 0;
    out.first_bad_pose = poses[0];
    out.first_bad_distance = 0.0;
    os << "not valid: " << *inside;
  } else if (segments == 0) {
    out.valid = at_waypoint[0] > margin;
    os << (out.valid ? "valid: a single pose, " : "not valid: a single pose ") << "at distance " << at_waypoint[0]
       << " (clearance " << margin << ")";
  } else if (!out.first_bad_segment) {
    out.valid = true;
    if (segments == 1) os << "valid: the one segment keeps the clearance " << margin;
    else os << "valid: every one of the " << segments << " segments keeps the clearance " << margin;
    if (out.contact_segments > 0)
      os << " (" << out.contact_segments << (out.contact_segments == 1 ? " segment in contact, certified as a pull"
                                                                       : " segments in contact, each certified as a pull")
         << " by the mate rule, tolerance " << problem.contact_tolerance << ")";
  } else {
    const std::size_t i = *out.first_bad_segment;
    const SegmentCheck& sc = out.segments[i];
    os << "not valid: segment " << i << " (waypoint " << i << " to " << i + 1 << ") ";
    if (sc.in_contact && rotation_angle(poses[i].rotation, poses[i + 1].rotation) > 1e-12)
      os << "has an end in contact but rotates (a motion in contact must be a pure translation)";
    else if (sc.in_contact)
      os << "has an end in contact and is not a pull the mate rule allows (tolerance " << problem.contact_tolerance
         << "): a pair that is no mate comes within the clearance " << margin << ", or a mate reaches deeper than the tolerance";
    else if (sc.t_blocked < 0.0)
      os << "could not be certified within the query cap (it grazes the clearance)";
    else if (sc.distance_at_block <= 0.0)
      os << "is in collision at t = " << sc.t_blocked;
    else
      os << "comes within " << sc.distance_at_block << " at t = " << sc.t_blocked << " (clearance " << margin << ")";
  }
  out.message = os.str();
  return out;
}

}  // namespace swept
