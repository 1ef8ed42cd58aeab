#pragma once
// Problems generated for the planner tests, and an independent dense check of returned paths.
#include "support/test_support.h"
#include "swept/plan/planner.h"
#include "swept/query/query.h"

#include <gtest/gtest.h>

#include <vector>

namespace swept::test {

/// Appends the 12 triangles of the box [lo, hi].
inline void add_box(std::vector<Triangle>& out, const Vec3& lo, const Vec3& hi) {
  auto b = box_triangles(lo, hi);
  out.insert(out.end(), b.begin(), b.end());
}

struct GeneratedProblem {
  Problem problem;
  TriangleSoup obstacles, body;
};

inline PlanScene scene_of(const GeneratedProblem& g, Fitter fitter = Fitter::inertia) {
  auto s = make_scene(g.obstacles, g.body, fitter, g.problem.reference_point);
  EXPECT_TRUE(s) << s.error().message;
  return std::move(*s);
}

/// A square peg of width w in a blind square hole with radial clearance c (0.1 % of w), pulled
/// out upwards. The peg's frame is at its centre.
inline GeneratedProblem peg_in_hole(double w = 10.0, double clearance_fraction = 1e-3) {
  GeneratedProblem g;
  const double c = clearance_fraction * w, depth = 2 * w, wall = w;
  const double h = w / 2 + c;  // half width of the hole
  auto& o = g.obstacles.triangles;
  add_box(o, Vec3(-h - wall, -h - wall, -depth - wall), Vec3(h + wall, h + wall, -depth));  // bottom
  add_box(o, Vec3(-h - wall, -h - wall, -depth), Vec3(-h, h + wall, 0));                 // four walls
  add_box(o, Vec3(h, -h - wall, -depth), Vec3(h + wall, h + wall, 0));
  add_box(o, Vec3(-h, -h - wall, -depth), Vec3(h, -h, 0));
  add_box(o, Vec3(-h, h, -depth), Vec3(h, h + wall, 0));
  const double len = 2.5 * w;
  add_box(g.body.triangles, Vec3(-w / 2, -w / 2, -len / 2), Vec3(w / 2, w / 2, len / 2));
  g.problem.start = Pose::from_translation(Vec3(0, 0, -depth + c + len / 2));
  g.problem.goal_outside = true;
  g.problem.goal_margin = 0.0;
  g.problem.clearance = c / 5;
  g.problem.time_limit = 60;
  return g;
}

/// A T-shaped slider in a T-slot open towards +x: it must slide out along x, then lift to a
/// goal above the block.
inline GeneratedProblem t_slot() {
  GeneratedProblem g;
  auto& o = g.obstacles.triangles;
  // Block [−20, 20] × [−15, 15] × [−10, 0] with a T-slot along x: a narrow neck |y| < 3 for
  // z ∈ [−3, 0] and a wide channel |y| < 8 for z ∈ [−9, −3]; closed at x = −20 by an end wall.
  add_box(o, Vec3(-20, -15, -10), Vec3(20, 15, -9));  // floor
  add_box(o, Vec3(-20, -15, -9), Vec3(20, -8, 0));     // side walls
  add_box(o, Vec3(-20, 8, -9), Vec3(20, 15, 0));
  add_box(o, Vec3(-20, -8, -3), Vec3(20, -3, 0));      // lips
  add_box(o, Vec3(-20, 3, -3), Vec3(20, 8, 0));
  add_box(o, Vec3(-22, -15, -10), Vec3(-20, 15, 0));   // end wall
  auto& b = g.body.triangles;
  add_box(b, Vec3(-6, -7, -8.5), Vec3(6, 7, -3.5));  // head in the channel
  add_box(b, Vec3(-6, -2.5, -3.5), Vec3(6, 2.5, 4));  // stem through the neck, sticking out
  g.problem.start = Pose::from_translation(Vec3(0, 0, 0));
  g.problem.goal = Pose::from_translation(Vec3(35, 0, 25));
  g.problem.clearance = 0.05;
  g.problem.rotation = RotationMode::none;
  g.problem.time_limit = 60;
  return g;
}

/// A cube through an L-shaped tunnel: in along +x, then up along +z.
inline GeneratedProblem l_tunnel() {
  GeneratedProblem g;
  auto& o = g.obstacles.triangles;
  // Solid block [0, 40] × [−10, 10] × [−10, 40] minus the tunnel: horizontal leg
  // x ∈ [0, 30], |y| < 5, z ∈ [−5, 5]; vertical leg x ∈ [20, 30], |y| < 5, z ∈ [−5, 40].
  add_box(o, Vec3(0, -10, -10), Vec3(40, 10, -5));   // floor
  add_box(o, Vec3(0, -10, -5), Vec3(40, -5, 40));    // sides
  add_box(o, Vec3(0, 5, -5), Vec3(40, 10, 40));
  add_box(o, Vec3(0, -5, 5), Vec3(20, 5, 40));       // roof of the horizontal leg
  add_box(o, Vec3(30, -5, -5), Vec3(40, 5, 40));     // far wall
  add_box(g.body.triangles, Vec3(-3.5, -3.5, -3.5), Vec3(3.5, 3.5, 3.5));
  g.problem.start = Pose::from_translation(Vec3(-8, 0, 0));  // in front of the entrance
  g.problem.goal = Pose::from_translation(Vec3(25, 0, 48));  // above the exit
  g.problem.clearance = 0.1;
  g.problem.rotation = RotationMode::none;
  g.problem.bounds = Aabb{Vec3(-12, -12, -12), Vec3(45, 12, 55)};
  g.problem.time_limit = 60;
  return g;
}

/// A bar longer than a slot is wide: it must turn to pass through the wall.
inline GeneratedProblem bar_through_slot() {
  GeneratedProblem g;
  auto& o = g.obstacles.triangles;
  // Wall x ∈ [−1, 1], y, z ∈ [−20, 20], with a slot |y| < 4, |z| < 2.
  add_box(o, Vec3(-1, -20, -20), Vec3(1, -4, 20));
  add_box(o, Vec3(-1, 4, -20), Vec3(1, 20, 20));
  add_box(o, Vec3(-1, -4, -20), Vec3(1, 4, -2));
  add_box(o, Vec3(-1, -4, 2), Vec3(1, 4, 20));
  add_box(g.body.triangles, Vec3(-0.75, -7, -0.75), Vec3(0.75, 7, 0.75));  // 14 long, along y
  g.problem.start = Pose::from_translation(Vec3(-10, 0, 0));
  g.problem.goal = Pose::from_translation(Vec3(10, 0, 0));
  g.problem.clearance = 0.05;
  g.problem.bounds = Aabb{Vec3(-14, -10, -10), Vec3(14, 10, 10)};
  g.problem.time_limit = 120;
  return g;
}

/// A body shut inside a closed box: no path.
inline GeneratedProblem enclosed() {
  GeneratedProblem g;
  auto& o = g.obstacles.triangles;
  add_box(o, Vec3(-10, -10, -10), Vec3(10, 10, -8));
  add_box(o, Vec3(-10, -10, 8), Vec3(10, 10, 10));
  add_box(o, Vec3(-10, -10, -8), Vec3(-8, 10, 8));
  add_box(o, Vec3(8, -10, -8), Vec3(10, 10, 8));
  add_box(o, Vec3(-8, -10, -8), Vec3(8, -8, 8));
  add_box(o, Vec3(-8, 8, -8), Vec3(8, 10, 8));
  add_box(g.body.triangles, Vec3(-2, -2, -2), Vec3(2, 2, 2));
  g.problem.start = Pose{};
  g.problem.goal_outside = true;
  g.problem.clearance = 0.1;
  g.problem.rotation = RotationMode::none;
  g.problem.time_limit = 5;
  return g;
}

/// Independent check of a path, with the query layer only: exact distance at ≥ 10^4 poses
/// spread over the segments by length, and the motion-clearance certificate of each segment.
/// Returns the smallest sampled distance. `skip_first` leaves the first segment (an escape from
/// contact) out of both checks.
inline double verify_path(const PlanScene& s, const Path& path, double margin, bool skip_first = false) {
  EXPECT_GE(path.poses.size(), 1u);
  const double r = motion_radius(s.body_tree, s.reference);
  double total = 0;
  std::vector<double> len;
  for (std::size_t i = 0; i + 1 < path.poses.size(); ++i) {
    len.push_back(motion_length(path.poses[i], path.poses[i + 1], s.reference, r));
    total += len.back();
  }
  double min_d = std::numeric_limits<double>::infinity();
  for (std::size_t i = skip_first ? 1 : 0; i + 1 < path.poses.size(); ++i) {
    const int n = std::max(64, static_cast<int>(std::ceil(10000.0 * len[i] / std::max(total, 1e-300))));
    for (int k = 0; k <= n; ++k) {
      const Pose q = interpolate(path.poses[i], path.poses[i + 1], static_cast<double>(k) / n, s.reference);
      const double d = distance(s.obstacle_tree, Pose{}, s.body_tree, q).distance;
      min_d = std::min(min_d, d);
    }
    const MotionResult m = motion_clearance(s.obstacle_tree, Pose{}, s.body_tree, path.poses[i], path.poses[i + 1],
                                            {.margin = margin, .reference = s.reference, .radius = r});
    EXPECT_TRUE(m.free) << "segment " << i << " not certified (blocked at t=" << m.t_blocked << ")";
  }
  EXPECT_GE(min_d, margin) << "the path comes closer than the margin";
  return min_d;
}

}  // namespace swept::test
