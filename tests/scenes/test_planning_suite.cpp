// The planner benchmark suite (swept/scenes/planning_suite.h): every problem's files load to the
// same problem from problem.toml and from the OMPL.app .cfg, its meshes are clean, its start and
// goal are clear by the brute-force oracle of tests/oracle, and its witness path (derived by hand
// from the construction) is certified by check_path: every problem is solvable. No planning.
#include "oracle/path_oracle.h"

#include "swept/geometry/solid.h"
#include "swept/io/mesh_io.h"
#include "swept/plan/check.h"
#include "swept/scenes/planning_suite.h"
#include "swept/scenes/scenes.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <numbers>
#include <optional>
#include <span>
#include <stdexcept>
#include <unistd.h>

namespace swept {
namespace {

namespace fs = std::filesystem;

fs::path temp_dir(const std::string& tag) {
  const fs::path dir = fs::temp_directory_path() / ("swept_suite_" + tag + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  return dir;
}

std::string read_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<oracle::Tri> oracle_tris(const std::vector<Triangle>& soup, const Pose& pose = {}) {
  std::vector<oracle::Tri> out;
  for (const Triangle& t : soup) out.push_back({{pose.apply(t.p), pose.apply(t.q), pose.apply(t.r)}});
  return out;
}

void expect_pose_near(const Pose& a, const Pose& b, const std::string& what) {
  EXPECT_LE((a.translation - b.translation).cwiseAbs().maxCoeff(), 1e-9) << what << " translation";
  EXPECT_LE((a.rotation - b.rotation).cwiseAbs().maxCoeff(), 1e-9) << what << " rotation";
}

bool contains(const Aabb& box, const Vec3& p) {
  return (p.array() >= box.min.array()).all() && (p.array() <= box.max.array()).all();
}

/// One problem generated and written once for all the tests of a parameter.
struct Written {
  scenes::SuiteProblem problem;
  scenes::SuiteFiles files;
  fs::path dir;
};

/// The problems written so far, their directories removed at exit.
struct WrittenCache {
  std::map<std::string, Written> problems;
  ~WrittenCache() {
    for (const auto& [name, w] : problems) {
      std::error_code ec;
      fs::remove_all(w.dir, ec);
    }
  }
};

const Written& written(const std::string& name) {
  static WrittenCache cache_holder;
  auto& cache = cache_holder.problems;
  auto it = cache.find(name);
  if (it != cache.end()) return it->second;
  Written w;
  auto p = scenes::suite_problem(name);
  if (!p) throw std::runtime_error(p.error().message);
  w.problem = *p;
  w.dir = temp_dir(name);
  auto f = scenes::write_suite_problem(w.problem, w.dir);
  if (!f) throw std::runtime_error(f.error().message);
  w.files = *f;
  return cache.emplace(name, std::move(w)).first->second;
}

/// The written problem read back from its problem.toml, and its trees built.
void read_back(const Written& w, std::optional<Problem>& problem, std::optional<PlanScene>& scene) {
  auto p = load_problem(w.files.problem_toml);
  ASSERT_TRUE(p) << p.error().message;
  auto s = load_scene(*p, p->build);
  ASSERT_TRUE(s) << s.error().message;
  problem = std::move(*p);
  scene = std::move(*s);
}

class SuiteTest : public testing::TestWithParam<std::string> {};

TEST_P(SuiteTest, CfgAndTomlLoadToTheSameProblem) {
  const Written& w = written(GetParam());
  auto toml = load_problem(w.files.problem_toml);
  auto cfg = load_problem(w.files.cfg);
  ASSERT_TRUE(toml) << toml.error().message;
  ASSERT_TRUE(cfg) << cfg.error().message;
  ASSERT_EQ(toml->body.size(), 1u);
  ASSERT_EQ(cfg->body.size(), 1u);
  ASSERT_EQ(toml->obstacles.size(), 1u);
  ASSERT_EQ(cfg->obstacles.size(), 1u);
  EXPECT_TRUE(fs::equivalent(toml->body[0].file, cfg->body[0].file));
  EXPECT_TRUE(fs::equivalent(toml->obstacles[0].file, cfg->obstacles[0].file));
  EXPECT_EQ(toml->body[0].file_unit, cfg->body[0].file_unit);
  EXPECT_EQ(toml->unit, cfg->unit);
  expect_pose_near(toml->body[0].pose, cfg->body[0].pose, "body mesh pose");
  expect_pose_near(toml->obstacles[0].pose, cfg->obstacles[0].pose, "obstacle mesh pose");
  expect_pose_near(toml->start, cfg->start, "start");
  ASSERT_TRUE(toml->goal && cfg->goal);
  EXPECT_FALSE(toml->goal_outside);
  expect_pose_near(*toml->goal, *cfg->goal, "goal");
  ASSERT_TRUE(toml->reference_point && cfg->reference_point);
  EXPECT_LE((*toml->reference_point - *cfg->reference_point).norm(), 1e-9);
  ASSERT_TRUE(toml->bounds && cfg->bounds);
  EXPECT_LE((toml->bounds->min - cfg->bounds->min).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LE((toml->bounds->max - cfg->bounds->max).cwiseAbs().maxCoeff(), 1e-9);
  // What the .cfg cannot say is in problem.toml, as generated.
  EXPECT_EQ(toml->clearance, w.problem.problem.problem.clearance);
  EXPECT_GT(toml->clearance, 0.0);
  EXPECT_EQ(toml->rotation, RotationMode::free);
  // The files' body frame is OMPL.app's: the same world placement as the design frame's.
  const Pose design_start = w.problem.problem.problem.start;
  for (const Triangle& t : w.problem.problem.body.triangles) {
    const Vec3 file_point = t.p - w.files.body_center;  // as the mesh pose places it
    EXPECT_LE((toml->start.apply(file_point) - design_start.apply(t.p)).norm(), 1e-9);
  }
}

TEST_P(SuiteTest, MeshesAreCleanAndModerate) {
  const Written& w = written(GetParam());
  for (const char* file : {"body.stl", "obstacles.stl"}) {
    auto model = import_mesh(w.dir / file);
    ASSERT_TRUE(model) << model.error().message;
    EXPECT_EQ(model->degenerate_triangles, 0u) << file;
    const TriangleSoup soup = model->merged();
    const bool body = std::string(file) == "body.stl";
    EXPECT_EQ(soup.triangles.size(), (body ? w.problem.problem.body : w.problem.problem.obstacles).triangles.size());
    EXPECT_LE(soup.triangles.size(), body ? 5000u : 50000u) << file;
  }
  // Box-made meshes are whole boxes, each a closed surface; the spiral tube and its cap are
  // closed B-rep solids, so every connected part of their tessellation is closed.
  for (const auto* soup : {&w.problem.problem.body, &w.problem.problem.obstacles}) {
    if (GetParam() == "spiral-tube" && soup == &w.problem.problem.obstacles) {
      const auto parts = surface_parts(soup->triangles);
      EXPECT_EQ(parts.size(), 2u) << "the tube and its cap";
      for (const SurfacePart& part : parts) EXPECT_TRUE(part.closed) << "an open part in the spiral tube";
      continue;
    }
    ASSERT_EQ(soup->triangles.size() % 12, 0u);
    for (std::size_t i = 0; i < soup->triangles.size(); i += 12) {
      const std::span<const Triangle> one(soup->triangles.data() + i, 12);
      const auto parts = surface_parts(one);
      ASSERT_EQ(parts.size(), 1u);
      EXPECT_TRUE(parts[0].closed) << "box " << i / 12;
    }
  }
}

TEST_P(SuiteTest, StartAndGoalAreClearAndInsideTheBounds) {
  const Written& w = written(GetParam());
  auto loaded = load_problem(w.files.problem_toml);
  ASSERT_TRUE(loaded) << loaded.error().message;
  const Problem& p = *loaded;
  const auto obstacles = oracle_tris(w.problem.problem.obstacles.triangles);
  // The brute-force oracle (all triangle pairs) in the design frame, where the poses are given.
  for (const Pose& pose : {w.problem.problem.problem.start, *w.problem.problem.problem.goal}) {
    const double d = oracle::exact_distance(obstacles, oracle_tris(w.problem.problem.body.triangles, pose));
    EXPECT_GT(d, p.clearance) << "pose at " << pose.translation.transpose();
  }
  // The reference point (the files' body-frame origin) stays in the bounds along the witness.
  for (const Pose& pose : w.files.witness_poses)
    EXPECT_TRUE(contains(*p.bounds, pose.translation)) << "witness pose out of bounds: " << pose.translation.transpose();
  auto scene = load_scene(p, p.build);
  ASSERT_TRUE(scene) << scene.error().message;
  EXPECT_FALSE(enclosure_at(*scene, p.start).has_value());
  EXPECT_FALSE(enclosure_at(*scene, *p.goal).has_value());
}

// The hand-derived witness path, certified with the problem's clearance by check_path (the
// planner's own certificate) and by the independent oracle: the problem is solvable. And the
// straight start → goal motion is not free: the problem needs its passage.
TEST_P(SuiteTest, WitnessPathIsCertified) {
  const Written& w = written(GetParam());
  std::optional<Problem> problem;
  std::optional<PlanScene> scene;
  ASSERT_NO_FATAL_FAILURE(read_back(w, problem, scene));
  const Path path{w.files.witness_poses};
  const PathCheckResult r = check_path(*problem, *scene, path);
  EXPECT_TRUE(r.valid) << r.message;
  EXPECT_GT(r.min_clearance, problem->clearance);
  expect_pose_near(path.poses.front(), problem->start, "witness start");
  expect_pose_near(path.poses.back(), *problem->goal, "witness end");
  // The witness as written (witness.json) reads back to the same poses.
  auto read = read_path(w.files.witness);
  ASSERT_TRUE(read) << read.error().message;
  ASSERT_EQ(read->poses.size(), path.poses.size());
  for (std::size_t i = 0; i < path.poses.size(); ++i) expect_pose_near(read->poses[i], path.poses[i], "witness.json");

  oracle::PathCheckInput in;
  in.obstacles = oracle_tris(scene->obstacles.triangles);
  in.body = oracle_tris(scene->body.triangles);
  for (const Pose& p : path.poses) in.poses.push_back({p.rotation, p.translation});
  in.reference = scene->reference;
  in.clearance = problem->clearance;
  in.dense_samples = 400;
  const oracle::PathCheckReport rep = oracle::check_path(in);
  EXPECT_TRUE(rep.valid) << rep.why;

  const PathCheckResult straight = check_path(*problem, *scene, Path{{problem->start, *problem->goal}});
  EXPECT_FALSE(straight.valid) << "the straight start-goal motion is free";
}

// check_path (the planner's final certification, and `swept check`) gives on two cores what it
// gives on one, field by field, for the witness and for the straight start → goal motion (free
// ends, a collision or a graze between them: a failing certificate). And each segment's smallest
// distance is the exact distance at the pose it names, by the oracle's brute force.
TEST_P(SuiteTest, CheckPathIsTheSameOnOneAndTwoCoresAndItsMinimaAreExact) {
  const Written& w = written(GetParam());
  std::optional<Problem> problem;
  std::optional<PlanScene> scene;
  ASSERT_NO_FATAL_FAILURE(read_back(w, problem, scene));
  const auto obstacles = oracle_tris(scene->obstacles.triangles);
  const Path straight{{problem->start, *problem->goal}};
  const Path witness{w.files.witness_poses};
  for (const Path* each : {&witness, &straight}) {
    const Path& path = *each;
    tbb::task_arena one(1), two(2);
    const PathCheckResult a = one.execute([&] { return check_path(*problem, *scene, path); });
    const PathCheckResult b = two.execute([&] { return check_path(*problem, *scene, path); });
    EXPECT_EQ(a.valid, b.valid);
    EXPECT_EQ(a.message, b.message);
    EXPECT_EQ(a.min_clearance, b.min_clearance);
    EXPECT_EQ(a.min_segment, b.min_segment);
    EXPECT_EQ(a.min_t, b.min_t);
    EXPECT_EQ(a.first_bad_segment, b.first_bad_segment);
    EXPECT_EQ(a.first_bad_distance, b.first_bad_distance);
    if (a.valid) {
      EXPECT_EQ(a.distance_queries, b.distance_queries);
    }
    ASSERT_EQ(a.segments.size(), path.poses.size() - 1);
    ASSERT_EQ(b.segments.size(), a.segments.size());
    if (each == &straight) {  // the case it is here for: a certificate that fails
      EXPECT_FALSE(a.valid);
      EXPECT_FALSE(a.segments.front().certified);
    }
    for (std::size_t i = 0; i < a.segments.size(); ++i) {
      const SegmentCheck &sa = a.segments[i], &sb = b.segments[i];
      EXPECT_EQ(sa.certified, sb.certified) << "segment " << i;
      EXPECT_EQ(sa.min_distance, sb.min_distance) << "segment " << i;
      EXPECT_EQ(sa.t_min, sb.t_min) << "segment " << i;
      EXPECT_EQ(sa.t_blocked, sb.t_blocked) << "segment " << i;
      EXPECT_EQ(sa.distance_at_block, sb.distance_at_block) << "segment " << i;
      const oracle::RigidPose at =
          oracle::interpolate_pose({path.poses[i].rotation, path.poses[i].translation},
                                   {path.poses[i + 1].rotation, path.poses[i + 1].translation}, sa.t_min, scene->reference);
      const double d = oracle::exact_distance(obstacles, oracle_tris(scene->body.triangles, Pose{at.R, at.t}));
      EXPECT_NEAR(sa.min_distance, d, 1e-9 * (1.0 + d)) << "segment " << i << " at t = " << sa.t_min;
    }
  }
}

TEST_P(SuiteTest, SameBytesEveryTime) {
  const Written& w = written(GetParam());
  const fs::path again = temp_dir(GetParam() + "_again");
  auto p = scenes::suite_problem(GetParam());
  ASSERT_TRUE(p) << p.error().message;
  auto f = scenes::write_suite_problem(*p, again);
  ASSERT_TRUE(f) << f.error().message;
  for (const std::string& n : std::vector<std::string>{"body.stl", "obstacles.stl", "problem.toml", GetParam() + ".cfg", "witness.json"}) {
    const std::string a = read_bytes(w.dir / n), b = read_bytes(again / n);
    EXPECT_FALSE(a.empty()) << n;
    EXPECT_EQ(a, b) << n << " differs between two runs";
  }
  fs::remove_all(again);
}

INSTANTIATE_TEST_SUITE_P(Suite, SuiteTest,
                         testing::Values("twisty-slot", "bug-trap", "hooks-1.5", "hooks-1.2", "hooks-1.1", "house",
                                         "cubicles", "spiral-tube"),
                         [](const testing::TestParamInfo<std::string>& i) {
                           std::string n = i.param;
                           for (char& c : n)
                             if (c == '-' || c == '.') c = '_';
                           return n;
                         });

TEST(Suite, CatalogueMatchesTheProblems) {
  ASSERT_EQ(scenes::suite_catalog().size(), 8u);
  for (const scenes::SuiteInfo& info : scenes::suite_catalog()) {
    EXPECT_TRUE(scenes::is_suite_problem(info.name));
    auto p = scenes::suite_problem(info.name);
    ASSERT_TRUE(p) << p.error().message;
    EXPECT_EQ(p->problem.name, info.name);
    EXPECT_GT(p->passage_width, p->body_width) << info.name;
    EXPECT_FALSE(p->passage.empty());
  }
  auto bad = scenes::suite_problem("no-such-problem");
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().message.find("bug-trap"), std::string::npos);
  EXPECT_FALSE(scenes::is_suite_problem("air-cleaner"));
  // The CAD scenes' generator names the suite in its errors and points a suite name to its writer.
  const fs::path dir = temp_dir("not_cad");
  auto unknown = scenes::generate_scene({.name = "no-such-problem", .output_dir = dir});
  ASSERT_FALSE(unknown);
  EXPECT_NE(unknown.error().message.find("hooks-1.1"), std::string::npos);
  auto suite = scenes::generate_scene({.name = "house", .output_dir = dir});
  ASSERT_FALSE(suite);
  EXPECT_NE(suite.error().message.find("write_suite_problem"), std::string::npos);
  fs::remove_all(dir);
}

// The trap's exit is as narrow as stated: a 2 × 2 channel for the 1.6 × 1.6 rod, 0.2 of play a
// side. Centred in the channel the rod is 0.2 from it; moved 0.25 sideways, or tilted by 0.1 rad,
// it is in collision.
TEST(Suite, TrapExitIsTwoWide) {
  const Written& w = written("bug-trap");
  EXPECT_EQ(w.problem.passage_width, 2.0);
  EXPECT_EQ(w.problem.body_width, 1.6);
  const auto obstacles = oracle_tris(w.problem.problem.obstacles.triangles);
  const auto& body = w.problem.problem.body.triangles;
  EXPECT_NEAR(oracle::exact_distance(obstacles, oracle_tris(body, Pose::from_translation(Vec3(6, 0, 0)))), 0.2, 1e-9);
  EXPECT_EQ(oracle::exact_distance(obstacles, oracle_tris(body, Pose::from_translation(Vec3(6, 0.25, 0)))), 0.0);
  EXPECT_EQ(oracle::exact_distance(obstacles, oracle_tris(body, Pose::from_axis_angle(Vec3::UnitZ(), 0.1, Vec3(6, 0, 0)))),
            0.0);
}

// The hooks' play is (gap − bar)/2: turned 30° and centred in the slanted slit the bar is that
// far from the fixed hook; unturned it jams in the two tighter ones (hooks-1.5 lets it through
// with less play: (g/2 − sin 30°)/cos 30° − 1 = 0.155).
TEST(Suite, HookGapsGiveTheStatedPlay) {
  constexpr double kTurn = 30.0 * std::numbers::pi / 180;
  for (const auto& [name, play] : {std::pair{"hooks-1.5", 0.5}, std::pair{"hooks-1.2", 0.2}, std::pair{"hooks-1.1", 0.1}}) {
    const Written& w = written(name);
    const auto obstacles = oracle_tris(w.problem.problem.obstacles.triangles);
    const auto& body = w.problem.problem.body.triangles;
    // Raised 8, the moving hook's bottom bar (z ∈ [8, 10]) is in the slit.
    const double d = oracle::exact_distance(obstacles, oracle_tris(body, Pose::from_axis_angle(Vec3::UnitZ(), kTurn, Vec3(0, 0, 8))));
    EXPECT_NEAR(d, play, 1e-9) << name;
    const double unturned = oracle::exact_distance(obstacles, oracle_tris(body, Pose::from_translation(Vec3(0, 0, 8))));
    if (play < 0.5) {
      EXPECT_EQ(unturned, 0.0) << name;
    } else {
      // The bar's corner (1, 1) to the slit's wall where it meets the slab's face y = 1.
      EXPECT_NEAR(unturned, (1.5 - std::sin(kTurn)) / std::cos(kTurn) - 1.0, 1e-9) << name;
    }
  }
}

#ifdef SWEPT_CLI
// `swept scene NAME` writes the files; `swept check` certifies the witness through either file.
TEST(Suite, CliWritesAndChecks) {
  const fs::path out = temp_dir("cli");
  const std::string cli = SWEPT_CLI;
  ASSERT_EQ(std::system((cli + " scene twisty-slot -o " + out.string() + " > /dev/null").c_str()), 0);
  for (const char* f : {"body.stl", "obstacles.stl", "problem.toml", "twisty-slot.cfg", "witness.json"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  EXPECT_EQ(std::system((cli + " check " + (out / "problem.toml").string() + " " + (out / "witness.json").string() +
                         " > /dev/null").c_str()),
            0);
  EXPECT_EQ(std::system((cli + " check " + (out / "twisty-slot.cfg").string() + " " +
                         (out / "witness.json").string() + " --clearance 0.05 > /dev/null")
                            .c_str()),
            0);
  const std::string list = out.string() + ".txt";
  ASSERT_EQ(std::system((cli + " scene --list > " + list).c_str()), 0);
  const std::string text = read_bytes(list);
  for (const scenes::SuiteInfo& s : scenes::suite_catalog()) EXPECT_NE(text.find(s.name), std::string::npos) << s.name;
  fs::remove(list);
  fs::remove_all(out);
}
#endif

}  // namespace
}  // namespace swept
