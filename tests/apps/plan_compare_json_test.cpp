// bench_plan's JSON, written by to_json() and read back by rows_from_json() for `swept bench
// paper` (bench/lib: plan_compare_rows.cpp): the figures the paper benchmark reports survive.
#include "swept/bench/plan_compare.h"
#include "swept/bench/timing.h"

#include <gtest/gtest.h>

#include <cmath>

namespace swept::bench {
namespace {

CompareRow row() {
  CompareRow r;
  r.name = "t_slot";
  r.kind = "box";
  r.clearance = 0.05;
  r.rotation = "free";
  r.body_triangles = 24;
  r.obstacle_triangles = 36;
  for (const FitterInfo& f : all_fitters()) {
    SweptRun s;
    s.fitter = f.fitter;
    s.plan_ms = 10.0 + static_cast<double>(s.fitter == Fitter::inertia);
    s.build_ms = 0.5;
    s.result.status = s.fitter == Fitter::pqp ? PlanStatus::no_path_time : PlanStatus::solved;
    r.swept.push_back(s);
  }
  r.deterministic = true;
  r.main_ms = {11.0, 12.0};
  r.ompl_fcl_build_ms = 3.5;
  for (std::uint32_t seed = 1; seed <= 3; ++seed)
    r.ompl.push_back({.seed = seed, .solved = seed != 2, .ms = 100.0 * seed, .status = "Exact solution",
                      .waypoints = 5, .checks = 1000, .verified = seed == 3 ? "collides" : "free",
                      .simplify_ms = seed == 1 ? 150.0 : seed == 3 ? 90.0 : 0.0,
                      .simplified_verified = seed == 1 ? "collides" : seed == 3 ? "free" : "",
                      .length = seed == 2 ? 0.0 : 7.0 * seed, .simplified_length = seed == 2 ? 0.0 : 5.0 * seed});
  return r;
}

TEST(PlanCompareJson, RowsReadBack) {
  CompareRow failed;
  failed.name = "air-cleaner";
  failed.kind = "cad";
  failed.error = "no such file";
  const std::vector<CompareRow> rows{row(), failed};
  const CompareOptions o{.time_limit = 10, .seeds = 3, .threads = 2};
  const auto back = rows_from_json(nlohmann::json::parse(to_json(rows, o).dump()));
  ASSERT_EQ(back.size(), 2u);
  const CompareRow& r = back[0];
  EXPECT_EQ(r.name, "t_slot");
  EXPECT_TRUE(r.error.empty());
  ASSERT_EQ(r.swept.size(), all_fitters().size());
  for (std::size_t i = 0; i < r.swept.size(); ++i) {
    EXPECT_EQ(r.swept[i].fitter, rows[0].swept[i].fitter);
    EXPECT_EQ(r.swept[i].plan_ms, rows[0].swept[i].plan_ms);
    EXPECT_EQ(r.swept[i].result.status, rows[0].swept[i].result.status);
  }
  EXPECT_EQ(r.ompl_successes(), 2);
  EXPECT_EQ(r.ompl_colliding(), 1);
  EXPECT_EQ(r.ompl_median(), 200.0);
  // Solve + simplify per seed: 250, 200 (not solved: nothing to simplify), 390.
  EXPECT_EQ(r.ompl_median_with_simplify(), 250.0);
  EXPECT_EQ(r.ompl_simplified_colliding(), 1);
  EXPECT_EQ(r.ompl[2].simplify_ms, 90.0);
  EXPECT_EQ(r.ompl[0].simplified_verified, "collides");
  EXPECT_EQ(r.ompl[2].length, 21.0);
  EXPECT_EQ(r.ompl[2].simplified_length, 15.0);
  EXPECT_EQ(r.ompl_fcl_build_ms, 3.5);
  EXPECT_EQ(r.swept_median(), 11.5);
  EXPECT_EQ(r.verdict(), rows[0].verdict());
  EXPECT_EQ(back[1].error, "no such file");
  EXPECT_EQ(back[1].verdict(), "not run");
}

TEST(PlanCompareJson, TheRunAtOneThreadIsPrintedWithItsShareOfTheMedian) {
  CompareRow r = row();
  r.one_thread_status = r.main().result.status;
  r.one_thread_hash = r.main().result.path_hash;
  r.one_thread_ms = 23.0;  // the median of 11 and 12 is 11.5: 23 / 11.5 = 2
  testing::internal::CaptureStdout();
  print_tables({r}, {.time_limit = 10, .seeds = 3, .threads = 2});
  const std::string out = testing::internal::GetCapturedStdout();
  EXPECT_NE(out.find("1 thread: yes (23.0 ms, 2.00x the median)"), std::string::npos) << out;

  r.one_thread_hash += 1;  // another path at one thread
  testing::internal::CaptureStdout();
  print_tables({r}, {.time_limit = 10, .seeds = 3, .threads = 2});
  EXPECT_NE(testing::internal::GetCapturedStdout().find("1 thread: NO (23.0 ms"), std::string::npos);
}

TEST(PlanCompareJson, SeedRunsReadBackAndTheirMedianCountsSeedZero) {
  CompareRow r = row();
  r.swept[0].result.status = PlanStatus::solved;  // seed 0, the main run
  r.swept[0].result.path_hash = 0xabc;
  r.path_checked = true;
  // Seed 0's median is 11.5 (runs 11 and 12); seeds 1-3 took 40, 9 and 30 ms (seed 3 found no
  // path): the median of 11.5, 40, 9, 30 is (11.5 + 30) / 2 = 20.75.
  r.seed_runs = {{.seed = 1, .status = PlanStatus::solved, .ms = 40.0, .path_hash = 0x1, .checked = true},
                 {.seed = 2, .status = PlanStatus::solved, .ms = 9.0, .path_hash = 0xabc, .checked = true},
                 {.seed = 3, .status = PlanStatus::no_path_time, .ms = 30.0, .path_hash = 0, .checked = std::nullopt}};
  EXPECT_EQ(r.swept_seeds_median(), 20.75);
  EXPECT_EQ(r.swept_seeds_solved(), 3);
  const CompareOptions o{.time_limit = 10, .seeds = 4, .threads = 2, .swept_seeds = true};
  const nlohmann::json j = to_json({r}, o);
  EXPECT_EQ(j["problems"][0]["swept_seeds_median_ms"], 20.75);
  EXPECT_EQ(j["problems"][0]["ratio_ompl_median_over_swept_seeds"], 200.0 / 20.75);
  const auto back = rows_from_json(nlohmann::json::parse(j.dump()));
  ASSERT_EQ(back[0].seed_runs.size(), 3u);
  EXPECT_EQ(back[0].seed_runs[2].status, PlanStatus::no_path_time);
  EXPECT_FALSE(back[0].seed_runs[2].checked);
  EXPECT_EQ(back[0].seed_runs[0].path_hash, 0x1u);
  EXPECT_EQ(back[0].swept_seeds_median(), 20.75);
  // The table: 3 of 4 solved, the median, the range, and seed 2's path is seed 0's (2 distinct).
  testing::internal::CaptureStdout();
  print_tables({r}, o);
  const std::string out = testing::internal::GetCapturedStdout();
  EXPECT_NE(out.find("3/4"), std::string::npos) << out;
  EXPECT_NE(out.find("20.8"), std::string::npos) << out;
  EXPECT_NE(out.find("9.0-40.0"), std::string::npos) << out;
  EXPECT_NE(out.find("2 distinct, 3 valid"), std::string::npos) << out;
  EXPECT_TRUE(std::isnan(row().swept_seeds_median()));  // no seed runs
  // The goal over seeds: seed 3 found no path while OMPL solved the problem.
  EXPECT_EQ(r.seeds_verdict(), "MISSED: a seed without a path");
  EXPECT_EQ(j["problems"][0]["goal_over_seeds"], "MISSED: a seed without a path");
  r.seed_runs[2].status = PlanStatus::solved;  // every seed solved: 200 / 20.75 = 9.6 >= 3
  EXPECT_EQ(r.seeds_verdict(), "met: >= 3x");
  r.seed_runs[0].ms = r.seed_runs[2].ms = 90.0;  // 11.5, 90, 9, 90: median 50.75, 200 / 50.75 = 3.94x
  EXPECT_EQ(r.seeds_verdict(), "met: >= 3x");
  r.seed_runs[1].ms = 95.0;  // 11.5, 90, 95, 90: median 90, 200 / 90 = 2.2x
  EXPECT_EQ(r.seeds_verdict(), "MISSED: < 3x");
  EXPECT_EQ(row().seeds_verdict(), "");
}

TEST(PlanCompareJson, SearchPhaseMediansBesideTheWholePlanAndOverSeeds) {
  CompareRow r = row();
  // swept ms: the median of 11 and 12 is 11.5; the search phases of three runs 7, 8 and 6 ms:
  // median 7, 61 % of 11.5. OMPL's median is 200 ms (100, 200 at the limit, 300): 200 / 7.
  r.main_search_ms = {7.0, 8.0, 6.0};
  EXPECT_EQ(r.swept_search_median(), 7.0);
  // Seeds 1-3 searched 20, 5 and 9 ms: with seed 0's 7, the median of 7, 20, 5, 9 is 8.
  r.seed_runs = {{.seed = 1, .status = PlanStatus::solved, .ms = 40.0, .search_ms = 20.0},
                 {.seed = 2, .status = PlanStatus::solved, .ms = 9.0, .search_ms = 5.0},
                 {.seed = 3, .status = PlanStatus::solved, .ms = 30.0, .search_ms = 9.0}};
  EXPECT_EQ(r.swept_seeds_search_median(), 8.0);
  const CompareOptions o{.time_limit = 10, .seeds = 4, .threads = 2, .swept_seeds = true};
  const nlohmann::json j = to_json({r}, o);
  EXPECT_EQ(j["problems"][0]["swept_search_median_ms"], 7.0);
  EXPECT_EQ(j["problems"][0]["ratio_ompl_median_over_swept_search"], 200.0 / 7.0);
  EXPECT_EQ(j["problems"][0]["swept_seeds_search_median_ms"], 8.0);
  EXPECT_EQ(j["problems"][0]["ratio_ompl_median_over_swept_seeds_search"], 25.0);
  const auto back = rows_from_json(nlohmann::json::parse(j.dump()));
  EXPECT_EQ(back[0].main_search_ms, r.main_search_ms);
  EXPECT_EQ(back[0].seed_runs[1].search_ms, 5.0);
  EXPECT_EQ(back[0].swept_seeds_search_median(), 8.0);
  testing::internal::CaptureStdout();
  print_tables({r}, o);
  const std::string out = testing::internal::GetCapturedStdout();
  const std::size_t at = out.find("To the first path");
  ASSERT_NE(at, std::string::npos) << out;
  const std::string line = out.substr(out.find("t_slot", at), out.find('\n', out.find("t_slot", at)) - out.find("t_slot", at));
  EXPECT_NE(line.find(" 7.0 "), std::string::npos) << line;
  EXPECT_NE(line.find(" 61% "), std::string::npos) << line;
  EXPECT_NE(line.find(" 28.57 "), std::string::npos) << line;
  EXPECT_NE(line.find(" 8.0 "), std::string::npos) << line;
  EXPECT_NE(line.find(" 25.00"), std::string::npos) << line;

  // A JSON written before the search phases were kept: no figures, and no table.
  nlohmann::json old = j;
  old["problems"][0].erase("swept_main_search_runs_ms");
  for (auto& s : old["problems"][0]["swept_seed_runs"]) s.erase("search_ms");
  const auto before = rows_from_json(old);
  EXPECT_TRUE(std::isnan(before[0].swept_search_median()));
  EXPECT_TRUE(std::isnan(before[0].swept_seeds_search_median()));
  testing::internal::CaptureStdout();
  print_tables(before, o);
  EXPECT_EQ(testing::internal::GetCapturedStdout().find("To the first path"), std::string::npos);
}

TEST(PlanCompareJson, StatusWordsReadBack) {
  for (const PlanStatus s : {PlanStatus::solved, PlanStatus::no_path_time, PlanStatus::no_path_budget, PlanStatus::no_path_bounds,
                             PlanStatus::no_path_resolution, PlanStatus::invalid_start, PlanStatus::invalid_goal,
                             PlanStatus::invalid_bounds})
    EXPECT_EQ(status_named(status_name(s)), s) << status_name(s);
  EXPECT_EQ(status_named("no path (time)"), PlanStatus::no_path_time);  // bench_plan before 2026-11-24
  EXPECT_FALSE(status_named("solved!"));
}

}  // namespace
}  // namespace swept::bench
