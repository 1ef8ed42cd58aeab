// `swept bench paper`, the driver: the scenes, the real CAD, OMPL, the merged runs, the outputs.
#include "swept/bench/output.h"
#include "swept/bench/paper.h"
#include "swept/bench/timing.h"

#include "swept/scenes/scenes.h"

#include <algorithm>
#include <iostream>
#include <stdexcept>

namespace swept::bench {

namespace fs = std::filesystem;

std::vector<std::string> planned_scenes(const Results& r) {
  std::vector<std::string> names;
  for (const SceneRun& s : r.scenes)
    if (s.error.empty()) names.push_back(s.name);
  return names;
}

const PlanRow* find_plan(const Results& r, const std::string& scene, Fitter f, SplitRule s) {
  return find_plan(r.plans, scene, f, s);
}

const QueryRow* find_query(const Results& r, const std::string& scene, const std::string& set, const std::string& engine) {
  return find_query(r.queries, scene, set, engine);
}

PaperRows rows_of(const Results& r) { return {r.meshes, r.plans, r.queries, planned_scenes(r)}; }

namespace {

/// Writes results.json, report.md and the plots; returns the report. Called after every scene so
/// that a long run interrupted part-way leaves the results measured so far.
std::string write_outputs(const Results& res, const PaperOptions& o, const fs::path& out, bool final_write) {
  const std::string date = utc_now(), machine = machine_description();
  std::vector<std::string> plots;
  write_plots(res, out / "img", plots);
  // Whole or not at all: an interrupted run keeps the previous complete results.json/report.md.
  nlohmann::json j = results_json(res, o, date, machine);
  j["complete"] = final_write;
  write_output((out / "results.json").string(), json_text(j, 2) + "\n");
  std::string md = markdown_report(res, o, date, machine, plots);
  if (!final_write) md = "> **Partial results**: the run was still going when this was written.\n\n" + md;
  write_output((out / "report.md").string(), md);
  if (final_write)
    log_line(o, std::string("bench paper: wrote ") + (out / "results.json").string() + ", " + (out / "report.md").string() + " and " + std::to_string(plots.size()) + " plots in " + (out / "img").string());
  return md;
}

}  // namespace

void log_line(const PaperOptions& o, const std::string& line) {
  if (o.log) o.log(line);
  else std::cerr << line << "\n";
}

std::string run_paper_benchmark(const PaperOptions& o) {
  scenes::Scale scale;
  if (!scenes::parse_scale(o.scale, scale)) throw std::runtime_error("unknown scale '" + o.scale + "' (test or paper)");
  const bool paper = scale == scenes::Scale::paper;
  if (o.runs < 1) throw std::runtime_error("--runs must be at least 1");
  if (o.out.empty()) throw std::runtime_error("give the output directory with --out DIR");
  for (const std::string& n : o.only) {
    bool known = false;
    for (const scenes::SceneInfo& s : scenes::catalog()) known = known || s.name == n;
    if (!known) throw std::runtime_error("--only: unknown scene '" + n + "' (see `swept scene --list`)");
  }
  const int poses = o.poses > 0 ? o.poses : (paper ? 20 : 5);
  const fs::path out(o.out);
  std::error_code ec;
  fs::create_directories(out, ec);
  if (ec || !fs::is_directory(out)) throw std::runtime_error(out.string() + ": cannot create the output directory");

  PaperSteps steps{o};
  for (const scenes::SceneInfo& info : scenes::catalog())
    if (!o.no_scenes && (o.only.empty() || std::find(o.only.begin(), o.only.end(), info.name) != o.only.end()))
      steps.total += scene_steps();
  steps.total += (o.no_cad ? 0 : cad_steps(paper)) + (o.no_ompl ? 0 : 1);

  Results res;
  for (const scenes::SceneInfo& info : scenes::catalog()) {
    if (o.no_scenes) break;
    if (!o.only.empty() && std::find(o.only.begin(), o.only.end(), info.name) == o.only.end()) continue;
    res.scenes.emplace_back();
    SceneRun& sr = res.scenes.back();
    sr.name = info.name;
    sr.paper_body = info.paper_body_triangles;
    sr.paper_obstacles = info.paper_obstacle_triangles;
    fs::path problem;
    if (!o.scenes_dir.empty() && fs::exists(fs::path(o.scenes_dir) / info.name / "problem.toml")) {
      problem = fs::path(o.scenes_dir) / info.name / "problem.toml";
      res.notes.push_back(info.name + ": scene files taken from " + problem.parent_path().string() +
                          " (generated earlier by `swept scene " + info.name + " --scale " + o.scale + "`)");
    } else {
      log_line(o, std::string("bench paper: generating ") + info.name + " at scale " + o.scale);
      const auto t0 = Clock::now();
      auto report = scenes::generate_scene({.name = info.name, .scale = scale, .output_dir = out / "scenes" / info.name});
      sr.generate_s = ms_since(t0) / 1e3;
      if (!report) {
        sr.error = report.error().message;
        res.notes.push_back(info.name + " not run: " + sr.error);
        log_line(o, std::string("bench paper: ") + res.notes.back());
        for (std::size_t i = scene_steps(); i > 0; --i) steps.step(info.name + " not run");
        continue;
      }
      problem = report->problem_file;
    }
    sr.problem_file = problem.string();
    run_scene(o, info, problem, res, poses, steps);
    write_outputs(res, o, out, false);
  }
  if (!o.no_cad) {
    run_cad(o, paper, res, steps);
    write_outputs(res, o, out, false);
  }
  run_ompl(o, paper, out, res);
  if (!o.no_ompl) steps.step("OMPL");
  const bool ompl_measured = !res.ompl.empty();
  const std::string ompl_status = res.ompl_status;
  for (const std::string& d : o.merge) merge_results(d, o, res);
  if (ompl_measured) res.ompl_status = ompl_status;  // measured here: this run's OMPL wins
  if (res.ompl.empty() && !o.merge.empty() && o.no_ompl) res.ompl_status = "not run (--no-ompl) in any merged run";
  return write_outputs(res, o, out, true);
}

}  // namespace swept::bench
