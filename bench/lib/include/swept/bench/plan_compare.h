#pragma once
/// The planner-vs-OMPL benchmark (bench_plan) as a library: swept's certified, deterministic
/// planner against OMPL's RRTConnect with FCL collision checking, on the same problems in one
/// run. Issue goal: solve every problem OMPL solves at ≤ 1/3 of its median time, and solve the
/// narrow-clearance disassembly problems it does not.
///
/// swept's side: PlanResult from plan() on a prebuilt scene (tree build reported apart), once per
/// fitter of all_fitters(), and the problem's fitter as many times as OMPL has seeds (at least
/// twice): its median time is the one compared, and every run must give the same path.
/// OMPL's side: see ompl_peer.h.
#include "swept/plan/planner.h"
#include "swept/plan/check.h"
#include "swept/plan/problem.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace swept::bench {

/// One benchmark problem: a generated box problem (meshes in memory) or a CAD scene's problem
/// file (meshes loaded by load_scene).
struct PlanCase {
  std::string name;
  Problem problem;
  std::optional<TriangleSoup> obstacles, body;  ///< set for the box problems
  std::string kind;                             ///< "box", "cad" or "suite" (planning_suite.h)
  /// swept's time limit on this problem, s (0: CompareOptions::time_limit, OMPL's). The issue
  /// allows swept 300 s on the problems OMPL is not expected to solve in 60 s.
  double swept_time_limit = 0.0;
};

struct CompareOptions {
  double time_limit = 60.0;   ///< s, for both planners
  int seeds = 5;              ///< OMPL runs (seeds 1..N); swept's problem fitter runs as often
  int threads = 0;            ///< swept's threads (0: all cores)
  bool collide_only = false;  ///< OMPL's validity check without the clearance
  /// One more run of the problem's fitter at 1 thread (when `threads` ≠ 1 and the problem was
  /// solved): the path hash must be the same as at `threads`.
  bool thread_check = false;
  /// swept over seeds as OMPL is: one more run of the problem's fitter for each of the seeds
  /// 1 … seeds − 1 (Problem::seed, another draw of the trees' samples), each path re-checked by
  /// check_path; their median with seed 0's beside OMPL's median over its seeds.
  bool swept_seeds = false;
};

/// One run of swept with another seed (CompareOptions::swept_seeds).
struct SeedRun {
  std::uint64_t seed = 0;
  PlanStatus status = PlanStatus::no_path_resolution;
  double ms = 0.0;
  std::uint64_t path_hash = 0;
  std::optional<bool> checked;  ///< check_path of its path; unset when not solved
  double search_ms = 0.0;       ///< its search phase (PlanResult::time_ms.search)
};

struct SweptRun {
  Fitter fitter = Fitter::inertia;
  PlanResult result;
  double plan_ms = 0.0;   ///< wall time of plan() on the prebuilt scene (no tree build)
  double build_ms = 0.0;  ///< building both trees
};

struct OmplRun {
  std::uint32_t seed = 0;
  bool solved = false;
  double ms = 0.0;
  std::string status;
  std::size_t waypoints = 0;
  std::uint64_t checks = 0;  ///< state validity checks
  /// The solution path re-checked between OMPL's samples by swept's certified motion query
  /// (margin 0): "free", "collides" (a pose in contact was found), or "undecided".
  std::string verified;
  /// After a solution, outside `ms`: OMPL's own shortcutting of the path
  /// (SimpleSetup::simplifySolution() with its defaults, as an OMPL.app user gets it), its time,
  /// and the simplified path re-checked as `verified` is. 0 and "" when not solved.
  double simplify_ms = 0.0;
  std::string simplified_verified;
  /// The raw and the simplified path's length in swept's motion metric (Σ ‖Δc‖ + r_max·θ about
  /// the scene's reference point, as PlanResult::path_length); 0 when not solved.
  double length = 0.0;
  double simplified_length = 0.0;
};

/// One problem's results.
struct CompareRow {
  std::string name, kind;
  std::size_t body_triangles = 0, obstacle_triangles = 0;
  double clearance = 0.0;
  std::string rotation;
  std::vector<SweptRun> swept;  ///< [0], [1]: the problem's fitter twice; then the other fitters
  bool deterministic = false;
  double swept_time_limit = 0.0;  ///< the limit swept had on this problem, s
  /// The thread check (CompareOptions::thread_check): the 1-thread run's status, hash and time;
  /// unset when not run.
  std::optional<PlanStatus> one_thread_status;
  std::uint64_t one_thread_hash = 0;
  double one_thread_ms = 0.0;
  /// The main run's path re-certified by check_path (what `swept check` runs), with the
  /// problem's clearance, apart from the planner; unset when it found no path.
  std::optional<bool> path_checked;
  std::vector<OmplRun> ompl;
  double ompl_fcl_build_ms = 0.0;
  std::string error;  ///< set when the problem could not be loaded
  /// plan() times of every run of the problem's fitter (swept is deterministic: the same path
  /// each time, so repeats measure the timing spread only).
  std::vector<double> main_ms;
  /// The search phase of each of those runs (PlanResult::time_ms.search): the time to swept's
  /// first path, every motion of it certified, before smoothing and the final certification.
  /// RRTConnect's solve time is the like-for-like figure: the time to its raw path.
  std::vector<double> main_search_ms;
  /// CompareOptions::swept_seeds: the runs with seeds 1 … seeds − 1 (empty when not asked).
  std::vector<SeedRun> seed_runs;

  const SweptRun& main() const { return swept.front(); }
  /// The thread check ran and gave the main run's status and path hash.
  bool one_thread_same() const;
  /// Median over the runs of the problem's fitter: compared with OMPL's median over seeds.
  double swept_median() const;
  /// Median over seed 0 (swept_median()) and the seed runs, a run without a path counted at its
  /// time (the limit, when that stopped it), as ompl_median() counts OMPL's failures; NaN
  /// without seed runs.
  double swept_seeds_median() const;
  /// Median of main_search_ms; NaN without them (bench_plan JSON written before 2026-11-29).
  double swept_search_median() const;
  /// Median over seed 0 (swept_search_median()) and the seed runs' search phases; NaN without
  /// seed runs or without seed 0's search times.
  double swept_seeds_search_median() const;
  /// Seed runs solved, seed 0 included.
  int swept_seeds_solved() const;
  int ompl_colliding() const;
  /// Solutions whose simplified path swept's motion check finds in contact.
  int ompl_simplified_colliding() const;
  int ompl_successes() const;
  /// Median over all seeds, failures counted at the time they took (the limit).
  double ompl_median() const;
  /// Median over all seeds of solve + simplification: a path smoothed as swept's is (swept's
  /// times include its smoothing). Failures count at the limit, as in ompl_median().
  double ompl_median_with_simplify() const;
  double ompl_min() const;
  double ompl_max() const;
  /// The goal for this problem: "met: >= 3x", "MISSED: OMPL solves it", ...
  std::string verdict() const;
  /// The same goal over seeds (CompareOptions::swept_seeds): every seed solved, and the median
  /// over seeds at ≤ 1/3 of OMPL's; "" without seed runs.
  std::string seeds_verdict() const;
};

/// Runs both planners on one problem (progress lines on stderr).
CompareRow run_case(const PlanCase& c, const CompareOptions& o);

/// The two tables bench_plan prints (problems side by side; swept per fitter), on stdout.
void print_tables(const std::vector<CompareRow>& rows, const CompareOptions& o);

/// bench_plan's JSON (read back by `swept bench paper`).
nlohmann::json to_json(const std::vector<CompareRow>& rows, const CompareOptions& o);
/// The rows of a bench_plan JSON: every figure to_json() writes except the swept runs' path
/// statistics (PlanResult keeps only status and message). Throws std::runtime_error on an
/// unknown fitter, nlohmann::json::exception on a malformed document.
std::vector<CompareRow> rows_from_json(const nlohmann::json& j);

}  // namespace swept::bench
