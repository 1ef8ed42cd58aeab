#include "cli_options.h"

#include <stdexcept>

namespace swept::cli {

ImportOptions ImportCliOptions::import_options() const {
  ImportOptions io;
  io.unit = unit;
  io.file_unit = file_unit;
  io.linear_deflection = deflection;
  io.angular_deflection = angular_deflection;
  io.max_triangles = max_triangles;
  return io;
}

void add_import_options(CLI::App& cmd, ImportCliOptions& o) {
  cmd.add_option("--deflection", o.deflection, "BRepMesh linear deflection for CAD files, in --unit")
      ->capture_default_str()->check(CLI::PositiveNumber);
  cmd.add_option("--angular-deflection", o.angular_deflection, "BRepMesh angular deflection for CAD files, radians")
      ->capture_default_str()->check(CLI::PositiveNumber);
  cmd.add_option("--max-triangles", o.max_triangles,
                 "Most triangles a CAD file may tessellate into (estimated before meshing), or a 3MF build place; past it: exit 1")
      ->capture_default_str()->check(CLI::PositiveNumber);
  cmd.add_option("--unit", o.unit, "Length unit of the output: m, cm, mm, um, in, ft")->capture_default_str();
  cmd.add_option("--file-unit", o.file_unit, "Unit of mesh files' coordinates (default mm; CAD and 3MF files carry their own)");
}

CLI::Option* add_fitter_option(CLI::App& cmd, std::string& text, const std::string& help, bool allow_all) {
  return cmd.add_option("--fitter", text, help + ": " + fitter_names(" | ") + (allow_all ? " | all" : ""));
}

CLI::Option* add_split_option(CLI::App& cmd, std::string& text, const std::string& help, bool allow_all) {
  std::string choices;
  for (const SplitRuleInfo& s : all_split_rules())
    choices += (choices.empty() ? "" : " | ") + std::string(s.name) + " = " + std::string(s.summary);
  return cmd.add_option("--split", text, help + ": " + choices + (allow_all ? " | all" : ""));
}

std::vector<Fitter> fitters_from(const std::string& text, bool allow_all) {
  std::vector<Fitter> out;
  if (allow_all && text == "all") {
    for (const FitterInfo& f : all_fitters()) out.push_back(f.fitter);
    return out;
  }
  Fitter f;
  if (!parse_fitter(text, f))
    throw std::runtime_error("unknown fitter '" + text + "' (" + fitter_names() + (allow_all ? " or all)" : ")"));
  return {f};
}

std::vector<SplitRule> split_rules_from(const std::string& text, bool allow_all) {
  std::vector<SplitRule> out;
  if (allow_all && text == "all") {
    for (const SplitRuleInfo& s : all_split_rules()) out.push_back(s.rule);
    return out;
  }
  SplitRule s;
  if (!parse_split_rule(text, s))
    throw std::runtime_error("unknown split rule '" + text + "' (" + split_rule_names() + (allow_all ? " or all)" : ")"));
  return {s};
}

}  // namespace swept::cli
