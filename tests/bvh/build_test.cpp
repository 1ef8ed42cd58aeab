// The RSS tree: containment invariant, determinism across thread counts, structure.
#include "support/tables.h"
#include "support/test_support.h"
#include "swept/bvh/bvh.h"
#include "swept/bvh/fitter.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <functional>
#include <map>
#include <numbers>

namespace swept {
namespace {

using test::Rng;

const std::vector<Fitter> kFitters = swept::test::every_fitter();
const std::vector<SplitRule> kSplits = swept::test::every_split_rule();

// Triangle range [begin, end) of every node (leaves' ranges are stored; internal nodes cover
// their children's adjacent ranges).
std::vector<std::pair<int, int>> node_ranges(const Bvh& bvh) {
  std::vector<std::pair<int, int>> range(bvh.nodes.size());
  std::function<std::pair<int, int>(int)> walk = [&](int i) {
    const Node& n = bvh.nodes[i];
    if (n.is_leaf()) return range[i] = {n.first, n.first + n.count};
    auto l = walk(n.first), r = walk(n.first + 1);
    EXPECT_EQ(l.second, r.first) << "children's triangles are not adjacent";
    return range[i] = {l.first, r.second};
  };
  walk(0);
  return range;
}

// Every vertex of every triangle lies in the RSS of its leaf and of every ancestor.
void expect_containment(const Bvh& bvh, const std::string& what) {
  const double tol = 1e-9 * bvh.extent;
  const auto range = node_ranges(bvh);
  std::size_t bad = 0;
  double worst = -1e300;
  for (std::size_t i = 0; i < bvh.nodes.size(); ++i) {
    for (int t = range[i].first; t < range[i].second; ++t)
      for (int v = 0; v < 3; ++v) {
        const double d = signed_distance(bvh.bv(i), bvh.triangles[t][v]);
        worst = std::max(worst, d);
        if (d > tol) ++bad;
      }
  }
  EXPECT_EQ(bad, 0u) << what << ": worst excess " << worst << " (tolerance " << tol << ")";
}

void expect_structure(const Bvh& bvh, std::size_t n, int leaf_size) {
  ASSERT_FALSE(bvh.empty());
  // The root every query starts from is the first node, decoded (a cache that must not drift).
  const Rss root = bvh.bv(0);
  EXPECT_EQ(bvh.root.axes, root.axes);
  EXPECT_EQ(bvh.root.center, root.center);
  EXPECT_EQ(bvh.root.half_length, root.half_length);
  EXPECT_EQ(bvh.root.radius, root.radius);
  std::size_t in_leaves = 0;
  for (const Node& node : bvh.nodes) {
    if (node.is_leaf()) {
      in_leaves += static_cast<std::size_t>(node.count);
      EXPECT_LE(node.count, leaf_size);
    } else {
      EXPECT_GT(node.first, 0);
      EXPECT_LT(static_cast<std::size_t>(node.first + 1), bvh.nodes.size());
    }
  }
  EXPECT_EQ(in_leaves, n);
  std::vector<std::uint32_t> ids = bvh.triangle_ids;
  std::sort(ids.begin(), ids.end());
  for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(ids[i], i);
  if (leaf_size == 1) {
    EXPECT_EQ(bvh.nodes.size(), 2 * n - 1);
  }
  // Every node is reached exactly once from the root, and the deepest is at `depth`.
  std::vector<int> seen(bvh.nodes.size(), 0);
  std::vector<std::pair<std::int32_t, int>> stack{{0, 1}};
  int deepest = 0;
  while (!stack.empty()) {
    const auto [i, d] = stack.back();
    stack.pop_back();
    ++seen[static_cast<std::size_t>(i)];
    deepest = std::max(deepest, d);
    const Node& node = bvh.nodes[static_cast<std::size_t>(i)];
    if (!node.is_leaf()) {
      stack.push_back({node.first, d + 1});
      stack.push_back({node.first + 1, d + 1});
    }
  }
  EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), static_cast<std::ptrdiff_t>(seen.size()));
  EXPECT_EQ(deepest, bvh.depth);
}

TEST(BuildBvh, ContainmentOnSliversAndDegenerates) {
  Rng rng(2024);
  auto tris = test::nasty_triangles(rng, 3000, 100.0);
  auto more = test::random_triangles(rng, 1000, 100.0, 20.0);
  tris.insert(tris.end(), more.begin(), more.end());
  for (Fitter f : kFitters)
    for (SplitRule s : kSplits) {
      auto bvh = build_bvh(tris, {.fitter = f, .split = s});
      ASSERT_TRUE(bvh) << bvh.error().message;
      expect_structure(*bvh, tris.size(), 1);
      expect_containment(*bvh, std::string(to_string(f)) + "/" + std::string(to_string(s)));
    }
}

TEST(BuildBvh, ContainmentFarFromOriginAndLeafSize) {
  Rng rng(5);
  auto tris = test::transformed(test::nasty_triangles(rng, 1500, 10.0), {rng.rotation(), Vec3(1e6, 2e6, -1e6)});
  for (int leaf : {1, 4}) {
    for (Fitter f : kFitters) {
      auto bvh = build_bvh(tris, {.fitter = f, .leaf_size = leaf});
      ASSERT_TRUE(bvh);
      expect_structure(*bvh, tris.size(), leaf);
      expect_containment(*bvh, std::string(to_string(f)) + " leaf " + std::to_string(leaf));
    }
  }
}

TEST(BuildBvh, SlenderSliversOfAspect1e4) {
  // A fan of long thin triangles of aspect ratio 1e4, the shape CAD exports of cylinders have.
  std::vector<Triangle> fan;
  for (int i = 0; i < 500; ++i) {
    const double a = 2 * std::numbers::pi * i / 500.0, b = 2 * std::numbers::pi * (i + 1) / 500.0;
    const Vec3 p(std::cos(a), std::sin(a), 0), q(std::cos(b), std::sin(b), 0);
    fan.push_back({p, q, p + Vec3(0, 0, 1e2 * (q - p).norm() * 100)});
  }
  for (Fitter f : kFitters)
    for (SplitRule s : kSplits) {
      auto bvh = build_bvh(fan, {.fitter = f, .split = s});
      ASSERT_TRUE(bvh);
      expect_containment(*bvh, "fan");
    }
}

TEST(BuildBvh, CoincidentCentroidsSplitAtTheMedian) {
  // Duplicated faces (as CAD exports have): every candidate plane leaves a side empty.
  const std::vector<Triangle> dup(64, Triangle{Vec3(0.1, 0.2, 0.3), Vec3(1.7, 0.2, 0.3), Vec3(0.4, 1.9, 0.3)});
  for (Fitter f : kFitters) {
    auto bvh = build_bvh(dup, {.fitter = f});
    ASSERT_TRUE(bvh);
    expect_structure(*bvh, dup.size(), 1);
    expect_containment(*bvh, "duplicates");
    EXPECT_EQ(bvh->depth, 7);  // balanced: log2 64 + 1 levels
  }
}

TEST(BuildBvh, NearlyCoincidentCentroids) {
  // Triangles rotated about a common centroid: centroids agree up to rounding.
  std::vector<Triangle> star;
  for (int i = 0; i < 64; ++i) {
    const Mat3 r = Eigen::AngleAxisd(0.1 * i, Vec3(0.3, 0.5, 0.8).normalized()).toRotationMatrix();
    star.push_back({r * Vec3(1, 0, 0), r * Vec3(-0.5, 0.8660254037844386, 0), r * Vec3(-0.5, -0.8660254037844386, 0)});
  }
  for (Fitter f : kFitters) {
    auto bvh = build_bvh(star, {.fitter = f});
    ASSERT_TRUE(bvh);
    expect_structure(*bvh, star.size(), 1);
    expect_containment(*bvh, "star");
  }
}

TEST(BuildBvh, ParallelEqualsSerialNodeForNode) {
  Rng rng(99);
  auto tris = test::nasty_triangles(rng, 20000, 50.0);
  auto more = test::random_triangles(rng, 20000, 50.0, 2.0);
  tris.insert(tris.end(), more.begin(), more.end());
  // Leaf size 1 fills every subtree's block of indices exactly; larger leaves leave its end
  // unused and the build closes the gaps: the same tree either way, reachable, every node once.
  for (const int leaf : {1, 3, 4}) {
    for (Fitter f : kFitters) {
      const std::string what = std::string(to_string(f)) + " leaf " + std::to_string(leaf);
      auto serial = build_bvh(tris, {.fitter = f, .leaf_size = leaf, .parallel = false});
      Result<Bvh> parallel = Error{};
      {
        tbb::global_control two(tbb::global_control::max_allowed_parallelism, 2);
        parallel = build_bvh(tris, {.fitter = f, .leaf_size = leaf, .parallel = true});
      }
      ASSERT_TRUE(serial && parallel);
      ASSERT_EQ(serial->nodes.size(), parallel->nodes.size()) << what;
      EXPECT_EQ(std::memcmp(serial->nodes.data(), parallel->nodes.data(), serial->nodes.size() * sizeof(Node)), 0) << what;
      EXPECT_EQ(serial->triangle_ids, parallel->triangle_ids) << what;
      EXPECT_EQ(serial->triangles.corners, parallel->triangles.corners) << what;
      EXPECT_EQ(serial->depth, parallel->depth) << what;
      expect_structure(*parallel, tris.size(), leaf);
      if (leaf > 1) expect_containment(*parallel, what);
    }
  }
}

// A parallel build of a large mesh maps its largest buffers in on every core before first use
// (the records, the nodes, the root's projections, the weld's arrays: 8 MB and up, so from about
// 90,000 triangles); the serial build does not. The trees must not differ.
TEST(BuildBvh, ParallelEqualsSerialOnAMeshLargeEnoughToPrefault) {
  Rng rng(7);
  const auto tris = test::random_triangles(rng, 150000, 500.0, 2.0);
  for (const SplitRule split : {SplitRule::largest, SplitRule::min_sa}) {
    const std::string what = std::string(to_string(split));
    auto serial = build_bvh(tris, {.split = split, .parallel = false});
    Result<Bvh> parallel = Error{};
    {
      tbb::global_control two(tbb::global_control::max_allowed_parallelism, 2);
      parallel = build_bvh(tris, {.split = split, .parallel = true});
    }
    ASSERT_TRUE(serial && parallel);
    ASSERT_EQ(serial->nodes.size(), parallel->nodes.size()) << what;
    EXPECT_EQ(std::memcmp(serial->nodes.data(), parallel->nodes.data(), serial->nodes.size() * sizeof(Node)), 0) << what;
    EXPECT_EQ(serial->triangle_ids, parallel->triangle_ids) << what;
    EXPECT_EQ(serial->triangles.corners, parallel->triangles.corners) << what;
    EXPECT_EQ(serial->triangles.vertices, parallel->triangles.vertices) << what;
    expect_structure(*parallel, tris.size(), 1);
  }
}

TEST(BuildBvh, RejectsBadInput) {
  EXPECT_FALSE(build_bvh(std::vector<Triangle>{}));
  std::vector<Triangle> tris{{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)},
                             {Vec3(0, 0, 0), Vec3(1, std::nan(""), 0), Vec3(0, 1, 0)}};
  auto r = build_bvh(tris);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find("triangle 1"), std::string::npos) << r.error().message;
  tris[1].q.y() = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(build_bvh(tris));
  EXPECT_FALSE(build_bvh(std::vector<Triangle>(1), {.leaf_size = 0}));
  // Nodes are stored in single precision: coordinates beyond ±1e30 are refused, by triangle.
  tris[1].q.y() = -2e30;
  r = build_bvh(tris);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find("triangle 1"), std::string::npos) << r.error().message;
  EXPECT_NE(r.error().message.find("1e30"), std::string::npos) << r.error().message;
  tris[1].q.y() = 1e29;
  EXPECT_TRUE(build_bvh(tris));
}

// A stored node (single precision, encode_rss) contains every point of the RSS it was given:
// corners of the rectangle pushed out by the radius in seeded directions, on RSSs of every
// scale, far from and near the tree's origin, and for axes that are no rotation at all.
TEST(BuildBvh, StoredNodesContainTheirRss) {
  Rng rng(4242);
  double worst = -1e300;
  for (int trial = 0; trial < 20000; ++trial) {
    const double scale = std::pow(10.0, rng.uniform(-6, 6));
    Rss v;
    v.axes = rng.rotation();
    if (trial % 50 == 0) v.axes.col(2) = -v.axes.col(2);  // a reflection
    if (trial % 50 == 1) v.axes = Mat3::Identity();
    const Vec3 origin = rng.vec(-1e3, 1e3) * scale;
    v.center = origin + rng.vec(-1e3, 1e3) * scale * (trial % 3 == 0 ? 1e-3 : 1.0);
    v.half_length = {rng.uniform(0, 1) * scale, rng.uniform(0, 0.1) * scale};
    v.radius = trial % 4 == 0 ? 0.0 : rng.uniform(0, 0.1) * scale;
    Node n;
    encode_rss(v, origin, n);
    const Rss stored = decode_rss(n, origin);
    const double magnitude = v.center.cwiseAbs().maxCoeff() + v.half_length[0] + v.half_length[1] + v.radius;
    for (int k = 0; k < 8; ++k) {
      Vec3 u = rng.vec(-1, 1);
      u = u.norm() > 0 ? u.normalized() : Vec3::UnitX();
      const double s = (k & 1 ? 1 : -1) * v.half_length[0], t = (k & 2 ? 1 : -1) * v.half_length[1];
      const Vec3 p = v.center + s * v.axes.col(0) + t * v.axes.col(1) + v.radius * u;
      // signed_distance itself rounds, at about 1e-16 of the coordinates.
      const double d = signed_distance(stored, p) / magnitude;
      worst = std::max(worst, d);
      ASSERT_LE(d, 1e-14) << "trial " << trial << " corner " << k;
    }
    // Outward, but not by much: lengths within float precision of the offset and the size.
    const double slack = 8 * 6e-8 * ((v.center - origin).norm() + v.half_length[0] + v.half_length[1] + v.radius);
    if (trial % 50 > 0) {
      EXPECT_LE(stored.radius, v.radius + slack) << trial;
      EXPECT_LE(stored.half_length[0], v.half_length[0] + slack) << trial;
    }
  }
  EXPECT_LE(worst, 1e-14);
}

// Triangles read back bit for bit as they were given, in leaf order (triangle_ids), with
// vertices shared only where equal bit for bit (so 0.0 and -0.0 stay apart).
TEST(BuildBvh, TrianglesReadBackBitForBitWithSharedVertices) {
  Rng rng(77);
  std::vector<Triangle> tris = test::box_triangles(Vec3(0, 0, 0), Vec3(1, 2, 3));  // 8 corners, 12 triangles
  tris.push_back({Vec3(-0.0, 0, 0), Vec3(1, 0, 0), Vec3(0, 2, 0)});  // -0.0: a 9th vertex
  const auto more = test::nasty_triangles(rng, 500, 5.0);
  tris.insert(tris.end(), more.begin(), more.end());
  auto bvh = build_bvh(tris);
  ASSERT_TRUE(bvh);
  ASSERT_EQ(bvh->triangles.size(), tris.size());
  for (std::size_t i = 0; i < tris.size(); ++i) {
    const Triangle got = bvh->triangles[i];
    const Triangle& want = tris[bvh->triangle_ids[i]];
    for (int c = 0; c < 3; ++c) ASSERT_EQ(std::memcmp(got[c].data(), want[c].data(), sizeof(Vec3)), 0) << i;
  }
  // Every distinct vertex once: count the distinct bit patterns independently.
  std::vector<std::array<std::uint64_t, 3>> keys;
  for (const Triangle& t : tris)
    for (int c = 0; c < 3; ++c) {
      std::array<std::uint64_t, 3> k;
      std::memcpy(k.data(), t[c].data(), sizeof(k));
      keys.push_back(k);
    }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  EXPECT_EQ(bvh->triangles.vertices.size(), keys.size());
  // Numbered in order of first use along the leaves (neighbouring leaves read nearby vertices):
  // replayed with a std::map over the bit patterns. The soup's ~1,500 vertices also make the
  // builder's table (sized for n / 2 vertices) grow twice.
  std::map<std::array<std::uint64_t, 3>, std::uint32_t> first_use;
  for (std::size_t i = 0; i < tris.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      std::array<std::uint64_t, 3> k;
      std::memcpy(k.data(), tris[bvh->triangle_ids[i]][c].data(), sizeof(k));
      const auto [it, added] = first_use.emplace(k, static_cast<std::uint32_t>(first_use.size()));
      ASSERT_EQ(bvh->triangles.corners[i][c], it->second) << "triangle " << i << " corner " << c;
    }
  auto box_only = build_bvh(std::vector<Triangle>(tris.begin(), tris.begin() + 13));
  ASSERT_TRUE(box_only);
  EXPECT_EQ(box_only->triangles.vertices.size(), 9u);
}

TEST(BuildBvh, SingleTriangleAndAllDegenerate) {
  auto one = build_bvh(std::vector<Triangle>{{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}});
  ASSERT_TRUE(one);
  EXPECT_EQ(one->nodes.size(), 1u);
  EXPECT_EQ(one->depth, 1);
  std::vector<Triangle> points(10, Triangle{Vec3(1, 2, 3), Vec3(1, 2, 3), Vec3(1, 2, 3)});
  for (Fitter f : kFitters) {
    auto b = build_bvh(points, {.fitter = f});
    ASSERT_TRUE(b);
    expect_containment(*b, "points");
    for (std::size_t i = 0; i < b->nodes.size(); ++i)
      EXPECT_TRUE(b->bv(i).axes.allFinite() && std::isfinite(b->bv(i).radius));
  }
}

TEST(BuildBvh, StatsAddUp) {
  auto cube = test::box_triangles(Vec3(0, 0, 0), Vec3(1, 2, 3));
  auto bvh = build_bvh(cube);
  ASSERT_TRUE(bvh);
  const BvhStats s = stats(*bvh);
  EXPECT_EQ(s.triangles, 12u);
  EXPECT_EQ(s.nodes, 23u);
  double sa = 0;
  for (std::size_t i = 0; i < bvh->nodes.size(); ++i) sa += surface_area(bvh->bv(i));
  EXPECT_DOUBLE_EQ(s.total_surface_area, sa);
  EXPECT_GT(s.total_volume, 0.0);
  EXPECT_GE(s.bytes, 23 * sizeof(Node) + 8 * sizeof(Vec3) + 12 * 3 * sizeof(std::uint32_t));
  // The root RSS holds the whole box: its SA is at least the box's.
  EXPECT_GE(surface_area(bvh->bv(0)), 2 * (2 + 3 + 6) - 1e-9);
}

// Node::area decides which node of a pair a traversal splits. Its values, derived by hand from
// the RSS's shape (two rectangles 2a × 2b, half-cylinders of radius r along the perimeter
// 4(a + b), and a sphere's worth of corners: 8ab + 4πr(a + b) + 4πr²), and against the
// fitters' surface_area of the decoded RSS on every node of a tree.
TEST(BuildBvh, NodeAreaIsTheRssSurfaceArea) {
  const double pi = std::numbers::pi;
  auto node = [](float a, float b, float r) {
    Node n;
    n.half_length = {a, b};
    n.radius = r;
    return n;
  };
  EXPECT_NEAR(node(1, 2, 0.5f).area(), 16.0 + 7.0 * pi, 1e-5);  // 16 + 6π + π
  EXPECT_NEAR(node(0, 0, 2).area(), 16.0 * pi, 1e-5);           // a sphere of radius 2
  EXPECT_NEAR(node(3, 1, 0).area(), 24.0, 1e-5);                 // a flat rectangle, both sides
  EXPECT_NEAR(node(5, 0, 1).area(), 24.0 * pi, 1e-4);            // a capsule: 2π·1·10 + 4π
  // A long thin node has the larger half-lengths plus radius, the square one the larger area.
  EXPECT_LT(node(4, 0, 0.1f).area(), node(1.5f, 1.5f, 0.1f).area());

  Rng rng(7);
  const auto tris = test::random_triangles(rng, 300, 100.0, 20.0);
  const auto bvh = build_bvh(tris, {.leaf_size = 2});
  ASSERT_TRUE(bvh);
  for (std::size_t i = 0; i < bvh->nodes.size(); ++i) {
    const double want = surface_area(bvh->bv(i));
    EXPECT_NEAR(bvh->nodes[i].area(), want, 1e-5 * want + 1e-9) << "node " << i;
  }
}

}  // namespace
}  // namespace swept
