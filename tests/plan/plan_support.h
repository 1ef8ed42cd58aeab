#pragma once
// Problems generated for the planner tests, and independent checks of returned paths: a dense
// check with swept's query layer (verify_path), and check_independently with the oracle of
// tests/oracle, which shares no code with swept.
#include "oracle/path_oracle.h"
#include "support/test_support.h"
#include "swept/plan/planner.h"
#include "swept/query/query.h"
#include "swept/scenes/box_problems.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>
#include <vector>

namespace swept::test {

using scenes::GeneratedProblem;

inline PlanScene scene_of(const GeneratedProblem& g, Fitter fitter = Fitter::inertia) {
  auto s = make_scene(g.obstacles, g.body, {.fitter = fitter}, g.problem.reference_point);
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
    const MotionResult m = motion_clearance(s.obstacle_tree, Pose{}, s.body_tree,
                                            {path.poses[i], path.poses[i + 1], s.reference, r}, {.margin = margin});
    EXPECT_TRUE(m.clear()) << "segment " << i << " not certified (blocked at t=" << m.t_blocked << ")";
  }
  EXPECT_GE(min_d, margin) << "the path comes closer than the margin";
  return min_d;
}

/// What the planner said about a path, where known (the command line prints it with --json).
struct PlannerFigures {
  std::optional<double> min_clearance;     ///< PlanResult::min_clearance
  std::optional<std::size_t> contact_segments;  ///< escape + approach segments
};

inline std::vector<oracle::Tri> oracle_triangles(const TriangleSoup& soup) {
  std::vector<oracle::Tri> out;
  out.reserve(soup.triangles.size());
  for (const Triangle& t : soup.triangles) out.push_back({{t.p, t.q, t.r}});
  return out;
}

/// The path checked by the oracle (tests/oracle): every segment certified with its own exact
/// distances, the contact rule of docs/planner.md by its consequence (no two triangles reach more
/// than the tolerance into each other), and the planner's figures compared with the oracle's
/// dense minimum.
///
/// The bound asserted on a reported minimum m (min_clearance over all pairs and segments), with D_min the oracle's smallest
/// exact distance at its dense samples, h their largest spacing (motion metric) and L the
/// longest segment:
///   D_min − h/2 − 1e-9  ≤  m  ≤  D_min + L/32 + 1e-9.
/// Lower: m is an exact distance at some pose on the path, so m ≥ the true minimum; distance
/// changes no faster than the motion metric, so the true minimum is ≥ D_min − h/2. Upper: the
/// planner samples every segment at 17 equally spaced points (its waypoints and 15 inside, then
/// a golden-section search that can only lower the minimum), so the true minimum lies within
/// L/32 of one of its samples and m ≤ true minimum + L/32 ≤ D_min + L/32. 1e-9 absorbs
/// rounding (paths written as text included).
inline oracle::PathCheckReport check_path_independently(const PlanScene& s, const Problem& problem, const Path& path,
                                                        const PlannerFigures& figures = {}) {
  oracle::PathCheckInput in;
  in.obstacles = oracle_triangles(s.obstacles);
  in.body = oracle_triangles(s.body);
  for (const Pose& p : path.poses) in.poses.push_back({p.rotation, p.translation});
  in.reference = s.reference;
  in.clearance = problem.clearance;
  in.contact_tolerance = problem.contact_tolerance;
  const auto t0 = std::chrono::steady_clock::now();
  const oracle::PathCheckReport rep = oracle::check_path(in);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  std::printf("oracle: %zu x %zu triangles, %zu segments: %s, dense min %.6g (spacing %.3g), %zu certificate queries, %.0f ms\n",
              in.obstacles.size(), in.body.size(), path.poses.size() - std::min<std::size_t>(path.poses.size(), 1),
              rep.valid ? "valid" : "INVALID", rep.dense_min, rep.dense_spacing, rep.certificate_queries, ms);
  if (rep.contact_segments > 0)
    std::printf("oracle: %zu segments in contact, deepest penetration %.6g\n", rep.contact_segments, rep.max_penetration);
  EXPECT_TRUE(rep.valid) << "the oracle refuses the path: " << rep.why;

  const double slack = 1e-9;
  auto expect_within = [&](double m, double dense_min, const char* what) {
    EXPECT_GE(m, dense_min - rep.dense_spacing / 2 - slack)
        << what << " " << m << " is below the oracle's dense minimum " << dense_min << " − spacing/2";
    EXPECT_LE(m, dense_min + rep.max_segment_length / 32 + slack)
        << what << " " << m << " is more than (longest segment)/32 above the oracle's dense minimum " << dense_min;
  };
  if (figures.min_clearance) expect_within(*figures.min_clearance, rep.dense_min, "min_clearance");
  if (figures.contact_segments) {
    EXPECT_EQ(*figures.contact_segments, rep.contact_segments) << "segments in contact";
  }
  return rep;
}

/// check_path_independently with every figure the planner reported.
inline oracle::PathCheckReport check_independently(const PlanScene& s, const Problem& problem, const PlanResult& r) {
  return check_path_independently(s, problem, r.path,
                                  {.min_clearance = r.min_clearance,
                                   .contact_segments = r.escape_segments + r.approach_segments});
}

}  // namespace swept::test
