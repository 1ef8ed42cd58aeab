// The escape from a start in contact, on fixtures whose only ways out (or lack of one) can be
// seen by hand. docs/planner.md: along the escape segment only the triangle pairs closer than
// clearance + contact tolerance at the start are exempt, pair by pair; every other pair keeps
// the clearance. Every solved path is checked by the independent oracle (tests/oracle).
#include "plan/plan_support.h"
#include "swept/geometry/distance.h"

namespace swept {
namespace {

using namespace swept::test;
using scenes::add_box;
using scenes::GeneratedProblem;

// A closed 12-triangle shell [-1, 1]³ with a box [-0.995, 0.995]³ inside: 0.005 from every face
// of the shell at the start. Every way out crosses the shell: the body's bottom face (1.995 from
// the lid at the start, so never exempt) meets the lid on the way up, and likewise on every side.
GeneratedProblem sealed_box() {
  GeneratedProblem g;
  g.name = "sealed_box";
  add_box(g.obstacles.triangles, Vec3(-1, -1, -1), Vec3(1, 1, 1));
  add_box(g.body.triangles, Vec3(-0.995, -0.995, -0.995), Vec3(0.995, 0.995, 0.995));
  g.problem.start = Pose{};
  g.problem.goal = Pose::from_translation(Vec3(0, 0, 10));
  g.problem.clearance = 0.01;
  g.problem.contact_tolerance = 0.02;
  g.problem.rotation = RotationMode::none;
  g.problem.time_limit = 20;
  return g;
}

// A base plate with a square shaft [-3, 3]² × [0, 30] standing on it, and a lid [-15, 15]² ×
// [0, 5] (the body) with a square hole of half width 3 + gap around the shaft, resting on the
// base (distance 0). With gap 0.02 (> clearance 0.01, < clearance + tolerance 0.03) the lid lifts
// off the base and slides up the shaft, 0.02 from it all the way: the one way out.
GeneratedProblem lid_over_shaft(double gap = 0.02) {
  GeneratedProblem g;
  g.name = "lid_over_shaft";
  auto& o = g.obstacles.triangles;
  add_box(o, Vec3(-20, -20, -5), Vec3(20, 20, 0));  // base
  add_box(o, Vec3(-3, -3, 0), Vec3(3, 3, 30));      // shaft
  const double h = 3 + gap;
  auto& b = g.body.triangles;  // body frame = world frame at the start
  add_box(b, Vec3(-15, -15, 0), Vec3(-h, 15, 5));
  add_box(b, Vec3(h, -15, 0), Vec3(15, 15, 5));
  add_box(b, Vec3(-h, -15, 0), Vec3(h, -h, 5));
  add_box(b, Vec3(-h, h, 0), Vec3(h, 15, 5));
  g.problem.start = Pose{};
  g.problem.goal_outside = true;
  g.problem.clearance = 0.01;
  g.problem.contact_tolerance = 0.02;
  g.problem.rotation = RotationMode::none;
  g.problem.time_limit = 20;
  return g;
}

// The same lid held down by a washer [-8, 8]² × [5, 5 + thickness] on the shaft, touching the
// lid's top. There is no way out: the base is below, the shaft through the hole, the washer
// above. A washer thinner than the contact threshold has all its triangles within it of the
// lid's top: a rule exempting every (body triangle in contact) × (obstacle triangle in contact)
// would let the lid's bottom face (5 below the washer at the start) pass through it.
GeneratedProblem lid_under_washer(double thickness) {
  GeneratedProblem g = lid_over_shaft();
  g.name = "lid_under_washer";
  add_box(g.obstacles.triangles, Vec3(-8, -8, 5), Vec3(8, 8, 5 + thickness));
  return g;
}

// A block [-3, 3] × [-4.98, 4.98] × [0, 6] on the floor of an open channel x ∈ [-20, 20],
// |y| < 5, walls 10 high: it touches the floor (distance 0) and is 0.02 from both walls: three
// contacts at once. Lifting it slides along both walls (0.02 > the clearance) and off the floor.
GeneratedProblem block_in_channel() {
  GeneratedProblem g;
  g.name = "block_in_channel";
  auto& o = g.obstacles.triangles;
  add_box(o, Vec3(-20, -8, -3), Vec3(20, 8, 0));   // floor
  add_box(o, Vec3(-20, -8, 0), Vec3(20, -5, 10));  // walls
  add_box(o, Vec3(-20, 5, 0), Vec3(20, 8, 10));
  add_box(g.body.triangles, Vec3(-3, -4.98, 0), Vec3(3, 4.98, 6));
  g.problem.start = Pose{};
  g.problem.goal = Pose::from_translation(Vec3(0, 0, 25));
  g.problem.clearance = 0.01;
  g.problem.contact_tolerance = 0.02;
  g.problem.rotation = RotationMode::none;
  g.problem.time_limit = 20;
  return g;
}

bool refused(const PlanResult& r) {
  return r.status == PlanStatus::no_path_resolution || r.status == PlanStatus::no_path_bounds ||
         r.status == PlanStatus::no_path_time || r.status == PlanStatus::invalid_start;
}

TEST(Escape, BodyInsideASealedBoxNeverLeaves) {
  const auto g = sealed_box();
  const PlanScene s = scene_of(g);
  const PlanResult r = plan(g.problem, s);
  EXPECT_FALSE(r.solved()) << r.message;
  EXPECT_TRUE(refused(r)) << r.message;
  EXPECT_TRUE(r.path.poses.empty());
  // With rotation allowed it is still shut in.
  auto free = g;
  free.problem.rotation = RotationMode::free;
  free.problem.time_limit = 5;
  const PlanResult rf = plan(free.problem, s);
  EXPECT_FALSE(rf.solved()) << rf.message;
}

TEST(Escape, ExemptionIsPairByPair) {
  // In the sealed box the pairs within 0.03 at the start are a face of the body with the
  // parallel face of the shell (2 × 2 triangles, 6 faces) and with the four faces of the shell
  // next to it (an edge of the body face is 0.005 from each of them), but never a face with the opposite face
  // (1.995 apart): the exempt set is not every body triangle in contact × every obstacle
  // triangle in contact (which would be all 12 × 12 = 144 pairs).
  const auto g = sealed_box();
  const PlanScene s = scene_of(g);
  const auto pairs = proximity_pairs(s.obstacle_tree, Pose{}, s.body_tree, Pose{}, {.threshold = 0.03}).pairs;
  EXPECT_GT(pairs.size(), 0u);
  EXPECT_LT(pairs.size(), 144u);
  // Each pair must be closer than the threshold, and the pairs of opposite faces are absent:
  // checked by brute force over all 144 pairs.
  std::size_t expected = 0;
  for (std::uint32_t i = 0; i < g.obstacles.triangles.size(); ++i)
    for (std::uint32_t j = 0; j < g.body.triangles.size(); ++j) {
      const bool close = triangle_distance(g.obstacles.triangles[i], g.body.triangles[j]).distance < 0.03;
      EXPECT_EQ(close, pairs.contains(i, j)) << i << ", " << j;
      expected += close;
    }
  EXPECT_EQ(pairs.size(), expected);
}

TEST(Escape, LidLiftsOffTheBaseAlongTheShaft) {
  const auto g = lid_over_shaft();
  const PlanScene s = scene_of(g);
  const PlanResult r = plan(g.problem, s);
  ASSERT_TRUE(r.solved()) << r.message;
  EXPECT_EQ(r.escape_segments, 1u);
  EXPECT_GT(r.exempt_pairs, 0u);
  // The lid rests on the base: the path's minimum over every pair is the start's 0; the escape
  // keeps every other pair at least the clearance apart.
  EXPECT_EQ(r.min_clearance, 0.0);
  EXPECT_GE(r.escape_clearance, g.problem.clearance);
  // The lid can only go up: every pose of the path has the lid at or above the base.
  for (const Pose& q : r.path.poses) EXPECT_GE(q.translation.z(), 0.0);
  check_independently(s, g.problem, r);
}

TEST(Escape, LidUnderAWasherIsRefused) {
  for (double thickness : {2.0, 0.02}) {
    const auto g = lid_under_washer(thickness);
    const PlanScene s = scene_of(g);
    const PlanResult r = plan(g.problem, s);
    EXPECT_FALSE(r.solved()) << "washer " << thickness << ": " << r.message;
    EXPECT_TRUE(refused(r)) << r.message;
  }
}

TEST(Escape, BlockWithThreeContactsLeavesUpwards) {
  const auto g = block_in_channel();
  const PlanScene s = scene_of(g);
  const PlanResult r = plan(g.problem, s);
  ASSERT_TRUE(r.solved()) << r.message;
  EXPECT_EQ(r.escape_segments, 1u);
  // The escape is a pure translation that leaves the floor.
  const Pose& a = r.path.poses[0];
  const Pose& b = r.path.poses[1];
  EXPECT_EQ(a.rotation, b.rotation);
  EXPECT_GT(b.translation.z(), a.translation.z());
  EXPECT_GE(r.escape_clearance, g.problem.clearance);
  check_independently(s, g.problem, r);
}

}  // namespace
}  // namespace swept
