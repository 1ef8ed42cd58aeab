// sweep_translation (motion.h) against brute force: every triangle pair, its smallest distance
// along the translation found by golden section on the oracle's triangle distance
// (tests/oracle, no code shared with the query layer), the pairs a rule leaves out skipped.
#include "oracle/path_oracle.h"
#include "support/test_support.h"
#include "swept/query/motion.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

namespace swept {
namespace {

using test::Rng;

oracle::Tri moved(const Triangle& t, const Pose& pose, const Vec3& shift) {
  return {{pose.apply(t.p) + shift, pose.apply(t.q) + shift, pose.apply(t.r) + shift}};
}

// Smallest distance between a (at pose_a) and b (at pose_b, then moved by τ·translation).
double pair_minimum(const Triangle& a, const Pose& pa, const Triangle& b, const Pose& pb, const Vec3& translation) {
  return oracle::translation_minimum(moved(a, pa, Vec3::Zero()), moved(b, pb, Vec3::Zero()), translation);
}

TEST(SweepTranslation, MatchesBruteForceWithAndWithoutARule) {
  Rng rng(11);
  int blocked = 0, clear = 0, checked = 0;
  for (int k = 0; k < 40; ++k) {
    const auto ta = test::random_triangles(rng, 80, 20.0, 4.0);
    const auto tb = test::random_triangles(rng, 40, 8.0, 3.0);
    const Bvh a = build_bvh(ta).value();
    const Bvh b = build_bvh(tb).value();
    const Pose pa{rng.rotation(), rng.vec(-2.0, 2.0)};
    const Pose pb{rng.rotation(), rng.vec(-30.0, 30.0)};
    // Towards A and past it, or short of it, or beside it.
    const Vec3 translation = rng.uniform(0.2, 2.0) * (rng.vec(-15.0, 15.0) - pb.translation);
    const double margin = rng.uniform(0.0, 1.0);
    // A rule that leaves out about half of the pairs, by their ids.
    const std::function<bool(std::uint32_t, std::uint32_t)> rule = [](std::uint32_t i, std::uint32_t j) {
      return (i * 7 + j * 3) % 2 == 0;
    };
    std::vector<double> minima(ta.size() * tb.size());
    for (std::uint32_t i = 0; i < ta.size(); ++i)
      for (std::uint32_t j = 0; j < tb.size(); ++j) minima[i * tb.size() + j] = pair_minimum(ta[i], pa, tb[j], pb, translation);
    for (const bool with_rule : {false, true}) {
      const SweepResult r = sweep_translation(a, pa, b, pb,
                                              {.translation = translation, .margin = margin,
                                               .exclude_if = with_rule ? &rule : nullptr});
      double nearest = INFINITY;  // over the pairs not left out
      for (std::uint32_t i = 0; i < ta.size(); ++i)
        for (std::uint32_t j = 0; j < tb.size(); ++j)
          if (!with_rule || !rule(i, j)) nearest = std::min(nearest, minima[i * tb.size() + j]);
      if (std::abs(nearest - margin) < 1e-7) continue;  // a tie the two arithmetics may call either way
      ++checked;
      EXPECT_EQ(r.clear, nearest > margin) << "case " << k << (with_rule ? " with the rule" : "") << ": nearest "
                                           << nearest << ", margin " << margin;
      if (!r.clear) {
        ++blocked;
        EXPECT_FALSE(with_rule && rule(r.triangle_a, r.triangle_b)) << "a left-out pair reported";
        EXPECT_LE(minima[r.triangle_a * tb.size() + r.triangle_b], margin + 1e-7)
            << "the reported pair does not block";
      } else {
        ++clear;
      }
    }
  }
  EXPECT_EQ(checked, 80);
  EXPECT_GT(blocked, 15);
  EXPECT_GT(clear, 15);
}

TEST(SweepTranslation, NodeRuleLeavesOutWholeSubtrees) {
  // A box sliding through another: blocked; with every node pair left out by the node rule,
  // clear without a single triangle test; with a node rule that never applies, blocked again.
  const Bvh a = build_bvh(test::box_triangles(Vec3(0, 0, 0), Vec3(10, 10, 10))).value();
  const Bvh b = build_bvh(test::box_triangles(Vec3(-5, 2, 2), Vec3(-3, 4, 4))).value();
  const std::function<bool(std::int32_t, std::int32_t)> all = [](std::int32_t, std::int32_t) { return true; };
  const std::function<bool(std::int32_t, std::int32_t)> none = [](std::int32_t, std::int32_t) { return false; };
  const Vec3 through(20, 0, 0);
  EXPECT_FALSE(sweep_translation(a, Pose{}, b, Pose{}, {.translation = through}).clear);
  const SweepResult skipped = sweep_translation(a, Pose{}, b, Pose{}, {.translation = through, .exclude_nodes_if = &all});
  EXPECT_TRUE(skipped.clear);
  EXPECT_EQ(skipped.stats.triangle_tests, 0u);
  EXPECT_FALSE(sweep_translation(a, Pose{}, b, Pose{}, {.translation = through, .exclude_nodes_if = &none}).clear);
  // Stopping 1 short of the box: clear at margin 0.99, blocked at 1.01.
  EXPECT_TRUE(sweep_translation(a, Pose{}, b, Pose{}, {.translation = Vec3(2, 0, 0), .margin = 0.99}).clear);
  EXPECT_FALSE(sweep_translation(a, Pose{}, b, Pose{}, {.translation = Vec3(2, 0, 0), .margin = 1.01}).clear);
}

}  // namespace
}  // namespace swept
