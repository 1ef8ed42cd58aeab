// bench_plan's output: the two tables on stdout and the JSON that `swept bench paper` reads back.
#include "swept/bench/plan_compare.h"

#include "swept/bench/timing.h"

#include <algorithm>
#include <cstdio>
#include <string>
#include <thread>

namespace swept::bench {
namespace {

std::string fmt(double v, int prec = 1) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", prec, v);
  return buf;
}

// swept's search phase beside RRTConnect's solve: each planner's time to its first path, before
// either smooths it (rows read from a JSON written before 2026-11-29 have no search times).
void print_search_table(const std::vector<CompareRow>& rows) {
  const bool seeds = std::any_of(rows.begin(), rows.end(), [](const CompareRow& r) { return !r.seed_runs.empty(); });
  if (std::none_of(rows.begin(), rows.end(), [](const CompareRow& r) { return r.error.empty() && !r.main_search_ms.empty(); }))
    return;
  std::printf("\nTo the first path: swept's search phase (every motion certified; before its smoothing and final "
              "certification) beside RRTConnect's solve (its raw path)\n");
  std::printf("%-18s %11s %11s %11s %8s", "problem", "search ms", "of swept ms", "OMPL ms", "ratio");
  if (seeds) std::printf(" %17s %8s", "search over seeds", "ratio");
  std::printf("\n");
  for (const CompareRow& r : rows) {
    if (!r.error.empty() || r.main_search_ms.empty()) continue;
    const double search = r.swept_search_median();
    std::printf("%-18s %11s %10s%% %11s %8s", r.name.c_str(), fmt(search).c_str(),
                fmt(100.0 * search / std::max(r.swept_median(), 1e-9), 0).c_str(), fmt(r.ompl_median()).c_str(),
                fmt(r.ompl_median() / std::max(search, 1e-9), 2).c_str());
    if (seeds && !r.seed_runs.empty())
      std::printf(" %17s %8s", fmt(r.swept_seeds_search_median()).c_str(),
                  fmt(r.ompl_median() / std::max(r.swept_seeds_search_median(), 1e-9), 2).c_str());
    std::printf("\n");
  }
  std::printf("search ms: median over the same runs as swept ms; of swept ms: its share of them; ratio: OMPL median / "
              "search ms. The goal columns above use swept ms, smoothing and final certification included.\n");
}

}  // namespace

void print_tables(const std::vector<CompareRow>& rows, const CompareOptions& o) {
  const double limit = o.time_limit;
  const int seeds = o.seeds, threads = o.threads;
  const bool collide_only = o.collide_only;
  std::printf("\nPlanner side by side: swept (fitter of the problem, %s threads) vs OMPL RRTConnect + FCL, "
              "%d seeds, %.0f s limit\n",
              threads > 0 ? std::to_string(threads).c_str() : "all", seeds, limit);
  for (const CompareRow& r : rows)
    if (r.error.empty() && r.swept_time_limit != limit)
      std::printf("swept's limit on %s: %.0f s (OMPL's: %.0f s)\n", r.name.c_str(), r.swept_time_limit, limit);
  if (collide_only) std::printf("OMPL's validity check: fcl::collide only (no clearance; swept still certifies it)\n");
  std::printf("%-18s %9s %11s %11s %-20s %5s | %7s %11s %21s %6s %11s | %8s %8s  %s\n", "problem", "clearance", "swept ms",
              "(+build)", "swept status", "wayp", "OMPL ok", "median ms", "min-max ms", "hit", "+simplify", "ratio", "ratio+s", "goal");
  for (const CompareRow& r : rows) {
    if (!r.error.empty()) {
      std::printf("%-18s  not run: %s\n", r.name.c_str(), r.error.c_str());
      continue;
    }
    const SweptRun& s = r.main();
    const std::string ok = std::to_string(r.ompl_successes()) + "/" + std::to_string(r.ompl.size());
    const std::string range = fmt(r.ompl_min()) + "-" + fmt(r.ompl_max());
    const std::string hit = std::to_string(r.ompl_colliding()) + "/" + std::to_string(r.ompl_simplified_colliding());
    std::printf("%-18s %9g %11s %11s %-20s %5zu | %7s %11s %21s %6s %11s | %8s %8s  %s\n", r.name.c_str(), r.clearance,
                fmt(r.swept_median()).c_str(), fmt(r.swept_median() + s.build_ms).c_str(), std::string(status_name(s.result.status)).c_str(),
                s.result.path.poses.size(), ok.c_str(), fmt(r.ompl_median()).c_str(), range.c_str(), hit.c_str(),
                fmt(r.ompl_median_with_simplify()).c_str(), fmt(r.ompl_median() / std::max(r.swept_median(), 1e-9), 2).c_str(),
                fmt(r.ompl_median_with_simplify() / std::max(r.swept_median(), 1e-9), 2).c_str(), r.verdict().c_str());
  }
  std::printf("swept ms: plan() on the prebuilt trees, median of as many runs as OMPL has seeds (same path each run); "
              "(+build): with the tree build. OMPL ok: exact solutions; "
              "median over all seeds, failures counted at the limit; hit: OMPL solutions that swept's certified "
              "motion check finds in contact between OMPL's discrete motion samples (raw path / simplified path); "
              "+simplify: median of OMPL's solve + its simplifySolution() (swept ms include swept's smoothing); "
              "ratio: OMPL median / swept ms (the goal's figure); ratio+s: OMPL +simplify / swept ms.\n");
  print_search_table(rows);
  std::printf("\nswept per fitter (plan ms of the first run without the tree build; build ms; status) and determinism\n");
  std::printf("%-18s", "problem");
  for (const FitterInfo& f : all_fitters()) std::printf(" %28s", std::string(f.name).c_str());
  std::printf("  %s\n", "same hash every run (and at 1 thread: its time, and how many times the median); check_path of the path");
  for (const CompareRow& r : rows) {
    if (!r.error.empty()) continue;
    std::printf("%-18s", r.name.c_str());
    for (const FitterInfo& fi : all_fitters()) {
      const auto it = std::find_if(r.swept.begin(), r.swept.end(), [&](const SweptRun& s) { return s.fitter == fi.fitter; });
      const std::string cell = fmt(it->plan_ms) + " +" + fmt(it->build_ms) + " " +
                               (it->result.solved() ? std::string("ok") : std::string(status_name(it->result.status)));
      std::printf(" %28s", cell.c_str());
    }
    char hash[32];
    std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(r.main().result.path_hash));
    // The run at 1 thread's time over the median: how much the other cores gave this run (a
    // machine whose second core is taken by something else gives less, and the ratio drops).
    std::string one;
    if (r.one_thread_status)
      one = std::string(r.one_thread_same() ? ", 1 thread: yes" : ", 1 thread: NO") + " (" + fmt(r.one_thread_ms) + " ms, " +
            fmt(r.one_thread_ms / std::max(r.swept_median(), 1e-9), 2) + "x the median)";
    const char* check = !r.path_checked ? "" : *r.path_checked ? "; check: valid" : "; check: NOT VALID";
    std::printf("  %s (%s)%s%s\n", r.deterministic ? "yes" : "NO", hash, one.c_str(), check);
  }
  if (std::none_of(rows.begin(), rows.end(), [](const CompareRow& r) { return !r.seed_runs.empty(); })) {
    std::fflush(stdout);
    return;
  }
  // swept over seeds, as OMPL is: seed 0 (its median above) and one run of each other seed.
  std::printf("\nswept over seeds 0-%d (another draw of the trees' samples each; seed 0: the median above, the others one run "
              "each; a run without a path counts at its time), beside OMPL's median over its seeds\n",
              seeds - 1);
  std::printf("%-18s %7s %11s %21s %11s %8s  %-22s %s\n", "problem", "solved", "median ms", "min-max ms", "OMPL ms", "ratio",
              "paths (check_path)", "goal over seeds");
  for (const CompareRow& r : rows) {
    if (!r.error.empty() || r.seed_runs.empty()) continue;
    double lo = r.swept_median(), hi = r.swept_median();
    int valid = r.path_checked.value_or(false) ? 1 : 0, distinct = 1;
    std::vector<std::uint64_t> hashes{r.main().result.path_hash};
    for (const SeedRun& s : r.seed_runs) {
      lo = std::min(lo, s.ms), hi = std::max(hi, s.ms);
      valid += s.checked.value_or(false) ? 1 : 0;
      if (std::find(hashes.begin(), hashes.end(), s.path_hash) == hashes.end() && s.status == PlanStatus::solved) ++distinct;
      hashes.push_back(s.path_hash);
    }
    const int n = static_cast<int>(r.seed_runs.size()) + 1;
    const std::string solved = std::to_string(r.swept_seeds_solved()) + "/" + std::to_string(n);
    const std::string range = fmt(lo) + "-" + fmt(hi);
    const std::string paths = std::to_string(distinct) + " distinct, " + std::to_string(valid) + " valid";
    std::printf("%-18s %7s %11s %21s %11s %8s  %-22s %s\n", r.name.c_str(), solved.c_str(), fmt(r.swept_seeds_median()).c_str(),
                range.c_str(), fmt(r.ompl_median()).c_str(), fmt(r.ompl_median() / std::max(r.swept_seeds_median(), 1e-9), 2).c_str(),
                paths.c_str(), r.seeds_verdict().c_str());
  }
  std::fflush(stdout);
}

}  // namespace swept::bench
