// Motions in contact — the escape from a start in contact, the approach to a goal in contact —
// on fixtures whose only ways out (or lack of one) can be seen by hand. docs/planner.md, "The
// contact model": a motion with an end in contact is a pull the mate rule allows; every other
// pair keeps the clearance. Every solved path is checked by the independent oracle
// (tests/oracle), which shares no code with the mate rule.
#include "assembly/assembly_support.h"
#include "plan/plan_support.h"
#include "swept/geometry/distance.h"
#include "swept/plan/check.h"

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

// The sealed box without its lid (the two triangles at z = 1): a 10-triangle open shell, a sheet
// with no inside, holding the body 0.005 from its floor and walls. The way out is a lift of a
// little over 2.
GeneratedProblem open_box() {
  GeneratedProblem g = sealed_box();
  g.name = "open_box";
  auto& o = g.obstacles.triangles;
  o.erase(std::remove_if(o.begin(), o.end(), [](const Triangle& t) { return t.p.z() == 1 && t.q.z() == 1 && t.r.z() == 1; }),
          o.end());
  EXPECT_EQ(o.size(), 10u);
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

TEST(Escape, LidLiftsOffTheBaseAlongTheShaft) {
  const auto g = lid_over_shaft();
  const PlanScene s = scene_of(g);
  const PlanResult r = plan(g.problem, s);
  ASSERT_TRUE(r.solved()) << r.message;
  EXPECT_EQ(r.escape_segments, 1u);
  // The lid rests on the base: the path's minimum over every pair is the start's 0.
  EXPECT_EQ(r.min_clearance, 0.0);
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
  check_independently(s, g.problem, r);
}

}  // namespace
}  // namespace swept

namespace swept {
namespace {

using namespace swept::test;

TEST(Contact, BoxComesOutOfAnOpenBox) {
  const auto g = open_box();
  const PlanScene s = scene_of(g);
  const PlanResult r = plan(g.problem, s);
  ASSERT_TRUE(r.solved()) << r.message;
  EXPECT_EQ(r.escape_segments, 1u);
  EXPECT_EQ(r.approach_segments, 0u);
  // Straight up, out past the rim (z = 1 + 0.995 + the clearance).
  const Vec3 lift = r.path.poses[1].translation - r.path.poses[0].translation;
  EXPECT_EQ(lift.x(), 0.0);
  EXPECT_EQ(lift.y(), 0.0);
  EXPECT_GT(lift.z(), 1.995 + g.problem.clearance);
  check_independently(s, g.problem, r);
  const PathCheckResult c = check_path(g.problem, s, r.path);
  EXPECT_TRUE(c.valid) << c.message;
  EXPECT_EQ(c.contact_segments, 1u);
}

TEST(Contact, BoxGoesIntoAnOpenBox) {
  // The insertion: the same path the other way, the goal in contact.
  auto g = open_box();
  g.problem.start = Pose::from_translation(Vec3(0, 0, 10));
  g.problem.goal = Pose{};
  const PlanScene s = scene_of(g);
  const PlanResult r = plan(g.problem, s);
  ASSERT_TRUE(r.solved()) << r.message;
  EXPECT_EQ(r.escape_segments, 0u);
  EXPECT_EQ(r.approach_segments, 1u);
  EXPECT_EQ(r.path.poses.back().translation, Vec3::Zero());
  check_independently(s, g.problem, r);
  // Without a contact tolerance a goal in contact is refused as before.
  g.problem.contact_tolerance = 0;
  EXPECT_EQ(plan(g.problem, s).status, PlanStatus::invalid_goal);
}

TEST(Contact, FromOneOpenBoxIntoAnother) {
  auto g = open_box();
  const std::size_t n = g.obstacles.triangles.size();
  for (std::size_t k = 0; k < n; ++k) {
    Triangle t = g.obstacles.triangles[k];
    for (int v = 0; v < 3; ++v) t[v].x() += 5;
    g.obstacles.triangles.push_back(t);
  }
  g.problem.goal = Pose::from_translation(Vec3(5, 0, 0));
  const PlanScene s = scene_of(g);
  const PlanResult r = plan(g.problem, s);
  ASSERT_TRUE(r.solved()) << r.message;
  EXPECT_EQ(r.escape_segments, 1u);
  EXPECT_EQ(r.approach_segments, 1u);
  check_independently(s, g.problem, r);
}

// A pulley (a ring of 16 segments, bore radius 3, outer 10, z ∈ [10, 20]) on a 24-gon shaft of
// radius 3 (z ∈ [0, 40]) standing on a base plate: the two tessellations of one circle cross by
// up to the 16-gon's sag, 3·(1 − cos(π/16)) ≈ 0.058, under the tolerance 0.1. Its only way off
// is along the shaft, up past its end.
GeneratedProblem pulley_on_shaft() {
  GeneratedProblem g;
  g.name = "pulley_on_shaft";
  scenes::add_box(g.obstacles.triangles, Vec3(-20, -20, -5), Vec3(20, 20, 0));
  add_prism(g.obstacles.triangles, 3, 24, 0, 40);
  add_ring(g.body.triangles, 3, 10, 16, 10, 20);
  g.problem.start = Pose{};
  g.problem.goal_outside = true;
  g.problem.clearance = 0.01;
  g.problem.contact_tolerance = 0.1;
  g.problem.rotation = RotationMode::none;
  g.problem.time_limit = 20;
  return g;
}

TEST(Contact, PulleySlidesOffAlongTheShaftNotSideways) {
  const auto g = pulley_on_shaft();
  const PlanScene s = scene_of(g);
  const PlanResult r = plan(g.problem, s);
  ASSERT_TRUE(r.solved()) << r.message;
  ASSERT_EQ(r.escape_segments, 1u);
  const Vec3 pull = r.path.poses[1].translation - r.path.poses[0].translation;
  EXPECT_EQ(pull.x(), 0.0);
  EXPECT_EQ(pull.y(), 0.0);
  EXPECT_GT(pull.z(), 20.0);  // off the shaft's end at z = 40
  check_independently(s, g.problem, r);
  // Sideways, the bore cuts the shaft: refused by the final check, and by the oracle.
  const Path sideways{{Pose{}, Pose::from_translation(Vec3(30, 0, 0))}};
  EXPECT_FALSE(check_path(g.problem, s, sideways).valid);
  oracle::PathCheckInput in;
  in.obstacles = oracle_triangles(s.obstacles);
  in.body = oracle_triangles(s.body);
  in.poses = {{Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero()}, {Eigen::Matrix3d::Identity(), Eigen::Vector3d(30, 0, 0)}};
  in.reference = s.reference;
  in.clearance = g.problem.clearance;
  in.contact_tolerance = g.problem.contact_tolerance;
  EXPECT_FALSE(oracle::check_path(in).valid);
}

}  // namespace
}  // namespace swept
