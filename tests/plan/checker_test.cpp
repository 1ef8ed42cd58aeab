// The planner's certificate (src/plan/checker.h) on motions whose answer is worked out by hand:
// a pure translation that grazes the margin is decided by the exact sweep, in a few queries
// instead of the certificate's thousands, and gives the certificate's answer.
#include "plan/checker.h"
#include "plan/plan_support.h"

#include <cmath>
#include <vector>

namespace swept {
namespace {

using namespace swept::test;
using scenes::add_box;
using scenes::GeneratedProblem;

constexpr double kMargin = 0.05;
constexpr double kGap = 1e-4;  // above the margin

// A body [−1.5, 1.5] × [−1, 1] × [−0.5, 0.5] over a flat floor (top z = 0, x, y ∈ [−20, 20]),
// its bottom at z = margin + gap: at that distance from the floor wherever it is over it.
// `bump`: a block on the floor, x ∈ [4.9, 5.1], z ∈ [0, 0.02], across the body's way.
GeneratedProblem body_over_a_floor(bool bump) {
  GeneratedProblem g;
  g.name = "body_over_a_floor";
  add_box(g.obstacles.triangles, Vec3(-20, -20, -1), Vec3(20, 20, 0));
  if (bump) add_box(g.obstacles.triangles, Vec3(4.9, -5, 0), Vec3(5.1, 5, 0.02));
  add_box(g.body.triangles, Vec3(-1.5, -1, -0.5), Vec3(1.5, 1, 0.5));
  g.problem.start = Pose::from_translation(Vec3(-10, 0, 0.5 + kMargin + kGap));
  g.problem.goal = Pose::from_translation(Vec3(10, 0, 0.5 + kMargin + kGap));
  g.problem.clearance = kMargin;
  return g;
}

TEST(Checker, AGrazingTranslationIsSweptNotBisected) {
  // 20 along the floor at a gap of 1e-4 above the margin: the certificate's pieces are at most
  // 2e-4 long, some 10^5 queries; the sweep decides it after the first kSweepAfter.
  const GeneratedProblem g = body_over_a_floor(false);
  const PlanScene scene = scene_of(g);
  const detail::Checker check(scene, kMargin);
  const Certificate c = check.certify(g.problem.start, -1, *g.problem.goal, -1);
  EXPECT_TRUE(c.clear());
  EXPECT_EQ(check.sweeps(), 1u);
  EXPECT_LE(check.distance_queries(), static_cast<std::uint64_t>(detail::Checker::kSweepAfter) + 2);
  EXPECT_EQ(check.cap_refusals(), 0u);
  // The goal's rotation off the start's by rounding (1e-15 rad, as a chain of interpolated poses
  // leaves it): swept too, with the margin raised by radius × angle (~2e-15).
  Pose turned = *g.problem.goal;
  turned.rotation = Eigen::AngleAxisd(1e-15, Vec3::UnitX()).toRotationMatrix();
  ASSERT_NE(turned.rotation, g.problem.start.rotation);
  const detail::Checker check_turned(scene, kMargin);
  EXPECT_TRUE(check_turned.certify(g.problem.start, -1, turned, -1).clear());
  EXPECT_EQ(check_turned.sweeps(), 1u);
  EXPECT_LE(check_turned.distance_queries(), static_cast<std::uint64_t>(detail::Checker::kSweepAfter) + 2);
  // By hand: the distance is margin + gap all along.
  for (double t : {0.0, 0.25, 0.5, 0.75, 1.0}) {
    const Pose q = interpolate(g.problem.start, *g.problem.goal, t, scene.reference);
    EXPECT_NEAR(distance(scene.obstacle_tree, Pose{}, scene.body_tree, q).distance, kMargin + kGap, 1e-12);
  }
}

TEST(Checker, AGrazingTranslationOverABumpIsBlockedWhereTheBumpIs) {
  // The bump's top is 0.0301 under the body's bottom: blocked wherever the body's edge comes
  // within √(0.05² − 0.0301²) ≈ 0.0399 of the bump sideways, i.e. for body centres x in
  // [4.9 − 1.5 − 0.0399, 5.1 + 1.5 + 0.0399]; the motion runs x = −10 → 10, t = (x + 10) / 20.
  const GeneratedProblem g = body_over_a_floor(true);
  const PlanScene scene = scene_of(g);
  const detail::Checker check(scene, kMargin);
  const Certificate c = check.certify(g.problem.start, -1, *g.problem.goal, -1);
  ASSERT_EQ(c.status, MotionStatus::blocked);
  EXPECT_EQ(check.sweeps(), 1u);
  // The bisection went on past the sweep: every query the checker made is the certificate's.
  EXPECT_EQ(check.distance_queries(), static_cast<std::uint64_t>(c.distance_queries));
  const double side = std::sqrt(kMargin * kMargin - (kMargin + kGap - 0.02) * (kMargin + kGap - 0.02));
  EXPECT_GE(c.t_blocked, (4.9 - 1.5 - side + 10) / 20 - 1e-9);
  EXPECT_LE(c.t_blocked, (5.1 + 1.5 + side + 10) / 20 + 1e-9);
  EXPECT_LE(c.distance_at_block, kMargin);
}

TEST(Checker, AMotionThatTurnsKeepsTheCertificate) {
  // The same grazing motion with a turn of 1e-3 rad about z on the way is not a translation:
  // no sweep, the certificate bisects (more queries than the sweep's threshold) and clears it
  // (the turn lifts no corner: the floor is flat and the body turns about the vertical).
  GeneratedProblem g = body_over_a_floor(false);
  g.problem.goal->translation.x() = -9;  // 1 long: some 10^4 pieces
  g.problem.goal->rotation = Eigen::AngleAxisd(1e-3, Vec3::UnitZ()).toRotationMatrix();
  const PlanScene scene = scene_of(g);
  const detail::Checker check(scene, kMargin);
  const Certificate c = check.certify(g.problem.start, -1, *g.problem.goal, -1);
  EXPECT_TRUE(c.clear());
  EXPECT_EQ(check.sweeps(), 0u);
  EXPECT_GT(check.distance_queries(), static_cast<std::uint64_t>(detail::Checker::kSweepAfter));
}

TEST(Checker, ASampleWithinTheMarginRefusesOnlyBlockedMotions) {
  // Over the floor at margin + gap: no sample is within the margin, the pre-check says nothing.
  const GeneratedProblem flat = body_over_a_floor(false);
  const PlanScene flat_scene = scene_of(flat);
  const detail::Checker flat_check(flat_scene, kMargin);
  EXPECT_FALSE(flat_check.blocked_at_samples(flat.problem.start, *flat.problem.goal));
  // Over the bump (blocked for t in [0.668, 0.832], worked out above): the sample t = 3/4 lies
  // in it, and so does the certificate's answer.
  const GeneratedProblem g = body_over_a_floor(true);
  const PlanScene scene = scene_of(g);
  const detail::Checker check(scene, kMargin);
  EXPECT_TRUE(check.blocked_at_samples(g.problem.start, *g.problem.goal));
  EXPECT_EQ(check.distance_queries(), 3u) << "t = 1/2, 1/4, then 3/4, where it stops";
  const Pose at = interpolate(g.problem.start, *g.problem.goal, 0.75, scene.reference);
  EXPECT_LE(distance(scene.obstacle_tree, Pose{}, scene.body_tree, at).distance, kMargin);
  EXPECT_EQ(check.certify(g.problem.start, -1, *g.problem.goal, -1).status, MotionStatus::blocked);
  // From x = −10 to x = 24 (t = (x + 10) / 34) the blocked stretch x in [3.36, 6.64] is t in
  // [0.393, 0.489], between the samples t = 3/8 (x = 2.75) and 1/2 (x = 7): the pre-check says
  // nothing, and the certificate finds it blocked.
  Pose far = *g.problem.goal;
  far.translation.x() = 24;
  EXPECT_FALSE(check.blocked_at_samples(g.problem.start, far));
  EXPECT_EQ(check.certify(g.problem.start, -1, far, -1).status, MotionStatus::blocked);
}

TEST(Checker, SuspectsDecideOnlyWhatTheQueryWould) {
  // A walk of short random steps through the L-tunnel's walls, as a search tree's steps go: each
  // pose measured twice, plainly and with the pairs the walk's earlier poses found closest or
  // blocking. Free poses must get the same bits; blocked ones must be blocked for both, and a
  // pair a suspect decides blocked is checked with the oracle's own triangle distance. The
  // query count is the same either way (a suspect's decision counts as the query it replaces).
  const GeneratedProblem g = scenes::l_tunnel();
  const PlanScene scene = scene_of(g);
  const double margin = 0.05;
  detail::Checker plain(scene, margin), suspected(scene, margin);
  plain.set_decide_blocked(true);
  suspected.set_decide_blocked(true);
  const std::vector<oracle::Tri> obstacles = oracle_triangles(g.obstacles);
  Rng rng(2026);
  detail::Suspects suspects;
  Pose pose = g.problem.start;
  const Aabb box = *g.problem.bounds;
  int blocked = 0, decided_by_suspect = 0, free = 0;
  for (int i = 0; i < 3000; ++i) {
    if (i % 50 == 0) pose = {rng.rotation(), rng.vec(0, 1).cwiseProduct(box.max - box.min) + box.min};
    else pose = {Eigen::AngleAxisd(rng.uniform(-0.2, 0.2), rng.vec(-1, 1).normalized()).toRotationMatrix() * pose.rotation,
                 pose.translation + rng.vec(-0.3, 0.3)};
    const double enough = margin + 0.5;
    const DistanceResult p = plain.measure(pose, enough);
    const DistanceResult s = suspected.measure(pose, enough, &suspects);
    ASSERT_EQ(p.distance <= margin, s.distance <= margin) << "pose " << i;
    if (p.distance > margin) {
      ++free;
      EXPECT_EQ(p.distance, s.distance) << "pose " << i;
      EXPECT_EQ(p.exact, s.exact) << "pose " << i;
      EXPECT_EQ(p.triangle_a, s.triangle_a) << "pose " << i;
      EXPECT_EQ(p.triangle_b, s.triangle_b) << "pose " << i;
      continue;
    }
    ++blocked;
    if (s.stats.bv_tests == 0) {
      ++decided_by_suspect;
      // Decided without a search: a triangle test per suspect tried, up to the one that blocks.
      EXPECT_GE(s.stats.triangle_tests, 1u);
      EXPECT_LE(s.stats.triangle_tests, detail::Suspects::kSize);
      const Triangle& t = g.body.triangles[s.triangle_b];
      const oracle::Tri body{{pose.apply(t.p), pose.apply(t.q), pose.apply(t.r)}};
      EXPECT_LE(oracle::triangle_distance(obstacles[s.triangle_a], body), margin + 1e-12) << "pose " << i;
      EXPECT_LE(s.distance, margin);
    }
  }
  EXPECT_EQ(plain.distance_queries(), suspected.distance_queries());
  // The walk crosses walls often, and the suspects decide most of its blocked poses.
  EXPECT_GT(free, 300);
  EXPECT_GT(blocked, 300);
  EXPECT_GT(decided_by_suspect, blocked / 2);
  // Without set_decide_blocked (exact distances asked for) the suspects are not used.
  const detail::Checker exact(scene, margin);
  detail::Suspects held = suspects;
  for (int i = 0; i < 200; ++i) {
    const Pose q{rng.rotation(), rng.vec(0, 1).cwiseProduct(box.max - box.min) + box.min};
    const DistanceResult a = exact.measure(q, 1e300), b = exact.measure(q, 1e300, &held);
    EXPECT_EQ(a.distance, b.distance) << "pose " << i;
    EXPECT_EQ(a.triangle_a, b.triangle_a) << "pose " << i;
    EXPECT_EQ(a.triangle_b, b.triangle_b) << "pose " << i;
  }
}

TEST(Checker, SuspectsKeepTheMostRecentPairsFirst) {
  detail::Suspects s;
  s.add({});  // not a pair: ignored
  EXPECT_FALSE(s.pairs[0].valid());
  for (std::uint32_t k = 1; k <= 5; ++k) s.add({k, 10 * k});
  // 5, 4, 3, 2 (1 dropped out); adding 3 again moves it up without a copy.
  EXPECT_EQ(s.pairs[0].a, 5u);
  EXPECT_EQ(s.pairs[3].a, 2u);
  s.add({3, 30});
  EXPECT_EQ(s.pairs[0].a, 3u);
  EXPECT_EQ(s.pairs[1].a, 5u);
  EXPECT_EQ(s.pairs[2].a, 4u);
  EXPECT_EQ(s.pairs[3].a, 2u);
}

}  // namespace
}  // namespace swept
