// The one problem-file writer (scenes/problem_toml.cpp): what it writes reads back through
// load_problem() as the same problem, for the box problems and for a problem using every key.
#include "swept/io/mesh_io.h"
#include "swept/plan/problem.h"
#include "swept/scenes/box_problems.h"
#include "swept/scenes/problem_toml.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <numbers>

namespace swept::scenes {
namespace {

namespace fs = std::filesystem;

/// Exactly equal (Eigen vectors compared by their largest difference: GoogleTest cannot print them).
void expect_same(const Vec3& a, const Vec3& b, const std::string& what) {
  EXPECT_EQ((a - b).cwiseAbs().maxCoeff(), 0.0) << what;
}

void expect_same_pose(const Pose& a, const Pose& b, const std::string& what) {
  expect_same(a.translation, b.translation, what);
  EXPECT_LT((a.rotation - b.rotation).norm(), 1e-15) << what;
}

const Pose kBodyPose = Pose::from_axis_angle({0, 1, 0}, 0.3, {1, 2, 3});

/// Writes `p` with two mesh files beside it (the body's at kBodyPose) and reads it back.
Problem round_trip(Problem p, const std::string& tag) {
  const fs::path dir = fs::temp_directory_path() / ("swept_problem_toml_" + tag + "_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const GeneratedProblem box = peg_in_hole();
  EXPECT_TRUE(write_stl_binary(dir / "o.stl", box.obstacles));
  EXPECT_TRUE(write_stl_binary(dir / "b.stl", box.body));
  p.obstacles = {mesh_ref("o.stl", "mm")};
  p.body = {mesh_ref("b.stl", "", kBodyPose)};
  std::ofstream(dir / "problem.toml") << problem_toml(p, "a test\nwith two lines");
  auto back = load_problem(dir / "problem.toml");
  fs::remove_all(dir);
  EXPECT_TRUE(back) << (back ? "" : back.error().message);
  return back ? *back : Problem{};
}

TEST(ProblemToml, EveryKeyReadsBack) {
  Problem p;
  p.unit = "mm";  // (another unit would scale the lengths as they are read)
  p.reference_point = Vec3(0.1, -0.2, 1.0 / 3.0);
  p.start = Pose::from_axis_angle({1, 1, 0}, 0.7, {-4.5, 1e-9, 7});
  p.goal = Pose::from_axis_angle({0, 0, 1}, 25.0 * std::numbers::pi / 180.0, {0, -1150, 300});
  p.bounds = Aabb{Vec3(-100, -1200, -3), Vec3(100, 50, 400)};
  p.rotation = RotationMode::limits;
  p.rotation_limits = {{{-0.5, 0.5}, {-1, 1}, {0, 0.25}}};
  p.clearance = 0.05;
  p.contact_tolerance = 1e-6;
  p.build = {.fitter = Fitter::rapid2, .split = SplitRule::largest, .leaf_size = 4};
  p.time_limit = 12.5;
  p.threads = 3;
  p.deflection = 0.02;
  p.max_triangles = 12345;
  const Problem q = round_trip(p, "all");
  EXPECT_EQ(q.unit, "mm");
  ASSERT_TRUE(q.reference_point);
  expect_same(*q.reference_point, *p.reference_point, "reference point");
  expect_same_pose(q.start, p.start, "start");
  ASSERT_TRUE(q.goal);
  expect_same_pose(*q.goal, *p.goal, "goal");
  EXPECT_FALSE(q.goal_outside);
  ASSERT_TRUE(q.bounds);
  expect_same(q.bounds->min, p.bounds->min, "bounds.min");
  expect_same(q.bounds->max, p.bounds->max, "bounds.max");
  EXPECT_EQ(q.rotation, RotationMode::limits);
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t k = 0; k < 2; ++k) EXPECT_NEAR(q.rotation_limits[i][k], p.rotation_limits[i][k], 1e-15);
  EXPECT_EQ(q.clearance, p.clearance);
  EXPECT_EQ(q.contact_tolerance, p.contact_tolerance);
  EXPECT_EQ(q.build.fitter, Fitter::rapid2);
  EXPECT_EQ(q.build.split, SplitRule::largest);
  EXPECT_EQ(q.build.leaf_size, 4);
  EXPECT_EQ(q.time_limit, 12.5);
  EXPECT_EQ(q.threads, 3);
  EXPECT_EQ(q.deflection, 0.02);
  EXPECT_EQ(q.max_triangles, 12345u);
  ASSERT_EQ(q.obstacles.size(), 1u);
  EXPECT_EQ(q.obstacles[0].file_unit, "mm");
  ASSERT_EQ(q.body.size(), 1u);
  expect_same_pose(q.body[0].pose, kBodyPose, "body pose");
}

TEST(ProblemToml, GoalOutsideReadsBack) {
  Problem p;
  p.goal_outside = true;
  p.goal_margin = 20;
  p.time_limit = 60;  // an integral value still reads as the float it is
  const Problem q = round_trip(p, "outside");
  EXPECT_TRUE(q.goal_outside);
  EXPECT_FALSE(q.goal);
  EXPECT_EQ(q.goal_margin, 20.0);
  EXPECT_EQ(q.time_limit, 60.0);
  EXPECT_EQ(q.rotation, RotationMode::free);
}

TEST(ProblemToml, TheBoxProblemsReadBack) {
  for (const GeneratedProblem& g : box_problems()) {
    const Problem q = round_trip(g.problem, g.name);
    expect_same_pose(q.start, g.problem.start, g.name);
    EXPECT_EQ(q.goal_outside, g.problem.goal_outside) << g.name;
    EXPECT_EQ(q.clearance, g.problem.clearance) << g.name;
    EXPECT_EQ(q.build.fitter, g.problem.build.fitter) << g.name;
    EXPECT_EQ(q.time_limit, g.problem.time_limit) << g.name;
    EXPECT_EQ(q.rotation, g.problem.rotation) << g.name;
  }
}

}  // namespace
}  // namespace swept::scenes
