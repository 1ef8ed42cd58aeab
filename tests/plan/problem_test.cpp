// Problem files (TOML and OMPL.app .cfg) and path files: good input round-trips, bad input
// gives a clear error naming the file and the key or line.
#include "plan/plan_support.h"
#include "swept/io/mesh_io.h"

#include <filesystem>
#include <fstream>
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
  EXPECT_EQ(p->fitter, Fitter::pqp);
  EXPECT_DOUBLE_EQ(p->clearance, 0.002);
  EXPECT_DOUBLE_EQ(p->start.translation.z(), -7.49);
  auto s = load_scene(*p, p->fitter);
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
  ASSERT_TRUE(p->bounds);
  EXPECT_DOUBLE_EQ(p->bounds->max.z(), 60);
  EXPECT_TRUE(p->body[0].center_on_vertex_mean);
  p->clearance = 0.002;
  auto s = load_scene(*p, p->fitter);
  ASSERT_TRUE(s) << s.error().message;
  // The robot mesh is centred on the mean of its vertices, as OMPL.app does.
  Vec3 mean = Vec3::Zero();
  for (const Triangle& t : s->body.triangles) mean += t.p + t.q + t.r;
  EXPECT_LT((mean / (3.0 * s->body.triangles.size())).norm(), 1e-12);
  const PlanResult r = plan(*p, *s);
  ASSERT_TRUE(r.solved()) << r.message;
  test::verify_path(*s, r.path, p->clearance);
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
  auto s = load_scene(*p, p->fitter);
  ASSERT_TRUE(s);
  EXPECT_EQ(plan(*p, *s).status, PlanStatus::invalid_start);
}

TEST_F(ProblemFiles, BadPathFiles) {
  EXPECT_FALSE(read_path(write("a.path", "1 2 3 0 0 0\n")));
  EXPECT_FALSE(read_path(write("b.path", "")));
  EXPECT_FALSE(read_path(write("c.json", "{\"poses\": [{\"translation\": [1, 2]}]}")));
  EXPECT_FALSE(read_path(dir / "none.path"));
}

}  // namespace
}  // namespace swept
