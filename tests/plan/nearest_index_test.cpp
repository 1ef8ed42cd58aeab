// The trees' nearest-node index (src/plan/nearest_index.h) against a scan of every node in
// order: the same index for every query, ties (the lowest index) and skipped nodes included.
// The scan uses the same metric formula, so that equal lengths compare equal on both sides;
// the formula itself is checked by hand in tree_search_test.cpp (NearestIsTheClosest...).
#include "plan/nearest_index.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace swept {
namespace {

using detail::motion_metric;
using detail::NearestIndex;

struct Node {
  Vec3 point;
  Quat rotation;
  bool keep = true;
};

std::int32_t scan(const std::vector<Node>& nodes, const Vec3& p, const Quat& q, double r) {
  std::int32_t best = -1;
  double best_length = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (!nodes[i].keep) continue;
    const double length = motion_metric(p, q, nodes[i].point, nodes[i].rotation, r);
    if (length < best_length) best_length = length, best = static_cast<std::int32_t>(i);
  }
  return best;
}

Quat random_rotation(std::mt19937_64& rng) {
  std::normal_distribution<double> n;
  return Quat(n(rng), n(rng), n(rng), n(rng)).normalized();
}

// Nodes of a tree-like cloud: clusters of near-equal poses (rotations a few 1e-9 apart, where
// acos rounds), exact duplicates, the same rotation as q and as −q, and nodes the predicate
// drops; queries at nodes, near them, and anywhere. Checked at every size up to 3,000, across
// the index's rebuilds.
void check_against_scan(double radius, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-10.0, 10.0), tiny(-1e-9, 1e-9), unit(0.0, 1.0);
  NearestIndex index(radius);
  std::vector<Node> nodes;
  int checked = 0;
  for (int n = 0; n < 3000; ++n) {
    Node node;
    const double kind = unit(rng);
    if (nodes.empty() || kind < 0.5) {
      node.point = Vec3(u(rng), u(rng), u(rng));
      node.rotation = random_rotation(rng);
    } else {
      const Node& near = nodes[rng() % nodes.size()];
      node.point = near.point;
      node.rotation = near.rotation;
      if (kind < 0.7) node.point += Vec3(tiny(rng), tiny(rng), tiny(rng));
      if (kind < 0.8) node.rotation = Quat(near.rotation.coeffs() + Eigen::Vector4d(tiny(rng), tiny(rng), tiny(rng), tiny(rng))).normalized();
      else if (kind < 0.9) node.rotation.coeffs() = -node.rotation.coeffs();  // the same rotation
      // else: an exact duplicate
    }
    node.keep = unit(rng) > 0.15;
    nodes.push_back(node);
    index.add(node.point, node.rotation);
    ASSERT_EQ(index.size(), nodes.size());
    for (int k = 0; k < 4; ++k) {
      Vec3 p(u(rng), u(rng), u(rng));
      Quat q = random_rotation(rng);
      if (k >= 2) {  // at or next to a node
        const Node& at = nodes[rng() % nodes.size()];
        p = at.point + (k == 3 ? Vec3(tiny(rng), tiny(rng), tiny(rng)) : Vec3::Zero());
        q = k == 3 ? Quat(-at.rotation.coeffs()) : at.rotation;
      }
      const std::int32_t expected = scan(nodes, p, q, radius);
      ASSERT_EQ(index.nearest(p, q, [&](std::size_t i) { return nodes[i].keep; }), expected)
          << "after " << nodes.size() << " nodes, query " << k;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 12000);
}

TEST(NearestIndex, AnswersAsAScanOfEveryNodeInOrder) {
  check_against_scan(1.0, 1);
  check_against_scan(20.0, 2);   // rotation dominates the metric
  check_against_scan(0.01, 3);   // translation dominates
}

TEST(NearestIndex, NoNodeKeptIsMinusOne) {
  NearestIndex index(1.0);
  EXPECT_EQ(index.nearest(Vec3::Zero(), Quat::Identity(), [](std::size_t) { return true; }), -1);
  for (int i = 0; i < 200; ++i) index.add(Vec3(i, 0, 0), Quat::Identity());
  EXPECT_EQ(index.nearest(Vec3::Zero(), Quat::Identity(), [](std::size_t) { return false; }), -1);
  EXPECT_EQ(index.nearest(Vec3(150.2, 0, 0), Quat::Identity(), [](std::size_t i) { return i % 2 == 1; }), 151);
  // All at one pose: the lowest index kept.
  NearestIndex same(1.0);
  for (int i = 0; i < 500; ++i) same.add(Vec3(1, 2, 3), Quat::Identity());
  EXPECT_EQ(same.nearest(Vec3(0, 0, 0), Quat::Identity(), [](std::size_t i) { return i >= 37; }), 37);
}

}  // namespace
}  // namespace swept
