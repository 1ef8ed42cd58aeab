#pragma once
/// Options several subcommands share, defined once: the mesh import options (--unit,
/// --file-unit, --deflection, --angular-deflection, --max-triangles) and the fitter and split-rule
/// choices, whose help texts and error messages come from the library's tables (all_fitters(),
/// all_split_rules()), so that a new fitter shows up in every command.
#include "swept/bvh/bvh.h"
#include "swept/io/mesh_io.h"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace swept::cli {

/// The import options of the commands that read mesh and CAD files.
struct ImportCliOptions {
  double deflection = 0.1;
  double angular_deflection = 0.5;
  std::size_t max_triangles = ImportOptions{}.max_triangles;
  std::string unit = "mm";
  std::string file_unit;

  ImportOptions import_options() const;
};

/// Adds --deflection, --angular-deflection, --max-triangles, --unit and --file-unit to `cmd`.
void add_import_options(CLI::App& cmd, ImportCliOptions& o);

/// Adds `--fitter NAME` to `cmd`: a name of all_fitters(), or with `allow_all` also "all".
CLI::Option* add_fitter_option(CLI::App& cmd, std::string& text, const std::string& help, bool allow_all);
/// Adds `--split NAME` to `cmd`: a name of all_split_rules(), or with `allow_all` also "all".
CLI::Option* add_split_option(CLI::App& cmd, std::string& text, const std::string& help, bool allow_all);

/// The fitters a --fitter value names: one, or every row of the table for "all". Throws
/// std::runtime_error listing the table's names for anything else.
std::vector<Fitter> fitters_from(const std::string& text, bool allow_all);
/// The split rules a --split value names, as fitters_from().
std::vector<SplitRule> split_rules_from(const std::string& text, bool allow_all);

}  // namespace swept::cli
