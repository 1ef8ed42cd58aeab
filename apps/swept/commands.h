#pragma once
/// Each subcommand of the `swept` CLI lives in its own file and registers itself here.
#include <CLI/CLI.hpp>

namespace swept::cli {

/// Thrown by a subcommand to end the program with a given exit code (after printing).
struct ExitCode {
  int code = 0;
};

void add_bvh_command(CLI::App& app);
void add_scene_command(CLI::App& app);
void add_mesh_stats_command(CLI::App& app);

}  // namespace swept::cli
