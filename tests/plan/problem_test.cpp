// Problem files (TOML and OMPL.app .cfg) and path files: good input round-trips, bad input
// gives a clear error naming the file and the key or line.
#include "plan/plan_support.h"
#include "swept/io/mesh_io.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <unistd.h>

namespace swept {
namespace {

namespace fs = std::filesystem;

class ProblemFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = fs::temp_directory_path() / ("swept_problem_" + std::to_string(::getpid()) + "_" +
                                       ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir);
    const auto g = scenes::peg_in_hole();
    ASSERT_TRUE(write_stl_binary(dir / "block.stl", g.obstacles));
    ASSERT_TRUE(write_stl_binary(dir / "peg.stl", g.body));
  }
  void TearDown() override { fs::remove_all(dir); }

  fs::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir / name) << text;
    return dir / name;
  }

  fs::path dir;
};

const char* kGood = R"(
unit = "mm"
[[obstacle]]
file = "block.stl"
[[body]]
file = "peg.stl"
pose = { translation = [0, 0, 0], axis = [0, 0, 1], angle_deg = 0 }
[start]
translation = [0, 0, -7.49]
quaternion = [0, 0, 0, 1]
[goal]
outside = true
margin = 1.0
[rotation]
mode = "limits"
limits_deg = [[-10, 10], [-10, 10], [-180, 180]]
[planner]
clearance = 0.002
fitter = "pqp"
time_limit = 30
threads = 1
)";

TEST_F(ProblemFiles, TomlRoundTrip) {
  auto p = load_problem(write("p.toml", kGood));
  ASSERT_TRUE(p) << p.error().message;
  EXPECT_EQ(p->obstacles.size(), 1u);
  EXPECT_EQ(p->body.size(), 1u);
  EXPECT_TRUE(p->goal_outside);
  EXPECT_DOUBLE_EQ(p->goal_margin, 1.0);
  EXPECT_EQ(p->rotation, RotationMode::limits);
  EXPECT_NEAR(p->rotation_limits[2][1], 3.14159265358979, 1e-12);
  EXPECT_EQ(p->build.fitter, Fitter::pqp);
  EXPECT_EQ(p->build.split, SplitRule::min_sa);  // the defaults where the file is silent
  EXPECT_EQ(p->build.leaf_size, 1);
  EXPECT_EQ(p->seed, 0u);  // the Halton sequence itself
  EXPECT_DOUBLE_EQ(p->clearance, 0.002);
  EXPECT_DOUBLE_EQ(p->start.translation.z(), -7.49);
  auto s = load_scene(*p, p->build);
  ASSERT_TRUE(s) << s.error().message;
  EXPECT_EQ(s->body.triangles.size(), 12u);
  const PlanResult r = plan(*p, *s);
  ASSERT_TRUE(r.solved()) << r.message;
  // Paths round-trip through both formats.
  for (const char* name : {"path.json", "path.path"}) {
    ASSERT_TRUE(write_path(dir / name, r.path, p->unit, s->reference));
    auto back = read_path(dir / name);
    ASSERT_TRUE(back) << back.error().message;
    ASSERT_EQ(back->poses.size(), r.path.poses.size());
    for (std::size_t i = 0; i < r.path.poses.size(); ++i) {
      EXPECT_LT((back->poses[i].translation - r.path.poses[i].translation).norm(), 1e-12);
      EXPECT_LT(rotation_angle(back->poses[i].rotation, r.path.poses[i].rotation), 1e-7);
    }
  }
}

TEST_F(ProblemFiles, TreeSettingsReachTheScene) {
  std::string text = kGood;
  text.replace(text.find("fitter = \"pqp\""), 14, "fitter = \"rapid2\"\nsplit = \"largest\"\nleaf_size = 4");
  auto p = load_problem(write("tree.toml", text));
  ASSERT_TRUE(p) << p.error().message;
  auto s = load_scene(*p, p->build);
  ASSERT_TRUE(s) << s.error().message;
  for (const Bvh* tree : {&s->obstacle_tree, &s->body_tree}) {
    EXPECT_EQ(tree->config.fitter, Fitter::rapid2);
    EXPECT_EQ(tree->config.split, SplitRule::largest);
    EXPECT_EQ(tree->config.leaf_size, 4);
    std::size_t largest_leaf = 0;
    for (const Node& n : tree->nodes) largest_leaf = std::max<std::size_t>(largest_leaf, n.is_leaf() ? n.count : 0);
    EXPECT_GT(largest_leaf, 1u);  // 12 triangles with leaves of up to 4: some leaf holds more than one
    EXPECT_LE(largest_leaf, 4u);
  }
}

TEST_F(ProblemFiles, SeedIsRead) {
  std::string text = kGood;
  text.replace(text.find("[planner]"), 9, "[planner]\nseed = 9223372036854775807");
  auto p = load_problem(write("seed.toml", text));
  ASSERT_TRUE(p) << p.error().message;
  EXPECT_EQ(p->seed, 9223372036854775807u);  // TOML's largest integer
}

TEST_F(ProblemFiles, OmplAppCfg) {
  auto p = load_problem(write("p.cfg", R"([problem]
name = peg
robot = peg.stl
world = block.stl
start.x = 0
start.y = 0
start.z = -7.49
start.theta = 0
start.axis.x = 0
start.axis.y = 0
start.axis.z = 1
goal.x = 0
goal.y = 0
goal.z = 40
goal.theta = 1.5707963267948966
goal.axis.x = 0
goal.axis.y = 0
goal.axis.z = 1
volume.min.x = -30
volume.min.y = -30
volume.min.z = -30
volume.max.x = 30
volume.max.y = 30
volume.max.z = 60
)"));
  ASSERT_TRUE(p) << p.error().message;
  ASSERT_TRUE(p->goal);
  EXPECT_NEAR(rotation_angle(Mat3::Identity(), p->goal->rotation), 1.5707963267948966, 1e-12);
  // Saved by Notepad as "UTF-8 with BOM": the byte-order mark before [problem] is not a line.
  const auto bom = load_problem(write("bom.cfg", "\xEF\xBB\xBF[problem]\nrobot = peg.stl\nworld = block.stl\nstart.x = 0\n"
                                                 "start.y = 0\nstart.z = -7.49\nstart.theta = 0\nstart.axis.x = 0\n"
                                                 "start.axis.y = 0\nstart.axis.z = 1\ngoal.x = 0\ngoal.y = 0\ngoal.z = 40\n"
                                                 "goal.theta = 0\ngoal.axis.x = 0\ngoal.axis.y = 0\ngoal.axis.z = 1\n"));
  EXPECT_TRUE(bom) << bom.error().message;
  ASSERT_TRUE(p->bounds);
  EXPECT_DOUBLE_EQ(p->bounds->max.z(), 60);
  p->clearance = 0.002;
  auto s = load_scene(*p, p->build);
  ASSERT_TRUE(s) << s.error().message;
  // The robot mesh is centred as OMPL.app centres it: on the mean of its joined vertices, for a
  // box (the peg) 4 per face, 24 in all, whose mean is the box's centre.
  EXPECT_LT(bounds(s->body.triangles).center().norm(), 1e-12);
  EXPECT_TRUE(p->body[0].pose.rotation.isIdentity());
  EXPECT_EQ(p->reference_point, Vec3::Zero());
  const PlanResult r = plan(*p, *s);
  ASSERT_TRUE(r.solved()) << r.message;
  test::verify_path(*s, r.path, p->clearance);
}

void expect_path_error(const Result<Path>& p, const std::string& needle) {
  ASSERT_FALSE(p) << "expected an error mentioning '" << needle << "'";
  EXPECT_NE(p.error().message.find(needle), std::string::npos) << p.error().message;
}

void expect_error(const Result<Problem>& p, const std::string& needle) {
  ASSERT_FALSE(p) << "expected an error mentioning '" << needle << "'";
  EXPECT_NE(p.error().message.find(needle), std::string::npos) << p.error().message;
}

TEST_F(ProblemFiles, BadFilesGiveClearErrors) {
  expect_error(load_problem(dir / "nope.toml"), "no such file");
  expect_error(load_problem(write("p.yaml", "x: 1")), "unknown problem format");
  std::string missing = kGood;
  missing.replace(missing.find("peg.stl"), 7, "gone.stl");
  expect_error(load_problem(write("m.toml", missing)), "gone.stl");
  expect_error(load_problem(write("bad.toml", "unit = \"mm\"\n[[obstacle]\nfile = 3\n")), "bad.toml:2");
  expect_error(load_problem(write("unit.toml", std::string(kGood).replace(std::string(kGood).find("\"mm\""), 4, "\"furlong\""))),
               "furlong");
  std::string no_goal = kGood;
  no_goal.replace(no_goal.find("[goal]"), 6, "[gaol]");
  expect_error(load_problem(write("g.toml", no_goal)), "gaol");
  std::string bad_quat = kGood;
  bad_quat.replace(bad_quat.find("[0, 0, 0, 1]"), 12, "[0, 0, 0]");
  expect_error(load_problem(write("q.toml", bad_quat)), "start.quaternion");
  expect_error(load_problem(write("c.cfg", "[problem]\nrobot = peg.stl\nworld = block.stl\nstart.x = abc\n")), "c.cfg:4");
  expect_error(load_problem(write("d.cfg", "[problem]\nrobot = peg.stl\n")), "world");
  expect_error(load_problem(write("e.cfg", "[problem]\nrobot = peg.stl\nworld = nothere.dae\n")), "nothere.dae");
  expect_error(load_problem(write("f.cfg", "[problem\n")), "f.cfg:1");
  // Start in collision and goal outside bounds are found when planning.
  std::string collide = kGood;
  collide.replace(collide.find("-7.49"), 5, "-30.0");
  auto p = load_problem(write("col.toml", collide));
  ASSERT_TRUE(p);
  auto s = load_scene(*p, p->build);
  ASSERT_TRUE(s);
  EXPECT_EQ(plan(*p, *s).status, PlanStatus::invalid_start);
}

// kGood with `line` inserted after the first line equal to `after`; `line_no` is set to the
// 1-based line the insertion lands on.
std::string with_line(const std::string& after, const std::string& line, int& line_no) {
  std::string text = kGood;
  const std::size_t at = text.find("\n" + after + "\n");
  EXPECT_NE(at, std::string::npos) << after;
  const std::size_t insert = at + after.size() + 2;
  text.insert(insert, line + "\n");
  line_no = 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(insert), '\n'));
  return text;
}

// docs/problem-format.md promises exit 1 for an unknown key: in every table, with its line.
TEST_F(ProblemFiles, UnknownKeysAreErrorsNamingTheKeyAndLine) {
  struct Case {
    const char* after;
    const char* line;
    const char* key;
  };
  const Case cases[] = {
      {"unit = \"mm\"", "colour = \"red\"", "colour"},
      {"[planner]", "clearence = 19", "planner.clearence"},
      {"[[obstacle]]", "pos = { translation = [0, 0, 10] }", "obstacle[0].pos"},
      {"[[body]]", "scale = 2", "body[0].scale"},
      {"[start]", "rotation = [0, 0, 0]", "start.rotation"},
      {"[goal]", "tolerance = 1", "goal.tolerance"},
      {"[rotation]", "limit = 3", "rotation.limit"},
      {"[[obstacle]]", "pose = { translation = [0, 0, 0], angle = 5 }", "obstacle[0].pose.angle"},
  };
  for (const Case& c : cases) {
    int line = 0;
    const auto file = write("unknown.toml", with_line(c.after, c.line, line));
    const auto p = load_problem(file);
    expect_error(p, file.string() + ":" + std::to_string(line) + ":");
    expect_error(p, std::string(c.key) + ": unknown key");
  }
  int line = 0;
  const std::string frame = with_line("[goal]", "", line) + "[body_frame]\ncentre = [0, 0, 0]\n[bounds]\nmin = [-50, -50, -50]\nmax = [50, 50, 50]\n";
  expect_error(load_problem(write("frame.toml", frame)), "body_frame.centre: unknown key");
  std::string bounds = frame;
  bounds.replace(bounds.find("centre"), 6, "reference_point");
  bounds.replace(bounds.find("max ="), 3, "mx ");
  expect_error(load_problem(write("bounds.toml", bounds)), "bounds.mx: unknown key");
  bounds.replace(bounds.find("mx "), 3, "max");
  auto good = load_problem(write("good.toml", bounds));
  ASSERT_TRUE(good) << good.error().message;
  EXPECT_TRUE(good->bounds);
  EXPECT_TRUE(good->reference_point);
}

// Every value is type- and range-checked; none silently becomes a default.
TEST_F(ProblemFiles, WrongTypesAndRangesAreErrorsNamingTheKeyAndLine) {
  struct Case {
    const char* at;    // a line of kGood: replaced by `line` if it starts with the same key, else followed by it
    const char* line;
    const char* needle;
    int line_offset = 0;  // the error's line relative to `line` (when another key is the culprit)
  };
  const Case cases[] = {
      {"fitter = \"pqp\"", "fitter = 5", "planner.fitter: must be a string"},
      {"fitter = \"pqp\"", "fitter = \"best\"", "planner.fitter: unknown fitter 'best' (pqp, rapid2, inertia)"},
      {"[planner]", "split = \"median\"", "planner.split: unknown split rule 'median' (min-sa, largest, min-sa-box)"},
      {"[planner]", "split = 2", "planner.split: must be a string"},
      {"[planner]", "leaf_size = 0", "planner.leaf_size: must be from 1 to 65536, got 0"},
      {"[planner]", "leaf_size = 4.5", "planner.leaf_size: must be a whole number"},
      {"threads = 1", "threads = 1.5", "planner.threads: must be a whole number"},
      {"threads = 1", "threads = 4294967297", "planner.threads: must be from 0 to 2147483647, got 4294967297"},
      {"threads = 1", "threads = -1", "planner.threads: must be from 0"},
      {"[planner]", "seed = -3", "planner.seed: must be 0 or more, got -3"},
      {"[planner]", "seed = 2.5", "planner.seed: must be a whole number"},
      {"[planner]", "seed = \"7\"", "planner.seed: must be a whole number"},
      {"clearance = 0.002", "clearance = \"1\"", "planner.clearance: must be a number"},
      {"clearance = 0.002", "clearance = nan", "planner.clearance: must be a finite number"},
      {"clearance = 0.002", "clearance = -0.5", "planner.clearance: must be ≥ 0"},
      {"time_limit = 30", "time_limit = 0", "planner.time_limit: must be > 0"},
      {"[planner]", "deflection = -inf", "planner.deflection: must be a finite number"},
      {"[[obstacle]]", "deflection = -1", "obstacle[0].deflection: must be > 0, got -1"},
      {"[[obstacle]]", "deflection = 0", "obstacle[0].deflection: must be > 0"},
      {"[[obstacle]]", "file_unit = 1000", "obstacle[0].file_unit: must be a string"},
      {"[[obstacle]]", "file_unit = \"yard\"", "obstacle[0].file_unit: unknown unit 'yard'"},
      {"file = \"peg.stl\"", "file = 3", "body[0].file: must be a string"},
      {"mode = \"limits\"", "mode = 1", "rotation.mode: must be a string"},
      {"outside = true", "outside = \"yes\"", "goal.outside: must be true or false"},
      {"outside = true", "outside = false", "goal.margin: only used with outside = true", 1},
      {"[goal]", "translation = [0, 0, 50]", "goal.translation: give either a goal pose or outside = true"},
      {"[start]", "axis = [0, 0, 1]", "start: give either quaternion or axis + angle_deg", 2},
      {"unit = \"mm\"", "unit = 5", "unit: must be a string"},
      {"margin = 1.0", "margin = inf", "goal.margin: must be a finite number"},
      {"mode = \"limits\"", "mode = \"free\"", "rotation.limits_deg: only used with mode = \"limits\"", 1},
      {"translation = [0, 0, -7.49]", "translation = [0, nan, -7.49]", "start.translation[1]: must be a finite number"},
  };
  for (const Case& c : cases) {
    const std::string at = c.at, line = c.line;
    std::string text = kGood;
    const std::size_t pos = text.find("\n" + at + "\n");
    ASSERT_NE(pos, std::string::npos) << at;
    const bool replace = at.substr(0, at.find(' ')) == line.substr(0, line.find(' '));
    const std::size_t line_start = replace ? pos + 1 : pos + at.size() + 2;
    if (replace) text.replace(pos + 1, at.size(), line);
    else text.insert(line_start, line + "\n");
    const int line_no = 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(line_start), '\n'));
    const auto file = write("typed.toml", text);
    const auto p = load_problem(file);
    expect_error(p, file.string() + ":" + std::to_string(line_no + c.line_offset) + ":");
    expect_error(p, c.needle);
  }
  std::string table = kGood;
  table.replace(table.find("[[obstacle]]"), 12, "[obstacle]");
  expect_error(load_problem(write("table.toml", table)), "obstacle: must be an array of tables: write [[obstacle]]");
  std::string zero = kGood;
  zero.replace(zero.find("axis = [0, 0, 1]"), 16, "axis = [0, 0, 0]");
  expect_error(load_problem(write("zero.toml", zero)), "body[0].pose.axis: must not be zero");
}

// A quaternion is normalized, but one whose length is far from 1 (1e300, 1e-200) is a mistake in
// the file, not a rotation: it is refused, naming the key and the length. An angle of more than
// ten turns likewise.
TEST_F(ProblemFiles, QuaternionsFarFromUnitAndHugeAnglesAreRefused) {
  for (const char* q : {"[0, 0, 1e300, 1e300]", "[1e-200, 0, 0, 0]", "[0, 0, 0, 1e-4]", "[0, 0, 2000, 0]"}) {
    std::string text = kGood;
    text.replace(text.find("quaternion = [0, 0, 0, 1]"), 25, std::string("quaternion = ") + q);
    const auto p = load_problem(write("far.toml", text));
    expect_error(p, "start.quaternion: must have a length near 1");
  }
  std::string longer = kGood;  // length 2: taken, and normalized
  longer.replace(longer.find("quaternion = [0, 0, 0, 1]"), 25, "quaternion = [0, 0, 1.41421356237, 1.41421356237]");
  auto p = load_problem(write("longer.toml", longer));
  ASSERT_TRUE(p) << p.error().message;
  EXPECT_NEAR(rotation_angle(Mat3::Identity(), p->start.rotation), std::numbers::pi / 2, 1e-10);
  EXPECT_NEAR(p->start.rotation(1, 0), 1.0, 1e-10);
  for (const char* angle : {"1e300", "-3601", "36000"}) {
    std::string text = kGood;
    text.replace(text.find("angle_deg = 0"), 13, std::string("angle_deg = ") + angle);
    expect_error(load_problem(write("angle.toml", text)), "body[0].pose.angle_deg: an angle of");
  }
  std::string turns = kGood;  // within a turn, negative
  turns.replace(turns.find("angle_deg = 0"), 13, "angle_deg = -270");
  p = load_problem(write("turns.toml", turns));
  ASSERT_TRUE(p) << p.error().message;
  EXPECT_NEAR(p->body[0].pose.rotation(1, 0), 1.0, 1e-12);  // -270° about z is +90°
  std::string axis = kGood;  // an axis is only a direction, whatever its length
  axis.replace(axis.find("axis = [0, 0, 1], angle_deg = 0"), 31, "axis = [0, 1e308, 1e308], angle_deg = 180");
  p = load_problem(write("axis.toml", axis));
  ASSERT_TRUE(p) << p.error().message;
  EXPECT_NEAR(p->body[0].pose.rotation(0, 0), -1.0, 1e-12);
  EXPECT_NEAR(p->body[0].pose.rotation(1, 2), 1.0, 1e-12);

  // A path file, written by a program, takes any non-zero quaternion, scaled by its largest
  // component before normalizing.
  auto path = read_path(write("huge.path", "1 2 3 0 0 1e300 1e300\n"));
  ASSERT_TRUE(path) << path.error().message;
  EXPECT_NEAR(path->poses[0].rotation(1, 0), 1.0, 1e-12);
  path = read_path(write("huge.json", R"({"poses": [{"translation": [1, 2, 3], "quaternion": [0, 0, 1e300, 1e300]}]})"));
  ASSERT_TRUE(path) << path.error().message;
  EXPECT_NEAR(path->poses[0].rotation(1, 0), 1.0, 1e-12);
}

const char* kCfg = R"([problem]
robot = peg.stl
world = block.stl
start.x = 0
start.y = 0
start.z = -7.49
start.theta = 0
start.axis.x = 0
start.axis.y = 0
start.axis.z = 1
goal.x = 0
goal.y = 0
goal.z = 40
goal.theta = 1.5
goal.axis.x = 0
goal.axis.y = 0
goal.axis.z = 1
)";

// A Z-up COLLADA robot in a .cfg: OMPL.app reads it with assimp's defaults, so the file's
// (x, y, z) is (x, z, -y), and centres it on the mean of the joined vertices. The triangle
// (1,2,3) (10,0,0) (0,20,30) [mm] becomes (1,3,-2) (10,0,0) (0,30,-20), centre (11/3, 11, -22/3).
TEST_F(ProblemFiles, CfgRobotIsCentredAsOmplAppCentresIt) {
  write("robot.dae", R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="millimeter" meter="0.001"/><up_axis>Z_UP</up_axis></asset>
  <library_geometries><geometry id="g"><mesh>
    <source id="p"><float_array id="a" count="9">1 2 3 10 0 0 0 20 30</float_array>
      <technique_common><accessor source="#a" count="3" stride="3">
        <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
      </accessor></technique_common></source>
    <vertices id="v"><input semantic="POSITION" source="#p"/></vertices>
    <triangles count="1"><input semantic="VERTEX" source="#v" offset="0"/><p>0 1 2</p></triangles>
  </mesh></geometry></library_geometries>
  <library_visual_scenes><visual_scene id="s"><node id="n"><instance_geometry url="#g"/></node></visual_scene>
  </library_visual_scenes>
  <scene><instance_visual_scene url="#s"/></scene>
</COLLADA>
)");
  std::string text = kCfg;
  text.replace(text.find("robot = peg.stl"), 15, "robot = robot.dae");
  auto p = load_problem(write("dae.cfg", text));
  ASSERT_TRUE(p) << p.error().message;
  // COLLADA's <unit> is applied by assimp (metres) and the .cfg keeps OMPL.app's numbers: the
  // file unit is "mm" for every .cfg mesh, so the millimetre file reads in metres' numbers.
  const Vec3 centre = -p->body[0].pose.translation;
  EXPECT_NEAR(centre.x(), 11.0 / 3 * 1e-3, 1e-8);
  EXPECT_NEAR(centre.y(), 11 * 1e-3, 1e-8);
  EXPECT_NEAR(centre.z(), -22.0 / 3 * 1e-3, 1e-8);
}

// A .cfg without volume.*: OMPL.app infers the bounds (InferEnvironmentBounds, then
// InferProblemDefinitionBounds, factor 1, addition 0): the box of the world mesh's vertices as
// assimp returns them, every mesh of the file (here a triangle and a line), up axis applied, then
// stretched to hold the start and the goal. Z-up (x, y, z) reads as (x, z, -y): the triangle
// (1,2,3) (10,0,0) (0,20,30) as (1,3,-2) (10,0,0) (0,30,-20), the line's end (-5,2,3) as (-5,3,-2);
// start (2, 5, -30), goal (4, 40, -10): min (-5, 0, -30), max (10, 40, 0). (Before, such a file
// got our TOML's default, a box grown well past the obstacles, and OMPL.app's Twistycool could be
// solved round its wall.)
TEST_F(ProblemFiles, CfgWithoutVolumeTakesTheBoundsOmplAppInfers) {
  write("world.dae", R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><up_axis>Z_UP</up_axis></asset>
  <library_geometries><geometry id="g"><mesh>
    <source id="p"><float_array id="a" count="12">1 2 3 10 0 0 0 20 30 -5 2 3</float_array>
      <technique_common><accessor source="#a" count="4" stride="3">
        <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
      </accessor></technique_common></source>
    <vertices id="v"><input semantic="POSITION" source="#p"/></vertices>
    <triangles count="1"><input semantic="VERTEX" source="#v" offset="0"/><p>0 1 2</p></triangles>
    <lines count="1"><input semantic="VERTEX" source="#v" offset="0"/><p>0 3</p></lines>
  </mesh></geometry></library_geometries>
  <library_visual_scenes><visual_scene id="s"><node id="n"><instance_geometry url="#g"/></node></visual_scene>
  </library_visual_scenes>
  <scene><instance_visual_scene url="#s"/></scene>
</COLLADA>
)");
  const std::string cfg = R"([problem]
robot = peg.stl
world = world.dae
start.x = 2
start.y = 5
start.z = -30
goal.x = 4
goal.y = 40
goal.z = -10
)";
  auto p = load_problem(write("novolume.cfg", cfg));
  ASSERT_TRUE(p) << p.error().message;
  ASSERT_TRUE(p->bounds);
  EXPECT_EQ(p->bounds->min, Vec3(-5, 0, -30));
  EXPECT_EQ(p->bounds->max, Vec3(10, 40, 0));

  // Given, volume.* is taken as it is.
  auto given = load_problem(write("volume.cfg", cfg + R"(volume.min.x = -100
volume.min.y = -100
volume.min.z = -100
volume.max.x = 100
volume.max.y = 100
volume.max.z = 100
)"));
  ASSERT_TRUE(given) << given.error().message;
  EXPECT_EQ(given->bounds->min, Vec3::Constant(-100));

  // A box flat along an axis (a flat world, start and goal in its plane) is an error naming it.
  write("flat.stl", "solid f\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 9 0 0\nvertex 0 9 0\nendloop\n"
                    "endfacet\nendsolid f\n");
  expect_error(load_problem(write("flat.cfg", "[problem]\nrobot = peg.stl\nworld = flat.stl\nstart.x = 1\nstart.y = 1\n"
                                              "start.z = 0\ngoal.x = 2\ngoal.y = 2\ngoal.z = 0\n")),
               "flat.cfg: no volume.* given, and the box OMPL.app would infer (the world mesh's, with the start and the "
               "goal) is flat along z");
}

// What OMPL.app hands to OMPL's planners (CFGBenchmark: the state sampler, the goal threshold,
// an optimization objective, the [benchmark] run limits and the [planner] list, as in its own
// cubicles_opt.cfg, alpha-1.5.cfg and bugtrap.cfg) is read without error and named in a note
// each, with its line; a file without them has no notes, and the problem is the same either way.
TEST_F(ProblemFiles, CfgSettingsForOmplsPlannersBecomeNotes) {
  auto plain = load_problem(write("plain.cfg", kCfg));
  ASSERT_TRUE(plain) << plain.error().message;
  EXPECT_TRUE(plain->notes.empty());
  const std::string text = std::string(kCfg) +
                           "objective = length\n"           // line 18
                           "# make PRM act like an optimizing planner:\n"
                           "objective.threshold = 0\n"      // 20
                           "sampler=obstacle_based\n"       // 21
                           "threshold=1e-15\n"              // 22
                           "\n[benchmark]\ntime_limit=300.0\nrun_count=50\n"  // header on 24
                           "\n[planner]\nrrt=\nrrt.range=10\naps=\naps=\n";  // 28; a planner twice is OMPL's
  auto p = load_problem(write("opt.cfg", text));
  ASSERT_TRUE(p) << p.error().message;
  ASSERT_EQ(p->notes.size(), 5u);
  const char* expected[] = {"opt.cfg:18: objective = length: ", "opt.cfg:20: objective.threshold = 0: ",
                            "opt.cfg:21: sampler = obstacle_based: ", "opt.cfg:22: threshold = 1e-15: ",
                            "opt.cfg:24: [benchmark] and [planner]: "};
  for (std::size_t i = 0; i < 5; ++i) EXPECT_NE(p->notes[i].find(expected[i]), std::string::npos) << p->notes[i];
  EXPECT_NE(p->notes[4].find("--time-limit"), std::string::npos);
  ASSERT_TRUE(p->goal && plain->goal);
  EXPECT_EQ(p->start.translation, plain->start.translation);
  EXPECT_EQ(p->goal->rotation, plain->goal->rotation);
  EXPECT_DOUBLE_EQ(p->time_limit, plain->time_limit);  // [benchmark] time_limit is not ours
}

TEST_F(ProblemFiles, CfgDuplicatesZeroAxesAndNonFiniteNumbersAreErrors) {
  ASSERT_TRUE(load_problem(write("good.cfg", kCfg)));
  expect_error(load_problem(write("dup.cfg", std::string(kCfg) + "goal.z = 50\n")), "dup.cfg:18: goal.z: given twice (first on line 13)");
  std::string zero = kCfg;
  zero.replace(zero.find("goal.axis.z = 1"), 15, "goal.axis.z = 0");
  expect_error(load_problem(write("zero.cfg", zero)), "zero.cfg:14: goal.theta: a rotation of 1.5 rad needs a non-zero goal.axis");
  std::string none = kCfg;
  none.erase(none.find("goal.axis.x"));
  expect_error(load_problem(write("none.cfg", none)), "none.cfg:14: goal.theta");
  std::string tiny = kCfg;
  tiny.replace(tiny.find("goal.axis.z = 1"), 15, "goal.axis.z = 1e-10");
  expect_error(load_problem(write("tiny.cfg", tiny)), "tiny.cfg:14: goal.theta");
  std::string still = kCfg;  // a zero axis with a zero angle is no rotation, as in OMPL
  still.replace(still.find("start.axis.z = 1"), 16, "start.axis.z = 0");
  auto p = load_problem(write("still.cfg", still));
  ASSERT_TRUE(p) << p.error().message;
  EXPECT_TRUE(p->start.rotation.isIdentity());
  for (const char* bad : {"inf", "nan", "-inf", "1e999"}) {
    std::string text = kCfg;
    text.replace(text.find("start.y = 0"), 11, std::string("start.y = ") + bad);
    expect_error(load_problem(write("nonfinite.cfg", text)), "nonfinite.cfg:5: start.y: must be a finite number");
  }
  std::string huge_axis = kCfg;
  huge_axis.replace(huge_axis.find("goal.axis.z = 1"), 15, "goal.axis.z = 1e308\ngoal.axis.z2 = 1");
  huge_axis.replace(huge_axis.find("goal.axis.y = 0"), 15, "goal.axis.y = 1e308");
  p = load_problem(write("huge.cfg", huge_axis));
  ASSERT_TRUE(p) << p.error().message;
  EXPECT_NEAR(rotation_angle(Mat3::Identity(), p->goal->rotation), 1.5, 1e-12);
}

// A key OMPL.app's [problem] section does not declare is a parameter for its planners there and
// nothing here: named in a note with its line, with the declared key a typo most likely meant
// (edit distance at most 2). OMPL.app's `name` is silent; `control` and `solution_length` are named.
TEST_F(ProblemFiles, CfgUnknownKeysAreNamedWithTheKeyMeant) {
  std::string text = kCfg;
  text.replace(text.find("start.theta = 0"), 15, "start.thetaa = 0");
  text += "name = peg in block\nlongest_valid_segment_fraction = 0.01\nvolume.mix.x = 3\n";
  auto p = load_problem(write("typo.cfg", text));
  ASSERT_TRUE(p) << p.error().message;
  const int typo_line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(text.find("start.thetaa")), '\n'));
  const int last = static_cast<int>(std::count(text.begin(), text.end(), '\n'));
  ASSERT_EQ(p->notes.size(), 3u) << ::testing::PrintToString(p->notes);
  EXPECT_TRUE(p->notes[0].ends_with("typo.cfg:" + std::to_string(typo_line) +
                                     ": start.thetaa: not a key of OMPL.app's [problem] section, ignored; did you mean start.theta?"))
      << p->notes[0];
  EXPECT_NE(p->notes[1].find("typo.cfg:" + std::to_string(last - 1) + ": longest_valid_segment_fraction: not a key"),
            std::string::npos) << p->notes[1];
  EXPECT_EQ(p->notes[1].find("did you mean"), std::string::npos) << p->notes[1];
  EXPECT_NE(p->notes[2].find("volume.mix.x: not a key of OMPL.app's [problem] section, ignored; did you mean volume.min.x?"),
            std::string::npos) << p->notes[2];
  auto control = load_problem(write("control.cfg", std::string(kCfg) + "control = kinematic_car\nsolution_length = 10\n"));
  ASSERT_TRUE(control) << control.error().message;
  ASSERT_EQ(control->notes.size(), 2u);
  EXPECT_NE(control->notes[0].find("control = kinematic_car: OMPL.app's control-based systems are not planned"), std::string::npos);
  EXPECT_NE(control->notes[1].find("solution_length = 10: "), std::string::npos);
  auto plain = load_problem(write("plain.cfg", kCfg));
  ASSERT_TRUE(plain);
  EXPECT_TRUE(plain->notes.empty());
}

// An angle past ten turns (|theta| > 20 pi rad) is refused, naming the key and its line.
TEST_F(ProblemFiles, CfgAnglesPastTenTurnsAreRefused) {
  for (const char* theta : {"1e300", "-63", "100"}) {
    std::string text = kCfg;
    text.replace(text.find("goal.theta = 1.5"), 16, std::string("goal.theta = ") + theta);
    expect_error(load_problem(write("angle.cfg", text)), "angle.cfg:14: goal.theta: an angle of " + std::string(theta) + " rad is more than 10 turns");
  }
  std::string text = kCfg;
  text.replace(text.find("goal.theta = 1.5"), 16, "goal.theta = -62.8");  // within ten turns
  ASSERT_TRUE(load_problem(write("ok.cfg", text)));
}

// OMPL's PathGeometric::print() form, in which OMPL.app ships its solution paths
// (resources/3D/*.path): per state "Compound state [", "RealVectorState [x y z]",
// "SO3State [qx qy qz qw]", "]". The second state is a half turn about y: (0, 1, 0, 0) in x y z w.
TEST_F(ProblemFiles, OmplPrintedPathFilesAreRead) {
  const std::string two = "Compound state [\nRealVectorState [270 160 -200]\nSO3State [0 0 0 1]\n]\n"
                          "Compound state [\nRealVectorState [270 160 -400]\nSO3State [6.12323e-17 1 6.12323e-17 3.7494e-33]\n]\n";
  auto path = read_path(write("printed.path", two));
  ASSERT_TRUE(path) << path.error().message;
  ASSERT_EQ(path->poses.size(), 2u);
  EXPECT_EQ(path->poses[0].translation, Vec3(270, 160, -200));
  EXPECT_TRUE(path->poses[0].rotation.isIdentity());
  EXPECT_EQ(path->poses[1].translation, Vec3(270, 160, -400));
  EXPECT_NEAR((path->poses[1].rotation - Vec3(-1, 1, -1).asDiagonal().toDenseMatrix()).norm(), 0.0, 1e-15);

  // The matrix form still reads every line.
  auto matrix = read_path(write("matrix.path", "1 2 3 0 0 0 1\n4 5 6 0 0 0 1\n7 8 9 0 0 0 1\n"));
  ASSERT_TRUE(matrix) << matrix.error().message;
  EXPECT_EQ(matrix->poses.size(), 3u);
  // Both forms saved with a UTF-8 byte-order mark (Notepad's "UTF-8 with BOM") read the same.
  const auto marked_matrix = read_path(write("bom.path", "\xEF\xBB\xBF" "1 2 3 0 0 0 1\n4 5 6 0 0 0 1\n7 8 9 0 0 0 1\n"));
  ASSERT_TRUE(marked_matrix) << marked_matrix.error().message;
  EXPECT_EQ(marked_matrix->poses.size(), 3u);
  EXPECT_EQ(marked_matrix->poses[0].translation, Vec3(1, 2, 3));
  const auto marked_printed = read_path(write("bom_printed.path", "\xEF\xBB\xBF" + two));
  ASSERT_TRUE(marked_printed) << marked_printed.error().message;
  EXPECT_EQ(marked_printed->poses.size(), path->poses.size());

  // Broken states name the file and line.
  expect_path_error(read_path(write("cut.path", "Compound state [\nRealVectorState [1 2 3]\n")),
                    "cut.path: the last state is cut short (line 2)");
  expect_path_error(read_path(write("noso3.path", "Compound state [\nRealVectorState [1 2 3]\n]\n")),
                    "noso3.path:3: expected 'SO3State [x y z w]'");
  expect_path_error(read_path(write("short.path", "Compound state [\nRealVectorState [1 2]\nSO3State [0 0 0 1]\n]\n")),
                    "short.path:2: RealVectorState: expected 3 numbers");
  expect_path_error(read_path(write("nan.path", "Compound state [\nRealVectorState [1 2 nan]\nSO3State [0 0 0 1]\n]\n")),
                    "nan.path:2: RealVectorState");
  expect_path_error(read_path(write("zero.path", "Compound state [\nRealVectorState [1 2 3]\nSO3State [0 0 0 0]\n]\n")),
                    "zero.path:4: zero quaternion");
  expect_path_error(read_path(write("mixed.path", "Compound state [\nRealVectorState [1 2 3]\nSO3State [0 0 0 1]\n]\n"
                                                  "1 2 3 0 0 0 1\n")),
                    "mixed.path:5: expected 'Compound state ['");
}

TEST_F(ProblemFiles, BadPathFiles) {
  EXPECT_FALSE(read_path(write("a.path", "1 2 3 0 0 0\n")));
  EXPECT_FALSE(read_path(write("b.path", "")));
  EXPECT_FALSE(read_path(write("c.json", "{\"poses\": [{\"translation\": [1, 2]}]}")));
  EXPECT_FALSE(read_path(dir / "none.path"));
}

}  // namespace
}  // namespace swept

namespace swept {
namespace {

// planner.max_triangles reaches the CAD import of every mesh of the problem.
TEST(ProblemBudget, MaxTrianglesReachesTheCadImport) {
  const fs::path dir = fs::temp_directory_path() / ("swept_problem_budget_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path box = fs::path(SWEPT_SOURCE_DIR) / "tests" / "data" / "io" / "box.brep";
  const auto g = scenes::peg_in_hole();
  ASSERT_TRUE(write_stl_binary(dir / "peg.stl", g.body));
  auto text = [&](const std::string& planner) {
    return "unit = \"mm\"\n[[obstacle]]\nfile = \"" + box.string() +
           "\"\n[[body]]\nfile = \"peg.stl\"\n[start]\ntranslation = [0, 0, 100]\nquaternion = [0, 0, 0, 1]\n"
           "[goal]\noutside = true\n[planner]\n" + planner;
  };
  std::ofstream(dir / "small.toml") << text("max_triangles = 4\n");
  std::ofstream(dir / "zero.toml") << text("max_triangles = 0\n");
  std::ofstream(dir / "fine.toml") << text("");
  auto small = load_problem(dir / "small.toml");
  ASSERT_TRUE(small) << small.error().message;
  EXPECT_EQ(small->max_triangles, 4u);
  const auto scene = load_scene(*small, small->build);
  ASSERT_FALSE(scene);
  EXPECT_NE(scene.error().message.find("max_triangles"), std::string::npos) << scene.error().message;
  EXPECT_FALSE(load_problem(dir / "zero.toml"));
  auto fine = load_problem(dir / "fine.toml");
  ASSERT_TRUE(fine) << fine.error().message;
  EXPECT_TRUE(load_scene(*fine, fine->build));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace swept
