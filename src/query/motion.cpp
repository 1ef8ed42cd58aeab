// Certified clearance of a straight SE(3) motion (Schwarzer, Saha, Latombe 2005, "Adaptive
// dynamic collision checking for single and multiple articulated robots in complex
// environments"): a sub-segment [t0, t1] is free when no body point can travel farther than
// the clearances at its ends allow, L(t0, t1) < (D(t0) − margin) + (D(t1) − margin); otherwise
// it is bisected. The one certificate of the library: motion_clearance, the planner's search
// and its final certification (src/plan/checker.h) all run `certify_motion`.
#include "swept/query/motion.h"

#include "swept/geometry/assert.h"

#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <vector>

namespace swept {

double motion_radius(const Bvh& b, const Vec3& reference) {
  double r2 = 0.0;
  // Every vertex of the tree once (its triangles share them).
  for (const Vec3& v : b.triangles.vertices) r2 = std::max(r2, (v - reference).squaredNorm());
  return std::sqrt(r2);
}

double motion_length(const Pose& from, const Pose& to, const Vec3& reference, double radius) {
  const double travel = (to.apply(reference) - from.apply(reference)).norm();
  // atan2 keeps small angles accurate (acos of a cosine near 1 loses half the digits).
  const Quat q(from.rotation.transpose() * to.rotation);
  const double angle = 2.0 * std::atan2(q.vec().norm(), std::abs(q.w()));
  return travel + radius * angle;
}

TranslationBound as_translation(const Motion& motion) {
  if (motion.from.rotation == motion.to.rotation) return {motion.to.translation - motion.from.translation, 0.0};
  const Quat q(motion.from.rotation.transpose() * motion.to.rotation);
  const double angle = 2.0 * std::atan2(q.vec().norm(), std::abs(q.w()));
  // The relative allowances cover rounding in the angle and in the interpolated rotations.
  return {motion.to.apply(motion.reference) - motion.from.apply(motion.reference),
          motion.radius * (angle * (1.0 + 1e-9) + 1e-15)};
}

std::optional<SweepResult> sweep_as_translation(const Bvh& a, const Pose& pose_a, const Bvh& b, const Motion& motion,
                                                double margin, double smallest,
                                                const std::function<bool(std::uint32_t, std::uint32_t)>* exclude_if) {
  const TranslationBound shift = as_translation(motion);
  if (!(shift.slack < 0.5 * (smallest - margin))) return std::nullopt;
  return sweep_translation(a, pose_a, b, motion.from,
                           {.translation = shift.translation, .margin = margin + shift.slack, .exclude_if = exclude_if});
}

Pose Motion::at(double t) const {
  return t <= 0.0 ? from : (t >= 1.0 ? to : interpolate(from, to, t, reference));
}

namespace {

// The certificate (motion.h), one piece or two pieces at a time (`width`).
Certificate certify(const Motion& motion, const LaneDistanceBound& distance_at, const CertificateOptions& options,
                    int width) {
  Certificate out;
  SWEPT_ASSERT(motion.radius >= 0.0, "Motion::radius must be given (motion_radius of the body)");
  if (!(motion.radius >= 0.0)) {
    out.status = MotionStatus::invalid_motion;
    return out;
  }
  const double m = options.margin;
  SWEPT_ASSERT(m >= 0.0, "the certificate's margin must be ≥ 0");
  // The sub-segment [t0, t1] has length (t1 − t0)·total: the reference point moves linearly
  // and the slerp turns at a constant rate. The relative allowance covers rounding in the
  // interpolated poses.
  const double total = motion.length() * (1.0 + 1e-9);
  auto seen = [&](double d) {
    ++out.distance_queries;
    out.min_distance = std::min(out.min_distance, d);
  };
  auto blocked = [&](double t, double d) {
    out.status = MotionStatus::blocked;
    out.t_blocked = t;
    out.distance_at_block = d;
    return out;
  };
  // Contact always blocks: with margin 0 a pose blocks at distance 0. The `enough` asked for
  // is always above the margin, so a bound returned at or below the margin is exact.
  double d0 = options.from_bound, d1 = options.to_bound;
  const bool ask0 = !(d0 >= 0.0), ask1 = !(d1 >= 0.0);
  if (ask0 && ask1 && width == 2) {
    tbb::parallel_invoke([&] { d0 = distance_at(motion.at(0.0), m + total, 0); },
                         [&] { d1 = distance_at(motion.at(1.0), m + total, 1); });
  } else {
    if (ask0) d0 = distance_at(motion.at(0.0), m + total, 0);
    if (ask1) d1 = distance_at(motion.at(1.0), m + total, 0);
  }
  if (ask0) seen(d0);
  if (ask1) seen(d1);
  out.min_distance = std::min({out.min_distance, d0, d1});
  if (d0 <= m) return blocked(0.0, d0);
  if (d1 <= m) return blocked(1.0, d1);

  struct Piece {
    double t0, d0, t1, d1;
  };
  struct Ask {
    Piece piece;
    double tm, enough, dm;
    bool from_back;  ///< taken from the back of the stack (`from_both_ends`); its halves go back there
  };
  // Depth first, in the order of the motion: the earliest piece at the front. Pieces are taken
  // from the front, and with `from_both_ends` the second of a pair from the back.
  std::deque<Piece> stack{{0.0, d0, 1.0, d1}};
  std::array<Ask, 2> asks{};
  int bisections = 0;
  while (!stack.empty()) {
    // The earliest `width` pieces not certified whole (with `from_both_ends`: the earliest and
    // the latest).
    int n = 0;
    while (n < width && !stack.empty()) {
      const bool back = n == 1 && options.from_both_ends;
      const Piece p = back ? stack.back() : stack.front();
      if (back) stack.pop_back();
      else stack.pop_front();
      const double length = total * (p.t1 - p.t0);
      if (length < (p.d0 - m) + (p.d1 - m)) continue;  // certified free
      // Too many pieces, or pieces too short to split, mean the motion grazes the margin:
      // ask the exact second opinion if there is one, else refuse rather than loop.
      const bool capped = ++bisections > options.max_queries || p.t1 - p.t0 < 1e-9;
      if ((capped || bisections > options.decide_after) && options.decide && !out.decided) {
        out.decided = true;
        if (options.decide(out.min_distance)) {
          out.status = MotionStatus::clear;
          return out;
        }
      }
      if (capped) {
        out.status = MotionStatus::refused_cap;
        return out;
      }
      if ((bisections & 63) == 0 && options.deadline && std::chrono::steady_clock::now() > *options.deadline) {
        out.status = MotionStatus::deadline;
        return out;
      }
      if (std::ranges::any_of(options.cancel, [](const std::atomic<bool>* c) { return c && c->load(std::memory_order_relaxed); })) {
        out.status = MotionStatus::cancelled;
        return out;
      }
      // Both halves are certified free once dm − m > length/2 − (min(d0, d1) − m) (positive
      // here, as the piece was not certified whole): the query need not be exact beyond that,
      // and stops sooner than it would at m + length/2. The pieces, and so the queries, are the
      // same.
      const double short_end = std::min(p.d0, p.d1) - m;
      const double need = 0.5 * length - std::max(0.0, short_end);
      asks[n++] = {p, 0.5 * (p.t0 + p.t1), m + need * (1.0 + 1e-9) + 1e-300, 0.0, back};
    }
    if (n == 0) break;
    auto ask = [&](int k) { asks[k].dm = distance_at(motion.at(asks[k].tm), asks[k].enough, k); };
    if (n == 2) tbb::parallel_invoke([&] { ask(0); }, [&] { ask(1); });
    else ask(0);
    for (int k = 0; k < n; ++k) seen(asks[k].dm);
    for (int k = 0; k < n; ++k)
      if (asks[k].dm <= m) return blocked(asks[k].tm, asks[k].dm);
    for (int k = n - 1; k >= 0; --k) {
      const Ask& a = asks[k];
      if (a.from_back) {
        stack.push_back({a.piece.t0, a.piece.d0, a.tm, a.dm});
        stack.push_back({a.tm, a.dm, a.piece.t1, a.piece.d1});
      } else {
        stack.push_front({a.tm, a.dm, a.piece.t1, a.piece.d1});
        stack.push_front({a.piece.t0, a.piece.d0, a.tm, a.dm});
      }
    }
  }
  out.status = MotionStatus::clear;
  return out;
}

}  // namespace

Certificate certify_motion(const Motion& motion, const DistanceBound& distance_at, const CertificateOptions& options) {
  return certify(motion, [&](const Pose& pose, double enough, int) { return distance_at(pose, enough); }, options, 1);
}

Certificate certify_motion_paired(const Motion& motion, const LaneDistanceBound& distance_at,
                                  const CertificateOptions& options) {
  return certify(motion, distance_at, options, 2);
}

MotionResult motion_clearance(const Bvh& a, const Pose& pose_a, const Bvh& b, const Motion& motion,
                              const MotionRequest& request) {
  MotionResult out;
  DistanceHint hint;  // coherence: each query starts from the previous one's closest pair
  auto tree_distance = [&](const Pose& pose, double enough) {
    const DistanceResult d = distance(a, pose_a, b, pose, {.enough = enough, .hint = hint});
    if (d.hint.valid()) hint = d.hint;
    out.stats.bv_tests += d.stats.bv_tests;
    out.stats.triangle_tests += d.stats.triangle_tests;
    return d.distance;
  };
  CertificateOptions options{.margin = request.margin, .max_queries = request.max_queries};
  if (request.sweep_after >= 0) {
    options.decide_after = request.sweep_after;
    options.decide = [&](double smallest) {
      const std::optional<SweepResult> s = sweep_as_translation(a, pose_a, b, motion, request.margin, smallest);
      if (!s) return false;
      ++out.sweeps;
      out.stats.bv_tests += s->stats.bv_tests;
      out.stats.triangle_tests += s->stats.triangle_tests;
      return s->clear;
    };
  }
  const Certificate c = certify_motion(motion, tree_distance, options);
  out.status = c.status;
  out.t_blocked = c.t_blocked;
  out.distance_at_block = c.distance_at_block;
  out.min_distance = c.min_distance;
  out.distance_queries = c.distance_queries;
  return out;
}

}  // namespace swept
