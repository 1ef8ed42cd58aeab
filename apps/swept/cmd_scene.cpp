// `swept scene`: generate the built-in CAD-like scenes (stand-ins for the paper's Table I cases).
#include "commands.h"
#include "output.h"

#include "swept/scenes/planning_suite.h"
#include "swept/scenes/scenes.h"

#include <nlohmann/json.hpp>

#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>

namespace swept::cli {
namespace {

struct SceneOptions {
  std::string name;
  std::string scale = "test";
  std::string output;
  bool list = false;
  bool json = false;
};

void list_scenes(bool json) {
  if (json) {
    nlohmann::json arr = nlohmann::json::array();
    for (const scenes::SceneInfo& s : scenes::catalog())
      arr.push_back({{"name", s.name}, {"summary", s.summary}, {"paper_body_triangles", s.paper_body_triangles},
                     {"paper_obstacle_triangles", s.paper_obstacle_triangles}});
    nlohmann::json suite = nlohmann::json::array();
    for (const scenes::SuiteInfo& s : scenes::suite_catalog())
      suite.push_back({{"name", s.name}, {"summary", s.summary}, {"ompl_app_counterpart", s.counterpart}});
    std::cout << json_text(nlohmann::json{{"scenes", arr}, {"benchmark_problems", suite}}, 2) << "\n";
    return;
  }
  for (const scenes::SceneInfo& s : scenes::catalog()) {
    std::cout << s.name << "\n    " << s.summary << "\n    paper scale (Table I): body "
              << s.paper_body_triangles << " triangles, obstacles " << s.paper_obstacle_triangles << " triangles\n";
  }
  std::cout << "\nPlanner benchmark problems (issue 13; problem.toml and an OMPL.app .cfg, --scale ignored):\n";
  for (const scenes::SuiteInfo& s : scenes::suite_catalog())
    std::cout << s.name << "\n    " << s.summary << "\n    counterpart of OMPL.app's " << s.counterpart << "\n";
}

/// A problem of the planner benchmark suite: meshes, problem.toml, NAME.cfg, witness.json.
void run_suite(const SceneOptions& o) {
  auto problem = scenes::suite_problem(o.name);
  if (!problem) throw std::runtime_error(problem.error().message);
  auto files = scenes::write_suite_problem(*problem, o.output);
  if (!files) throw std::runtime_error(files.error().message);
  const scenes::SuiteFiles& f = *files;
  if (o.json) {
    std::cout << json_text(nlohmann::json{{"scene", o.name},
                                {"problem", f.problem_toml.string()},
                                {"cfg", f.cfg.string()},
                                {"witness", f.witness.string()},
                                {"body_triangles", f.body_triangles},
                                {"obstacle_triangles", f.obstacle_triangles},
                                {"clearance", f.problem.clearance},
                                {"passage_width", problem->passage_width},
                                {"body_width", problem->body_width},
                                {"passage", problem->passage}},
                           2)
              << "\n";
    return;
  }
  Table t({"file", "role", "triangles"});
  t.add({"body.stl", "body", fmt_int(f.body_triangles)});
  t.add({"obstacles.stl", "obstacle", fmt_int(f.obstacle_triangles)});
  t.print(std::cout);
  std::cout << "passage: " << problem->passage << "\n"
            << "problem: " << f.problem_toml.string() << "\n"
            << "OMPL.app: " << f.cfg.string() << "\n"
            << "witness path: " << f.witness.string() << "\n";
}

void run(const SceneOptions& o) {
  if (o.list) {
    list_scenes(o.json);
    return;
  }
  if (o.name.empty()) throw std::runtime_error("scene: give a scene NAME or --list");
  if (o.output.empty()) throw std::runtime_error("scene: give the output directory with -o DIR");
  if (scenes::is_suite_problem(o.name)) {
    run_suite(o);
    return;
  }
  scenes::Scale scale;
  if (!scenes::parse_scale(o.scale, scale)) throw std::runtime_error("unknown scale '" + o.scale + "' (test or paper)");
  auto report = scenes::generate_scene({.name = o.name, .scale = scale, .output_dir = o.output});
  if (!report) throw std::runtime_error(report.error().message);
  const scenes::SceneReport& r = *report;
  if (o.json) {
    nlohmann::json files = nlohmann::json::array();
    for (const scenes::MeshFile& f : r.meshes)
      files.push_back({{"file", f.file}, {"role", f.body ? "body" : "obstacle"}, {"triangles", f.triangles}});
    std::cout << json_text(nlohmann::json{{"scene", r.name},
                                {"scale", o.scale},
                                {"problem", r.problem_file.string()},
                                {"meshes", files},
                                {"body_triangles", r.body_triangles},
                                {"obstacle_triangles", r.obstacle_triangles},
                                {"target_body_triangles", r.target_body_triangles},
                                {"target_obstacle_triangles", r.target_obstacle_triangles},
                                {"body_deflection_mm", r.body_deflection},
                                {"obstacle_deflection_mm", r.obstacle_deflection},
                                {"angular_deflection_rad", r.angular_deflection},
                                {"tessellations", r.tessellations},
                                {"seconds", r.seconds}},
                           2)
              << "\n";
    return;
  }
  Table t({"file", "role", "triangles"});
  for (const scenes::MeshFile& f : r.meshes) t.add({f.file, f.body ? "body" : "obstacle", fmt_int(f.triangles)});
  t.print(std::cout);
  std::cout << "body: " << r.body_triangles << " triangles (target " << r.target_body_triangles << ", deflection "
            << fmt_sci(r.body_deflection) << " mm)\n"
            << "obstacles: " << r.obstacle_triangles << " triangles (target " << r.target_obstacle_triangles
            << ", deflection " << fmt_sci(r.obstacle_deflection) << " mm)\n"
            << "angular deflection " << fmt_sci(r.angular_deflection) << " rad, " << r.tessellations
            << " BRepMesh runs, " << fmt_fixed(r.seconds, 1) << " s\n"
            << "problem: " << r.problem_file.string() << "\n";
}

}  // namespace

void add_scene_command(CLI::App& app) {
  auto o = std::make_shared<SceneOptions>();
  CLI::App* cmd = app.add_subcommand(
      "scene",
      "Generate a built-in CAD-like scene: B-rep solids modelled with OpenCASCADE, tessellated with\n"
      "BRepMesh (serial, deterministic), written as binary STL meshes plus problem.toml for `swept plan`.\n"
      "--scale paper matches the paper's Table I triangle counts (within 20 %); --scale test stays\n"
      "under 30,000 triangles. `swept scene --list` describes the scenes.\n"
      "Also the planner benchmark problems (issue 13): twisty-slot, bug-trap, hooks-1.5, hooks-1.2,\n"
      "hooks-1.1, house, cubicles, spiral-tube; each written as meshes, problem.toml, an OMPL.app\n"
      "NAME.cfg (the same problem) and witness.json (a path free by construction).\n"
      "And two assemblies for `swept disassemble`, each with an assembly.toml: gearbox (STL parts)\n"
      "and pin-in-bore (OpenCASCADE .brep parts, whose cylinders the contact model uses).");
  cmd->add_option("name", o->name, "Scene name (see --list)");
  cmd->add_option("--scale", o->scale, "test | paper")->capture_default_str();
  cmd->add_option("-o,--output", o->output, "Output directory (created if missing)");
  cmd->add_flag("--list", o->list, "Describe the scenes and exit");
  cmd->add_flag("--json", o->json, "Print the report as JSON");
  cmd->callback([o] { run(*o); });
}

}  // namespace swept::cli
