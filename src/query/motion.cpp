// Certified clearance of a straight SE(3) motion (Schwarzer, Saha, Latombe 2005, "Adaptive
// dynamic collision checking for single and multiple articulated robots in complex
// environments"): a sub-segment [t0, t1] is free when no body point can travel farther than
// the clearances at its ends allow, L(t0, t1) < (D(t0) − margin) + (D(t1) − margin); otherwise
// it is bisected. Distances are asked only for what the certificate needs (`enough`).
#include "swept/query/query.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace swept {

double motion_radius(const Bvh& b, const Vec3& reference) {
  double r2 = 0.0;
  for (const Triangle& t : b.triangles)
    for (int i = 0; i < 3; ++i) r2 = std::max(r2, (t[i] - reference).squaredNorm());
  return std::sqrt(r2);
}

double motion_length(const Pose& from, const Pose& to, const Vec3& reference, double radius) {
  const double travel = (to.apply(reference) - from.apply(reference)).norm();
  // atan2 keeps small angles accurate (acos of a cosine near 1 loses half the digits).
  const Quat q(from.rotation.transpose() * to.rotation);
  const double angle = 2.0 * std::atan2(q.vec().norm(), std::abs(q.w()));
  return travel + radius * angle;
}

MotionResult motion_clearance(const Bvh& a, const Pose& pose_a, const Bvh& b, const Pose& from,
                              const Pose& to, const MotionRequest& request) {
  MotionResult out;
  const double m = request.margin;
  // The sub-segment [t0, t1] of the interpolated motion has length (t1 − t0)·total: the
  // reference point moves linearly and the slerp turns at a constant rate. The relative
  // allowance covers rounding in the interpolated poses.
  const double total =
      motion_length(from, to, request.reference, request.radius) * (1.0 + 1e-9);

  auto clearance = [&](double t, double enough) {
    const Pose pose = t == 0.0 ? from : (t == 1.0 ? to : interpolate(from, to, t, request.reference));
    const DistanceResult d = distance(a, pose_a, b, pose, {.enough = enough});
    ++out.distance_queries;
    out.stats.bv_tests += d.stats.bv_tests;
    out.stats.triangle_tests += d.stats.triangle_tests;
    out.min_distance = std::min(out.min_distance, d.distance);
    return d.distance;
  };
  auto blocked = [&](double t, double d) {
    out.free = false;
    out.t_blocked = t;
    out.distance_at_block = d;
    return out;
  };

  // The first end alone certifies everything when D(0) − m > total.
  const double d0 = clearance(0.0, std::max(m, total + m));
  // Contact always blocks, so a zero margin means collision-free.
  auto too_close = [m](double d) { return d < m || d <= 0.0; };
  if (too_close(d0)) return blocked(0.0, d0);
  if (out.distance_queries >= request.max_queries) return out;
  const double d1 = clearance(1.0, std::max(m, total + 2.0 * m - d0));
  if (too_close(d1)) return blocked(1.0, d1);

  struct Segment {
    double t0, t1, d0, d1;
  };
  std::vector<Segment> stack;  // depth first, earliest sub-segment first
  stack.push_back({0.0, 1.0, d0, d1});
  while (!stack.empty()) {
    const Segment s = stack.back();
    stack.pop_back();
    const double length = (s.t1 - s.t0) * total;
    if (length < (s.d0 - m) + (s.d1 - m)) continue;  // certified free
    const double tm = 0.5 * (s.t0 + s.t1);
    if (out.distance_queries >= request.max_queries || !(tm > s.t0 && tm < s.t1)) {
      return out;  // not certified (cap reached or parameter resolution exhausted)
    }
    const double half = 0.5 * length;
    const double need = std::max({m, half + 2.0 * m - s.d0, half + 2.0 * m - s.d1});
    const double dm = clearance(tm, need);
    if (too_close(dm)) return blocked(tm, dm);
    stack.push_back({tm, s.t1, dm, s.d1});
    stack.push_back({s.t0, tm, s.d0, dm});
  }
  out.free = true;
  return out;
}

}  // namespace swept
