// swept's exact triangle distance against the oracle's (tests/oracle), two implementations that
// share no code: they must agree on random, touching, crossing and degenerate pairs.
#include "oracle/path_oracle.h"
#include "support/test_support.h"
#include "swept/geometry/distance.h"

#include <gtest/gtest.h>

#include <cmath>

namespace swept {
namespace {

oracle::Tri to_oracle(const Triangle& t) { return {{t.p, t.q, t.r}}; }

TEST(OracleAgreement, TriangleDistanceOnRandomAndNastyPairs) {
  test::Rng rng(2024);
  // Random triangles crowded in a small cube (many crossings and near misses), and the nasty
  // mix (slivers, zero-area, repeated vertices, big and tiny) from the test support.
  const auto a = test::random_triangles(rng, 400, 2.0, 1.5);
  const auto b = test::random_triangles(rng, 400, 2.0, 1.5);
  const auto n = test::nasty_triangles(rng, 400, 2.0);
  int crossings = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (const auto* other : {&b, &n}) {
      for (std::size_t k = 0; k < 40; ++k) {
        const Triangle& x = a[i];
        const Triangle& y = (*other)[(i * 37 + k * 11) % other->size()];
        const double ours = triangle_distance(x, y).distance;
        const double theirs = oracle::triangle_distance(to_oracle(x), to_oracle(y));
        ASSERT_TRUE(std::isfinite(theirs));
        // Both are exact up to rounding of coordinates of size ~2.
        EXPECT_NEAR(ours, theirs, 1e-12) << "pair " << i << ", " << k;
        crossings += theirs == 0.0;
      }
    }
  }
  EXPECT_GT(crossings, 100) << "the sample should hold many intersecting pairs";
}

}  // namespace
}  // namespace swept
