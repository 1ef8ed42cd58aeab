// The two primitives of the exact translation sweep (sweep_translation, motion.h), against
// answers that share no code with them: the oracle's triangle distance (tests/oracle) minimised
// over the sweep by golden section (the distance of two convex sets is convex in a translation
// of one of them), and the exact rectangle distance sampled densely along the sweep.
#include "oracle/path_oracle.h"
#include "support/test_support.h"
#include "swept/geometry/distance.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace swept {
namespace {

using test::Rng;

oracle::Tri to_oracle(const Triangle& t) { return {{t.p, t.q, t.r}}; }

// min over τ ∈ [0, 1] of the oracle distance between a and b + τ·sweep.
double oracle_sweep_minimum(const Triangle& a, const Triangle& b, const Vec3& sweep) {
  return oracle::translation_minimum(to_oracle(a), to_oracle(b), sweep);
}

TEST(SweepPrimitives, TriangleSweepWithinAgreesWithTheOracle) {
  Rng rng(77);
  int within = 0, apart = 0, skipped = 0;
  for (int k = 0; k < 4000; ++k) {
    const auto a = test::random_triangles(rng, 1, 4.0, 2.0)[0];
    const auto b = test::random_triangles(rng, 1, 4.0, 2.0, rng.vec(-3.0, 3.0))[0];
    Vec3 sweep = rng.vec(-6.0, 6.0);
    if (k % 4 == 1) {  // in b's plane: the prism is flat
      const Vec3 n = (b.q - b.p).cross(b.r - b.p).normalized();
      sweep -= sweep.dot(n) * n;
    }
    if (k % 8 == 3) sweep = Vec3::Zero();
    const double limit = k % 5 == 0 ? 0.0 : rng.uniform(0.0, 2.0);
    const double truth = oracle_sweep_minimum(a, b, sweep);
    if (std::abs(truth - limit) < 1e-7) {
      ++skipped;
      continue;
    }
    const bool expect = truth <= limit;
    EXPECT_EQ(triangle_sweep_within(a, b, sweep, limit), expect)
        << "pair " << k << ": oracle minimum " << truth << ", limit " << limit;
    (expect ? within : apart) += 1;
  }
  EXPECT_GT(within, 500);
  EXPECT_GT(apart, 500);
  EXPECT_LT(skipped, 40);
}

TEST(SweepPrimitives, ATriangleInsideThePrismIsWithin) {
  // b sweeps straight up through a small triangle that touches none of the prism's faces: the
  // distance is 0 only because a lies inside (no face of the prism comes near it).
  const Triangle b{{0, 0, 0}, {10, 0, 0}, {0, 10, 0}};
  const Triangle a{{2, 2, 5}, {3, 2, 5}, {2, 3, 5.5}};
  EXPECT_TRUE(triangle_sweep_within(a, b, Vec3(0, 0, 10), 0.0));
  EXPECT_FALSE(triangle_sweep_within(a, b, Vec3(0, 0, 4), 0.5));   // stops 1 below it
  EXPECT_TRUE(triangle_sweep_within(a, b, Vec3(0, 0, 4), 1.0));    // ... which is within 1
  EXPECT_FALSE(triangle_sweep_within(a, b, Vec3(0, 0, -10), 4.9));  // the other way
}

TEST(SweepPrimitives, SweptRectangleBoundNeverExceedsTheDistanceAlongTheSweep) {
  Rng rng(5);
  int positive = 0;
  for (int k = 0; k < 3000; ++k) {
    RectanglePair p;
    p.rotation = rng.rotation();
    p.translation = rng.vec(-8.0, 8.0);
    for (double& h : p.a) h = rng.uniform(0.0, 3.0);
    for (double& h : p.b) h = rng.uniform(0.0, 3.0);
    const Vec3 sweep = k % 10 == 0 ? Vec3::Zero() : rng.vec(-10.0, 10.0);
    double sampled = INFINITY;
    for (int i = 0; i <= 2000; ++i) {
      RectanglePair q = p;
      q.translation += (i / 2000.0) * sweep;
      sampled = std::min(sampled, rectangle_distance(q));
    }
    const double bound = swept_rectangle_lower_bound(p, sweep);
    EXPECT_LE(bound, sampled + 1e-9) << "pair " << k;
    // Early exit: a stop_at below the answer still returns a valid bound ≥ it.
    const double early = swept_rectangle_lower_bound(p, sweep, 0.5 * bound);
    EXPECT_LE(early, sampled + 1e-9);
    if (bound > 0.0) {
      ++positive;
      EXPECT_GE(early, 0.5 * bound - 1e-9);
    }
  }
  EXPECT_GT(positive, 300);  // not a bound that is never useful
}

}  // namespace
}  // namespace swept
