// `swept bench queries` end to end on two small meshes: a row per fitter and leaf size, the memory
// per triangle counted here from the tree layout, FCL's node-pair counters (distance and collide),
// the collide answers checked against FCL's, the split rule option and its errors (no timing
// assertions).
#include "support/cli_support.h"

#include "swept/bvh/bvh.h"
#include "swept/io/mesh_io.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>
#include <string>
#include <unistd.h>

namespace swept {
namespace {

namespace fs = std::filesystem;

// A closed box of w × h × d, each face split into k × k squares of two triangles.
TriangleSoup box(double w, double h, double d, int k) {
  TriangleSoup soup;
  const Vec3 size(w, h, d);
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (const double side : {0.0, 1.0}) {
      for (int i = 0; i < k; ++i)
        for (int j = 0; j < k; ++j) {
          auto corner = [&](int di, int dj) {
            Vec3 p = Vec3::Zero();
            p[axis] = side * size[axis];
            p[u] = (i + di) * size[u] / k;
            p[v] = (j + dj) * size[v] / k;
            return p;
          };
          soup.triangles.push_back({corner(0, 0), corner(1, 0), corner(1, 1)});
          soup.triangles.push_back({corner(0, 0), corner(1, 1), corner(0, 1)});
        }
    }
  }
  return soup;
}

class BenchQueries : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = fs::temp_directory_path() / ("swept_bench_queries_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    ASSERT_TRUE(write_stl_binary(dir / "a.stl", box(10, 6, 4, 4)));  // 192 triangles
    ASSERT_TRUE(write_stl_binary(dir / "b.stl", box(3, 3, 8, 3)));   // 108 triangles
  }
  void TearDown() override { fs::remove_all(dir); }
  std::string files() const { return (dir / "a.stl").string() + " " + (dir / "b.stl").string(); }
  fs::path dir;
};

TEST_F(BenchQueries, RowsPerFitterAndLeafSizeWithMemoryAndFclNodePairs) {
  // stdout only: the JSON document (the batch line goes to stderr).
  const test::CliRun r = test::run_cli("bench queries " + files() + " --leaf-size 1,2 --poses 3 --json", false);
  ASSERT_EQ(r.code, 0) << r.out;
  const auto doc = nlohmann::json::parse(r.out);
  ASSERT_EQ(doc["sets"].size(), 3u);
  const std::size_t na = 192, nb = 108;
  // Leaf size 1: 2n − 1 nodes per tree; three vertex indices and an input index per triangle;
  // the vertices, shared: a box's grid of k × k squares per face has the (k + 1)³ − (k − 1)³
  // lattice points on its surface, 98 for a (k = 4) and 56 for b (k = 3); bytes over both
  // meshes' triangles.
  const std::size_t va = 98, vb = 56;
  const double leaf1 = static_cast<double>((2 * na - 1 + 2 * nb - 1) * sizeof(Node) +
                                           (na + nb) * 4 * sizeof(std::uint32_t) + (va + vb) * sizeof(Vec3) +
                                           2 * sizeof(Bvh)) /
                       static_cast<double>(na + nb);
  for (const auto& set : doc["sets"]) {
    std::map<std::string, nlohmann::json> rows;
    for (const auto& row : set["results"]) rows[row["engine"].get<std::string>()] = row;
    ASSERT_EQ(rows.size(), 2 * all_fitters().size() + 2) << set["name"];
    for (const FitterInfo& f : all_fitters()) {
      const std::string name = "swept-" + std::string(f.name);
      ASSERT_TRUE(rows.count(name + "/leaf1") && rows.count(name + "/leaf2")) << name;
      EXPECT_DOUBLE_EQ(rows[name + "/leaf1"]["bytes_per_triangle"].get<double>(), leaf1) << name;
      EXPECT_LT(rows[name + "/leaf2"]["bytes_per_triangle"].get<double>(), leaf1) << name;
      EXPECT_GT(rows[name + "/leaf1"]["bv_tests_per_distance"].get<double>(), 0.0) << name;
      EXPECT_GE(rows[name + "/leaf1"]["bv_tests_per_collide"].get<double>(), 1.0) << name;
    }
    // FCL's node pairs per distance query come from its own counter now.
    for (const char* fcl : {"fcl-obbrss", "fcl-rss"}) {
      ASSERT_TRUE(rows.count(fcl)) << fcl;
      EXPECT_GT(rows[fcl]["bv_tests_per_distance"].get<double>(), 0.0) << fcl;
      EXPECT_TRUE(rows[fcl]["bytes_per_triangle"].is_null()) << fcl;
    }
    // FCL's collide node pairs: counted for OBBRSS (its oriented traversal), not for RSS (its
    // collide copies the models).
    EXPECT_GE(rows["fcl-obbrss"]["bv_tests_per_collide"].get<double>(), 1.0);
    EXPECT_TRUE(rows["fcl-rss"]["bv_tests_per_collide"].is_null());
  }
  EXPECT_LE(doc["max_rel_distance_diff_vs_fcl"].get<double>(), 1e-9);
  // Every pose's collide answer checked against FCL's: overlapping, near and far, 3 each.
  EXPECT_EQ(doc["collide_answers_compared_with_fcl"].get<int>(), 9);
  EXPECT_EQ(doc["collide_answers_differing_from_fcl"].get<int>(), 0);
}

TEST_F(BenchQueries, SplitRuleAndBadOptions) {
  test::CliRun r = test::run_cli("bench queries " + files() + " --split largest --poses 2");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("split rule largest"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("swept-pqp "), std::string::npos) << r.out;  // one leaf size: plain names
  r = test::run_cli("bench queries " + files() + " --split widest");
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.out.find("widest"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(split_rule_names()), std::string::npos) << r.out;
  r = test::run_cli("bench queries " + files() + " --leaf-size 0");
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.out.find("--leaf-size"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace swept
