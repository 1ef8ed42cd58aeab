#pragma once
// What `swept plan` and `swept check` read: a problem file, or with --part the problem of taking
// one part out of an assembly (swept::part_problem, as `swept disassemble` poses it).
#include "cli_options.h"

#include "swept/assembly/disassemble.h"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace swept::cli {

struct ProblemSource {
  std::string file;  ///< problem file, or the assembly with `part`
  std::optional<Fitter> fitter;     ///< overrides the problem file's
  std::string part;
  std::optional<double> clearance;  ///< with `part`: default 0.01
  double tolerance = 0.0;           ///< with `part`: ≤ 0, twice the deflection
  ImportCliOptions import;
};

/// --part, --tolerance and the import options (each command has its own --clearance).
void add_part_options(CLI::App& cmd, ProblemSource& source);

/// Reads the problem (and builds the scene), or the assembly and the part's problem. Throws
/// std::runtime_error naming the file.
PartProblem load_problem_source(const ProblemSource& source);

}  // namespace swept::cli
