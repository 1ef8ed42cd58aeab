// `swept bvh` end to end: the table, the JSON document, and errors for bad input.
#include "swept/io/mesh_io.h"

#include "support/cli_support.h"

#include "swept/bvh/bvh.h"

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

int run_cli(const std::string& args, std::string& out) {
  const test::CliRun r = test::run_cli(args);
  out = r.out;
  return r.code;
}

// What reading a file leaves out is said: `swept bvh` and `swept mesh-stats` print each import
// warning on stderr ("swept: warning: ...") and list them in --json. An OBJ whose first object
// holds points and a line only: that part is left out, the square is read.
TEST(BvhCli, ImportWarningsOnStderrAndInJson) {
  const fs::path dir = fs::temp_directory_path() / ("swept_bvh_warn_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path obj = dir / "marked.obj";
  std::ofstream(obj) << "o marks\nv 0 0 0\nv 1 0 0\np 1\nl 1 2\no square\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\nf 3 4 5 6\n";
  const std::string warning = obj.string() + ": part 'marks' has no triangles";
  for (const std::string command : {"bvh ", "mesh-stats "}) {
    const test::CliRun text = test::run_cli(command + obj.string(), /*with_stderr=*/true);
    ASSERT_EQ(text.code, 0) << command << text.out;
    EXPECT_NE(text.out.find("swept: warning: " + warning), std::string::npos) << command << text.out;
    const test::CliRun json = test::run_cli(command + "--json " + obj.string(), /*with_stderr=*/false);
    ASSERT_EQ(json.code, 0) << command << json.out;
    const auto doc = nlohmann::json::parse(json.out);
    ASSERT_EQ(doc.at("meshes").size(), 1u) << command;
    EXPECT_EQ(doc["meshes"][0].at("triangles").get<std::size_t>(), 2u) << command;
    ASSERT_EQ(doc["meshes"][0].at("warnings").size(), 1u) << command;
    EXPECT_EQ(doc["meshes"][0]["warnings"][0].get<std::string>().rfind(warning, 0), 0u) << command;
  }
  fs::remove_all(dir);
}

// `--json` prints one document and nothing else, whichever reader ran: OpenCASCADE's IGES
// reader wrote "Total number of loaded entities" (in colour) to stdout, before the document.
TEST(BvhCli, JsonOfCadFilesIsTheWholeOutput) {
  for (const char* name : {"box.igs", "box.brep", "box_mm.step", "assembly.step"}) {
    const fs::path file = fs::path(SWEPT_SOURCE_DIR) / "tests" / "data" / "io" / name;
    for (const std::string command : {"bvh --json ", "mesh-stats --json "}) {
      const test::CliRun r = test::run_cli(command + file.string(), /*with_stderr=*/false);
      ASSERT_EQ(r.code, 0) << command << name << "\n" << r.out;
      EXPECT_EQ(r.out.rfind("{", 0), 0u) << command << name << " printed before its document:\n" << r.out;
      EXPECT_FALSE(nlohmann::json::parse(r.out, nullptr, false).is_discarded()) << command << name << "\n" << r.out;
    }
  }
}

TEST(BvhCli, JsonForEveryFitterAndSplit) {
  const fs::path dir = fs::temp_directory_path() / ("swept_bvh_cli_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  TriangleSoup soup;
  for (int i = 0; i < 50; ++i) {
    const double x = i;
    soup.triangles.push_back({Vec3(x, 0, 0), Vec3(x + 1, 0, 0), Vec3(x, 1, 0.1 * i)});
  }
  ASSERT_TRUE(write_stl_binary(dir / "strip.stl", soup));
  std::string out;
  ASSERT_EQ(run_cli("bvh " + (dir / "strip.stl").string() + " --fitter all --split all --json", out), 0) << out;
  const auto doc = nlohmann::json::parse(out);
  ASSERT_EQ(doc["meshes"].size(), 1u);
  const auto& m = doc["meshes"][0];
  EXPECT_EQ(m["triangles"].get<int>(), 50);
  ASSERT_EQ(m["fitters"].size(), all_fitters().size() * all_split_rules().size());
  for (const auto& f : m["fitters"]) {
    for (const char* key : {"fitter", "split", "nodes", "depth", "total_surface_area", "total_volume", "build_ms", "bytes"})
      EXPECT_TRUE(f.contains(key)) << key;
    EXPECT_EQ(f["nodes"].get<int>(), 99);
    EXPECT_GT(f["total_surface_area"].get<double>(), 0.0);
  }
  // The aligned table names every fitter.
  ASSERT_EQ(run_cli("bvh " + (dir / "strip.stl").string() + " --fitter all", out), 0);
  for (const FitterInfo& f : all_fitters()) EXPECT_NE(out.find(f.name), std::string::npos) << f.name;
  EXPECT_NE(out.find("total SA"), std::string::npos);
  // Bad input: a missing file, an unknown fitter.
  EXPECT_NE(run_cli("bvh " + (dir / "none.stl").string(), out), 0);
  EXPECT_NE(run_cli("bvh " + (dir / "strip.stl").string() + " --fitter best", out), 0);
  EXPECT_NE(out.find("best"), std::string::npos) << out;
  EXPECT_NE(out.find(fitter_names()), std::string::npos) << out;  // the error lists the table's names
  std::ofstream(dir / "empty.stl") << "";
  EXPECT_EQ(run_cli("bvh " + (dir / "empty.stl").string(), out), 1);
  EXPECT_NE(out.find("empty.stl"), std::string::npos) << out;
  fs::remove_all(dir);
}

// The memory a tree reports is what it holds: nodes, triangles, their input indices and the struct,
// counted here from the layout (50 triangles: 99 nodes at one triangle per leaf; one leaf of all
// 50 at leaf size 50), and per triangle. Triangles are three indices into shared vertices: the
// strip's triangle i has corners (i, 0, 0), (i + 1, 0, 0) and (i, 1, i / 10), so its 150 corners
// are 51 points on the x axis and 50 others: 101 vertices.
TEST(BvhCli, MemoryPerTriangleAtEachLeafSize) {
  const fs::path dir = fs::temp_directory_path() / ("swept_bvh_cli_mem_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  TriangleSoup soup;
  for (int i = 0; i < 50; ++i) soup.triangles.push_back({Vec3(i, 0, 0), Vec3(i + 1, 0, 0), Vec3(i, 1, 0.1 * i)});
  ASSERT_TRUE(write_stl_binary(dir / "strip.stl", soup));
  const std::size_t per_triangle = 3 * sizeof(std::uint32_t) + sizeof(std::uint32_t);
  const std::size_t vertices = 101 * sizeof(Vec3);
  for (const auto& [leaf, nodes] : std::array<std::pair<int, std::size_t>, 2>{{{1, 99}, {50, 1}}}) {
    std::string out;
    ASSERT_EQ(run_cli("bvh " + (dir / "strip.stl").string() + " --leaf-size " + std::to_string(leaf) + " --json", out), 0) << out;
    const auto doc = nlohmann::json::parse(out);
    const auto& f = doc["meshes"][0]["fitters"][0];
    EXPECT_EQ(f["leaf_size"].get<int>(), leaf);
    EXPECT_EQ(f["nodes"].get<std::size_t>(), nodes);
    const std::size_t bytes = nodes * sizeof(Node) + 50 * per_triangle + vertices + sizeof(Bvh);
    EXPECT_EQ(f["bytes"].get<std::size_t>(), bytes);
    EXPECT_DOUBLE_EQ(f["bytes_per_triangle"].get<double>(), static_cast<double>(bytes) / 50.0);
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace swept
