// The planner-vs-OMPL benchmark, one problem: see swept/bench/plan_compare.h.
#include "swept/bench/plan_compare.h"

#include "swept/bench/fcl_model.h"
#include "swept/bench/ompl_peer.h"
#include "swept/bench/search_space.h"
#include "swept/bench/timing.h"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <optional>

namespace swept::bench {
namespace {

/// The problem's tree settings with another fitter.
BuildConfig build_config(const Problem& problem, Fitter fitter) {
  BuildConfig config = problem.build;
  config.fitter = fitter;
  return config;
}

Result<PlanScene> scene_for(const PlanCase& c, Fitter fitter) {
  if (c.obstacles) return make_scene(*c.obstacles, *c.body, build_config(c.problem, fitter), c.problem.reference_point);
  return load_scene(c.problem, build_config(c.problem, fitter));
}

SweptRun run_swept(const Problem& problem, const PlanScene& scene, Fitter fitter, double limit, int threads) {
  SweptRun run;
  run.fitter = fitter;
  run.build_ms = scene.build_ms;
  PlanOptions options;
  options.time_limit = limit;
  options.threads = threads;
  const auto t0 = Clock::now();
  run.result = plan(problem, scene, options);
  run.plan_ms = ms_since(t0);
  return run;
}

}  // namespace

CompareRow run_case(const PlanCase& c, const CompareOptions& o) {
  const double limit = c.swept_time_limit > 0.0 ? c.swept_time_limit : o.time_limit;  // swept's
  const int seeds = o.seeds, threads = o.threads;
  CompareRow row;
  row.swept_time_limit = limit;
  row.name = c.name;
  row.kind = c.kind;
  row.clearance = c.problem.clearance;
  row.rotation = c.problem.rotation == RotationMode::none ? "none" : c.problem.rotation == RotationMode::free ? "free" : "limits";
  std::vector<Fitter> fitters{c.problem.build.fitter, c.problem.build.fitter};
  for (const FitterInfo& f : all_fitters())
    if (f.fitter != c.problem.build.fitter) fitters.push_back(f.fitter);
  std::optional<PlanScene> main_scene;
  for (std::size_t i = 0; i < fitters.size(); ++i) {
    if (i == 1 && main_scene) {  // the determinism check reuses the scene
      row.swept.push_back(run_swept(c.problem, *main_scene, fitters[i], limit, threads));
    } else {
      auto scene = scene_for(c, fitters[i]);
      if (!scene) {
        row.error = scene.error().message;
        return row;
      }
      row.swept.push_back(run_swept(c.problem, *scene, fitters[i], limit, threads));
      if (i == 0) main_scene = std::move(*scene);
    }
    const SweptRun& s = row.swept.back();
    std::fprintf(stderr, "  swept %-8s %-22s plan %10.1f ms  search %8.1f ms  build %7.1f ms  waypoints %zu  length %.4g\n",
                 std::string(to_string(s.fitter)).c_str(), std::string(status_name(s.result.status)).c_str(), s.plan_ms,
                 s.result.time_ms.search, s.build_ms, s.result.path.poses.size(), s.result.path_length);
  }
  // More runs of the problem's fitter, as many in all as OMPL gets seeds (at least two): the
  // median time, and every run must give the same path.
  const PlanResult& first = row.swept[0].result;
  auto same = [&](const PlanResult& r) { return r.status == first.status && r.path_hash == first.path_hash; };
  row.deterministic = same(row.swept[1].result);
  row.main_ms = {row.swept[0].plan_ms, row.swept[1].plan_ms};
  row.main_search_ms = {row.swept[0].result.time_ms.search, row.swept[1].result.time_ms.search};
  // (A run that ends on the time limit is not repeated: its median is the limit anyway.)
  for (int k = 2; first.status != PlanStatus::no_path_time && k < seeds; ++k) {
    const SweptRun again = run_swept(c.problem, *main_scene, c.problem.build.fitter, limit, threads);
    row.main_ms.push_back(again.plan_ms);
    row.main_search_ms.push_back(again.result.time_ms.search);
    row.deterministic = row.deterministic && same(again.result);
  }
  if (first.solved()) {  // as `swept check` would: the path against the problem, apart from the planner
    const PathCheckResult check = check_path(c.problem, *main_scene, first.path);
    row.path_checked = check.valid;
    std::fprintf(stderr, "  swept path check: %s\n", check.message.c_str());
  }
  if (o.thread_check && threads != 1 && first.solved()) {
    const SweptRun one = run_swept(c.problem, *main_scene, c.problem.build.fitter, limit, 1);
    row.one_thread_status = one.result.status;
    row.one_thread_hash = one.result.path_hash;
    row.one_thread_ms = one.plan_ms;
    std::fprintf(stderr, "  swept 1 thread  %-22s plan %10.1f ms  same path: %s\n",
                 std::string(status_name(one.result.status)).c_str(), one.plan_ms, same(one.result) ? "yes" : "NO");
  }
  if (o.swept_seeds) {  // other draws of the trees' samples, one run each, as OMPL's seeds
    for (int k = 1; k < seeds; ++k) {
      Problem seeded = c.problem;
      seeded.seed = static_cast<std::uint64_t>(k);
      const SweptRun s = run_swept(seeded, *main_scene, c.problem.build.fitter, limit, threads);
      SeedRun run{.seed = seeded.seed, .status = s.result.status, .ms = s.plan_ms, .path_hash = s.result.path_hash,
                  .search_ms = s.result.time_ms.search};
      if (s.result.solved()) run.checked = check_path(seeded, *main_scene, s.result.path).valid;
      row.seed_runs.push_back(run);
      std::fprintf(stderr, "  swept seed %-3d %-22s plan %10.1f ms  search %8.1f ms  waypoints %zu%s\n", k,
                   std::string(status_name(s.result.status)).c_str(), s.plan_ms, s.result.time_ms.search,
                   s.result.path.poses.size(), !run.checked ? "" : *run.checked ? "  check: valid" : "  check: NOT VALID");
    }
  }
  row.body_triangles = main_scene->body.triangles.size();
  row.obstacle_triangles = main_scene->obstacles.triangles.size();

  const SearchSpace g = planner_search_space(c.problem, *main_scene);
  const auto t0 = Clock::now();
  const auto body = fcl_model<fcl::OBBRSSd>(main_scene->body.triangles);
  const auto obstacles = fcl_model<fcl::OBBRSSd>(main_scene->obstacles.triangles);
  row.ompl_fcl_build_ms = ms_since(t0);
  for (int k = 0; k < seeds; ++k) {
    const auto seed = static_cast<std::uint32_t>(k + 1);
    row.ompl.push_back(run_ompl(c.problem, g, *main_scene, *body, *obstacles, seed, o));
    const OmplRun& r = row.ompl.back();
    std::fprintf(stderr, "  ompl  seed %-3u %-22s %10.1f ms  checks %llu  waypoints %zu%s%s", r.seed, r.status.c_str(),
                 r.ms, static_cast<unsigned long long>(r.checks), r.waypoints, r.solved ? "  path " : "",
                 r.verified.c_str());
    if (r.solved)
      std::fprintf(stderr, "  length %.4g  simplify %.1f ms: length %.4g, path %s", r.length, r.simplify_ms,
                   r.simplified_length, r.simplified_verified.c_str());
    std::fprintf(stderr, "\n");
  }
  return row;
}

}  // namespace swept::bench
