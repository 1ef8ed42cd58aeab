// A problem file or a part of an assembly (part_source.h).
#include "part_source.h"

#include "swept/plan/planner.h"

#include <stdexcept>

namespace swept::cli {

void add_part_options(CLI::App& cmd, ProblemSource& source) {
  cmd.add_option("--part", source.part,
                 "Read the first argument as an assembly (as swept disassemble reads it) and take this part out: the "
                 "part as the body at its mounted pose, every other part an obstacle, the goal outside their box, any "
                 "rotation, the contact model of swept disassemble (names as swept disassemble prints them)");
  cmd.add_option("--tolerance", source.tolerance,
                 "The contact tolerance: how far mates may reach into each other at a start or goal in contact "
                 "(a problem file's planner.contact_tolerance; with --part default 2 x --deflection)")
      ->check(CLI::PositiveNumber);
  add_import_options(cmd, source.import);
}

PartProblem load_problem_source(const ProblemSource& source) {
  if (source.part.empty()) {
    auto problem = load_problem(source.file);
    if (!problem) throw std::runtime_error(problem.error().message);
    if (source.fitter) problem->build.fitter = *source.fitter;
    if (source.tolerance > 0) problem->contact_tolerance = source.tolerance;
    auto scene = load_scene(*problem, problem->build);
    if (!scene) throw std::runtime_error(scene.error().message);
    return {std::move(*problem), std::move(*scene)};
  }
  auto assembly = read_assembly(source.file, AssemblyReadOptions{source.import.import_options()});
  if (!assembly) throw std::runtime_error(assembly.error().message);
  const auto part = find_part(*assembly, source.part);
  if (!part) throw std::runtime_error(part.error().message);
  if (source.fitter) throw std::runtime_error("--fitter goes with a problem file, not with --part");
  DisassemblyOptions options;
  options.clearance = source.clearance.value_or(0.01);
  options.tolerance = source.tolerance > 0 ? source.tolerance : 2.0 * source.import.deflection;
  std::vector<std::size_t> all(assembly->parts.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
  auto pp = part_problem(*assembly, {*part}, all, options);
  if (!pp) throw std::runtime_error(source.file + ": " + pp.error().message);
  pp->scene.warnings = assembly->warnings;
  pp->problem.time_limit = 60.0;
  pp->problem.threads = 0;
  return std::move(*pp);
}

}  // namespace swept::cli
