#pragma once
/// What both programs of the CLI share: `swept` itself and `swept-tools` (the scene generators
/// and the benchmarks, which `swept scene` and `swept bench` run; tools_path.h).
#include <CLI/CLI.hpp>

namespace swept::cli {

/// Parses the command line with `app` and runs the chosen subcommand. --help and --version end
/// with code 0; any other command-line error (a missing file, an unknown option, a value out of
/// range) is bad input: one line on stderr and code 1, not CLI11's own codes (105, 106, ...);
/// a subcommand's ExitCode ends with its code, any other exception with one line and code 1.
int run_cli(CLI::App& app, int argc, char** argv);

}  // namespace swept::cli
