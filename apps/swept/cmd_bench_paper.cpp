// `swept bench paper`: the paper's Tables II–IV reproduced in one run, with the peers beside
// them. The options are parsed here; the benchmark is the swept_bench library
// (bench/lib: swept/bench/paper.h).
#include "bench_group.h"
#include "commands.h"
#include "progress_line.h"

#include "swept/bench/paper.h"
#include "swept/bvh/bvh.h"

#include <iostream>
#include <memory>

namespace swept::cli {

void add_bench_paper_command(CLI::App& app) {
  CLI::App* bench = bench_group(app);
  auto o = std::make_shared<bench::PaperOptions>();
  CLI::App* cmd = bench->add_subcommand(
      "paper",
      "The paper's Tables II-IV in one run: for each scene of `swept scene` and real CAD files, each fitter\n"
      "(" + fitter_names() + ") under each split rule (" + split_rule_names() + "): total RSS surface area\n"
      "and volume, planner wall time (median of N runs, min-max, speed-up against " +
          std::string(to_string(bench::baseline_fitter())) + ", distance\n"
      "queries), build time; FCL's build and query times on the same meshes and pose sets, and OMPL\n"
      "RRTConnect + FCL via bench_plan. Writes results.json, report.md and SVG plots (img/) into --out.");
  cmd->add_option("--scale", o->scale, "test | paper")->capture_default_str();
  cmd->add_option("--runs", o->runs, "runs per figure (median, min-max)")->capture_default_str();
  cmd->add_option("--out", o->out, "output directory")->required();
  cmd->add_option("--scenes", o->scenes_dir, "use scenes generated earlier: DIR/<name>/problem.toml");
  cmd->add_option("--data", o->data_dir, "the real CAD data directory")->capture_default_str();
  cmd->add_option("--only", o->only, "only these scenes")->delimiter(',');
  cmd->add_flag("--no-scenes", o->no_scenes, "skip the scenes (e.g. a process for the real CAD only)");
  cmd->add_flag("--no-cad", o->no_cad, "skip the real CAD meshes");
  cmd->add_option("--merge", o->merge,
                  "merge the results.json of earlier runs' output directories into this report (a long run "
                  "split into processes)")
      ->delimiter(',');
  cmd->add_option("--poses", o->poses, "poses per query set (default 5 at test scale, 20 at paper scale)");
  cmd->add_option("--threads", o->threads, "planner threads (0: all cores)")->capture_default_str();
  cmd->add_option("--time-limit", o->time_limit, "planner time limit, s (default: the problem's)");
  cmd->add_flag("--no-ompl", o->no_ompl, "do not run OMPL (bench_plan)");
  cmd->add_option("--bench-plan", o->bench_plan, "the bench_plan program (default: <build>/bench/bench_plan)");
  cmd->add_option("--ompl-time-limit", o->ompl_time_limit, "OMPL time limit per run, s (default 10 test, 60 paper)");
  auto quiet = std::make_shared<bool>(false);
  cmd->add_flag("-q,--quiet", *quiet, "No progress line (there is none either when stderr is not a terminal)");
  cmd->callback([o, quiet] {
    ProgressLine line(!*quiet);
    bench::PaperOptions run = *o;
    if (line.on()) {
      run.log = [&line](const std::string& text) { line.message(text); };
      run.progress = [&line](std::size_t done, std::size_t total, const std::string& step) {
        line.count("bench paper", done, total, "steps", step);
      };
    }
    const std::string report = bench::run_paper_benchmark(run);
    line.clear();
    std::cout << report;
  });
}

}  // namespace swept::cli
