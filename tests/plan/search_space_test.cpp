// The planner's exported search space and goal test (search_space.h), worked out by hand.
#include "plan/plan_support.h"
#include "swept/plan/search_space.h"

#include <cmath>

namespace swept {
namespace {

using namespace swept::test;
using scenes::add_box;
using scenes::GeneratedProblem;

// Obstacles: the cube [−1, 1]³; body: the cube [−0.5, 0.5]³ (reference point at its centre,
// r_max = √0.75); goal margin 0.5.
GeneratedProblem two_cubes() {
  GeneratedProblem g;
  g.name = "two_cubes";
  add_box(g.obstacles.triangles, Vec3(-1, -1, -1), Vec3(1, 1, 1));
  add_box(g.body.triangles, Vec3(-0.5, -0.5, -0.5), Vec3(0.5, 0.5, 0.5));
  g.problem.start = Pose::from_translation(Vec3(0, 0, 10));
  g.problem.goal_outside = true;
  g.problem.goal_margin = 0.5;
  return g;
}

TEST(SearchSpace, AutomaticBoundsAndGoalBox) {
  const GeneratedProblem g = two_cubes();
  const PlanScene scene = scene_of(g);
  const SearchSpace s = search_space(g.problem, scene);
  const double r = std::sqrt(0.75);
  EXPECT_NEAR(s.radius, r, 1e-15);
  EXPECT_EQ(s.reference, Vec3::Zero());
  EXPECT_EQ(s.goal_box.min, Vec3::Constant(-1.5));
  EXPECT_EQ(s.goal_box.max, Vec3::Constant(1.5));
  // Grown by 2.2·r + 0.05·size, size = the obstacles' diagonal 2√3; extended to the start.
  const double grow = 2.2 * r + 0.05 * 2 * std::sqrt(3.0);
  EXPECT_NEAR(s.bounds.min.x(), -1.5 - grow, 1e-12);
  EXPECT_NEAR(s.bounds.max.y(), 1.5 + grow, 1e-12);
  EXPECT_NEAR(s.bounds.min.z(), -1.5 - grow, 1e-12);
  EXPECT_EQ(s.bounds.max.z(), 10.0);
  EXPECT_TRUE(in_bounds(s, Vec3(0, 0, 10)));
  EXPECT_FALSE(in_bounds(s, Vec3(0, 0, 10.001)));
  // Given bounds are taken as they are.
  GeneratedProblem given = g;
  given.problem.bounds = Aabb{Vec3(-7, -8, -9), Vec3(7, 8, 9)};
  const SearchSpace sg = search_space(given.problem, scene);
  EXPECT_EQ(sg.bounds.min, Vec3(-7, -8, -9));
  EXPECT_EQ(sg.bounds.max, Vec3(7, 8, 9));
}

TEST(SearchSpace, GoalTests) {
  GeneratedProblem g = two_cubes();
  const PlanScene scene = scene_of(g);
  const SearchSpace s = search_space(g.problem, scene);
  const double r = std::sqrt(0.75);
  // Outside: the bounding sphere clears the grown box [−1.5, 1.5]³ on some axis.
  EXPECT_TRUE(goal_reached(s, g.problem, Pose::from_translation(Vec3(0, 0, 1.5 + r + 1e-9))));
  EXPECT_FALSE(goal_reached(s, g.problem, Pose::from_translation(Vec3(0, 0, 1.5 + r - 1e-9))));
  EXPECT_TRUE(goal_reached(s, g.problem, Pose::from_translation(Vec3(-1.5 - r - 1e-9, 0, 0))));
  EXPECT_FALSE(goal_reached(s, g.problem, Pose::from_translation(Vec3(1.6, 1.6, 1.6))));  // a corner is not enough
  EXPECT_TRUE(outside_goal_box(s, Vec3(0, 3, 0)));
  // A goal pose: exactly that pose.
  g.problem.goal_outside = false;
  g.problem.goal = Pose::from_translation(Vec3(5, 0, 0));
  EXPECT_TRUE(goal_reached(s, g.problem, Pose::from_translation(Vec3(5, 0, 0))));
  EXPECT_FALSE(goal_reached(s, g.problem, Pose::from_translation(Vec3(5, 0, 1e-12))));
  EXPECT_FALSE(goal_reached(s, g.problem, Pose::from_translation(Vec3(0, 0, 10))));
}

TEST(SearchSpace, ThePlannerEndsWhereItsGoalTestSays) {
  const GeneratedProblem g = two_cubes();
  const PlanScene scene = scene_of(g);
  GeneratedProblem near = g;
  near.problem.start = Pose::from_translation(Vec3(0, 0, 2));  // 0.5 above the cube, inside the grown box
  near.problem.clearance = 0.05;
  const PlanResult r = plan(near.problem, scene);
  ASSERT_TRUE(r.solved()) << r.message;
  const SearchSpace s = search_space(near.problem, scene);
  EXPECT_TRUE(goal_reached(s, near.problem, r.path.poses.back()));
  for (std::size_t i = 0; i + 1 < r.path.poses.size(); ++i)
    EXPECT_FALSE(goal_reached(s, near.problem, r.path.poses[i])) << i;
}

}  // namespace
}  // namespace swept
