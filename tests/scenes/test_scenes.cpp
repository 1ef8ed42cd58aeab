// The built-in scenes at test scale: deterministic bytes, triangle budget, a parsable problem
// file, a start pose clear of the obstacles, no straight escape, and a hand-made witness path
// that is certified free (so the scene is solvable).
#include "scene_checks.h"

#include "swept/bvh/bvh.h"
#include "swept/io/mesh_io.h"
#include "swept/query/query.h"
#include "swept/scenes/scenes.h"

#include <gtest/gtest.h>
#include <toml++/toml.h>

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <numbers>
#include <string>
#include <unistd.h>

namespace swept::test {
namespace {

namespace fs = std::filesystem;

fs::path temp_dir(const std::string& tag) {
  const fs::path dir = fs::temp_directory_path() / ("swept_scenes_" + tag + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  return dir;
}

std::string read_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

Vec3 vec3_of(const toml::node_view<const toml::node>& node) {
  const toml::array* a = node.as_array();
  if (!a || a->size() != 3) throw std::runtime_error("expected [x, y, z]");
  return {a->get(0)->value<double>().value(), a->get(1)->value<double>().value(), a->get(2)->value<double>().value()};
}

Pose pose_of(const toml::node_view<const toml::node>& table) {
  const Vec3 t = vec3_of(table["translation"]);
  const toml::array* q = table["quaternion"].as_array();
  if (!q || q->size() != 4) throw std::runtime_error("expected quaternion = [x, y, z, w]");
  const Quat quat(q->get(3)->value<double>().value(), q->get(0)->value<double>().value(),
                  q->get(1)->value<double>().value(), q->get(2)->value<double>().value());
  return Pose::from_quaternion(quat, t);
}

std::vector<Triangle> load_all(const fs::path& dir, const toml::array* entries) {
  std::vector<Triangle> all;
  for (const toml::node& e : *entries) {
    const fs::path file = dir / e.as_table()->get("file")->value<std::string>().value();
    auto model = import_mesh(file);
    if (!model) throw std::runtime_error(model.error().message);
    const TriangleSoup soup = model->merged();
    all.insert(all.end(), soup.triangles.begin(), soup.triangles.end());
  }
  return all;
}

/// A generated scene, read back through its problem file.
struct LoadedScene {
  scenes::SceneReport report;
  std::vector<Triangle> body, obstacles;
  Pose start, goal;
  bool goal_outside = false;
  double goal_margin = 0.0;
  double clearance = 0.0;
};

LoadedScene generate_and_load(const std::string& name) {
  const fs::path dir = temp_dir(name);
  auto report = scenes::generate_scene({.name = name, .scale = scenes::Scale::test, .output_dir = dir});
  if (!report) throw std::runtime_error(report.error().message);
  LoadedScene s;
  s.report = *report;
  const toml::table problem = toml::parse_file((dir / "problem.toml").string());
  EXPECT_EQ(problem["unit"].value_or(std::string()), "mm");
  EXPECT_EQ(problem["rotation"]["mode"].value_or(std::string()), "free");
  EXPECT_EQ(problem["planner"]["time_limit"].value_or(0.0), 60.0);
  s.clearance = problem["planner"]["clearance"].value<double>().value();
  EXPECT_GE(s.clearance, 0.5);
  EXPECT_LE(s.clearance, 1.0);
  s.obstacles = load_all(dir, problem["obstacle"].as_array());
  s.body = load_all(dir, problem["body"].as_array());
  s.start = pose_of(problem["start"]);
  s.goal_outside = problem["goal"]["outside"].value_or(false);
  if (s.goal_outside) {
    s.goal_margin = problem["goal"]["margin"].value<double>().value();
  } else {
    s.goal = pose_of(problem["goal"]);
  }
  // The bounds must contain the start and goal positions of the body frame.
  const Vec3 lo = vec3_of(problem["bounds"]["min"]), hi = vec3_of(problem["bounds"]["max"]);
  EXPECT_TRUE((s.start.translation.array() >= lo.array()).all() && (s.start.translation.array() <= hi.array()).all());
  if (!s.goal_outside) {
    EXPECT_TRUE((s.goal.translation.array() >= lo.array()).all() && (s.goal.translation.array() <= hi.array()).all());
  }
  fs::remove_all(dir);
  return s;
}

Pose translated(const Pose& p, const Vec3& d) { return {p.rotation, p.translation + d}; }

/// The 26 directions of the 3×3×3 stencil.
std::vector<Vec3> stencil_directions() {
  std::vector<Vec3> dirs;
  for (int x = -1; x <= 1; ++x)
    for (int y = -1; y <= 1; ++y)
      for (int z = -1; z <= 1; ++z)
        if (x || y || z) dirs.push_back(Vec3(x, y, z).normalized());
  return dirs;
}

/// Moving straight along `dir` from `start` hits an obstacle before the body leaves the
/// obstacles' bounding box (a collision found at a sample is a real collision).
bool straight_escape_blocked(const TriangleGrid& grid, const std::vector<Triangle>& body, const Pose& start,
                             const Vec3& dir) {
  const double step = 4.0;
  for (int i = 1;; ++i) {
    const std::vector<Triangle> w = placed(body, translated(start, step * i * dir));
    const Aabb b = bounds(w);
    if ((b.min.array() > grid.bounds().max.array()).any() || (b.max.array() < grid.bounds().min.array()).any())
      return false;
    if (collides(grid, w)) return true;
  }
}

class SceneTest : public testing::TestWithParam<std::string> {};

TEST_P(SceneTest, SameParametersGiveIdenticalBytes) {
  const fs::path a = temp_dir(GetParam() + "_a"), b = temp_dir(GetParam() + "_b");
  auto ra = scenes::generate_scene({.name = GetParam(), .scale = scenes::Scale::test, .output_dir = a});
  auto rb = scenes::generate_scene({.name = GetParam(), .scale = scenes::Scale::test, .output_dir = b});
  ASSERT_TRUE(ra.ok()) << ra.error().message;
  ASSERT_TRUE(rb.ok()) << rb.error().message;
  std::vector<std::string> names{"problem.toml"};
  for (const scenes::MeshFile& f : ra->meshes) names.push_back(f.file);
  ASSERT_EQ(ra->meshes.size(), rb->meshes.size());
  for (const std::string& n : names) {
    const std::string x = read_bytes(a / n), y = read_bytes(b / n);
    EXPECT_FALSE(x.empty()) << n;
    EXPECT_EQ(x, y) << n << " differs between two runs";
  }
  fs::remove_all(a);
  fs::remove_all(b);
}

TEST_P(SceneTest, TestScaleIsSmallCleanAndNeedsManoeuvring) {
  const LoadedScene s = generate_and_load(GetParam());
  const std::size_t total = s.body.size() + s.obstacles.size();
  EXPECT_EQ(total, s.report.body_triangles + s.report.obstacle_triangles);
  EXPECT_LT(total, 30000u);
  EXPECT_GT(s.body.size(), 1000u);
  EXPECT_GT(s.obstacles.size(), 1000u);
  // Body/obstacle proportions follow Table I (each side within 20 % of its share).
  EXPECT_NEAR(static_cast<double>(s.report.body_triangles), static_cast<double>(s.report.target_body_triangles),
              0.2 * static_cast<double>(s.report.target_body_triangles));

  const TriangleGrid grid(s.obstacles, 30.0);
  // Start pose: clear of the obstacles by more than the planner's clearance.
  const double d0 = capped_distance(grid, placed(s.body, s.start), 50.0);
  EXPECT_GT(d0, s.clearance) << "start pose too close to the obstacles";
  // The query layer agrees with the brute-force distance at the start pose.
  {
    auto body_tree = build_bvh(s.body);
    auto obstacle_tree = build_bvh(s.obstacles);
    ASSERT_TRUE(body_tree.ok() && obstacle_tree.ok());
    const DistanceResult q = distance(*body_tree, s.start, *obstacle_tree, Pose::identity());
    if (d0 < 50.0) {
      EXPECT_NEAR(q.distance, d0, 1e-9 * (1.0 + d0)) << "swept::distance disagrees with the brute force";
    } else {
      EXPECT_GE(q.distance, 50.0 - 1e-9);
    }
    EXPECT_FALSE(collide(*body_tree, s.start, *obstacle_tree, Pose::identity()).colliding);
  }
  // Goal pose (when it is a pose) clear as well.
  if (!s.goal_outside) {
    EXPECT_GT(capped_distance(grid, placed(s.body, s.goal), 50.0), s.clearance);
  }
  // No straight translation escapes: every direction of the 26-stencil is blocked.
  for (const Vec3& d : stencil_directions())
    EXPECT_TRUE(straight_escape_blocked(grid, s.body, s.start, d)) << "straight escape along " << d.transpose();
  // And, for a goal pose, the straight start → goal motion collides.
  if (!s.goal_outside) {
    const MovingBody mb = moving_body(s.body);
    bool hit = false;
    for (int i = 1; i < 400 && !hit; ++i) hit = collides(grid, placed(s.body, interpolate(s.start, s.goal, i / 400.0, mb.reference)));
    EXPECT_TRUE(hit) << "the straight start-goal motion is free";
  }
}

// A hand-made path per scene, certified free with the problem's clearance: the scene is solvable.
TEST_P(SceneTest, WitnessPathIsCertifiedFree) {
  const LoadedScene s = generate_and_load(GetParam());
  const TriangleGrid grid(s.obstacles, 30.0);
  const MovingBody mb = moving_body(s.body);
  std::vector<Pose> path{s.start};
  const auto world_box = [&](const Pose& p) { return bounds(placed(s.body, p)); };
  if (GetParam() == "air-cleaner") {
    path.push_back(translated(s.start, {0, 0, 170}));     // lift over the low front rail
    path.push_back(translated(path.back(), {0, -750, 0}));  // out through the front
  } else if (GetParam() == "cylinder-head") {
    path.push_back(translated(s.start, {0, 0, 165}));  // lift off the block
    const Pose& p1 = path.back();
    const Vec3 c = p1.apply(mb.reference);
    const Mat3 r = Eigen::AngleAxisd(std::numbers::pi / 2, Vec3::UnitX()).toRotationMatrix() * p1.rotation;
    path.push_back({r, c - r * mb.reference});  // stand it on its side
    const Aabb b = world_box(path.back());
    path.push_back(translated(path.back(), {0, -100 - b.center().y(), 0}));  // under the top slot
    path.push_back(translated(path.back(), {0, 0, grid.bounds().max.z() + s.goal_margin + 10 - b.min.z()}));
  } else {
    path.push_back(translated(s.start, {-15, 0, 0}));     // back, from under the dashboard's lip
    path.push_back(translated(path.back(), {0, 0, 388}));  // off the gear lever and the hand brake
    path.push_back(translated(path.back(), {0, -1150, 0}));  // over the seat, out of the door
    path.push_back(s.goal);
  }
  for (std::size_t i = 0; i + 1 < path.size(); ++i)
    EXPECT_TRUE(motion_free(grid, mb, path[i], path[i + 1], s.clearance)) << "witness segment " << i << " not free";
  if (s.goal_outside) {
    const Aabb b = world_box(path.back());
    const Aabb o = grid.bounds();
    const bool outside = (b.min.array() > o.max.array() + s.goal_margin).any() ||
                         (b.max.array() < o.min.array() - s.goal_margin).any();
    EXPECT_TRUE(outside) << "witness path does not end outside";
  }
}

INSTANTIATE_TEST_SUITE_P(Builtin, SceneTest, testing::Values("air-cleaner", "cylinder-head", "tunnel-console"),
                         [](const testing::TestParamInfo<std::string>& i) {
                           std::string n = i.param;
                           for (char& c : n)
                             if (c == '-') c = '_';
                           return n;
                         });

TEST(Scenes, CatalogueAndErrors) {
  const auto& cat = scenes::catalog();
  ASSERT_EQ(cat.size(), 3u);
  EXPECT_EQ(cat[0].paper_body_triangles, 1253476u);
  EXPECT_EQ(cat[2].paper_obstacle_triangles, 300567u);
  auto bad = scenes::generate_scene({.name = "no-such-scene", .output_dir = temp_dir("bad")});
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().message.find("no-such-scene"), std::string::npos);
  EXPECT_NE(bad.error().message.find("air-cleaner"), std::string::npos);
  scenes::Scale scale;
  EXPECT_TRUE(scenes::parse_scale("paper", scale));
  EXPECT_EQ(scale, scenes::Scale::paper);
  EXPECT_FALSE(scenes::parse_scale("huge", scale));
}

#ifdef SWEPT_CLI
TEST(Scenes, CliListsScenesAndRejectsUnknownNames) {
  const fs::path out = temp_dir("cli_list");
  const std::string list = out.string() + ".txt";
  ASSERT_EQ(std::system((std::string(SWEPT_CLI) + " scene --list > " + list).c_str()), 0);
  const std::string text = read_bytes(list);
  for (const scenes::SceneInfo& s : scenes::catalog()) EXPECT_NE(text.find(s.name), std::string::npos) << s.name;
  EXPECT_NE(std::system((std::string(SWEPT_CLI) + " scene no-such-scene -o " + out.string() + " 2> " + list).c_str()), 0);
  EXPECT_NE(read_bytes(list).find("unknown scene"), std::string::npos);
  EXPECT_NE(std::system((std::string(SWEPT_CLI) + " scene air-cleaner --scale huge -o " + out.string() + " 2> " + list).c_str()), 0);
  EXPECT_NE(read_bytes(list).find("unknown scale"), std::string::npos);
  fs::remove(list);
  fs::remove_all(out);
}
#endif

}  // namespace
}  // namespace swept::test
