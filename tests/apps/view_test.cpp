// `swept view`: the written page (self-contained, offline, the scene data and the clearance
// samples) and, where Chromium is installed, the page rendered in a headless browser.
#include "support/test_support.h"

#include "swept/io/mesh_io.h"
#include "swept/plan/problem.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include <sys/wait.h>

namespace fs = std::filesystem;

namespace swept {
namespace {

#ifdef SWEPT_CLI

struct CommandOutput {
  int exit_code = -1;
  std::string text;  // stdout and stderr
};

CommandOutput run_command(const std::string& command) {
  CommandOutput out;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return out;
  char buffer[4096];
  while (std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) out.text.append(buffer, n);
  const int status = pclose(pipe);
  out.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return out;
}

std::string quoted(const fs::path& p) {
  std::string out = p.string();
  out.insert(out.begin(), '\'');
  out.push_back('\'');
  return out;
}

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

/// A 100 × 100 × 10 mm plate with a 30 × 30 mm square hole, and a 20 × 20 × 60 mm peg standing
/// in the hole (5 mm from each side); the path lifts the peg out, moves it aside and turns it.
struct PegScene {
  fs::path dir;
  fs::path problem;
  fs::path path;
  fs::path html;
};

PegScene write_peg_scene(const std::string& name) {
  PegScene s;
  s.dir = fs::path(SWEPT_BINARY_DIR) / "test_output" / name;
  fs::remove_all(s.dir);
  fs::create_directories(s.dir);

  TriangleSoup plate{"plate", {}};
  auto add_box = [&](Vec3 lo, Vec3 hi) {
    for (const Triangle& t : test::box_triangles(lo, hi)) plate.triangles.push_back(t);
  };
  add_box({-50, -50, 0}, {-15, 50, 10});  // the four sides of the hole
  add_box({15, -50, 0}, {50, 50, 10});
  add_box({-15, -50, 0}, {15, -15, 10});
  add_box({-15, 15, 0}, {15, 50, 10});
  const TriangleSoup peg{"peg", test::box_triangles({-10, -10, -30}, {10, 10, 30})};
  EXPECT_TRUE(write_stl_binary(s.dir / "plate.stl", plate));
  EXPECT_TRUE(write_stl_binary(s.dir / "peg.stl", peg));

  s.problem = s.dir / "peg_in_hole.toml";
  std::ofstream(s.problem) << "unit = \"mm\"\n"
                              "[[obstacle]]\nfile = \"plate.stl\"\n"
                              "[[body]]\nfile = \"peg.stl\"\n"
                              "[body_frame]\nreference_point = [0, 0, 0]\n"
                              "[start]\ntranslation = [0, 0, 5]\n"
                              "[goal]\ntranslation = [90, 0, 80]\n"
                              "[planner]\nclearance = 1.0\n";
  Path path;
  path.poses.push_back(Pose::from_translation({0, 0, 5}));
  path.poses.push_back(Pose::from_translation({0, 0, 60}));
  path.poses.push_back(Pose::from_axis_angle({1, 0, 0}, 1.5707963267948966, {90, 0, 80}));
  s.path = s.dir / "peg_in_hole.path.json";
  EXPECT_TRUE(write_path(s.path, path, "mm", Vec3::Zero()));
  s.html = s.dir / "peg_in_hole.html";
  return s;
}

/// The JSON the page carries in <script id="swept-data">.
nlohmann::json page_data(const std::string& html) {
  const std::string open = "<script id=\"swept-data\" type=\"application/json\">";
  const auto begin = html.find(open);
  if (begin == std::string::npos) return nullptr;
  const auto end = html.find("</script>", begin);
  if (end == std::string::npos) return nullptr;
  return nlohmann::json::parse(html.substr(begin + open.size(), end - begin - open.size()));
}

TEST(ViewCommand, WritesOneSelfContainedPage) {
  const PegScene s = write_peg_scene("view_page");
  const auto r = run_command(std::string(SWEPT_CLI) + " view " + quoted(s.problem) + " " + quoted(s.path) +
                             " -o " + quoted(s.html) + " --samples 200");
  ASSERT_EQ(r.exit_code, 0) << r.text;
  const std::string html = read_text(s.html);

  // Self-contained: no external scripts, styles or images; three.js inlined.
  EXPECT_EQ(html.find(" src="), std::string::npos);
  EXPECT_EQ(html.find("<link"), std::string::npos);
  EXPECT_NE(html.find("OrbitControls"), std::string::npos) << "three's OrbitControls are not bundled";
  EXPECT_EQ(html.find("<script", html.find("</script>") + 1), html.rfind("<script"))
      << "expected exactly the data script and the viewer script";

  const nlohmann::json data = page_data(html);
  ASSERT_TRUE(data.is_object());
  EXPECT_EQ(data["format"], 1);
  EXPECT_EQ(data["unit"], "mm");
  // 4 boxes of 12 triangles; 8 vertices each (the boxes touch but share no corner).
  EXPECT_EQ(data["meshes"]["obstacles"]["triangles"], 48);
  EXPECT_EQ(data["meshes"]["body"]["triangles"], 12);
  EXPECT_EQ(data["meshes"]["body"]["vertices"], 8);
  EXPECT_EQ(data["meshes"]["body"]["min"][2], -30.0);

  const auto& waypoints = data["waypoints"];
  ASSERT_EQ(waypoints.size(), 3u);
  EXPECT_EQ(waypoints[0]["s"], 0.0);
  EXPECT_EQ(waypoints[2]["s"], 1.0);
  EXPECT_GT(waypoints[1]["s"].get<double>(), 0.0);
  EXPECT_LT(waypoints[1]["s"].get<double>(), 1.0);

  // Clearance: the peg stands 5 mm from each side of the hole at the start; the samples rise
  // as it leaves, and the closest points are 'distance' apart.
  const auto& c = data["clearance"];
  ASSERT_EQ(c["s"].size(), 200u);
  ASSERT_EQ(c["distance"].size(), 200u);
  ASSERT_EQ(c["point_a"].size(), 600u);
  EXPECT_NEAR(c["distance"][0].get<double>(), 5.0, 1e-9);
  EXPECT_NEAR(c["min"].get<double>(), 5.0, 1e-9);
  EXPECT_GT(c["distance"][199].get<double>(), 20.0);
  EXPECT_EQ(c["margin"], 1.0);
  for (std::size_t k = 0; k < 200; k += 37) {
    const Vec3 a(c["point_a"][3 * k], c["point_a"][3 * k + 1], c["point_a"][3 * k + 2]);
    const Vec3 b(c["point_b"][3 * k], c["point_b"][3 * k + 1], c["point_b"][3 * k + 2]);
    EXPECT_NEAR((a - b).norm(), c["distance"][k].get<double>(), 1e-9) << "sample " << k;
    EXPECT_LE(a.z(), 10.0 + 1e-9) << "point_a must lie on the plate (sample " << k << ")";
  }
}

TEST(ViewCommand, MeshesDecodeToTheInputWithinQuantisation) {
  const fs::path source = SWEPT_SOURCE_DIR;
  if (run_command("node --version").exit_code != 0) GTEST_SKIP() << "node is not installed";
  PegScene s = write_peg_scene("view_decode");
  // Obstacles: seeded random triangles (steps of every sign and size between vertices).
  test::Rng rng(20261122);
  const TriangleSoup cloud{"cloud", test::random_triangles(rng, 3000, 200.0, 30.0, Vec3(0, 0, 150))};
  ASSERT_TRUE(write_stl_binary(s.dir / "cloud.stl", cloud));
  s.problem = s.dir / "cloud.toml";
  std::ofstream(s.problem) << "unit = \"mm\"\n[[obstacle]]\nfile = \"cloud.stl\"\n"
                              "[[body]]\nfile = \"peg.stl\"\n[start]\ntranslation = [0, 0, 5]\n"
                              "[goal]\ntranslation = [0, 0, 400]\n";
  auto r = run_command(std::string(SWEPT_CLI) + " view " + quoted(s.problem) + " " + quoted(s.path) + " -o " +
                       quoted(s.html));
  ASSERT_EQ(r.exit_code, 0) << r.text;
  r = run_command("node " + quoted(source / "tests" / "viewer" / "decode_page.mjs") + " " + quoted(s.html));
  ASSERT_EQ(r.exit_code, 0) << r.text;
  const nlohmann::json decoded = nlohmann::json::parse(r.text);

  // The STL holds float32: compare with what the importer reads back.
  auto check = [&](const char* name, const fs::path& stl) {
    auto model = import_mesh(stl);
    ASSERT_TRUE(model) << model.error().message;
    const std::vector<Triangle> expected = model->merged().triangles;
    const double step = bounds(expected).size().maxCoeff() / 65535.0;  // one quantisation step
    const auto& got = decoded[name];
    ASSERT_EQ(got.size(), expected.size()) << name;
    for (std::size_t t = 0; t < expected.size(); ++t)
      for (int k = 0; k < 3; ++k) {
        const Vec3 v(got[t][k][0].get<double>(), got[t][k][1].get<double>(), got[t][k][2].get<double>());
        ASSERT_LE((v - expected[t][k]).norm(), step) << name << " triangle " << t << " corner " << k;
      }
  };
  check("obstacles", s.dir / "cloud.stl");
  check("body", s.dir / "peg.stl");
}

TEST(ViewCommand, ReadsOmplPathsAndRejectsBadInput) {
  const PegScene s = write_peg_scene("view_errors");
  const fs::path ompl = s.dir / "lift.path";
  std::ofstream(ompl) << "0 0 5 0 0 0 1\n0 0 90 0 0 0 1\n";
  auto r = run_command(std::string(SWEPT_CLI) + " view " + quoted(s.problem) + " " + quoted(ompl) + " -o " +
                       quoted(s.html));
  EXPECT_EQ(r.exit_code, 0) << r.text;
  EXPECT_TRUE(page_data(read_text(s.html)).is_object());

  const fs::path missing = s.dir / "no_such.path";
  r = run_command(std::string(SWEPT_CLI) + " view " + quoted(s.problem) + " " + quoted(missing) + " -o " +
                  quoted(s.html));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.text.find("no_such.path"), std::string::npos) << r.text;

  const fs::path bad = s.dir / "bad.path";
  std::ofstream(bad) << "0 0 5 0 0 0 1\n0 0 nan 0 0 0 1\n";
  r = run_command(std::string(SWEPT_CLI) + " view " + quoted(s.problem) + " " + quoted(bad) + " -o " +
                  quoted(s.html));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.text.find("bad.path:2"), std::string::npos) << r.text;
}

TEST(ViewCommand, RendersInHeadlessChromiumAndTheBodyMoves) {
  const fs::path chromium = "/usr/bin/chromium";
  const fs::path source = SWEPT_SOURCE_DIR;
  if (!fs::exists(chromium)) GTEST_SKIP() << "no Chromium at " << chromium << " (apt-get install chromium)";
  if (run_command("node --version").exit_code != 0) GTEST_SKIP() << "node is not installed";
  if (!fs::exists(source / "viewer" / "node_modules" / "playwright-core"))
    GTEST_SKIP() << "viewer/node_modules/playwright-core is missing (npm ci in viewer/)";

  const PegScene s = write_peg_scene("view_browser");
  auto r = run_command(std::string(SWEPT_CLI) + " view " + quoted(s.problem) + " " + quoted(s.path) + " -o " +
                       quoted(s.html));
  ASSERT_EQ(r.exit_code, 0) << r.text;
  r = run_command("node " + quoted(source / "tests" / "viewer" / "view_screenshots.mjs") + " " + quoted(s.html) +
                  " " + quoted(s.dir) + " --play-seconds 2");
  EXPECT_EQ(r.exit_code, 0) << r.text;
  EXPECT_TRUE(fs::exists(s.dir / "peg_in_hole-start.png")) << r.text;
  EXPECT_TRUE(fs::exists(s.dir / "peg_in_hole-end.png")) << r.text;
  std::cout << r.text;
}

#else

TEST(ViewCommand, NeedsTheCli) { GTEST_SKIP() << "the swept CLI is not built (SWEPT_BUILD_APPS=OFF)"; }

#endif

}  // namespace
}  // namespace swept
