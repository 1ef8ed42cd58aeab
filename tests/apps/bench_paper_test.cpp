// `swept bench paper` at test scale, end to end (a smoke test: every table, the JSON, the plots;
// no timing assertions).
#include "support/test_support.h"

#include "support/cli_support.h"

#include "swept/bvh/bvh.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace swept {
namespace {

namespace fs = std::filesystem;

using test::CliRun;
using test::run_cli;

std::string slurp(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

class BenchPaper : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = fs::temp_directory_path() / ("swept_bench_paper_" + std::to_string(::getpid()));
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }
  fs::path dir;
};

TEST_F(BenchPaper, TestScaleProducesEveryTableTheJsonAndThePlots) {
  const fs::path out = dir / "out";
  // Two of the three scenes keep the test under two minutes on a loaded machine (tunnel-console
  // alone plans for ~30 s of CPU over its six configurations).
  std::string args =
      "bench paper --scale test --runs 1 --poses 2 --no-ompl --only air-cleaner,cylinder-head --out " + out.string();
  const std::optional<fs::path> data = test::shared_data();
  if (data)
    args += " --data " + data->string();
  else
    args += " --no-cad";
  const CliRun r = run_cli(args);
  ASSERT_EQ(r.code, 0) << r.out;

  const auto j = nlohmann::json::parse(slurp(out / "results.json"));
  ASSERT_EQ(j["scenes"].size(), 2u);
  // Tables II and IV: every mesh, every fitter of the table under every split rule, FCL beside them.
  const std::size_t configs_per_mesh = all_fitters().size() * all_split_rules().size();
  std::size_t scene_meshes = 0, cad_meshes = 0;
  for (const auto& m : j["meshes"]) {
    const std::string kind = m["kind"];
    (kind == "cad" ? cad_meshes : scene_meshes) += 1;
    EXPECT_GT(m["triangles"].get<std::size_t>(), 0u);
    ASSERT_EQ(m["trees"].size(), configs_per_mesh) << m["name"];
    std::set<std::string> configs;
    for (const auto& t : m["trees"]) {
      configs.insert(t["fitter"].get<std::string>() + "/" + t["split"].get<std::string>());
      EXPECT_GT(t["total_surface_area_mm2"].get<double>(), 0.0);
      EXPECT_GT(t["total_volume_mm3"].get<double>(), 0.0);
      EXPECT_GE(t["nodes"].get<std::size_t>(), 1u);
      EXPECT_EQ(t["build_ms"]["samples"].size(), 1u);
    }
    EXPECT_EQ(configs.size(), configs_per_mesh);
    EXPECT_EQ(m["fcl_obbrss_build_ms"]["samples"].size(), 1u);
  }
  EXPECT_EQ(scene_meshes, 4u);  // body and obstacles of each scene
  if (data) {
    EXPECT_GE(cad_meshes, 1u);
  }
  // Table III: every scene with every configuration.
  ASSERT_EQ(j["plans"].size(), 2u * configs_per_mesh);  // 2 scenes × every fitter × every split rule
  for (const auto& p : j["plans"]) {
    EXPECT_EQ(p["statuses"].size(), 1u);
    EXPECT_GT(p["distance_queries"].get<std::uint64_t>(), 0u) << p["scene"] << " " << p["fitter"];
    if (p["fitter"] == std::string(all_fitters().front().name)) {  // the baseline of the speed-ups
      EXPECT_DOUBLE_EQ(p["speedup_vs_pqp"]["median"].get<double>(), 1.0);
    }
  }
  // Queries: 3 pose sets × (every swept tree + FCL OBBRSS + FCL RSS) per scene.
  EXPECT_EQ(j["queries"].size(), 2u * 3u * (configs_per_mesh + 2u));
  EXPECT_EQ(j["claims"].size(), 4u);
  EXPECT_TRUE(j["complete"].get<bool>());
  EXPECT_EQ(j["ompl"]["status"], "not run (--no-ompl)");

  const std::string md = slurp(out / "report.md");
  for (const char* heading : {"Table I ", "Table II ", "Table III ", "Table IV ", "query times per pose set",
                              "OMPL RRTConnect", "The paper's claims", "Command: `swept bench paper --scale test"})
    EXPECT_NE(md.find(heading), std::string::npos) << heading;
  for (const char* plot : {"paper-speedup.svg", "paper-query-distance.svg", "paper-query-collide.svg", "paper-trees.svg"}) {
    const std::string svg = slurp(out / "img" / plot);
    EXPECT_EQ(svg.rfind("<svg", 0), 0u) << plot;
    EXPECT_NE(svg.find("<rect x="), std::string::npos) << plot;
    EXPECT_NE(svg.find("</svg>"), std::string::npos) << plot;
    EXPECT_NE(md.find(std::string("img/") + plot), std::string::npos) << plot;
  }

  // --merge: a run split into processes gives back the same tables, measuring nothing.
  const fs::path merged = dir / "merged";
  const CliRun m = run_cli("bench paper --scale test --runs 1 --no-scenes --no-cad --no-ompl --merge " + out.string() +
                           " --out " + merged.string());
  ASSERT_EQ(m.code, 0) << m.out;
  const auto jm = nlohmann::json::parse(slurp(merged / "results.json"));
  EXPECT_EQ(jm["meshes"].size(), j["meshes"].size());
  ASSERT_EQ(jm["plans"].size(), j["plans"].size());
  for (std::size_t i = 0; i < j["plans"].size(); ++i) {
    EXPECT_EQ(jm["plans"][i]["cpu_ms"]["samples"], j["plans"][i]["cpu_ms"]["samples"]);
    EXPECT_EQ(jm["plans"][i]["distance_queries"], j["plans"][i]["distance_queries"]);
  }
  EXPECT_EQ(jm["queries"].size(), j["queries"].size());
  EXPECT_NE(slurp(merged / "report.md").find("merged " + (out / "results.json").string()), std::string::npos);
}

TEST_F(BenchPaper, RejectsBadOptions) {
  CliRun r = run_cli("bench paper --scale huge --out " + (dir / "x").string());
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.out.find("unknown scale 'huge'"), std::string::npos) << r.out;
  r = run_cli("bench paper --runs 0 --out " + (dir / "x").string());
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.out.find("--runs"), std::string::npos) << r.out;
  r = run_cli("bench paper --only nowhere --out " + (dir / "x").string());
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.out.find("unknown scene 'nowhere'"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace swept
