#pragma once
/// `swept bench paper` as a library: the paper's Tables II–IV reproduced in one run, with the
/// peers beside them. For each scene of `swept scene` (body † and obstacles ‡) and a handful of
/// real CAD files of ../shared/data, for each fitter of all_fitters() under each split rule of
/// all_split_rules():
/// - Table II: total RSS surface area and volume of the tree;
/// - Table III: planner time per scene (median of N runs, min–max), speed-up against PQP_FIT,
///   distance queries issued;
/// - Table IV: tree build time (serial build, median of N runs);
/// - peers: FCL's OBBRSS and RSS build times on the same meshes, collide/distance times on the
///   seeded pose sets of pose_sets.h, and OMPL RRTConnect + FCL on the same problems (merged from
///   the `bench_plan` program when it is built).
/// Writes results.json, report.md and SVG plots (img/) into the output directory.
///
/// One file per phase: paper_measure.cpp (scenes), paper_cad.cpp (real CAD), paper_ompl.cpp
/// (bench_plan), paper_json.cpp (results.json written and merged back), paper_report.cpp
/// (report.md), paper_plots.cpp (img/), paper_run.cpp (the driver).
#include "swept/bench/paper_verdicts.h"
#include "swept/scenes/scenes.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <limits>
#include <functional>
#include <string>
#include <vector>

namespace swept::bench {

/// The options of `swept bench paper` (the CLI's flags, one field each).
struct PaperOptions {
  std::string scale = "test";
  int runs = 3;
  std::string out;
  std::string scenes_dir;  ///< pre-generated scenes (DIR/<name>/problem.toml); empty: generate
  std::string data_dir = "../shared/data";
  std::vector<std::string> only;  ///< scene names; empty: all
  bool no_scenes = false;
  bool no_cad = false;
  std::vector<std::string> merge;  ///< output directories of earlier runs whose results.json are merged in
  int poses = 0;             ///< per pose set; 0: 5 at test scale, 20 at paper scale
  int threads = 1;           ///< planner threads
  double time_limit = 0.0;   ///< planner time limit, s; 0: the problem's
  bool no_ompl = false;
  std::string bench_plan;    ///< path of the bench_plan program; empty: beside this build
  double ompl_time_limit = 0.0;  ///< s; 0: 10 at test scale, 60 at paper scale
  /// Where the run's log lines go (what it generates, measures and writes); empty: stderr.
  std::function<void(const std::string& line)> log;
  /// Called after each step: a scene's fitter and split rule measured, a CAD mesh measured, the
  /// OMPL run; (steps done, steps in all, the step just done). Not called when empty.
  std::function<void(std::size_t done, std::size_t total, const std::string& step)> progress;
};

/// One line of the run's log (PaperOptions::log, else stderr).
void log_line(const PaperOptions& o, const std::string& line);

/// Runs the benchmark: validates the options (std::runtime_error on bad ones), measures, writes
/// the outputs into `o.out` after every scene (an interrupted run leaves what it measured) and
/// returns the final report.md text.
std::string run_paper_benchmark(const PaperOptions& o);

// ---- the results (MeshRow, PlanRow, QueryRow: paper_verdicts.h) --------------------------------

struct SceneRun {
  std::string name;
  std::size_t body_triangles = 0, obstacle_triangles = 0;
  std::size_t paper_body = 0, paper_obstacles = 0;
  double load_ms = 0.0, generate_s = 0.0;
  std::string problem_file;
  std::string error;  ///< not run: why
};

struct OmplRow {
  std::string problem;
  int successes = 0, runs = 0;
  double median_ms = std::numeric_limits<double>::quiet_NaN();
  double min_ms = median_ms, max_ms = median_ms;
  double swept_ms = median_ms;  ///< bench_plan's own swept run (problem's fitter)
  std::string swept_status;
  double fcl_build_ms = median_ms;
};

struct Results {
  std::vector<SceneRun> scenes;
  std::vector<MeshRow> meshes;
  std::vector<PlanRow> plans;
  std::vector<QueryRow> queries;
  std::vector<std::string> notes;  ///< skipped inputs, peers not run
  std::vector<OmplRow> ompl;
  std::string ompl_status;  ///< how the OMPL column was obtained, or why it is absent
  double ompl_time_limit = 0.0;
};

/// The scenes that were planned (no error), in run order.
std::vector<std::string> planned_scenes(const Results& r);
/// The rows the verdicts are drawn from.
PaperRows rows_of(const Results& r);
const PlanRow* find_plan(const Results& r, const std::string& scene, Fitter f, SplitRule s);
const QueryRow* find_query(const Results& r, const std::string& scene, const std::string& set, const std::string& engine);

// ---- the phases --------------------------------------------------------------------------------

/// The run's steps, counted for PaperOptions::progress.
struct PaperSteps {
  const PaperOptions& options;
  std::size_t done = 0, total = 0;
  void step(const std::string& what) {
    ++done;
    if (options.progress) options.progress(done, total, what);
  }
};

/// The steps of run_scene (one per split rule and fitter) and of run_cad (one per mesh measured).
std::size_t scene_steps();
std::size_t cad_steps(bool paper);

/// Measures one scene (problem file already generated): every tree, plan and query row, FCL's
/// builds and queries. Appends to `res`; `res.scenes.back()` is this scene's SceneRun.
void run_scene(const PaperOptions& o, const scenes::SceneInfo& info, const std::filesystem::path& problem_file,
               Results& res, int poses_per_set, PaperSteps& steps);

/// Tables II and IV for a mesh that is not planned with (the real CAD).
MeshRow measure_mesh(const std::string& name, const std::string& source, const std::vector<Triangle>& tris, int runs);

/// The real CAD meshes of the data directory (the paper-only ones at paper scale).
void run_cad(const PaperOptions& o, bool paper, Results& res, PaperSteps& steps);

/// OMPL RRTConnect + FCL on the same scenes, through the bench_plan program; sets
/// res.ompl_status in every case.
void run_ompl(const PaperOptions& o, bool paper, const std::filesystem::path& out, Results& res);

/// results.json, and reading one back (--merge: appends DIR/results.json to `res`).
nlohmann::json results_json(const Results& r, const PaperOptions& o, const std::string& date, const std::string& machine);
void merge_results(const std::filesystem::path& dir, const PaperOptions& o, Results& res);

/// report.md.
std::string markdown_report(const Results& r, const PaperOptions& o, const std::string& date,
                            const std::string& machine, const std::vector<std::string>& plots);
/// The command line that reproduces a run of these options.
std::string command_line(const PaperOptions& o);
/// CPU, threads, memory, OS and compiler of this machine, one line.
std::string machine_description();
/// "2026-11-24 05:00 UTC".
std::string utc_now();

/// The SVG plots, written into `img`; appends the file names written to `files`.
void write_plots(const Results& r, const std::filesystem::path& img, std::vector<std::string>& files);

/// "12.3 (11.9–12.8)", or "12.3" for a single run; "n/a" for none.
std::string fmt_spread(const Spread& s, int digits);
/// %.*g, "n/a" when not finite.
std::string fmt_g(double v, int digits = 4);

}  // namespace swept::bench
