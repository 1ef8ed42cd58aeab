// `swept bench queries A B`: collide / distance / tolerance timings of swept's RSS trees (one per
// fitter) and FCL's OBBRSS and RSS trees, side by side. The options are parsed here; the
// benchmark is the swept_bench library (bench/lib: swept/bench/queries.h).
#include "bench_group.h"
#include "commands.h"

#include "swept/bench/queries.h"

#include <iostream>
#include <memory>

namespace swept::cli {

void add_bench_queries_command(CLI::App& app) {
  CLI::App* bench = bench_group(app);
  auto opts = std::make_shared<bench::QueriesOptions>();
  CLI::App* cmd = bench->add_subcommand(
      "queries", "Collide/distance/tolerance timings: swept's fitters vs FCL OBBRSS and RSS");
  cmd->add_option("A", opts->file_a, "first mesh or CAD file")->required();
  cmd->add_option("B", opts->file_b, "second mesh or CAD file (may be the same)")->required();
  cmd->add_option("--poses", opts->poses, "poses per set")->capture_default_str();
  cmd->add_option("--seed", opts->seed, "seed of the pose sets")->capture_default_str();
  cmd->add_flag("--json", opts->json, "machine-readable output");
  cmd->callback([opts] { bench::run_queries_benchmark(*opts, std::cout, std::cerr); });
}

}  // namespace swept::cli
