// The escape phase on its own (src/plan/escape.cpp): a peg resting on the bottom of its hole.
// escape_test.cpp runs the same rules through plan() end to end.
#include "plan/escape.h"
#include "plan/phase_support.h"
#include "swept/geometry/distance.h"
#include "swept/plan/check.h"

#include <algorithm>

namespace swept {
namespace {

using namespace swept::test;
using scenes::add_box;
using scenes::GeneratedProblem;

// A peg [−1, 1]² × [0, 4] standing on the bottom (z = 0) of a hole of half width 1.02 and depth
// 3: distance 0 to the bottom, 0.02 to the four walls. Clearance 0.01, contact tolerance 0.02:
// the bottom is a mate of the lift (it separates), the walls keep 0.02 > 0.01 along it, so the
// escape is straight up, to the first step of the ladder s_k = 10^-3·size·1.5^k whose pose
// clears the bottom by more than 0.01.
GeneratedProblem peg_on_the_bottom(double h = 1.02) {
  GeneratedProblem g;
  g.name = "peg_on_the_bottom";
  auto& o = g.obstacles.triangles;
  add_box(o, Vec3(-3, -3, -1), Vec3(3, 3, 0));  // bottom
  add_box(o, Vec3(h, -3, 0), Vec3(3, 3, 3));    // walls
  add_box(o, Vec3(-3, -3, 0), Vec3(-h, 3, 3));
  add_box(o, Vec3(-h, h, 0), Vec3(h, 3, 3));
  add_box(o, Vec3(-h, -3, 0), Vec3(h, -h, 3));
  add_box(g.body.triangles, Vec3(-1, -1, 0), Vec3(1, 1, 4));
  g.problem.start = Pose{};
  g.problem.goal_outside = true;
  g.problem.clearance = 0.01;
  g.problem.contact_tolerance = 0.02;
  g.problem.rotation = RotationMode::none;
  return g;
}

detail::ContactMoves contact_of(const PhaseRig& rig) {
  return detail::ContactMoves(rig.scene, rig.problem().clearance, rig.problem().contact_tolerance);
}

TEST(EscapePhase, PegLeavesStraightUpToTheFirstClearPose) {
  PhaseRig rig(peg_on_the_bottom());
  const auto way = detail::escape_from_contact(rig.context, contact_of(rig), rig.problem().start);
  ASSERT_TRUE(way);
  ASSERT_EQ(way->size(), 1u);  // one pull
  const Pose* escape = &way->back();
  // size = max(diagonal of [−3, 3]² × [−1, 3], 2·r_max): √88 ≈ 9.38, so s_0 ≈ 0.0094 leaves the
  // peg 0.0094 ≤ 0.01 above the bottom and s_1 = 1.5·s_0 ≈ 0.0141 is the first clear pose.
  const double s0 = 1e-3 * rig.context.scene_size();
  EXPECT_NEAR(rig.context.scene_size(), std::sqrt(88.0), 1e-12);
  EXPECT_EQ(escape->rotation, Mat3::Identity());
  EXPECT_NEAR(escape->translation.z(), s0 * 1.5, 1e-15);
  EXPECT_NEAR(escape->translation.x(), 0.0, 1e-15);
  EXPECT_NEAR(escape->translation.y(), 0.0, 1e-15);
  // The escape segment satisfies the rules of docs/planner.md, checked by the oracle.
  check_path_independently(rig.scene, rig.problem(), Path{{rig.problem().start, *escape}}, {.contact_segments = 1});
}

TEST(EscapePhase, APegThatGrazesItsWallsLeavesByTheSweep) {
  // The walls 2e-10 above the clearance (0.01), the contact tolerance 1e-10: the walls are no
  // mates and keep 2e-10 above the margin all the way up. The lift is decided by the exact sweep
  // of the translation (a certificate would need pieces some 10^-10 long).
  GeneratedProblem g = peg_on_the_bottom(1.0 + 0.01 + 2e-10);
  g.problem.contact_tolerance = 1e-10;
  PhaseRig rig(g);
  const detail::ContactMoves contact = contact_of(rig);
  const auto way = detail::escape_from_contact(rig.context, contact, g.problem.start);
  ASSERT_TRUE(way);
  ASSERT_EQ(way->size(), 1u);
  EXPECT_GE(contact.sweeps(), 1u);
  const Pose& escape = way->back();
  EXPECT_EQ(escape.rotation, Mat3::Identity());
  EXPECT_NEAR(escape.translation.z(), 1.5e-3 * rig.context.scene_size(), 1e-15);
  EXPECT_EQ(escape.translation.x(), 0.0);
  EXPECT_EQ(escape.translation.y(), 0.0);
  // Independently, pair by pair with the oracle's exact minimum over the translation: every
  // pair that does not touch at the start (the walls) stays above the clearance all the way up.
  const Eigen::Vector3d lift = escape.translation;
  double closest = std::numeric_limits<double>::infinity();
  for (const oracle::Tri& o : oracle_triangles(rig.scene.obstacles))
    for (const oracle::Tri& b : oracle_triangles(rig.scene.body)) {
      if (oracle::triangle_distance(o, b) < 1e-9) continue;  // the bottom, which the lift leaves
      closest = std::min(closest, oracle::translation_minimum(o, b, lift));
    }
  EXPECT_GT(closest, g.problem.clearance);
  EXPECT_NEAR(closest, g.problem.clearance + 2e-10, 1e-12);
  // The plan starts with that escape, and `swept check`'s checker certifies it the same way.
  const PlanResult r = plan(g.problem, rig.scene);
  ASSERT_TRUE(r.solved()) << r.message;
  EXPECT_EQ(r.path.poses[1].translation, escape.translation);
  const PathCheckResult c = check_path(g.problem, rig.scene, r.path);
  EXPECT_TRUE(c.valid) << c.message;
  EXPECT_EQ(c.contact_segments, 1u);
  EXPECT_GE(c.sweeps, 1u);
}

TEST(EscapePhase, NoEscapeWhenTheWallsPress) {
  // Walls 0.005 inside the peg's sides (an interference deeper than the tolerance 0.002): no
  // pull is allowed, the way out is refused.
  GeneratedProblem g = peg_on_the_bottom(0.995);
  g.problem.contact_tolerance = 0.002;
  PhaseRig rig(g);
  EXPECT_FALSE(detail::escape_from_contact(rig.context, contact_of(rig), g.problem.start));
}

TEST(EscapePhase, PlanBeginsWithTheSameEscape) {
  const GeneratedProblem g = peg_on_the_bottom();
  PhaseRig rig(g);
  const auto way = detail::escape_from_contact(rig.context, contact_of(rig), g.problem.start);
  ASSERT_TRUE(way);
  const Pose* escape = &way->back();
  const PlanResult r = plan(g.problem, rig.scene);
  ASSERT_TRUE(r.solved()) << r.message;
  ASSERT_GE(r.path.poses.size(), 2u);
  EXPECT_EQ(r.escape_segments, 1u);
  EXPECT_EQ(r.path.poses[1].translation, escape->translation);
  check_independently(rig.scene, g.problem, r);
}

}  // namespace
}  // namespace swept
