// `swept check` on paths whose answers are derived by hand: a cube along the middle of the
// L-shaped tunnel keeps exactly 1.5 from its walls; the straight line from start to goal goes
// through the block; a box inside a sealed shell has no valid way out even with the contact
// model. Exit codes: 0 valid, 2 not valid, 1 bad input.
#include "swept/plan/problem.h"
#include "swept/scenes/box_problems.h"

#include "support/cli_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace swept {
namespace {

namespace fs = std::filesystem;

class CheckCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = fs::temp_directory_path() / ("swept_check_cli_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const auto g = scenes::l_tunnel();
    EXPECT_TRUE(scenes::write_problem_files(g, (dir / "tunnel").string()));
    problem = (dir / "tunnel" / "problem.toml").string();
  }
  void TearDown() override { fs::remove_all(dir); }
  std::string path_file(const std::vector<Vec3>& points, const std::string& name) {
    Path p;
    for (const Vec3& x : points) p.poses.push_back(Pose::from_translation(x));
    const fs::path f = dir / name;
    EXPECT_TRUE(write_path(f, p, "mm", Vec3::Zero()));
    return f.string();
  }
  fs::path dir;
  std::string problem;
};

// The cube (half width 3.5) enters the tunnel (|y| < 5, z in [-5, 5]) along its axis, goes to
// x = 25, the middle of the vertical leg (x in [20, 30]), and rises: 1.5 from the walls all the way.
TEST_F(CheckCli, MiddleOfTheTunnelKeepsOnePointFive) {
  const std::string path = path_file({{-8, 0, 0}, {25, 0, 0}, {25, 0, 48}}, "middle.json");
  test::CliRun r = test::run_cli("check " + problem + " " + path + " --json", false);
  ASSERT_EQ(r.code, 0) << r.out;
  auto doc = nlohmann::json::parse(r.out);
  EXPECT_TRUE(doc["valid"].get<bool>());
  EXPECT_NEAR(doc["min_clearance"].get<double>(), 1.5, 1e-9);
  EXPECT_TRUE(doc["first_invalid"].is_null());
  EXPECT_EQ(doc["segments"].size(), 2u);
  // Just below 1.5 the path keeps the clearance; at 1.5 it does not (distance ≤ clearance blocks).
  EXPECT_EQ(test::run_cli("check " + problem + " " + path + " --clearance 1.49", false).code, 0);
  r = test::run_cli("check " + problem + " " + path + " --clearance 1.5 --json", false);
  ASSERT_EQ(r.code, 2) << r.out;
  doc = nlohmann::json::parse(r.out);
  EXPECT_FALSE(doc["valid"].get<bool>());
  EXPECT_FALSE(doc["first_invalid"]["colliding"].get<bool>());
  EXPECT_NEAR(doc["first_invalid"]["distance"].get<double>(), 1.5, 1e-9);
  // The same path as OMPL's .path (interpolated about the body frame's origin, here its centre).
  Path p;
  for (const Vec3& x : {Vec3(-8, 0, 0), Vec3(25, 0, 0), Vec3(25, 0, 48)}) p.poses.push_back(Pose::from_translation(x));
  ASSERT_TRUE(write_path(dir / "middle.path", p, "mm", Vec3::Zero()));
  EXPECT_EQ(test::run_cli("check " + problem + " " + (dir / "middle.path").string(), false).code, 0);
  // The text names the count of segments, and a single one as such.
  EXPECT_NE(test::run_cli("check " + problem + " " + path).out.find("every one of the 2 segments keeps the clearance"),
            std::string::npos);
  const std::string first_leg = path_file({{-8, 0, 0}, {25, 0, 0}}, "first_leg.json");
  const test::CliRun one = test::run_cli("check " + problem + " " + first_leg);
  EXPECT_EQ(one.code, 0) << one.out;
  EXPECT_NE(one.out.find("valid: the one segment keeps the clearance"), std::string::npos) << one.out;
}

TEST_F(CheckCli, StraightThroughTheBlockCollides) {
  const std::string path = path_file({{-8, 0, 0}, {25, 0, 48}}, "straight.json");
  const test::CliRun r = test::run_cli("check " + problem + " " + path + " --json", false);
  ASSERT_EQ(r.code, 2) << r.out;
  const auto doc = nlohmann::json::parse(r.out);
  EXPECT_FALSE(doc["valid"].get<bool>());
  EXPECT_EQ(doc["first_invalid"]["segment"].get<int>(), 0);
  EXPECT_TRUE(doc["first_invalid"]["colliding"].get<bool>());
  EXPECT_EQ(doc["min_clearance"].get<double>(), 0.0);
  // The text summary names the first bad pose.
  const test::CliRun t = test::run_cli("check " + problem + " " + path);
  EXPECT_EQ(t.code, 2);
  EXPECT_NE(t.out.find("in collision"), std::string::npos) << t.out;
}

TEST_F(CheckCli, PlannedPathsAreValid) {
  const std::string out = (dir / "planned.json").string();
  ASSERT_EQ(test::run_cli("plan " + problem + " -q -o " + out).code, 0);
  EXPECT_EQ(test::run_cli("check " + problem + " " + out).code, 0);
}

TEST_F(CheckCli, EscapeFromASealedBoxIsNotValid) {
  scenes::GeneratedProblem g;
  g.name = "sealed";
  scenes::add_box(g.obstacles.triangles, Vec3(-1, -1, -1), Vec3(1, 1, 1));
  scenes::add_box(g.body.triangles, Vec3(-0.995, -0.995, -0.995), Vec3(0.995, 0.995, 0.995));
  g.problem.goal = Pose::from_translation(Vec3(0, 0, 10));
  g.problem.clearance = 0.01;
  g.problem.contact_tolerance = 0.02;
  g.problem.rotation = RotationMode::none;
  ASSERT_TRUE(scenes::write_problem_files(g, (dir / "sealed").string()));
  const std::string sealed = (dir / "sealed" / "problem.toml").string();
  const std::string path = path_file({{0, 0, 0}, {0, 0, 10}}, "up.json");
  const test::CliRun r = test::run_cli("check " + sealed + " " + path + " --json", false);
  ASSERT_EQ(r.code, 2) << r.out;
  const auto doc = nlohmann::json::parse(r.out);
  EXPECT_EQ(doc["contact_segments"].get<int>(), 1);
  EXPECT_TRUE(doc["segments"][0]["in_contact"].get<bool>());
  EXPECT_LT(doc["first_invalid"]["distance"].get<double>(), 0.01);
}

TEST_F(CheckCli, BadInputExitsOne) {
  EXPECT_EQ(test::run_cli("check " + problem + " " + (dir / "missing.json").string()).code, 1);
  std::ofstream(dir / "broken.json") << "{\"poses\": [";
  EXPECT_EQ(test::run_cli("check " + problem + " " + (dir / "broken.json").string()).code, 1);
  std::ofstream(dir / "broken.path") << "1 2 3 0 0 0\n";
  EXPECT_EQ(test::run_cli("check " + problem + " " + (dir / "broken.path").string()).code, 1);
  const std::string path = path_file({{-8, 0, 0}}, "one.json");
  EXPECT_EQ(test::run_cli("check " + problem + " " + path + " --reference 1,2").code, 1);
  EXPECT_EQ(test::run_cli("check " + (dir / "nope.toml").string() + " " + path).code, 1);
}

}  // namespace
}  // namespace swept
