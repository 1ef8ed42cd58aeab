// `swept plan` outcomes whose answers are known without running the planner: a body shut in a
// sealed box never gets a path (exit 2, no file written), a search stopped by its time limit says
// so, and a free straight move gives exactly [start, goal] with the hash the documented FNV-1a
// gives for those two poses.
#include "swept/scenes/box_problems.h"

#include "support/cli_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <unistd.h>

namespace swept {
namespace {

namespace fs = std::filesystem;

class PlanOutcomes : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = fs::temp_directory_path() / ("swept_plan_outcomes_" + std::to_string(::getpid()));
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }
  std::string write(const scenes::GeneratedProblem& g) {
    const fs::path d = dir / g.name;
    EXPECT_TRUE(scenes::write_problem_files(g, d.string()));
    return (d / "problem.toml").string();
  }
  fs::path dir;
};

TEST_F(PlanOutcomes, SealedBoxExitsTwoAndWritesNothing) {
  scenes::GeneratedProblem g;
  g.name = "sealed";
  scenes::add_box(g.obstacles.triangles, Vec3(-1, -1, -1), Vec3(1, 1, 1));
  scenes::add_box(g.body.triangles, Vec3(-0.995, -0.995, -0.995), Vec3(0.995, 0.995, 0.995));
  g.problem.goal = Pose::from_translation(Vec3(0, 0, 10));
  g.problem.clearance = 0.01;
  g.problem.contact_tolerance = 0.02;
  g.problem.rotation = RotationMode::none;
  g.problem.time_limit = 20;
  const fs::path out = dir / "sealed.json";
  const test::CliRun r = test::run_cli("plan " + write(g) + " -q -o " + out.string());
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("no path"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(PlanOutcomes, NoPathMessageNamesTheTimeLimit) {
  // Shut in a closed box with rotation free: the search cannot finish within 2 s.
  const test::CliRun r = test::run_cli("plan " + write(scenes::enclosed()) + " -q --time-limit 2");
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("no path"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("time limit of 2 s"), std::string::npos) << r.out;
}

// FNV-1a 64 over the bytes of each pose: the rotation row by row, then the translation
// (include/swept/plan/planner.h), written here from that description.
std::uint64_t fnv1a(const std::vector<std::array<double, 12>>& poses) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (const auto& p : poses)
    for (double v : p) {
      unsigned char bytes[8];
      std::memcpy(bytes, &v, 8);
      for (unsigned char b : bytes) h = (h ^ b) * 0x100000001b3ull;
    }
  return h;
}

TEST_F(PlanOutcomes, FreeStraightMoveIsStartThenGoal) {
  scenes::GeneratedProblem g;
  g.name = "free";
  scenes::add_box(g.obstacles.triangles, Vec3(0, 20, 0), Vec3(1, 21, 1));  // far from the motion
  scenes::add_box(g.body.triangles, Vec3(-1, -1, -1), Vec3(1, 1, 1));
  g.problem.start = Pose::from_translation(Vec3(-5, 0, 0));
  g.problem.goal = Pose::from_translation(Vec3(5, 0, 0));
  g.problem.clearance = 0.5;
  g.problem.rotation = RotationMode::none;
  const test::CliRun r = test::run_cli("plan " + write(g) + " --json -q", /*with_stderr=*/false);
  ASSERT_EQ(r.code, 0) << r.out;
  const auto doc = nlohmann::json::parse(r.out);
  EXPECT_EQ(doc["waypoints"].get<int>(), 2);
  // The obstacle [0, 1] × [20, 21] × [0, 1] is nearest to the body's face y = 1 while the body
  // passes over x ∈ [0, 1] (their z ranges overlap): 19 apart.
  EXPECT_NEAR(doc["min_clearance"].get<double>(), 19.0, 1e-9);
  const std::array<double, 12> start{1, 0, 0, 0, 1, 0, 0, 0, 1, -5, 0, 0};
  const std::array<double, 12> goal{1, 0, 0, 0, 1, 0, 0, 0, 1, 5, 0, 0};
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(fnv1a({start, goal})));
  EXPECT_EQ(doc["path_hash"].get<std::string>(), hex);
}

}  // namespace
}  // namespace swept
