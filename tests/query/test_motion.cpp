// Certified motion clearance (Schwarzer, Saha, Latombe 2005) against a dense check: 10^4
// samples of the exact distance plus a golden-section refinement around every sampled local
// minimum. A certified motion must never come closer than the margin; a blocked one must be
// blocked where it says.
#include "swept/geometry/assert.h"
#include "swept/query/motion.h"
#include "swept/query/query.h"

#include "support/test_support.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

namespace swept {
namespace {

using test::Rng;

Bvh build(const std::vector<Triangle>& tris) {
  Result<Bvh> r = build_bvh(tris);
  EXPECT_TRUE(r.ok());
  return std::move(r).value();
}

/// Minimum distance along the motion by dense sampling and refinement near the minima.
double dense_minimum(const Bvh& a, const Bvh& b, const Pose& from, const Pose& to, const Vec3& ref,
                     int samples = 10000) {
  auto dist = [&](double t) {
    return distance(a, Pose::identity(), b, interpolate(from, to, t, ref)).distance;
  };
  std::vector<double> d(samples + 1);
  for (int i = 0; i <= samples; ++i) d[i] = dist(static_cast<double>(i) / samples);
  double best = *std::min_element(d.begin(), d.end());
  for (int i = 0; i <= samples; ++i) {
    const bool local = (i == 0 || d[i] <= d[i - 1]) && (i == samples || d[i] <= d[i + 1]);
    if (!local) continue;
    // Golden section on the bracket around the sampled minimum.
    double lo = std::max(0.0, (i - 1.0) / samples), hi = std::min(1.0, (i + 1.0) / samples);
    const double g = (std::sqrt(5.0) - 1) / 2;
    double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo), f1 = dist(x1), f2 = dist(x2);
    for (int k = 0; k < 40; ++k) {
      if (f1 < f2) {
        hi = x2; x2 = x1; f2 = f1; x1 = hi - g * (hi - lo); f1 = dist(x1);
      } else {
        lo = x1; x1 = x2; f1 = f2; x2 = lo + g * (hi - lo); f2 = dist(x2);
      }
    }
    best = std::min({best, f1, f2});
  }
  return best;
}

TEST(MotionLength, BoundsEveryVertexDisplacement) {
  Rng rng(4);
  const auto tris = test::random_triangles(rng, 50, 4, 1);
  const Bvh b = build(tris);
  const Vec3 ref(0.3, -0.2, 0.1);
  const double radius = motion_radius(b, ref);
  for (int it = 0; it < 200; ++it) {
    const Pose from{rng.rotation(), rng.vec(-5, 5)};
    const Pose to{rng.rotation(), rng.vec(-5, 5)};
    const double len = motion_length(from, to, ref, radius);
    for (int k = 1; k <= 20; ++k) {
      const double t = k / 20.0;
      const Pose p = interpolate(from, to, t, ref);
      for (const Triangle& tr : tris)
        for (int i = 0; i < 3; ++i)
          EXPECT_LE((p.apply(tr[i]) - from.apply(tr[i])).norm(), t * len * (1 + 1e-9) + 1e-12);
    }
  }
  // Tiny rotations keep their length (no acos cancellation).
  const Pose r0 = Pose::identity();
  const Pose r1 = Pose::from_axis_angle(Vec3::UnitZ(), 1e-10, Vec3::Zero());
  EXPECT_NEAR(motion_length(r0, r1, Vec3::Zero(), 1.0), 1e-10, 1e-20);
}

TEST(MotionClearance, NeverCertifiesAMotionADenseCheckFindsTooClose) {
  Rng rng(8);
  // Obstacles: a random soup plus a zero-thickness plate (two triangles) that a coarse
  // sampled check would step over.
  std::vector<Triangle> obstacles = test::random_triangles(rng, 150, 20, 3);
  obstacles.push_back({{0, -3, -3}, {0, 3, -3}, {0, 3, 3}});
  obstacles.push_back({{0, -3, -3}, {0, 3, 3}, {0, -3, 3}});
  const Bvh a = build(obstacles);
  const auto body_tris = test::box_triangles({-0.3, -0.2, -0.1}, {0.3, 0.2, 0.1});
  const Bvh b = build(body_tris);
  const Vec3 ref = Vec3::Zero();
  const double radius = motion_radius(b, ref);
  int free_count = 0, blocked_count = 0;
  for (int it = 0; it < 40; ++it) {
    const Pose from{rng.rotation(), rng.vec(-14, 14)};
    const Pose to{rng.rotation(), rng.vec(-14, 14)};
    const double margin = 0.05 * (it % 4);
    const MotionResult m = motion_clearance(a, Pose::identity(), b, {from, to, ref, radius}, {.margin = margin});
    const double dense = dense_minimum(a, b, from, to, ref, 10000);
    if (m.clear()) {
      ++free_count;
      EXPECT_GE(dense, margin) << "certified a motion that comes within " << dense << " < " << margin;
      EXPECT_GE(m.min_distance, margin);
    } else {
      ASSERT_EQ(m.status, MotionStatus::blocked) << "query cap reached";
      ++blocked_count;
      const double at = distance(a, Pose::identity(), b, interpolate(from, to, m.t_blocked, ref)).distance;
      const double exact_at = m.t_blocked == 0.0 ? distance(a, Pose::identity(), b, from).distance
                              : m.t_blocked == 1.0 ? distance(a, Pose::identity(), b, to).distance
                                                   : at;
      EXPECT_LT(exact_at, margin + 1e-12);
      EXPECT_NEAR(m.distance_at_block, exact_at, 1e-9);
    }
  }
  std::printf("motion_clearance: %d free, %d blocked of 40 random motions\n", free_count, blocked_count);
  EXPECT_GT(free_count, 3);
  EXPECT_GT(blocked_count, 3);
}

TEST(MotionClearance, ThinPlateBetweenSamplesIsCaught) {
  // A plate of zero thickness at x = 0; the body crosses it in a single long step, so a check
  // at 10 or 100 samples misses it entirely.
  const std::vector<Triangle> plate = {{{0, -5, -5}, {0, 5, -5}, {0, 5, 5}}, {{0, -5, -5}, {0, 5, 5}, {0, -5, 5}}};
  const Bvh a = build(plate);
  const Bvh b = build(test::box_triangles({-0.01, -0.5, -0.5}, {0.01, 0.5, 0.5}));
  const Vec3 ref = Vec3::Zero();
  const double radius = motion_radius(b, ref);
  const Pose from = Pose::from_translation({-10.1, 0, 0});
  const Pose to = Pose::from_translation({9.9, 0, 0});
  for (int n : {10, 100}) {
    bool sampled_hit = false;
    for (int i = 0; i <= n; ++i)
      sampled_hit |= collide(a, Pose::identity(), b, interpolate(from, to, double(i) / n, ref)).colliding;
    EXPECT_FALSE(sampled_hit) << "the test setup should fool a " << n << "-sample check";
  }
  const MotionResult m = motion_clearance(a, Pose::identity(), b, {from, to, ref, radius}, {.margin = 0.0});
  EXPECT_EQ(m.status, MotionStatus::blocked);
  EXPECT_NEAR(m.t_blocked, 0.505, 0.001);
  // A parallel pass beside the plate is certified.
  const MotionResult beside = motion_clearance(
      a, Pose::identity(), b, {Pose::from_translation({-10, 0, 7}), Pose::from_translation({10, 0, 7}), ref, radius},
      {.margin = 0.1});
  EXPECT_TRUE(beside.clear());
  std::printf("thin plate: blocked after %d queries; pass beside it certified with %d queries\n",
              m.distance_queries, beside.distance_queries);
}

TEST(MotionClearance, CertifiesFreeMotionsWithFewQueries) {
  Rng rng(12);
  const Bvh a = build(test::box_triangles({-1, -1, -1}, {1, 1, 1}));
  const Bvh b = build(test::box_triangles({-0.2, -0.2, -0.2}, {0.2, 0.2, 0.2}));
  const double radius = motion_radius(b, Vec3::Zero());
  int total = 0, worst = 0;
  for (int it = 0; it < 50; ++it) {
    // Motions on a shell around the box, clearance 1..3, with rotation.
    const Vec3 p0 = Vec3(4, 0, 0) + rng.vec(-0.3, 0.3);
    const Vec3 p1 = Vec3(0, 4, 0) + rng.vec(-0.3, 0.3);
    const Pose from{rng.rotation(), p0}, to{rng.rotation(), p1};
    const MotionResult m = motion_clearance(a, Pose::identity(), b, {from, to, Vec3::Zero(), radius}, {.margin = 0.1});
    EXPECT_TRUE(m.clear()) << it;
    EXPECT_GE(dense_minimum(a, b, from, to, Vec3::Zero(), 10000), 0.1);
    total += m.distance_queries;
    worst = std::max(worst, m.distance_queries);
  }
  std::printf("free motions past a box: %.1f distance queries on average, %d at most\n", total / 50.0, worst);
  EXPECT_LE(worst, 64);
}

TEST(MotionClearance, QueryCapMeansRefused) {
  const Bvh a = build(test::box_triangles({-1, -1, -1}, {1, 1, 1}));
  const Bvh b = build(test::box_triangles({-0.2, -0.2, -0.2}, {0.2, 0.2, 0.2}));
  const double radius = motion_radius(b, Vec3::Zero());
  // Passing the box's top face 1e-12 above the margin: the bisection needs pieces about
  // 1e-12 long over the face, far more than 50 queries; only the cap stops it.
  const Motion grazing{Pose::from_translation({-3, 1.3, 0}), Pose::from_translation({3, 1.3, 0}), Vec3::Zero(), radius};
  const MotionResult m = motion_clearance(a, Pose::identity(), b, grazing,
                                          {.margin = 0.1 - 1e-12, .max_queries = 50, .sweep_after = -1});
  EXPECT_EQ(m.status, MotionStatus::refused_cap);
  EXPECT_EQ(m.sweeps, 0);
  EXPECT_FALSE(m.clear());
  EXPECT_LE(m.distance_queries, 52);  // 50 bisections and the two ends
  // Above the pass's distance the first midpoint (over the face, 0.1 away) blocks.
  const MotionResult too_close = motion_clearance(a, Pose::identity(), b, grazing, {.margin = 0.2});
  EXPECT_EQ(too_close.status, MotionStatus::blocked);
  EXPECT_EQ(too_close.t_blocked, 0.5);
  EXPECT_NEAR(too_close.distance_at_block, 0.1, 1e-12);
}

TEST(MotionClearance, AGrazingTranslationIsSwept) {
  // The pass of QueryCapMeansRefused, 1e-12 above the margin all along the box's top face: the
  // bisection would need pieces ~1e-12 long (it refuses at the parameter resolution); the exact
  // sweep of the translation decides it clear after the first 64 bisection queries.
  const Bvh a = build(test::box_triangles({-1, -1, -1}, {1, 1, 1}));
  const Bvh b = build(test::box_triangles({-0.2, -0.2, -0.2}, {0.2, 0.2, 0.2}));
  const Motion grazing{Pose::from_translation({-3, 1.3, 0}), Pose::from_translation({3, 1.3, 0}), Vec3::Zero(),
                       motion_radius(b, Vec3::Zero())};
  const MotionResult m = motion_clearance(a, Pose::identity(), b, grazing, {.margin = 0.1 - 1e-12});
  EXPECT_TRUE(m.clear());
  EXPECT_EQ(m.sweeps, 1);
  EXPECT_EQ(m.distance_queries, 66);  // the two ends and 64 midpoints
  EXPECT_GE(dense_minimum(a, b, grazing.from, grazing.to, Vec3::Zero(), 2000), 0.1 - 1e-12);
  // Without the sweep the certificate gives up at the parameter resolution.
  EXPECT_EQ(motion_clearance(a, Pose::identity(), b, grazing, {.margin = 0.1 - 1e-12, .sweep_after = -1}).status,
            MotionStatus::refused_cap);
  // Rotating by a hair is not a translation: no sweep.
  Motion turning = grazing;
  turning.to.rotation = Eigen::AngleAxisd(1e-9, Vec3::UnitX()).toRotationMatrix();
  EXPECT_EQ(motion_clearance(a, Pose::identity(), b, turning, {.margin = 0.1 - 1e-12, .max_queries = 200}).sweeps, 0);
}

TEST(MotionClearance, AsTranslationBoundsHowFarATurnStrays) {
  // Every vertex of the body, at 201 poses along turning motions, lies within `slack` of where
  // the pure translation of the reference point (rotation kept) puts it.
  const Bvh b = build(test::box_triangles({-0.5, -0.2, -0.1}, {0.7, 0.3, 0.4}));
  const Vec3 reference(0.1, 0.05, 0.1);
  const double radius = motion_radius(b, reference);
  Rng rng(7);
  for (double angle : {1e-15, 1e-9, 1e-3, 0.5}) {
    const Vec3 axis = Vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)).normalized();
    const Pose from = Pose::from_axis_angle(Vec3(0, 0, 1), 0.3, Vec3(1, 2, 3));
    const Pose to{Eigen::AngleAxisd(angle, axis).toRotationMatrix() * from.rotation, Vec3(2, -1, 3.5)};
    const Motion m{from, to, reference, radius};
    const TranslationBound t = as_translation(m);
    EXPECT_NEAR(t.slack, radius * angle, 1e-9 * radius * angle + 1e-14) << angle;
    EXPECT_LT((t.translation - (to.apply(reference) - from.apply(reference))).norm(), 1e-15);
    double worst = 0.0;
    for (int k = 0; k <= 200; ++k) {
      const Pose at = m.at(k / 200.0);
      for (const Vec3& v : b.triangles.vertices)
        worst = std::max(worst, (at.apply(v) - (from.apply(v) + k / 200.0 * t.translation)).norm());
    }
    // Up to the rounding of the poses themselves (coordinates ~4: a few 1e-16 each).
    EXPECT_LE(worst, t.slack + 1e-14) << angle;
    if (angle >= 1e-3) {
      EXPECT_GT(worst, 0.5 * t.slack) << angle;  // and not far above it
    }
  }
  // Equal rotations: exactly the pure translation.
  const Motion straight{Pose::from_translation({0, 0, 0}), Pose::from_translation({1, 2, 3}), reference, radius};
  EXPECT_EQ(as_translation(straight).slack, 0.0);
  EXPECT_EQ(as_translation(straight).translation, Vec3(1, 2, 3));
}

TEST(MotionClearance, AGrazingMotionThatTurnsByAHairIsSweptToo) {
  // The pass 1e-4 above the margin, ending turned by 1e-12 rad (the rounding a chain of poses
  // leaves in a rotation): no body point strays 1e-12 from the translation, far inside the gap.
  const Bvh a = build(test::box_triangles({-1, -1, -1}, {1, 1, 1}));
  const Bvh b = build(test::box_triangles({-0.2, -0.2, -0.2}, {0.2, 0.2, 0.2}));
  Motion turning{Pose::from_translation({-3, 1.3, 0}), Pose::from_translation({3, 1.3, 0}), Vec3::Zero(),
                 motion_radius(b, Vec3::Zero())};
  turning.to.rotation = Eigen::AngleAxisd(1e-12, Vec3::UnitY()).toRotationMatrix();
  ASSERT_NE(turning.to.rotation, turning.from.rotation);
  const double margin = 0.1 - 1e-4;
  const MotionResult m = motion_clearance(a, Pose::identity(), b, turning, {.margin = margin});
  EXPECT_TRUE(m.clear());
  EXPECT_EQ(m.sweeps, 1);
  EXPECT_EQ(m.distance_queries, 66);
  EXPECT_GE(dense_minimum(a, b, turning.from, turning.to, Vec3::Zero(), 2000), margin);
  // The certificate alone agrees, at a price.
  const MotionResult plain = motion_clearance(a, Pose::identity(), b, turning, {.margin = margin, .sweep_after = -1});
  EXPECT_TRUE(plain.clear());
  EXPECT_GT(plain.distance_queries, 1000);
}

TEST(MotionClearance, AGrazingTranslationOverABumpIsBlockedOnceWhereTheBumpIs) {
  // The same pass 1e-4 above the margin (0.0999), over a bump on the face, x ∈ [0.3, 0.4],
  // 0.02 high: B (half width 0.2) is within the margin of it for centres
  // x ∈ [0.3 − 0.2 − s, 0.4 + 0.2 + s], s = √(0.0999² − 0.08²), and the motion runs
  // x = −3 → 3, t = (x + 3) / 6. The bisection spends its first 64 queries grazing the face
  // left of the bump; the sweep finds the motion blocked; the bisection goes on from there
  // (it does not start again) to where.
  std::vector<Triangle> tris = test::box_triangles({-1, -1, -1}, {1, 1, 1});
  const std::vector<Triangle> bump = test::box_triangles({0.3, 1, -1}, {0.4, 1.02, 1});
  tris.insert(tris.end(), bump.begin(), bump.end());
  const Bvh a = build(tris);
  const Bvh b = build(test::box_triangles({-0.2, -0.2, -0.2}, {0.2, 0.2, 0.2}));
  const Motion grazing{Pose::from_translation({-3, 1.3, 0}), Pose::from_translation({3, 1.3, 0}), Vec3::Zero(),
                       motion_radius(b, Vec3::Zero())};
  const double margin = 0.0999;
  const MotionResult m = motion_clearance(a, Pose::identity(), b, grazing, {.margin = margin});
  ASSERT_EQ(m.status, MotionStatus::blocked);
  EXPECT_EQ(m.sweeps, 1);
  const double s = std::sqrt(margin * margin - 0.08 * 0.08);
  EXPECT_GE(m.t_blocked, (0.3 - 0.2 - s + 3) / 6 - 1e-12);
  EXPECT_LE(m.t_blocked, (0.4 + 0.2 + s + 3) / 6 + 1e-12);
  EXPECT_LE(m.distance_at_block, margin);
  // The same verdict and the same queries as the certificate alone: the sweep added none.
  const MotionResult plain = motion_clearance(a, Pose::identity(), b, grazing, {.margin = margin, .sweep_after = -1});
  EXPECT_EQ(plain.status, MotionStatus::blocked);
  EXPECT_EQ(plain.t_blocked, m.t_blocked);
  EXPECT_EQ(plain.distance_queries, m.distance_queries);
}

// One certificate core: a hand-made distance function (a wall at x = 2, the body a point)
// shows the bisection, the end bounds, the deadline and the missing radius.
TEST(CertifyMotion, BisectsEndBoundsDeadlineAndRadius) {
  auto wall = [](double x_wall) {
    return [x_wall](const Pose& pose, double) { return std::abs(x_wall - pose.translation.x()); };
  };
  const Motion toward{Pose::from_translation({0, 0, 0}), Pose::from_translation({1, 0, 0}), Vec3::Zero(), 0.0};
  // 1 + 1 > 1: certified from the two ends alone.
  Certificate c = certify_motion(toward, wall(2.0), {.margin = 0.0});
  EXPECT_EQ(c.status, MotionStatus::clear);
  EXPECT_EQ(c.distance_queries, 2);
  // Margin 0.5: (2 − 0.5) + (1 − 0.5) = 2 > 1, still two queries.
  EXPECT_TRUE(certify_motion(toward, wall(2.0), {.margin = 0.5}).clear());
  // Margin 1: the end at distance 1 blocks (a pose blocks at distance ≤ margin).
  c = certify_motion(toward, wall(2.0), {.margin = 1.0});
  EXPECT_EQ(c.status, MotionStatus::blocked);
  EXPECT_EQ(c.t_blocked, 1.0);
  // Known end bounds are used instead of queries; a weak one forces bisection.
  int calls = 0;
  auto counted = [&](const Pose& pose, double enough) {
    ++calls;
    return wall(2.0)(pose, enough);
  };
  c = certify_motion(toward, counted, {.margin = 0.0, .from_bound = 2.0, .to_bound = 1.0});
  EXPECT_TRUE(c.clear());
  EXPECT_EQ(calls, 0);
  calls = 0;
  c = certify_motion(toward, counted, {.margin = 0.0, .from_bound = 0.1, .to_bound = 0.1});
  EXPECT_TRUE(c.clear());
  EXPECT_GT(calls, 0);
  // A wall crossed by the motion blocks at a midpoint, with the distance found there.
  c = certify_motion(toward, wall(0.5), {.margin = 0.0});
  EXPECT_EQ(c.status, MotionStatus::blocked);
  EXPECT_EQ(c.t_blocked, 0.5);
  EXPECT_EQ(c.distance_at_block, 0.0);
  // A past deadline stops a long certificate (checked every 64 bisections).
  const Motion along{Pose::from_translation({0, 0, 0}), Pose::from_translation({1, 0, 0}), Vec3::Zero(), 0.0};
  auto plate = [](const Pose&, double) { return 1e-7; };  // pieces certify below 2e-7 of length
  c = certify_motion(along, plate, {.margin = 0.0, .deadline = std::chrono::steady_clock::now() - std::chrono::seconds(1)});
  EXPECT_EQ(c.status, MotionStatus::deadline);
  EXPECT_EQ(c.distance_queries, 2 + 63);
  // A cancel flag stops it before its next query: set beforehand, after the ends; set by the
  // tenth query (as another thread would), right after it.
  std::atomic<bool> cancel{true};
  c = certify_motion(along, plate, {.margin = 0.0, .cancel = {&cancel}});
  EXPECT_EQ(c.status, MotionStatus::cancelled);
  EXPECT_FALSE(c.clear());
  EXPECT_EQ(c.distance_queries, 2);
  cancel = false;
  int asked = 0;
  auto plate_until_cancelled = [&](const Pose& pose, double enough) {
    if (++asked == 10) cancel = true;
    return plate(pose, enough);
  };
  c = certify_motion(along, plate_until_cancelled, {.margin = 0.0, .cancel = {&cancel}});
  EXPECT_EQ(c.status, MotionStatus::cancelled);
  EXPECT_EQ(c.distance_queries, 10);
  // The second flag does the same (one can be the certificate's own, the other its search's).
  cancel = false;
  asked = 0;
  std::atomic<bool> search_stopped{false};
  auto plate_until_stopped = [&](const Pose& pose, double enough) {
    if (++asked == 7) search_stopped = true;
    return plate(pose, enough);
  };
  c = certify_motion(along, plate_until_stopped, {.margin = 0.0, .cancel = {&cancel, &search_stopped}});
  EXPECT_EQ(c.status, MotionStatus::cancelled);
  EXPECT_EQ(c.distance_queries, 7);
  // Unset, they change nothing.
  search_stopped = false;
  c = certify_motion(toward, wall(2.0), {.margin = 0.0, .cancel = {&cancel, &search_stopped}});
  EXPECT_TRUE(c.clear());
#if !SWEPT_ASSERTS_ENABLED
  // Without a radius the certificate refuses to answer (asserted when asserts are on).
  const Motion no_radius{Pose::identity(), Pose::from_axis_angle(Vec3::UnitZ(), 1.0, Vec3::Zero())};
  EXPECT_EQ(certify_motion(no_radius, wall(2.0), {}).status, MotionStatus::invalid_motion);
#endif
}

// The paired certificate against the plain one, on hand-made distance functions (a point body
// among walls): a free motion is cut into the same pieces (the same midpoints asked, the same
// count), a blocked one is blocked where the distance is at most the margin, and one lane is
// never asked twice at once; the same with the pair taken from both ends (`from_both_ends`).
TEST(CertifyMotion, PairedCutsTheSamePiecesTwoAtATime) {
  tbb::task_arena arena(2);
  arena.execute([] {
    const Motion along{Pose::from_translation({0, 0, 0}), Pose::from_translation({10, 0, 0}), Vec3::Zero(), 0.0};
    // Walls x = w (each at distance |x − w|) and a plate y = −h under the path.
    struct Scene {
      std::vector<double> walls;
      double plate;
      double at(const Pose& pose) const {
        double d = std::abs(pose.translation.y() + plate);
        for (double w : walls) d = std::min(d, std::abs(pose.translation.x() - w));
        return d;
      }
    };
    const std::vector<Scene> scenes{{{}, 0.3}, {{-1.0, 11.5}, 0.05}, {{12.0}, 1e-3}, {{3.7}, 0.3}, {{0.2, 9.9}, 0.2},
                                    {{6.25}, 0.01}};
    int clear = 0, blocked = 0;  // (a wall crossed at margin 0 is refused: no midpoint lands on it)
    for (std::size_t k = 0; k < scenes.size(); ++k) {
      const Scene& scene = scenes[k];
      for (const auto& [margin, both] : {std::pair{0.0, false}, std::pair{0.005, false}, std::pair{0.1, false},
                                         std::pair{0.0, true}, std::pair{0.005, true}, std::pair{0.1, true}}) {
        std::vector<double> plain_ts;
        const Certificate plain = certify_motion(
            along,
            [&](const Pose& pose, double) {
              plain_ts.push_back(pose.translation.x());
              return scene.at(pose);
            },
            {.margin = margin, .max_queries = 100000});
        std::array<std::vector<double>, 2> lane_ts;
        std::array<std::atomic<int>, 2> busy{};
        std::atomic<int> overlaps{0};
        const Certificate paired = certify_motion_paired(
            along,
            [&](const Pose& pose, double, int lane) {
              if (busy[lane]++ != 0) ++overlaps;
              lane_ts[lane].push_back(pose.translation.x());
              const double d = scene.at(pose);
              --busy[lane];
              return d;
            },
            {.margin = margin, .max_queries = 100000, .from_both_ends = both});
        SCOPED_TRACE(testing::Message() << "scene " << k << ", margin " << margin << (both ? ", from both ends" : ""));
        EXPECT_EQ(overlaps.load(), 0);
        std::vector<double> paired_ts = lane_ts[0];
        paired_ts.insert(paired_ts.end(), lane_ts[1].begin(), lane_ts[1].end());
        EXPECT_EQ(paired.distance_queries, static_cast<int>(paired_ts.size()));
        ASSERT_EQ(plain.status, paired.status);
        if (plain.clear()) {
          std::sort(plain_ts.begin(), plain_ts.end());
          std::sort(paired_ts.begin(), paired_ts.end());
          EXPECT_EQ(plain_ts, paired_ts);
          EXPECT_EQ(plain.distance_queries, paired.distance_queries);
          EXPECT_EQ(plain.min_distance, paired.min_distance);
          ++clear;
        } else if (paired.status == MotionStatus::blocked) {
          ++blocked;
          EXPECT_LE(paired.distance_at_block, margin);
          EXPECT_EQ(scene.at(along.at(paired.t_blocked)), paired.distance_at_block);
        }
      }
    }
    EXPECT_GE(clear, 12);
    EXPECT_GE(blocked, 8);
  });
}

// A motion blocked only near its end (a wall at x = 9.7 of 0 → 10, a plate under the path that
// cuts it into many pieces): the pair taken from both ends reaches the wall in a handful of
// queries (41 here); the two earliest certify almost the whole motion first (505). Near the
// start (x = 0.3) lane 0 still works from the start, so both find the wall early (27 and 41).
TEST(CertifyMotion, FromBothEndsFindsALateBlockSooner) {
  tbb::task_arena arena(2);
  arena.execute([] {
    const Motion along{Pose::from_translation({0, 0, 0}), Pose::from_translation({10, 0, 0}), Vec3::Zero(), 0.0};
    for (const double wall : {9.7, 0.3}) {
      auto at = [wall](const Pose& pose) {
        return std::min(std::abs(pose.translation.y() + 0.02), std::abs(pose.translation.x() - wall));
      };
      std::array<Certificate, 2> c;  // the two earliest, then from both ends
      for (const bool both : {false, true})
        c[both] = certify_motion_paired(
            along, [&](const Pose& pose, double, int) { return at(pose); },
            {.margin = 0.01, .max_queries = 100000, .from_both_ends = both});
      SCOPED_TRACE(testing::Message() << "wall at x = " << wall);
      for (const Certificate& k : c) {
        ASSERT_EQ(k.status, MotionStatus::blocked);
        EXPECT_LE(k.distance_at_block, 0.01);
        EXPECT_EQ(at(along.at(k.t_blocked)), k.distance_at_block);
        EXPECT_NEAR(10.0 * k.t_blocked, wall, 0.01 + 1e-9);
      }
      if (wall > 5.0) {
        EXPECT_GT(c[0].distance_queries, 400);  // pieces about 0.02 long, all the way to the wall
        EXPECT_LT(c[1].distance_queries, 60);
      } else {
        EXPECT_LT(c[0].distance_queries, 60);
        EXPECT_LT(c[1].distance_queries, 60);  // lane 1 spends its half at the far end
      }
    }
  });
}

}  // namespace
}  // namespace swept
