// swept-tools: the subcommands of `swept` that need OpenCASCADE's modelling libraries or the
// peer libraries (FCL): `scene` (the built-in CAD-like scenes, modelled with OpenCASCADE) and
// `bench` (side by side with FCL). `swept scene ...` and `swept bench ...` run this program
// with the same arguments (tools_path.h), so that every other command starts without loading
// those libraries: their relocations took ~25 of the ~30 ms any `swept` command spent starting.
#include "cli_main.h"
#include "commands.h"

int main(int argc, char** argv) {
  CLI::App app{"swept: the built-in scenes and the benchmarks (run as `swept scene` and `swept bench`)."};
  app.require_subcommand(1);
  swept::cli::add_scene_command(app);
  swept::cli::add_bench_queries_command(app);
  swept::cli::add_bench_paper_command(app);
  return swept::cli::run_cli(app, argc, argv);
}
