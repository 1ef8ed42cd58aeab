// `swept plan` end to end: exit codes, the JSON document, the path files, determinism across
// thread counts, and a golden path hash. Every path the command line writes is read back and
// checked by the oracle of tests/oracle against the problem file it was planned for.
#include "swept/plan/problem.h"
#include "swept/scenes/box_problems.h"
#include "swept/scenes/planning_suite.h"

#include "assembly/assembly_support.h"
#include "plan/plan_support.h"
#include "support/cli_support.h"

#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sys/wait.h>
#include <unistd.h>

namespace swept {
namespace {

namespace fs = std::filesystem;

using test::CliRun;

CliRun run(const std::string& args) { return test::run_cli("plan " + args, /*with_stderr=*/false); }

// What `swept plan --json` reported about its path.
test::PlannerFigures figures_of(const nlohmann::json& doc) {
  test::PlannerFigures f;
  f.min_clearance = doc.at("min_clearance").get<double>();
  std::size_t contact = 0;
  for (const char* end : {"escape", "approach"})
    if (!doc.at(end).is_null()) contact += doc.at(end).at("segments").get<std::size_t>();
  f.contact_segments = contact;
  return f;
}

// The path file the command line wrote, read back and checked by the oracle with the meshes and
// settings of the problem file (read by the io layer, as the command line reads them).
void check_written_path(const std::string& problem_file, const fs::path& path_file, const test::PlannerFigures& f = {}) {
  auto problem = load_problem(problem_file);
  ASSERT_TRUE(problem) << problem.error().message;
  auto scene = load_scene(*problem, problem->build);
  ASSERT_TRUE(scene) << scene.error().message;
  auto path = read_path(path_file);
  ASSERT_TRUE(path) << path.error().message;
  SCOPED_TRACE(path_file.string());
  test::check_path_independently(*scene, *problem, *path, f);
}

class PlanCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = fs::temp_directory_path() / ("swept_plan_cli_" + std::to_string(::getpid()));
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }
  std::string problem(const scenes::GeneratedProblem& g) {
    const fs::path d = dir / g.name;
    EXPECT_TRUE(scenes::write_problem_files(g, d.string()));
    return (d / "problem.toml").string();
  }
  fs::path dir;
};

TEST_F(PlanCli, SolvesWritesPathsAndJson) {
  const std::string p = problem(scenes::l_tunnel());
  const CliRun r = run(p + " --json -o " + (dir / "path.json").string());
  ASSERT_EQ(r.code, 0) << r.out;
  const auto doc = nlohmann::json::parse(r.out);
  for (const char* key : {"solved", "waypoints", "path_length", "min_clearance", "time_ms", "queries", "path_hash"})
    EXPECT_TRUE(doc.contains(key)) << key;
  for (const char* key : {"build", "search", "smooth", "total", "cpu"}) EXPECT_TRUE(doc["time_ms"].contains(key)) << key;
  EXPECT_GT(doc["time_ms"]["cpu"].get<double>(), 0.0);  // the planner's threads' time, after the build
  for (const char* key : {"distance", "proximity", "sweep"}) EXPECT_TRUE(doc["queries"].contains(key)) << key;
  EXPECT_TRUE(doc["solved"].get<bool>());
  EXPECT_TRUE(doc["notes"].is_array() && doc["notes"].empty());  // a TOML asks nothing swept ignores
  EXPECT_TRUE(doc["warnings"].is_array() && doc["warnings"].empty());  // its meshes lose nothing
  EXPECT_GE(doc["min_clearance"].get<double>(), 0.1);
  auto path = read_path(dir / "path.json");
  ASSERT_TRUE(path) << path.error().message;
  EXPECT_EQ(path->poses.size(), doc["waypoints"].get<std::size_t>());
  check_written_path(p, dir / "path.json", figures_of(doc));
  // OMPL's .path format when the name says so.
  ASSERT_EQ(run(p + " -q -o " + (dir / "path.path").string()).code, 0);
  auto ompl = read_path(dir / "path.path");
  ASSERT_TRUE(ompl);
  EXPECT_EQ(ompl->poses.size(), path->poses.size());
  check_written_path(p, dir / "path.path", figures_of(doc));
}

// What reading a mesh leaves out reaches the user: the certificate covers the triangles read, so
// `swept plan` and `swept check` print each import warning (and --json lists them). Here an OBJ
// obstacle holds a part of points and lines only, next to a wall, which is left out.
TEST_F(PlanCli, MeshWarningsArePrintedAndListed) {
  const fs::path d = dir / "warned";
  fs::create_directories(d);
  std::ofstream(d / "obstacles.obj") << "o marks\nv 0 0 0\nv 1 0 0\np 1\nl 1 2\n"
                                        "o wall\nv 10 -50 -50\nv 10 50 -50\nv 10 50 50\nv 10 -50 50\nf 3 4 5 6\n";
  std::ofstream(d / "body.stl") << "solid b\nfacet normal 0 0 1\nouter loop\nvertex -1 -1 0\nvertex 1 -1 0\n"
                                   "vertex 0 1 0\nendloop\nendfacet\nendsolid b\n";
  std::ofstream(d / "problem.toml") << "unit = \"mm\"\n[[obstacle]]\nfile = \"obstacles.obj\"\n[[body]]\nfile = \"body.stl\"\n"
                                       "[start]\ntranslation = [0, 0, 0]\n[goal]\ntranslation = [-20, 0, 0]\n"
                                       "[bounds]\nmin = [-50, -50, -50]\nmax = [50, 50, 50]\n";
  const std::string p = (d / "problem.toml").string();
  const std::string warning = (d / "obstacles.obj").string() + ": part 'marks' has no triangles";
  const CliRun text = run(p + " -o " + (d / "path.json").string());
  ASSERT_EQ(text.code, 0) << text.out;
  EXPECT_NE(text.out.find("\nwarning      " + warning), std::string::npos) << text.out;
  const CliRun json = run(p + " --json -q");
  ASSERT_EQ(json.code, 0) << json.out;
  const auto doc = nlohmann::json::parse(json.out);
  ASSERT_EQ(doc.at("warnings").size(), 1u);
  EXPECT_EQ(doc["warnings"][0].get<std::string>().rfind(warning, 0), 0u) << doc["warnings"];
  const CliRun check = test::run_cli("check " + p + " " + (d / "path.json").string(), false);
  ASSERT_EQ(check.code, 0) << check.out;
  EXPECT_NE(check.out.find("\nwarning      " + warning), std::string::npos) << check.out;
  const CliRun check_json = test::run_cli("check " + p + " " + (d / "path.json").string() + " --json", false);
  ASSERT_EQ(check_json.code, 0) << check_json.out;
  EXPECT_EQ(nlohmann::json::parse(check_json.out).at("warnings").size(), 1u);
}

TEST_F(PlanCli, TheCheckOfWrittenPathsCanFail) {
  // The same check on a path through material and on an overstated minimum: each is one
  // failure, so a planner that wrote either would not pass these tests.
  const std::string p = problem(scenes::l_tunnel());
  const fs::path out = dir / "path.json";
  const CliRun r = run(p + " --json -o " + out.string());
  ASSERT_EQ(r.code, 0) << r.out;
  const auto doc = nlohmann::json::parse(r.out);
  auto path = read_path(out);
  ASSERT_TRUE(path && path->poses.size() >= 3) << "the tunnel needs a turn";
  auto problem_read = load_problem(p);
  ASSERT_TRUE(problem_read);
  // Straight from start to goal, cutting the tunnel's corner.
  const fs::path cut = dir / "cut.json";
  ASSERT_TRUE(write_path(cut, Path{{path->poses.front(), path->poses.back()}}, problem_read->unit,
                         problem_read->reference_point.value_or(Vec3::Zero())));
  EXPECT_NONFATAL_FAILURE(check_written_path(p, cut), "the oracle refuses the path");
  // A minimum 100 mm above what the path comes to (more than the longest segment / 32 allows).
  test::PlannerFigures overstated = figures_of(doc);
  *overstated.min_clearance += 100.0;
  EXPECT_NONFATAL_FAILURE(check_written_path(p, out, overstated), "above the oracle's dense minimum");
}

TEST_F(PlanCli, StartInContactEscapesAndTheOracleAgrees) {
  // The peg rests on the bottom of its blind hole against one wall (distance 0): with a contact
  // tolerance the first segment is an escape, which the oracle checks with its own contact rule.
  auto g = scenes::peg_in_hole(10.0, 1e-2);
  g.name = "peg_contact";
  g.problem.start = Pose::from_translation(Vec3(-1e-2 * 10.0, 0, -20 + 12.5));
  g.problem.clearance = 0.01;
  g.problem.contact_tolerance = 0.02;
  const std::string p = problem(g);
  const CliRun r = run(p + " --json -o " + (dir / "escape.json").string());
  ASSERT_EQ(r.code, 0) << r.out;
  const auto doc = nlohmann::json::parse(r.out);
  ASSERT_FALSE(doc["escape"].is_null()) << r.out;
  check_written_path(p, dir / "escape.json", figures_of(doc));
}

TEST_F(PlanCli, SameHashAtAnyThreadCountAndGolden) {
  const std::string p = problem(scenes::t_slot());
  std::vector<std::string> hashes;
  for (const char* threads : {"1", "2", "1"}) {
    const fs::path out = dir / (std::string("path_") + threads + ".json");
    const CliRun r = run(p + " --json --threads " + threads + " -o " + out.string());
    ASSERT_EQ(r.code, 0) << r.out;
    const auto doc = nlohmann::json::parse(r.out);
    hashes.push_back(doc["path_hash"].get<std::string>());
    if (hashes.size() == 1) check_written_path(p, out, figures_of(doc));  // the others are the same path
  }
  EXPECT_EQ(hashes[0], hashes[1]);
  EXPECT_EQ(hashes[0], hashes[2]);
  // The golden hash of this problem's path: a change here means the planner's output changed
  // (update it deliberately, with the reason in the commit).
  EXPECT_EQ(hashes[0], "eccd1423d9656024");
}

TEST_F(PlanCli, SeedFromTheFileOrTheCommandLine) {
  // The suite's house is solved by the trees, whose samples the seed shifts: planner.seed in the
  // file and --seed give the same path, the JSON names the seed, the path passes the oracle, and
  // seed 0 (the default) is another path.
  scenes::GeneratedProblem g = scenes::suite::house().problem;
  g.problem.seed = 3;
  const std::string seeded = problem(g);
  g.problem.seed = 0;
  g.name = "house-plain";
  const std::string plain = problem(g);
  const fs::path out = dir / "seeded.json";
  const CliRun from_file = run(seeded + " --json -o " + out.string());
  ASSERT_EQ(from_file.code, 0) << from_file.out;
  const auto doc = nlohmann::json::parse(from_file.out);
  EXPECT_EQ(doc["seed"], 3);
  check_written_path(seeded, out, figures_of(doc));
  const CliRun from_flag = run(plain + " --json --seed 3");
  ASSERT_EQ(from_flag.code, 0) << from_flag.out;
  EXPECT_EQ(nlohmann::json::parse(from_flag.out)["path_hash"], doc["path_hash"]);
  const CliRun zero = run(plain + " --json");
  ASSERT_EQ(zero.code, 0) << zero.out;
  EXPECT_EQ(nlohmann::json::parse(zero.out)["seed"], 0);
  EXPECT_NE(nlohmann::json::parse(zero.out)["path_hash"], doc["path_hash"]);
  // The flag's range is the file's: 0 to 2^63 − 1.
  for (const char* bad : {"-1", "1.5", "9223372036854775808"}) EXPECT_EQ(run(plain + " --seed " + bad).code, 1) << bad;
}

TEST_F(PlanCli, ExitCodes) {
  // No path: 2, with the limit named.
  auto g = scenes::enclosed();
  g.problem.time_limit = 3;
  const CliRun none = run(problem(g) + " -q");
  EXPECT_EQ(none.code, 2);
  // Bad input: 1.
  EXPECT_EQ(run((dir / "missing.toml").string()).code, 1);
  std::ofstream(dir / "bad.toml") << "unit = [\n";
  EXPECT_EQ(run((dir / "bad.toml").string()).code, 1);
  auto collide = scenes::l_tunnel();
  collide.name = "collide";
  collide.problem.start = Pose::from_translation(Vec3(10, 0, 8));
  EXPECT_EQ(run(problem(collide)).code, 1);
}

// A shaft and a pulley as two objects of one OBJ file (assimp's parts: "shaft", "pulley"): the
// pulley's bore (16 segments) on the 24-gon shaft, the tessellations crossing by the sag
// 3·(1 − cos(π/16)) ≈ 0.058 < the tolerance 0.1. The problem names the pulley as the body and the
// rest of the same file as the obstacle.
void write_shaft_and_pulley(const fs::path& obj) {
  std::vector<Triangle> shaft, pulley;
  test::add_prism(shaft, 3, 24, 0, 40);
  test::add_ring(pulley, 3, 10, 16, 10, 20);
  std::ofstream out(obj);
  out.precision(17);
  std::size_t v = 0;
  for (const auto& [name, tris] : {std::pair{"shaft", &shaft}, std::pair{"pulley", &pulley}}) {
    out << "o " << name << "\n";
    for (const Triangle& t : *tris) {
      for (int k = 0; k < 3; ++k) out << "v " << t[k].x() << " " << t[k].y() << " " << t[k].z() << "\n";
      out << "f " << v + 1 << " " << v + 2 << " " << v + 3 << "\n";
      v += 3;
    }
  }
}

std::string part_problem_text(const std::string& obstacle_keys, const std::string& body_keys) {
  return "unit = \"mm\"\n[[obstacle]]\nfile = \"unit.obj\"\n" + obstacle_keys + "[[body]]\nfile = \"unit.obj\"\n" + body_keys +
         "[start]\ntranslation = [0, 0, 0]\n[goal]\noutside = true\n"
         "[planner]\nclearance = 0.01\ncontact_tolerance = 0.1\n[rotation]\nmode = \"none\"\n";
}

TEST_F(PlanCli, APartOfAFileIsTheBodyAndTheRestTheObstacle) {
  write_shaft_and_pulley(dir / "unit.obj");
  auto write = [&](const std::string& name, const std::string& obstacle, const std::string& body) {
    std::ofstream(dir / name) << part_problem_text(obstacle, body);
    return (dir / name).string();
  };
  const std::string p = write("pulley.toml", "except = [\"pulley\"]\n", "part = \"pulley\"\n");
  const CliRun r = run(p + " --json -o " + (dir / "pulley.json").string());
  ASSERT_EQ(r.code, 0) << r.out;
  const auto doc = nlohmann::json::parse(r.out);
  ASSERT_FALSE(doc["escape"].is_null()) << r.out;
  check_written_path(p, dir / "pulley.json", figures_of(doc));
  auto path = read_path(dir / "pulley.json");
  ASSERT_TRUE(path);
  const Vec3 pull = path->poses[1].translation - path->poses[0].translation;
  EXPECT_EQ(pull.x(), 0.0);  // along the shaft, off one of its ends
  EXPECT_EQ(pull.y(), 0.0);
  EXPECT_GT(std::abs(pull.z()), 20.0);

  // Bad input names the file and the parts.
  auto refused = [&](const std::string& name, const std::string& obstacle, const std::string& body, const std::string& says) {
    const CliRun bad = test::run_cli("plan " + write(name, obstacle, body));
    EXPECT_EQ(bad.code, 1) << bad.out;
    EXPECT_NE(bad.out.find(says), std::string::npos) << bad.out;
  };
  refused("unknown.toml", "except = [\"pulley\"]\n", "part = \"wheel\"\n", "no part named 'wheel' (its parts: shaft, pulley)");
  refused("unknown_except.toml", "except = [\"wheel\"]\n", "part = \"pulley\"\n", "no part named 'wheel'");
  refused("both.toml", "", "part = \"pulley\"\n", "part 'pulley' is the body and also an obstacle");
  refused("both_keys.toml", "part = \"shaft\"\nexcept = [\"pulley\"]\n", "part = \"pulley\"\n", "give either part or except, not both");
  refused("empty.toml", "except = [\"pulley\", \"shaft\"]\n", "part = \"pulley\"\n", "except leaves no part");
  refused("not_strings.toml", "except = [1]\n", "part = \"pulley\"\n", "must be a string");
}

}  // namespace
}  // namespace swept
