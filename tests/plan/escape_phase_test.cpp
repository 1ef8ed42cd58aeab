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
// every pair within 0.03 is exempt, the bottom's and the walls'. The walls keep 0.02 > 0.01
// along a lift, so the escape is straight up, to the first step of the ladder
// s_k = 10^-3·size·1.5^k whose pose clears the bottom by more than 0.01.
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

void exempt_start_pairs(PhaseRig& rig) {
  const Problem& p = rig.problem();
  rig.check.set_exempt(proximity_pairs(rig.scene.obstacle_tree, Pose{}, rig.scene.body_tree, p.start,
                                       {.threshold = p.clearance + p.contact_tolerance})
                           .pairs);
}

bool has_direction(const std::vector<Vec3>& dirs, const Vec3& d) {
  return std::any_of(dirs.begin(), dirs.end(), [&](const Vec3& e) { return e.dot(d) > 1.0 - 1e-9; });
}

TEST(EscapePhase, SeparatingDirectionsOfAPegOnTheBottom) {
  PhaseRig rig(peg_on_the_bottom());
  exempt_start_pairs(rig);
  ASSERT_GT(rig.check.exempt().size(), 0u);
  const std::vector<Vec3> dirs = detail::separating_directions(rig.scene, rig.problem().start, rig.check.exempt());
  // The bottom's normal toward the peg, each wall's normal toward the peg, and the diagonals
  // of the bottom with each wall (out of a corner).
  EXPECT_TRUE(has_direction(dirs, Vec3(0, 0, 1)));
  for (const Vec3& wall : {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0)}) {
    EXPECT_TRUE(has_direction(dirs, wall)) << wall.transpose();
    EXPECT_TRUE(has_direction(dirs, (wall + Vec3(0, 0, 1)).normalized())) << wall.transpose();
  }
  for (const Vec3& d : dirs) EXPECT_NEAR(d.norm(), 1.0, 1e-12);
}

TEST(EscapePhase, PegLeavesStraightUpToTheFirstClearPose) {
  PhaseRig rig(peg_on_the_bottom());
  exempt_start_pairs(rig);
  const std::optional<Pose> escape = detail::escape_from_contact(rig.context, rig.problem().start);
  ASSERT_TRUE(escape);
  // size = max(diagonal of [−3, 3]² × [−1, 3], 2·r_max): √88 ≈ 9.38, so s_0 ≈ 0.0094 leaves the
  // peg 0.0094 ≤ 0.01 above the bottom and s_1 = 1.5·s_0 ≈ 0.0141 is the first clear pose.
  const double s0 = 1e-3 * rig.context.scene_size();
  EXPECT_NEAR(rig.context.scene_size(), std::sqrt(88.0), 1e-12);
  EXPECT_EQ(escape->rotation, Mat3::Identity());
  EXPECT_NEAR(escape->translation.z(), s0 * 1.5, 1e-15);
  EXPECT_NEAR(escape->translation.x(), 0.0, 1e-15);
  EXPECT_NEAR(escape->translation.y(), 0.0, 1e-15);
  // The escape segment satisfies the rules of docs/planner.md, checked by the oracle.
  check_path_independently(rig.scene, rig.problem(), Path{{rig.problem().start, *escape}});
}

TEST(EscapePhase, APegThatGrazesItsWallsLeavesByTheSweep) {
  // The walls 2e-10 above the clearance (0.01), the contact tolerance 1e-10: only the bottom's
  // pairs are exempt (distance 0), the walls' are not (0.01 + 2e-10 > 0.01 + 1e-10) and keep
  // 2e-10 above the margin all the way up. The lift of PegLeavesStraightUpToTheFirstClearPose
  // (0.0141 long) would need bisection pieces some 10^-10 long — past the certificate's cap;
  // the exact sweep of the translation, with the bottom's pairs left out, clears it.
  GeneratedProblem g = peg_on_the_bottom(1.0 + 0.01 + 2e-10);
  g.problem.contact_tolerance = 1e-10;
  PhaseRig rig(g);
  exempt_start_pairs(rig);
  ASSERT_GT(rig.check.exempt().size(), 0u);
  for (const ContactPair& p : rig.check.exempt().pairs)  // the bottom's top face only
    EXPECT_EQ(triangle_distance(rig.scene.obstacles.triangles[p.triangle_a], rig.scene.body.triangles[p.triangle_b]).distance,
              0.0);
  const std::optional<Pose> escape = detail::escape_from_contact(rig.context, g.problem.start);
  ASSERT_TRUE(escape);
  EXPECT_GE(rig.check.sweeps(), 1u);
  EXPECT_EQ(rig.check.cap_refusals(), 0u);
  EXPECT_EQ(escape->rotation, Mat3::Identity());
  EXPECT_NEAR(escape->translation.z(), 1.5e-3 * rig.context.scene_size(), 1e-15);
  EXPECT_EQ(escape->translation.x(), 0.0);
  EXPECT_EQ(escape->translation.y(), 0.0);
  // The oracle's own certificate bisects too (it would refuse at its cap): checked instead pair
  // by pair with its exact minimum over the translation — every pair outside the exemption
  // stays above the clearance along the whole lift.
  const Eigen::Vector3d lift = escape->translation;
  double closest = std::numeric_limits<double>::infinity();
  for (const oracle::Tri& o : oracle_triangles(rig.scene.obstacles))
    for (const oracle::Tri& b : oracle_triangles(rig.scene.body)) {
      if (oracle::triangle_distance(o, b) < g.problem.clearance + g.problem.contact_tolerance) continue;  // exempt
      closest = std::min(closest, oracle::translation_minimum(o, b, lift));
    }
  EXPECT_GT(closest, g.problem.clearance);
  EXPECT_NEAR(closest, g.problem.clearance + 2e-10, 1e-12);
  // The plan starts with that escape, and `swept check`'s checker certifies it the same way.
  const PlanResult r = plan(g.problem, rig.scene);
  ASSERT_TRUE(r.solved()) << r.message;
  EXPECT_EQ(r.path.poses[1].translation, escape->translation);
  const PathCheckResult c = check_path(g.problem, rig.scene, r.path);
  EXPECT_TRUE(c.valid) << c.message;
  EXPECT_EQ(c.escape_segments, 1u);
  EXPECT_GE(c.sweeps, 1u);
  EXPECT_NEAR(c.escape_clearance, closest, 1e-12);
}

TEST(EscapePhase, NoEscapeWithoutExemption) {
  // Without exempt pairs the peg's contact with the bottom blocks every translation at once.
  PhaseRig rig(peg_on_the_bottom());
  EXPECT_FALSE(detail::escape_from_contact(rig.context, rig.problem().start));
}

TEST(EscapePhase, PlanBeginsWithTheSameEscape) {
  const GeneratedProblem g = peg_on_the_bottom();
  PhaseRig rig(g);
  exempt_start_pairs(rig);
  const std::optional<Pose> escape = detail::escape_from_contact(rig.context, g.problem.start);
  ASSERT_TRUE(escape);
  const PlanResult r = plan(g.problem, rig.scene);
  ASSERT_TRUE(r.solved()) << r.message;
  ASSERT_GE(r.path.poses.size(), 2u);
  EXPECT_EQ(r.escape_segments, 1u);
  EXPECT_EQ(r.path.poses[1].translation, escape->translation);
  check_independently(rig.scene, g.problem, r);
}

}  // namespace
}  // namespace swept
