// Lazy weighted A* on the grid (src/plan/lazy_astar.cpp), run on its own.
#include "plan/lazy_astar.h"
#include "plan/phase_support.h"

#include <array>
#include <cmath>
#include <optional>
#include <vector>

namespace swept {
namespace {

using namespace swept::test;
using scenes::add_box;
using scenes::GeneratedProblem;

// A cube [−0.5, 0.5]³ in front of a wall [−0.5, 0.5] × [−5, 5]² that stands between its start
// (−3, 0, 0) and its goal (3, 0, 0): the straight line is blocked, the way is round the wall.
GeneratedProblem wall_between() {
  GeneratedProblem g;
  g.name = "wall_between";
  add_box(g.obstacles.triangles, Vec3(-0.5, -5, -5), Vec3(0.5, 5, 5));
  add_box(g.body.triangles, Vec3(-0.5, -0.5, -0.5), Vec3(0.5, 0.5, 0.5));
  g.problem.start = Pose::from_translation(Vec3(-3, 0, 0));
  g.problem.goal = Pose::from_translation(Vec3(3, 0, 0));
  g.problem.clearance = 0.05;
  g.problem.rotation = RotationMode::none;
  return g;
}

TEST(LazyAStar, Heuristic) {
  {
    PhaseRig rig(wall_between());
    const detail::Grid grid(rig.space, rig.problem().start, rig.problem().start, 0.05, rig.context.scene_size());
    const detail::LazyGridSearch search(rig.context, grid, rig.problem().start, 1.0);
    EXPECT_DOUBLE_EQ(search.heuristic(rig.problem().start), 6.0);  // a translation of 6
    EXPECT_EQ(search.heuristic(*rig.problem().goal), 0.0);
  }
  {
    // Goal outside [−10, 10]³; r_max = √12: from the centre the sphere leaves after 10 + √12.
    PhaseRig rig(scenes::enclosed());
    const detail::Grid grid(rig.space, rig.problem().start, rig.problem().start, 0.1, rig.context.scene_size());
    const detail::LazyGridSearch search(rig.context, grid, rig.problem().start, 1.0);
    EXPECT_NEAR(search.heuristic(Pose{}), 10 + std::sqrt(12.0), 1e-12);
    EXPECT_NEAR(search.heuristic(Pose::from_translation(Vec3(0, -4, 0))), 6 + std::sqrt(12.0), 1e-12);
  }
}

TEST(LazyAStar, QueryingAheadChangesNoDecision) {
  // The same expansions, outcome and path with the next node queried ahead as without, on
  // problems solved at several levels and on one whose budget runs out (the closed box).
  std::vector<GeneratedProblem> problems{wall_between(), scenes::l_tunnel(), scenes::t_slot(), scenes::enclosed()};
  int ahead_used = 0;
  for (const GeneratedProblem& g : problems) {
    SCOPED_TRACE(g.name);
    std::array<std::optional<std::vector<Pose>>, 2> paths;
    std::array<std::size_t, 2> expansions{};
    std::array<std::uint64_t, 2> queries{};
    std::array<detail::GridOutcome, 2> outcomes{};
    for (int ahead = 0; ahead < 2; ++ahead) {
      PhaseRig rig(g);
      const Pose start = rig.problem().start;
      const detail::Grid grid(rig.space, start, start, rig.problem().clearance, rig.context.scene_size());
      detail::LazyGridSearch search(rig.context, grid, start, rig.start_distance(start));
      search.set_query_ahead(ahead == 1);
      const std::uint64_t before = rig.check.distance_queries();
      paths[ahead] = search.run(outcomes[ahead], 3000);
      expansions[ahead] = search.expansions();
      queries[ahead] = rig.check.distance_queries() - before;
    }
    EXPECT_EQ(outcomes[0], outcomes[1]);
    EXPECT_EQ(expansions[0], expansions[1]);
    ASSERT_EQ(paths[0].has_value(), paths[1].has_value());
    if (paths[0]) {
      ASSERT_EQ(paths[0]->size(), paths[1]->size());
      for (std::size_t k = 0; k < paths[0]->size(); ++k) {
        EXPECT_EQ((*paths[0])[k].translation, (*paths[1])[k].translation);
        EXPECT_EQ((*paths[0])[k].rotation, (*paths[1])[k].rotation);
      }
    }
    ahead_used += queries[0] != queries[1];
  }
  EXPECT_GT(ahead_used, 0);  // the nodes ahead were queried somewhere
}

TEST(LazyAStar, GoesRoundTheWall) {
  PhaseRig rig(wall_between());
  const Pose start = rig.problem().start;
  const detail::Grid grid(rig.space, start, start, rig.problem().clearance, rig.context.scene_size());
  detail::LazyGridSearch search(rig.context, grid, start, rig.start_distance(start));
  detail::GridOutcome outcome = detail::GridOutcome::resolution;
  const auto path = search.run(outcome);
  ASSERT_TRUE(path);
  EXPECT_EQ(outcome, detail::GridOutcome::found);
  EXPECT_EQ(path->front().translation, start.translation);
  EXPECT_EQ(path->back().translation, rig.problem().goal->translation);
  // Round the wall: some waypoint is beyond its edge (|y| or |z| ≥ 5 + 0.5).
  bool round = false;
  for (const Pose& q : *path)
    round = round || std::abs(q.translation.y()) >= 5.5 || std::abs(q.translation.z()) >= 5.5;
  EXPECT_TRUE(round);
  EXPECT_GT(rig.context.edges_checked, 0u);
  check_path_independently(rig.scene, rig.problem(), Path{*path});
}

TEST(LazyAStar, ExhaustsALevelWhenShutIn) {
  PhaseRig rig(scenes::enclosed());
  const Pose start = rig.problem().start;
  const detail::Grid grid(rig.space, start, start, rig.problem().clearance, rig.context.scene_size());
  detail::LazyGridSearch search(rig.context, grid, start, rig.start_distance(start));
  bool exhausted = false;
  EXPECT_FALSE(search.search_level(0, std::size_t{1} << 20, exhausted));
  EXPECT_TRUE(exhausted);
  // A budget of one expansion stops before the open list is empty.
  detail::LazyGridSearch short_search(rig.context, grid, start, rig.start_distance(start));
  EXPECT_FALSE(short_search.search_level(0, 1, exhausted));
  EXPECT_FALSE(exhausted);
}

}  // namespace
}  // namespace swept
