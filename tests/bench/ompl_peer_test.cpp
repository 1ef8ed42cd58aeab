// bench_plan's OMPL side (bench/lib: ompl_peer.cpp): each RRTConnect solution is simplified by
// OMPL's own simplifySolution(), timed apart from the solve, re-checked, and measured in swept's
// motion metric. Built only with the benchmarks (it links OMPL).
#include "swept/bench/fcl_model.h"
#include "swept/bench/ompl_peer.h"
#include "swept/bench/search_space.h"
#include "swept/query/motion.h"
#include "swept/scenes/box_problems.h"

#include <gtest/gtest.h>

namespace swept::bench {
namespace {

TEST(OmplPeer, SimplifiesEachSolutionApartFromTheSolve) {
  // The L-tunnel: RRTConnect solves it in milliseconds (docs/lab/bench-plan-history.md).
  const scenes::GeneratedProblem g = scenes::l_tunnel();
  auto scene = make_scene(g.obstacles, g.body, g.problem.build, g.problem.reference_point);
  ASSERT_TRUE(scene) << scene.error().message;
  ASSERT_TRUE(g.problem.goal);
  const SearchSpace space = planner_search_space(g.problem, *scene);
  const auto body = fcl_model<fcl::OBBRSSd>(scene->body.triangles);
  const auto obstacles = fcl_model<fcl::OBBRSSd>(scene->obstacles.triangles);
  const CompareOptions options{.time_limit = 20, .seeds = 2, .threads = 1};
  // The straight move from start to goal: no path between them is shorter in the metric.
  const double direct = motion_length(g.problem.start, *g.problem.goal, scene->reference, scene->radius);
  CompareRow row;
  for (std::uint32_t seed = 1; seed <= 2; ++seed) {
    const OmplRun run = run_ompl(g.problem, space, *scene, *body, *obstacles, seed, options);
    ASSERT_TRUE(run.solved) << "seed " << seed << ": " << run.status;
    EXPECT_EQ(run.verified, "free") << seed;
    EXPECT_GT(run.simplify_ms, 0.0) << seed;
    EXPECT_FALSE(run.simplified_verified.empty()) << seed;
    EXPECT_GE(run.length, direct - 1e-9) << seed;
    EXPECT_GE(run.simplified_length, direct - 1e-9) << seed;
    // Shortcutting a sampled path through an L: shorter than what RRTConnect found.
    EXPECT_LT(run.simplified_length, run.length) << seed;
    row.ompl.push_back(run);
  }
  EXPECT_GT(row.ompl_median_with_simplify(), row.ompl_median());
}

}  // namespace
}  // namespace swept::bench
