// `swept mesh-stats` and scenes::mesh_stats(): hand-computed figures, and the CLI on a
// generated STL.
#include "swept/io/mesh_io.h"
#include "swept/scenes/mesh_stats.h"
#include "swept/scenes/scenes.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <unistd.h>

namespace swept::test {
namespace {

namespace fs = std::filesystem;

TEST(MeshStats, HandComputedFigures) {
  const double h = std::sqrt(3.0) / 2.0;
  std::vector<Triangle> tris{
      {{0, 0, 0}, {1, 0, 0}, {0.5, h, 0}},       // equilateral: area √3/4, aspect 1/h = 2/√3
      {{0, 0, 0}, {20, 0, 0}, {0, 1, 0}},        // right triangle: area 10; longest edge √401
      {{0, 0, 0}, {4, 0, 0}, {0, 2, 0}},         // area 4; aspect √20 / (8/√20) = 20/8
      {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}},         // collinear: degenerate
      {{5, 5, 5}, {5, 5, 5}, {5, 5, 5}},         // a point: degenerate
  };
  const scenes::MeshStats s = scenes::mesh_stats(tris);
  EXPECT_EQ(s.triangles, 5u);
  EXPECT_EQ(s.degenerate, 2u);
  EXPECT_NEAR(s.area_min, std::sqrt(3.0) / 4.0, 1e-12);
  EXPECT_NEAR(s.area_max, 10.0, 1e-12);
  EXPECT_NEAR(s.area_ratio, 10.0 / (std::sqrt(3.0) / 4.0), 1e-9);
  const double a_right = 401.0 / 20.0;  // l / (2A / l) = l² / 2A
  EXPECT_NEAR(s.aspect_max, a_right, 1e-9);
  EXPECT_NEAR(s.aspect_median, 20.0 / 8.0, 1e-12);  // of {1.1547, 2.5, 20.05}
  EXPECT_NEAR(s.aspect_over_10, 1.0 / 3.0, 1e-12);

  const scenes::MeshStats empty = scenes::mesh_stats({});
  EXPECT_EQ(empty.triangles, 0u);
  EXPECT_EQ(empty.area_ratio, 0.0);
  const scenes::MeshStats only_bad = scenes::mesh_stats({tris[3], tris[4]});
  EXPECT_EQ(only_bad.degenerate, 2u);
  EXPECT_EQ(only_bad.aspect_median, 0.0);
  EXPECT_TRUE(std::isfinite(only_bad.area_ratio));
}

#ifdef SWEPT_CLI
std::string run(const std::string& command) {
  std::string out;
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  if (!pipe) return out;
  std::array<char, 4096> buf;
  while (std::fgets(buf.data(), buf.size(), pipe.get())) out += buf.data();
  return out;
}

// The number after "key": in the CLI's JSON output.
double json_number(const std::string& json, const std::string& key) {
  const std::size_t at = json.find("\"" + key + "\":");
  if (at == std::string::npos) return std::nan("");
  return std::stod(json.substr(at + key.size() + 3));
}

TEST(MeshStats, CliOnGeneratedSceneStl) {
  const fs::path dir = fs::temp_directory_path() / ("swept_mesh_stats_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  auto report = scenes::generate_scene({.name = "tunnel-console", .scale = scenes::Scale::test, .output_dir = dir});
  ASSERT_TRUE(report.ok()) << report.error().message;
  const fs::path stl = dir / "console.stl";
  auto model = import_mesh(stl);
  ASSERT_TRUE(model.ok()) << model.error().message;
  const scenes::MeshStats expected = scenes::mesh_stats(model->merged().triangles);
  EXPECT_EQ(expected.triangles, report->meshes.front().triangles);
  // CAD tessellations spread: large/small area ratio far above 1, many slivers.
  EXPECT_GT(expected.area_ratio, 100.0);
  EXPECT_GT(expected.aspect_over_10, 0.01);

  const std::string json = run(std::string(SWEPT_CLI) + " mesh-stats --json " + stl.string());
  EXPECT_EQ(json_number(json, "triangles"), static_cast<double>(expected.triangles));
  EXPECT_EQ(json_number(json, "degenerate_triangles"), static_cast<double>(expected.degenerate));
  EXPECT_NEAR(json_number(json, "area_ratio"), expected.area_ratio, 1e-9 * expected.area_ratio);
  EXPECT_NEAR(json_number(json, "aspect_ratio_median"), expected.aspect_median, 1e-9 * expected.aspect_median);
  EXPECT_NEAR(json_number(json, "aspect_ratio_over_10_fraction"), expected.aspect_over_10, 1e-12);

  const std::string table = run(std::string(SWEPT_CLI) + " mesh-stats " + stl.string());
  EXPECT_NE(table.find("median aspect"), std::string::npos);
  EXPECT_NE(table.find(std::to_string(expected.triangles)), std::string::npos);
  // A missing file is an error, exit code 1 or CLI11's.
  EXPECT_NE(std::system((std::string(SWEPT_CLI) + " mesh-stats " + (dir / "missing.stl").string() + " 2>/dev/null").c_str()), 0);
  fs::remove_all(dir);
}
#endif

}  // namespace
}  // namespace swept::test
