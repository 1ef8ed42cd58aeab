// `swept bench queries A B`: collide / distance / tolerance timings of swept's RSS trees (one per
// fitter) and FCL's OBBRSS and RSS trees, side by side. The options are parsed here; the
// benchmark is the swept_bench library (bench/lib: swept/bench/queries.h).
#include "bench_group.h"
#include "cli_options.h"
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
  cmd->add_option("--leaf-size", opts->leaf_sizes,
                  "triangles per leaf of swept's trees; several sizes separated by commas give a row per fitter and size")
      ->delimiter(',')
      ->capture_default_str()
      ->check(CLI::Range(1, kMaxLeafSize));
  auto split = std::make_shared<std::string>(to_string(opts->split));
  add_split_option(*cmd, *split, "Split rule of swept's trees", false)->capture_default_str();
  cmd->add_flag("--json", opts->json, "machine-readable output");
  cmd->callback([opts, split] {
    opts->split = split_rules_from(*split, false).front();
    bench::run_queries_benchmark(*opts, std::cout, std::cerr);
  });
}

}  // namespace swept::cli
