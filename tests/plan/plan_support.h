#pragma once
// Problems generated for the planner tests, and an independent dense check of returned paths.
#include "support/test_support.h"
#include "swept/plan/planner.h"
#include "swept/query/query.h"
#include "swept/scenes/box_problems.h"

#include <gtest/gtest.h>

#include <vector>

namespace swept::test {

using scenes::GeneratedProblem;

inline PlanScene scene_of(const GeneratedProblem& g, Fitter fitter = Fitter::inertia) {
  auto s = make_scene(g.obstacles, g.body, fitter, g.problem.reference_point);
  EXPECT_TRUE(s) << s.error().message;
  return std::move(*s);
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
