// `swept mesh-stats`: how widely triangle sizes and shapes spread in mesh and CAD files.
#include "cli_options.h"
#include "commands.h"
#include "output.h"
#include "progress_line.h"

#include "swept/io/mesh_io.h"
#include "swept/scenes/mesh_stats.h"

#include <nlohmann/json.hpp>

#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace swept::cli {
namespace {

struct MeshStatsOptions {
  std::vector<std::string> files;
  ImportCliOptions import;
  bool json = false;
  bool quiet = false;
  bool markdown = false;
};

void run(const MeshStatsOptions& o) {
  const std::vector<std::string> header{"file", "triangles", "degenerate", "area max/min", "median aspect", "aspect>10"};
  Table table(header);
  std::string md = "|";
  for (const std::string& h : header) md += " " + h + " |";
  md += "\n|---|---:|---:|---:|---:|---:|\n";
  nlohmann::json meshes = nlohmann::json::array();
  for (const std::string& file : o.files) {
    auto model = import_mesh_with_progress(file, o.import.import_options(), o.quiet);
    if (!model) throw std::runtime_error(model.error().message);
    for (const std::string& w : model->warnings) std::cerr << "swept: warning: " << w << "\n";
    const scenes::MeshStats s = scenes::mesh_stats(model->merged().triangles);
    table.add({file, fmt_int(s.triangles), fmt_int(s.degenerate), fmt_sci(s.area_ratio), fmt_fixed(s.aspect_median, 2),
               fmt_fixed(100.0 * s.aspect_over_10, 1) + " %"});
    md += "| " + file + " | " + fmt_int(s.triangles) + " | " + fmt_int(s.degenerate) + " | " + fmt_sci(s.area_ratio) +
          " | " + fmt_fixed(s.aspect_median, 2) + " | " + fmt_fixed(100.0 * s.aspect_over_10, 1) + " % |\n";
    meshes.push_back({{"file", file},
                      {"unit", o.import.unit},
                      {"triangles", s.triangles},
                      {"degenerate_triangles", s.degenerate},
                      {"area_min", s.area_min},
                      {"area_max", s.area_max},
                      {"area_ratio", s.area_ratio},
                      {"aspect_ratio_median", s.aspect_median},
                      {"aspect_ratio_max", s.aspect_max},
                      {"aspect_ratio_over_10_fraction", s.aspect_over_10},
                      {"warnings", model->warnings}});
  }
  if (o.json) {
    std::cout << json_text(nlohmann::json{{"meshes", meshes}}, 2) << "\n";
  } else if (o.markdown) {
    std::cout << md;
  } else {
    table.print(std::cout);
  }
}

}  // namespace

void add_mesh_stats_command(CLI::App& app) {
  auto o = std::make_shared<MeshStatsOptions>();
  CLI::App* cmd = app.add_subcommand(
      "mesh-stats",
      "Triangle-size and shape spread per file: triangles, degenerate triangles (2*area/longest edge^2\n"
      "<= 1e-12), largest/smallest area ratio, median aspect ratio (longest edge / smallest height) and\n"
      "the share of triangles with aspect ratio > 10 (both over the non-degenerate triangles).\n"
      "A file with several parts counts as one mesh.");
  cmd->add_option("files", o->files, "Mesh or CAD files (STL, OBJ, PLY, OFF, 3MF, glTF/GLB, DAE, STEP, IGES, BREP)")
      ->required()->check(CLI::ExistingFile);
  add_import_options(*cmd, o->import);
  cmd->add_flag("--json", o->json, "Print one JSON document instead of the table");
  cmd->add_flag("-q,--quiet", o->quiet, "No progress line while a CAD file is read (none either when stderr is not a terminal)");
  cmd->add_flag("--markdown", o->markdown, "Print a Markdown table instead of the aligned one");
  cmd->callback([o] { run(*o); });
}

}  // namespace swept::cli
