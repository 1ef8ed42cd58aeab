// `swept bvh`: the paper's Tables II and IV for mesh and CAD files.
#include "cli_options.h"
#include "commands.h"
#include "output.h"
#include "progress_line.h"

#include "swept/bvh/bvh.h"
#include "swept/io/mesh_io.h"

#include <nlohmann/json.hpp>
#include <tbb/global_control.h>

#include <chrono>
#include <filesystem>
#include <map>
#include <sstream>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace swept::cli {
namespace {

struct BvhOptions {
  std::vector<std::string> files;
  std::string fitter = "inertia";
  std::string split = "min-sa";
  ImportCliOptions import;
  int leaf_size = 1;
  int threads = 0;
  bool json = false;
  bool quiet = false;
  bool markdown = false;
};

void run(const BvhOptions& o) {
  const auto fitters = fitters_from(o.fitter, true);
  const auto splits = split_rules_from(o.split, true);
  std::unique_ptr<tbb::global_control> limit;
  if (o.threads > 0)
    limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, o.threads);

  nlohmann::json meshes = nlohmann::json::array();
  std::ostringstream md;
  const std::string base(all_fitters().front().name);  // the ratios' reference: the table's first fitter
  md << "| file | triangles | fitter | split | nodes | depth | total SA | total volume | SA / " << base << " | volume / "
     << base << " | build ms |\n"
     << "|---|---:|---|---|---:|---:|---:|---:|---:|---:|---:|\n";
  Table table({"file", "fitter", "split", "triangles", "nodes", "depth", "total SA", "total volume",
               "build ms", "bytes", "bytes/tri"});
  for (const std::string& file : o.files) {
    auto model = import_mesh_with_progress(file, o.import.import_options(), o.quiet);
    if (!model) throw std::runtime_error(model.error().message);
    for (const std::string& w : model->warnings) std::cerr << "swept: warning: " << w << "\n";
    const TriangleSoup soup = model->merged();
    nlohmann::json entry{{"file", file}, {"triangles", soup.triangles.size()},
                         {"degenerate_triangles", model->degenerate_triangles}, {"unit", o.import.unit},
                         {"warnings", model->warnings}};
    nlohmann::json rows = nlohmann::json::array();
    std::map<SplitRule, BvhStats> base_stats;  // reference row for the ratios (the table's first fitter)
    for (Fitter f : fitters) {
      for (SplitRule s : splits) {
        BuildConfig config{.fitter = f, .split = s, .leaf_size = o.leaf_size, .parallel = o.threads != 1};
        const auto t0 = std::chrono::steady_clock::now();
        auto bvh = build_bvh(soup.triangles, config);
        const auto t1 = std::chrono::steady_clock::now();
        if (!bvh) throw std::runtime_error(file + ": " + bvh.error().message);
        const double ms = std::chrono::duration<double, std::milli>(t1 - t0).count();
        const BvhStats st = stats(*bvh);
        const double per_triangle = static_cast<double>(st.bytes) / static_cast<double>(st.triangles);
        rows.push_back({{"fitter", to_string(f)}, {"split", to_string(s)}, {"nodes", st.nodes},
                        {"depth", st.depth}, {"total_surface_area", st.total_surface_area},
                        {"total_volume", st.total_volume}, {"build_ms", ms}, {"leaf_size", o.leaf_size},
                        {"bytes", st.bytes}, {"bytes_per_triangle", per_triangle}});
        if (f == all_fitters().front().fitter) base_stats[s] = st;
        auto ratio = [&](double v, double ref) { return base_stats.count(s) && ref > 0 ? fmt_fixed(v / ref, 3) : std::string("–"); };
        md << "| " << std::filesystem::path(file).filename().string() << " | " << st.triangles << " | " << to_string(f) << " | "
           << to_string(s) << " | " << st.nodes << " | " << st.depth << " | " << fmt_sci(st.total_surface_area) << " | "
           << fmt_sci(st.total_volume) << " | "
           << ratio(st.total_surface_area, base_stats.count(s) ? base_stats[s].total_surface_area : 0) << " | "
           << ratio(st.total_volume, base_stats.count(s) ? base_stats[s].total_volume : 0) << " | " << fmt_fixed(ms, 1) << " |\n";
        table.add({file, std::string(to_string(f)), std::string(to_string(s)), fmt_int(st.triangles),
                   fmt_int(st.nodes), std::to_string(st.depth), fmt_sci(st.total_surface_area),
                   fmt_sci(st.total_volume), fmt_fixed(ms, 1), fmt_int(st.bytes), fmt_fixed(per_triangle, 0)});
      }
    }
    entry["fitters"] = rows;
    meshes.push_back(entry);
  }
  if (o.json) {
    std::cout << json_text(nlohmann::json{{"meshes", meshes}}, 2) << "\n";
  } else if (o.markdown) {
    std::cout << md.str();
  } else {
    table.print(std::cout);
  }
}

}  // namespace

void add_bvh_command(CLI::App& app) {
  auto o = std::make_shared<BvhOptions>();
  CLI::App* cmd = app.add_subcommand(
      "bvh",
      "Build RSS trees and report the paper's Table II/IV figures: triangles, nodes, depth, total RSS\n"
      "surface area and volume, build time and memory, per file and fitter. A CAD file with several\n"
      "solids counts as one soup (all parts together).");
  cmd->add_option("files", o->files, "Mesh or CAD files (STL, OBJ, PLY, OFF, 3MF, glTF/GLB, DAE, STEP, IGES, BREP)")
      ->required()->check(CLI::ExistingFile);
  add_fitter_option(*cmd, o->fitter, "Fitter", true)->capture_default_str();
  add_split_option(*cmd, o->split, "Split rule", true)->capture_default_str();
  add_import_options(*cmd, o->import);
  cmd->add_option("--leaf-size", o->leaf_size, "Triangles per leaf")->capture_default_str()->check(CLI::PositiveNumber);
  cmd->add_option("--threads", o->threads, "Build threads (0: all cores; 1: serial build)")->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("--json", o->json, "Print one JSON document instead of the table");
  cmd->add_flag("-q,--quiet", o->quiet, "No progress line while a CAD file is read (none either when stderr is not a terminal)");
  cmd->add_flag("--markdown", o->markdown, "Print a Markdown table, with SA and volume relative to " + std::string(all_fitters().front().name) +
                    " (list it first)");
  cmd->callback([o] { run(*o); });
}

}  // namespace swept::cli
