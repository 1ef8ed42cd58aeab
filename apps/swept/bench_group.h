#pragma once
/// The `swept bench` group: `queries` and `paper` register under it, whichever comes first
/// creating it.
#include <CLI/CLI.hpp>

namespace swept::cli {

inline CLI::App* bench_group(CLI::App& app) {
  try {
    return app.get_subcommand("bench");
  } catch (const CLI::OptionNotFound&) {
    CLI::App* bench = app.add_subcommand("bench", "Benchmarks against peer libraries");
    bench->require_subcommand(1);
    return bench;
  }
}

}  // namespace swept::cli
