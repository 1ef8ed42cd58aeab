// bench_plan's results: the rows' figures, and their JSON written by bench_plan and read back by
// `swept bench paper` (the one place that knows the keys).
#include "swept/bench/plan_compare.h"

#include "swept/bench/timing.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <thread>

namespace swept::bench {
namespace {

/// Median of a sample (the mean of the middle two for an even count); 0 for none.
double median(std::vector<double> t) {
  if (t.empty()) return 0.0;
  std::sort(t.begin(), t.end());
  const std::size_t n = t.size();
  return n % 2 ? t[n / 2] : 0.5 * (t[n / 2 - 1] + t[n / 2]);
}

}  // namespace

double CompareRow::swept_median() const { return main_ms.empty() ? main().plan_ms : median(main_ms); }

namespace {

/// Median of seed 0's figure and one field of every seed run; NaN without seed runs or without
/// seed 0's figure (NaN).
double over_seeds(double seed_zero, const std::vector<SeedRun>& runs, double SeedRun::*field) {
  if (runs.empty() || std::isnan(seed_zero)) return std::numeric_limits<double>::quiet_NaN();
  std::vector<double> t{seed_zero};
  for (const SeedRun& s : runs) t.push_back(s.*field);
  return median(std::move(t));
}

}  // namespace

double CompareRow::swept_seeds_median() const { return over_seeds(swept_median(), seed_runs, &SeedRun::ms); }

double CompareRow::swept_search_median() const {
  return main_search_ms.empty() ? std::numeric_limits<double>::quiet_NaN() : median(main_search_ms);
}

double CompareRow::swept_seeds_search_median() const {
  return over_seeds(swept_search_median(), seed_runs, &SeedRun::search_ms);
}

int CompareRow::swept_seeds_solved() const {
  return static_cast<int>(main().result.solved()) +
         static_cast<int>(std::count_if(seed_runs.begin(), seed_runs.end(), [](const SeedRun& s) { return s.status == PlanStatus::solved; }));
}

bool CompareRow::one_thread_same() const {
  return one_thread_status && !swept.empty() && *one_thread_status == main().result.status &&
         one_thread_hash == main().result.path_hash;
}

int CompareRow::ompl_colliding() const {
  return static_cast<int>(std::count_if(ompl.begin(), ompl.end(), [](const OmplRun& r) { return r.verified == "collides"; }));
}

int CompareRow::ompl_simplified_colliding() const {
  return static_cast<int>(
      std::count_if(ompl.begin(), ompl.end(), [](const OmplRun& r) { return r.simplified_verified == "collides"; }));
}

int CompareRow::ompl_successes() const {
  return static_cast<int>(std::count_if(ompl.begin(), ompl.end(), [](const OmplRun& r) { return r.solved; }));
}

double CompareRow::ompl_median() const {
  std::vector<double> t;
  for (const auto& r : ompl) t.push_back(r.ms);
  return median(std::move(t));
}

double CompareRow::ompl_median_with_simplify() const {
  std::vector<double> t;
  for (const auto& r : ompl) t.push_back(r.ms + r.simplify_ms);
  return median(std::move(t));
}

double CompareRow::ompl_min() const {
  double m = std::numeric_limits<double>::infinity();
  for (const auto& r : ompl) m = std::min(m, r.ms);
  return m;
}

double CompareRow::ompl_max() const {
  double m = 0.0;
  for (const auto& r : ompl) m = std::max(m, r.ms);
  return m;
}

std::string CompareRow::seeds_verdict() const {
  if (!error.empty() || seed_runs.empty()) return "";
  const bool every = swept_seeds_solved() == static_cast<int>(seed_runs.size()) + 1;
  if (ompl_successes() == 0) return every ? "met: OMPL 0 %" : "a seed without a path";
  if (!every) return "MISSED: a seed without a path";
  return ompl_median() / std::max(swept_seeds_median(), 1e-9) >= 3.0 ? "met: >= 3x" : "MISSED: < 3x";
}

std::string CompareRow::verdict() const {
  if (!error.empty()) return "not run";
  const bool ours = main().result.solved();
  const int theirs = ompl_successes();
  const double ratio = ompl_median() / std::max(swept_median(), 1e-9);
  if (!ours && theirs == 0) {
    const PlanStatus s = main().result.status;
    if (s == PlanStatus::no_path_bounds || s == PlanStatus::no_path_resolution) return "neither (swept: no path)";
    return "neither solved";
  }
  if (!ours) return "MISSED: OMPL solves it";
  if (theirs == 0) return "met: OMPL 0 %";
  return ratio >= 3.0 ? "met: >= 3x" : "MISSED: < 3x";
}

nlohmann::json to_json(const std::vector<CompareRow>& rows, const CompareOptions& o) {
  const double limit = o.time_limit;
  const int seeds = o.seeds, threads = o.threads;
  const bool collide_only = o.collide_only;
  nlohmann::json j;
  j["time_limit_s"] = limit;
  j["seeds"] = seeds;
  j["swept_threads"] = threads;
  j["ompl_collide_only"] = collide_only;
  j["hardware_threads"] = std::thread::hardware_concurrency();
  for (const CompareRow& r : rows) {
    nlohmann::json p;
    p["name"] = r.name;
    p["kind"] = r.kind;
    if (!r.error.empty()) {
      p["error"] = r.error;
      j["problems"].push_back(p);
      continue;
    }
    p["clearance"] = r.clearance;
    p["rotation"] = r.rotation;
    p["body_triangles"] = r.body_triangles;
    p["obstacle_triangles"] = r.obstacle_triangles;
    for (const SweptRun& s : r.swept) {
      char hash[32];
      std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(s.result.path_hash));
      p["swept"].push_back({{"fitter", std::string(to_string(s.fitter))},
                            {"status", std::string(status_name(s.result.status))},
                            {"message", s.result.message},
                            {"plan_ms", s.plan_ms},
                            {"build_ms", s.build_ms},
                            {"result_total_ms", s.result.time_ms.total},
                            {"result_total_minus_build_ms", s.result.time_ms.total - s.result.time_ms.build},
                            {"search_ms", s.result.time_ms.search},
                            {"smooth_ms", s.result.time_ms.smooth},
                            {"waypoints", s.result.path.poses.size()},
                            {"path_length", s.result.path_length},
                            {"min_clearance", s.result.min_clearance},
                            {"distance_queries", s.result.queries.distance},
                            {"nodes_checked", s.result.nodes_checked},
                            {"level", s.result.level},
                            {"path_hash", hash}});
    }
    p["swept_deterministic"] = r.deterministic;
    p["swept_time_limit_s"] = r.swept_time_limit;
    if (r.path_checked) p["swept_path_checked"] = *r.path_checked;
    if (r.one_thread_status) {
      char one[32];
      std::snprintf(one, sizeof one, "%016llx", static_cast<unsigned long long>(r.one_thread_hash));
      p["swept_one_thread"] = {{"status", std::string(status_name(*r.one_thread_status))},
                               {"path_hash", one},
                               {"plan_ms", r.one_thread_ms},
                               {"same_path", r.one_thread_same()}};
    }
    p["swept_main_runs_ms"] = r.main_ms;
    p["swept_median_ms"] = r.swept_median();
    if (!r.main_search_ms.empty()) {
      p["swept_main_search_runs_ms"] = r.main_search_ms;
      p["swept_search_median_ms"] = r.swept_search_median();
    }
    if (!r.seed_runs.empty()) {
      for (const SeedRun& s : r.seed_runs) {
        char hash[32];
        std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(s.path_hash));
        p["swept_seed_runs"].push_back({{"seed", s.seed},
                                        {"status", std::string(status_name(s.status))},
                                        {"plan_ms", s.ms},
                                        {"path_hash", hash},
                                        {"path_checked", s.checked ? nlohmann::json(*s.checked) : nlohmann::json(nullptr)},
                                        {"search_ms", s.search_ms}});
      }
      p["swept_seeds_solved"] = r.swept_seeds_solved();
      p["swept_seeds_median_ms"] = r.swept_seeds_median();
      if (!r.main_search_ms.empty()) p["swept_seeds_search_median_ms"] = r.swept_seeds_search_median();
    }
    p["ompl_fcl_build_ms"] = r.ompl_fcl_build_ms;
    for (const OmplRun& o : r.ompl)
      p["ompl"].push_back({{"seed", o.seed},
                           {"solved", o.solved},
                           {"status", o.status},
                           {"ms", o.ms},
                           {"waypoints", o.waypoints},
                           {"path_verified", o.verified},
                           {"validity_checks", o.checks},
                           {"simplify_ms", o.simplify_ms},
                           {"simplified_path_verified", o.simplified_verified},
                           {"path_length", o.length},
                           {"simplified_path_length", o.simplified_length}});
    p["ompl_successes"] = r.ompl_successes();
    p["ompl_paths_colliding"] = r.ompl_colliding();
    p["ompl_median_ms"] = r.ompl_median();
    p["ompl_simplified_paths_colliding"] = r.ompl_simplified_colliding();
    p["ompl_median_with_simplify_ms"] = r.ompl_median_with_simplify();
    p["ratio_ompl_median_over_swept"] = r.ompl_median() / std::max(r.swept_median(), 1e-9);
    p["ratio_ompl_median_with_simplify_over_swept"] = r.ompl_median_with_simplify() / std::max(r.swept_median(), 1e-9);
    if (!r.main_search_ms.empty())
      p["ratio_ompl_median_over_swept_search"] = r.ompl_median() / std::max(r.swept_search_median(), 1e-9);
    if (!r.seed_runs.empty() && !r.main_search_ms.empty())
      p["ratio_ompl_median_over_swept_seeds_search"] = r.ompl_median() / std::max(r.swept_seeds_search_median(), 1e-9);
    if (!r.seed_runs.empty()) {
      p["ratio_ompl_median_over_swept_seeds"] = r.ompl_median() / std::max(r.swept_seeds_median(), 1e-9);
      p["goal_over_seeds"] = r.seeds_verdict();
    }
    p["goal"] = r.verdict();
    j["problems"].push_back(p);
  }
  return j;
}

namespace {

Fitter fitter_named(const std::string& name) {
  Fitter f = Fitter::inertia;
  if (!parse_fitter(name, f)) throw std::runtime_error("bench_plan JSON: unknown fitter '" + name + "'");
  return f;
}

}  // namespace

std::vector<CompareRow> rows_from_json(const nlohmann::json& j) {
  std::vector<CompareRow> rows;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const auto& p : j.value("problems", nlohmann::json::array())) {
    CompareRow r;
    r.name = p.value("name", "");
    r.kind = p.value("kind", "");
    r.error = p.value("error", "");
    r.clearance = p.value("clearance", 0.0);
    r.rotation = p.value("rotation", "");
    r.body_triangles = p.value("body_triangles", std::size_t{0});
    r.obstacle_triangles = p.value("obstacle_triangles", std::size_t{0});
    for (const auto& s : p.value("swept", nlohmann::json::array())) {
      SweptRun run;
      run.fitter = fitter_named(s.value("fitter", ""));
      run.plan_ms = s.value("plan_ms", nan);
      run.build_ms = s.value("build_ms", nan);
      run.result.status = status_named(s.value("status", "")).value_or(PlanStatus::no_path_resolution);
      run.result.message = s.value("message", "");
      r.swept.push_back(std::move(run));
    }
    r.deterministic = p.value("swept_deterministic", false);
    r.swept_time_limit = p.value("swept_time_limit_s", j.value("time_limit_s", 0.0));
    if (p.contains("swept_path_checked")) r.path_checked = p["swept_path_checked"].get<bool>();
    if (p.contains("swept_one_thread")) {
      const auto& one = p["swept_one_thread"];
      r.one_thread_status = status_named(one.value("status", "")).value_or(PlanStatus::no_path_resolution);
      r.one_thread_hash = std::stoull(one.value("path_hash", std::string("0")), nullptr, 16);
      r.one_thread_ms = one.value("plan_ms", nan);
    }
    r.main_ms = p.value("swept_main_runs_ms", std::vector<double>{});
    r.main_search_ms = p.value("swept_main_search_runs_ms", std::vector<double>{});  // absent before 2026-11-29
    for (const auto& s : p.value("swept_seed_runs", nlohmann::json::array())) {  // with --swept-seeds
      SeedRun run;
      run.seed = s.value("seed", std::uint64_t{0});
      run.status = status_named(s.value("status", "")).value_or(PlanStatus::no_path_resolution);
      run.ms = s.value("plan_ms", nan);
      run.path_hash = std::stoull(s.value("path_hash", std::string("0")), nullptr, 16);
      if (s.contains("path_checked") && !s["path_checked"].is_null()) run.checked = s["path_checked"].get<bool>();
      run.search_ms = s.value("search_ms", nan);
      r.seed_runs.push_back(run);
    }
    r.ompl_fcl_build_ms = p.value("ompl_fcl_build_ms", nan);
    for (const auto& o : p.value("ompl", nlohmann::json::array())) {
      OmplRun run;
      run.seed = o.value("seed", 0u);
      run.solved = o.value("solved", false);
      run.status = o.value("status", "");
      run.ms = o.value("ms", 0.0);
      run.waypoints = o.value("waypoints", std::size_t{0});
      run.verified = o.value("path_verified", "");
      run.checks = o.value("validity_checks", std::uint64_t{0});
      run.simplify_ms = o.value("simplify_ms", 0.0);  // absent before 2026-11-27
      run.simplified_verified = o.value("simplified_path_verified", "");
      run.length = o.value("path_length", 0.0);
      run.simplified_length = o.value("simplified_path_length", 0.0);
      r.ompl.push_back(std::move(run));
    }
    rows.push_back(std::move(r));
  }
  return rows;
}

}  // namespace swept::bench
