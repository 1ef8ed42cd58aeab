// `swept bvh`: the paper's Tables II and IV for mesh and CAD files.
#include "commands.h"
#include "output.h"

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
  double deflection = 0.1;
  double angular_deflection = 0.5;
  std::size_t max_triangles = ImportOptions{}.max_triangles;
  std::string unit = "mm";
  std::string file_unit;
  int leaf_size = 1;
  int threads = 0;
  bool json = false;
  bool markdown = false;
};

std::vector<Fitter> fitters_from(const std::string& text) {
  if (text == "all") return {Fitter::pqp, Fitter::rapid2, Fitter::inertia};
  Fitter f;
  if (!parse_fitter(text, f)) throw std::runtime_error("unknown fitter '" + text + "' (pqp, rapid2, inertia or all)");
  return {f};
}

std::vector<SplitRule> splits_from(const std::string& text) {
  if (text == "all") return {SplitRule::min_sa, SplitRule::largest};
  SplitRule s;
  if (!parse_split_rule(text, s)) throw std::runtime_error("unknown split rule '" + text + "' (min-sa, largest or all)");
  return {s};
}

void run(const BvhOptions& o) {
  const auto fitters = fitters_from(o.fitter);
  const auto splits = splits_from(o.split);
  std::unique_ptr<tbb::global_control> limit;
  if (o.threads > 0)
    limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, o.threads);

  nlohmann::json meshes = nlohmann::json::array();
  std::ostringstream md;
  md << "| file | triangles | fitter | split | nodes | depth | total SA | total volume | SA / pqp | volume / pqp | build ms |\n"
     << "|---|---:|---|---|---:|---:|---:|---:|---:|---:|---:|\n";
  Table table({"file", "fitter", "split", "triangles", "nodes", "depth", "total SA", "total volume",
               "build ms", "bytes"});
  for (const std::string& file : o.files) {
    ImportOptions io;
    io.unit = o.unit;
    io.file_unit = o.file_unit;
    io.linear_deflection = o.deflection;
    io.angular_deflection = o.angular_deflection;
    io.max_triangles = o.max_triangles;
    auto model = import_mesh(file, io);
    if (!model) throw std::runtime_error(model.error().message);
    const TriangleSoup soup = model->merged();
    nlohmann::json entry{{"file", file}, {"triangles", soup.triangles.size()},
                         {"degenerate_triangles", model->degenerate_triangles}, {"unit", o.unit}};
    nlohmann::json rows = nlohmann::json::array();
    std::map<SplitRule, BvhStats> pqp_stats;  // reference row for the ratios
    for (Fitter f : fitters) {
      for (SplitRule s : splits) {
        BuildConfig config{.fitter = f, .split = s, .leaf_size = o.leaf_size, .parallel = o.threads != 1};
        const auto t0 = std::chrono::steady_clock::now();
        auto bvh = build_bvh(soup.triangles, config);
        const auto t1 = std::chrono::steady_clock::now();
        if (!bvh) throw std::runtime_error(file + ": " + bvh.error().message);
        const double ms = std::chrono::duration<double, std::milli>(t1 - t0).count();
        const BvhStats st = stats(*bvh);
        rows.push_back({{"fitter", to_string(f)}, {"split", to_string(s)}, {"nodes", st.nodes},
                        {"depth", st.depth}, {"total_surface_area", st.total_surface_area},
                        {"total_volume", st.total_volume}, {"build_ms", ms}, {"bytes", st.bytes}});
        if (f == Fitter::pqp) pqp_stats[s] = st;
        auto ratio = [&](double v, double ref) { return pqp_stats.count(s) && ref > 0 ? fmt_fixed(v / ref, 3) : std::string("–"); };
        md << "| " << std::filesystem::path(file).filename().string() << " | " << st.triangles << " | " << to_string(f) << " | "
           << to_string(s) << " | " << st.nodes << " | " << st.depth << " | " << fmt_sci(st.total_surface_area) << " | "
           << fmt_sci(st.total_volume) << " | "
           << ratio(st.total_surface_area, pqp_stats.count(s) ? pqp_stats[s].total_surface_area : 0) << " | "
           << ratio(st.total_volume, pqp_stats.count(s) ? pqp_stats[s].total_volume : 0) << " | " << fmt_fixed(ms, 1) << " |\n";
        table.add({file, std::string(to_string(f)), std::string(to_string(s)), fmt_int(st.triangles),
                   fmt_int(st.nodes), std::to_string(st.depth), fmt_sci(st.total_surface_area),
                   fmt_sci(st.total_volume), fmt_fixed(ms, 1), fmt_int(st.bytes)});
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
  cmd->add_option("files", o->files, "Mesh or CAD files (STL, OBJ, PLY, OFF, glTF/GLB, DAE, STEP, IGES, BREP)")
      ->required()->check(CLI::ExistingFile);
  cmd->add_option("--fitter", o->fitter, "Fitter: pqp | rapid2 | inertia | all")->capture_default_str();
  cmd->add_option("--split", o->split, "Split rule: min-sa (try e1,e2,e3; smallest SA(L)+SA(R)) | largest (e1 only, PQP) | all")
      ->capture_default_str();
  cmd->add_option("--deflection", o->deflection, "BRepMesh linear deflection for CAD files, in --unit")
      ->capture_default_str()->check(CLI::PositiveNumber);
  cmd->add_option("--angular-deflection", o->angular_deflection, "BRepMesh angular deflection for CAD files, radians")
      ->capture_default_str()->check(CLI::PositiveNumber);
  cmd->add_option("--max-triangles", o->max_triangles,
                  "Most triangles a CAD file may tessellate into (estimated before meshing; past it: exit 1)")
      ->capture_default_str()->check(CLI::PositiveNumber);
  cmd->add_option("--unit", o->unit, "Length unit of the output: m, cm, mm, um, in, ft")->capture_default_str();
  cmd->add_option("--file-unit", o->file_unit, "Unit of mesh files' coordinates (default mm; CAD files carry their own)");
  cmd->add_option("--leaf-size", o->leaf_size, "Triangles per leaf")->capture_default_str()->check(CLI::PositiveNumber);
  cmd->add_option("--threads", o->threads, "Build threads (0: all cores; 1: serial build)")->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("--json", o->json, "Print one JSON document instead of the table");
  cmd->add_flag("--markdown", o->markdown, "Print a Markdown table, with SA and volume relative to pqp (list pqp first)");
  cmd->callback([o] { run(*o); });
}

}  // namespace swept::cli
