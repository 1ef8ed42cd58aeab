#pragma once
/// Each subcommand of the `swept` CLI lives in its own file and registers itself here.
#include <CLI/CLI.hpp>

namespace swept::cli {

/// Thrown by a subcommand to end the program with a given exit code (after printing).
struct ExitCode {
  int code = 0;
};

void add_bvh_command(CLI::App& app);
void add_plan_command(CLI::App& app);
void add_check_command(CLI::App& app);
void add_view_command(CLI::App& app);
void add_scene_command(CLI::App& app);
void add_mesh_stats_command(CLI::App& app);
void add_bench_queries_command(CLI::App& app);
void add_bench_paper_command(CLI::App& app);
void add_disassemble_command(CLI::App& app);

}  // namespace swept::cli

namespace swept {
struct Assembly;
struct DisassemblyResult;
struct Problem;
struct PlanScene;
struct Path;
}  // namespace swept

namespace swept::cli {

/// Writes the self-contained HTML viewer (three.js bundled in) of a problem and a path:
/// obstacles, the body animated along the path, the clearance plot. Throws std::runtime_error.
void write_view_file(const Problem& problem, const PlanScene& scene, const Path& path,
                     const std::string& html_file);

/// Writes the self-contained HTML viewer of a disassembly (scene data format 2): every part at
/// its mounted pose, the removals played one after the other along their paths, removed parts
/// fading. Throws std::runtime_error.
void write_disassembly_view_file(const Assembly& assembly, const DisassemblyResult& result,
                                 const std::string& html_file);

}  // namespace swept::cli
