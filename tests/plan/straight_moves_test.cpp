// The straight-move phase on scenes whose answer can be worked out by hand (src/plan/straight_moves.cpp).
#include "plan/directions.h"
#include "plan/phase_support.h"
#include "plan/straight_moves.h"

#include <array>
#include <cmath>

namespace swept {
namespace {

using namespace swept::test;
using scenes::add_box;
using scenes::GeneratedProblem;

// A body [−1.5, 1.5] × [−1, 1] × [−0.5, 0.5] lying between a floor (top z = 0, x, y ∈ [−20, 20])
// and a roof (z ∈ [3, 4], x, y ∈ [−5, 5]), its centre at z = 1.5: 1 from both. The reference
// point (bounds [−21, 21]² × [−5, 30]) cannot go far enough sideways to leave the goal box
// (|x|, |y| > 20 + r, r = √3.5 ≈ 1.87), up is the roof and down the floor, so no single move
// works. Two do: slide along +x by half the room (to x = 10.5, clear of the roof, the
// directions +z, −z tried first all fail), then lift until the bounding sphere clears the
// goal box's top: z = 4 + r.
GeneratedProblem body_under_a_roof() {
  GeneratedProblem g;
  g.name = "body_under_a_roof";
  add_box(g.obstacles.triangles, Vec3(-20, -20, -1), Vec3(20, 20, 0));
  add_box(g.obstacles.triangles, Vec3(-5, -5, 3), Vec3(5, 5, 4));
  add_box(g.body.triangles, Vec3(-1.5, -1, -0.5), Vec3(1.5, 1, 0.5));
  g.problem.start = Pose::from_translation(Vec3(0, 0, 1.5));
  g.problem.goal_outside = true;
  g.problem.bounds = Aabb{Vec3(-21, -21, -5), Vec3(21, 21, 30)};
  g.problem.clearance = 0.05;
  g.problem.rotation = RotationMode::none;
  return g;
}

TEST(StraightMoves, LiftsOutOfAChannelInOneMove) {
  // The same body in an open channel (floor and two walls, no roof): straight up.
  GeneratedProblem g = body_under_a_roof();
  g.obstacles.triangles.clear();
  add_box(g.obstacles.triangles, Vec3(-20, -20, -1), Vec3(20, 20, 0));
  add_box(g.obstacles.triangles, Vec3(-20, -20, 0), Vec3(20, -1.5, 3));
  add_box(g.obstacles.triangles, Vec3(-20, 1.5, 0), Vec3(20, 20, 3));
  PhaseRig rig(g);
  const Pose start = rig.problem().start;
  const auto path = detail::straight_moves(rig.context, start, rig.start_distance(start));
  ASSERT_TRUE(path);
  ASSERT_EQ(path->size(), 2u);
  const double r = std::sqrt(3.5);
  EXPECT_EQ((*path)[1].rotation, start.rotation);
  EXPECT_NEAR((*path)[1].translation.z(), 3 + r, 1e-9);  // the sphere just clears the top (z = 3)
  EXPECT_EQ((*path)[1].translation.x(), 0.0);
  EXPECT_EQ(rig.context.edges_checked, 1u);
  check_path_independently(rig.scene, rig.problem(), Path{*path});
}

TEST(StraightMoves, SlidesFromUnderARoofThenLifts) {
  PhaseRig rig(body_under_a_roof());
  const Pose start = rig.problem().start;
  const auto path = detail::straight_moves(rig.context, start, rig.start_distance(start));
  ASSERT_TRUE(path);
  ASSERT_EQ(path->size(), 3u);
  EXPECT_EQ((*path)[1].translation, Vec3(10.5, 0, 1.5));
  EXPECT_NEAR((*path)[2].translation.x(), 10.5, 1e-12);
  EXPECT_NEAR((*path)[2].translation.z(), 4 + std::sqrt(3.5), 1e-9);
  check_path_independently(rig.scene, rig.problem(), Path{*path});
}

TEST(StraightMoves, NoneWhenShutIn) {
  PhaseRig rig(scenes::enclosed());
  const Pose start = rig.problem().start;
  const std::uint64_t before = rig.context.check.distance_queries();
  EXPECT_FALSE(detail::straight_moves(rig.context, start, rig.start_distance(start)));
  // Every candidate was tried, and every one runs into a wall of the box at one of its samples
  // (Checker::blocked_at_samples): refused before any certificate ran.
  EXPECT_GT(rig.context.check.distance_queries(), before);
  EXPECT_EQ(rig.context.edges_checked, 0u);
}

TEST(StraightMoves, CandidateDirectionsAndRoom) {
  PhaseRig rig(body_under_a_roof());
  const std::vector<Vec3> dirs = detail::candidate_directions(rig.context, rig.problem().start);
  // No goal pose: the six world directions, +z first, then ± each principal axis of the body
  // that is not one of them (the fit of a triangulated box is a little off its edges).
  ASSERT_GE(dirs.size(), 6u);
  const std::array<Vec3, 6> world = {Vec3(0, 0, 1), Vec3(0, 0, -1), Vec3(1, 0, 0),
                                     Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0)};
  for (int i = 0; i < 6; ++i) EXPECT_EQ(dirs[i], world[i]) << i;
  EXPECT_LE(dirs.size(), 12u);
  for (std::size_t i = 0; i < dirs.size(); ++i) {
    EXPECT_NEAR(dirs[i].norm(), 1.0, 1e-12);
    for (std::size_t j = 0; j < i; ++j) EXPECT_LE(dirs[i].dot(dirs[j]), 1.0 - 1e-9) << i << " repeats " << j;
  }
  const Aabb box{Vec3(-1, -1, -1), Vec3(1, 1, 1)};
  EXPECT_DOUBLE_EQ(detail::room_along(box, Vec3(0, 0, 0), Vec3(1, 0, 0)), 1.0);
  EXPECT_DOUBLE_EQ(detail::room_along(box, Vec3(0.5, 0, 0), Vec3(-1, 0, 0)), 1.5);
  EXPECT_NEAR(detail::room_along(box, Vec3(0, 0, 0), Vec3(1, 1, 0).normalized()), std::sqrt(2.0), 1e-15);
  EXPECT_EQ(detail::room_along(box, Vec3(2, 0, 0), Vec3(1, 0, 0)), 0.0);
}

}  // namespace
}  // namespace swept
