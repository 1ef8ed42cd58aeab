// `swept bench paper`, results.json: written after every scene, and read back by --merge (one run
// split into processes, e.g. a scene per process). The one serializer of the paper's results.
#include "swept/bench/output.h"
#include "swept/bench/paper.h"

#include <fstream>
#include <limits>
#include <stdexcept>

namespace swept::bench {

namespace fs = std::filesystem;

namespace {

nlohmann::json to_json(const Spread& s) {
  return {{"median", s.median}, {"min", s.min}, {"max", s.max}, {"samples", s.samples}};
}

}  // namespace

nlohmann::json results_json(const Results& r, const PaperOptions& o, const std::string& date, const std::string& machine) {
  nlohmann::json j;
  j["command"] = command_line(o);
  j["date"] = date;
  j["machine"] = machine;
  j["scale"] = o.scale;
  j["runs"] = o.runs;
  j["planner_threads"] = o.threads;
  for (const SceneRun& s : r.scenes)
    j["scenes"].push_back({{"name", s.name},
                           {"problem", s.problem_file},
                           {"body_triangles", s.body_triangles},
                           {"obstacle_triangles", s.obstacle_triangles},
                           {"paper_body_triangles", s.paper_body},
                           {"paper_obstacle_triangles", s.paper_obstacles},
                           {"generate_s", s.generate_s},
                           {"load_ms", s.load_ms},
                           {"error", s.error}});
  for (const MeshRow& m : r.meshes) {
    nlohmann::json trees = nlohmann::json::array();
    for (const TreeFigures& t : m.trees)
      trees.push_back({{"fitter", std::string(to_string(t.fitter))},
                       {"split", std::string(to_string(t.split))},
                       {"total_surface_area_mm2", t.stats.total_surface_area},
                       {"total_volume_mm3", t.stats.total_volume},
                       {"nodes", t.stats.nodes},
                       {"depth", t.stats.depth},
                       {"bytes", t.stats.bytes},
                       {"build_ms", to_json(t.build_ms)}});
    j["meshes"].push_back({{"name", m.name},
                           {"source", m.source},
                           {"kind", m.kind},
                           {"triangles", m.triangles},
                           {"paper_triangles", m.paper_triangles},
                           {"trees", trees},
                           {"fcl_obbrss_build_ms", to_json(m.fcl_obbrss_build_ms)},
                           {"fcl_rss_build_ms", to_json(m.fcl_rss_build_ms)}});
  }
  for (const PlanRow& p : r.plans) {
    const PlanRow* base = find_plan(r, p.scene, baseline_fitter(), p.split);
    const Ratio sp = base ? ratio_of(base->cpu_ms, p.cpu_ms) : Ratio{};
    j["plans"].push_back({{"scene", p.scene},
                          {"fitter", std::string(to_string(p.fitter))},
                          {"split", std::string(to_string(p.split))},
                          {"cpu_ms", to_json(p.cpu_ms)},
                          {"wall_ms", to_json(p.wall_ms)},
                          {"speedup_vs_pqp", {{"median", sp.value}, {"min", sp.low}, {"max", sp.high}}},
                          {"statuses", p.statuses},
                          {"solved", p.solved},
                          {"distance_queries", p.distance_queries},
                          {"waypoints", p.waypoints},
                          {"same_path_every_run", p.same_path}});
  }
  for (const QueryRow& q : r.queries)
    j["queries"].push_back({{"scene", q.scene},
                            {"set", q.set},
                            {"engine", q.engine},
                            {"poses", q.poses},
                            {"collide_us", to_json(q.collide_us)},
                            {"distance_us", to_json(q.distance_us)}});
  j["ompl"]["status"] = r.ompl_status;
  j["ompl"]["time_limit_s"] = r.ompl_time_limit;
  j["ompl"]["problems"] = nlohmann::json::array();
  for (const OmplRow& w : r.ompl)
    j["ompl"]["problems"].push_back({{"problem", w.problem},
                                     {"successes", w.successes},
                                     {"runs", w.runs},
                                     {"median_ms", w.median_ms},
                                     {"min_ms", w.min_ms},
                                     {"max_ms", w.max_ms},
                                     {"fcl_build_ms", w.fcl_build_ms},
                                     {"swept_inertia_ms", w.swept_ms},
                                     {"swept_status", w.swept_status}});
  for (const ClaimVerdict& c : assess_claims(rows_of(r), o.runs))
    j["claims"].push_back({{"claim", c.claim}, {"verdict", std::string(to_string(c.verdict))}, {"finding", c.text()}});
  j["peer_findings"] = peer_findings(rows_of(r));
  j["notes"] = r.notes;
  return j;
}

// ---- merging earlier runs (one run split into processes, e.g. a scene per process) ------------

namespace {

Spread spread_from_json(const nlohmann::json& j) {
  std::vector<double> samples;
  if (j.is_object() && j.contains("samples"))
    for (const auto& v : j["samples"])
      if (v.is_number()) samples.push_back(v.get<double>());
  return spread_of(samples);
}

template <class T>
T get_or(const nlohmann::json& j, const char* key, T fallback) {
  return j.contains(key) && !j[key].is_null() ? j[key].get<T>() : fallback;
}

Fitter fitter_from(const nlohmann::json& j, const std::string& file) {
  Fitter f;
  if (!parse_fitter(j.get<std::string>(), f)) throw std::runtime_error(file + ": unknown fitter " + json_text(j));
  return f;
}

SplitRule split_from(const nlohmann::json& j, const std::string& file) {
  SplitRule s;
  if (!parse_split_rule(j.get<std::string>(), s)) throw std::runtime_error(file + ": unknown split rule " + json_text(j));
  return s;
}

}  // namespace

/// Appends the results of DIR/results.json (written by this command) to `res`.
void merge_results(const fs::path& dir, const PaperOptions& o, Results& res) {
  const fs::path file = dir / "results.json";
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file.string() + ": cannot read (--merge names output directories of earlier runs)");
  nlohmann::json j;
  try {
    in >> j;
    const std::string f = file.string();
    if (get_or<int>(j, "runs", 0) != o.runs)
      res.notes.push_back(f + " was measured with --runs " + std::to_string(get_or<int>(j, "runs", 0)));
    if (get_or<std::string>(j, "scale", "") != o.scale)
      throw std::runtime_error(f + ": scale '" + get_or<std::string>(j, "scale", "") + "', not '" + o.scale + "'");
    res.notes.push_back("merged " + f + (get_or<bool>(j, "complete", false) ? "" : " (an interrupted, partial run)") +
                        ", measured " + get_or<std::string>(j, "date", "?") + " by `" +
                        get_or<std::string>(j, "command", "?") + "`");
    for (const auto& s : j.value("scenes", nlohmann::json::array())) {
      SceneRun sr;
      sr.name = s.at("name");
      sr.problem_file = get_or<std::string>(s, "problem", "");
      sr.body_triangles = get_or<std::size_t>(s, "body_triangles", 0);
      sr.obstacle_triangles = get_or<std::size_t>(s, "obstacle_triangles", 0);
      sr.paper_body = get_or<std::size_t>(s, "paper_body_triangles", 0);
      sr.paper_obstacles = get_or<std::size_t>(s, "paper_obstacle_triangles", 0);
      sr.generate_s = get_or<double>(s, "generate_s", 0.0);
      sr.load_ms = get_or<double>(s, "load_ms", 0.0);
      sr.error = get_or<std::string>(s, "error", "");
      res.scenes.push_back(std::move(sr));
    }
    for (const auto& m : j.value("meshes", nlohmann::json::array())) {
      MeshRow row;
      row.name = m.at("name");
      row.source = get_or<std::string>(m, "source", "");
      row.kind = get_or<std::string>(m, "kind", "");
      row.triangles = get_or<std::size_t>(m, "triangles", 0);
      row.paper_triangles = get_or<std::size_t>(m, "paper_triangles", 0);
      for (const auto& t : m.at("trees")) {
        TreeFigures tf{fitter_from(t.at("fitter"), f), split_from(t.at("split"), f), {}, spread_from_json(t["build_ms"])};
        tf.stats.triangles = row.triangles;
        tf.stats.total_surface_area = t.at("total_surface_area_mm2");
        tf.stats.total_volume = t.at("total_volume_mm3");
        tf.stats.nodes = get_or<std::size_t>(t, "nodes", 0);
        tf.stats.depth = get_or<int>(t, "depth", 0);
        tf.stats.bytes = get_or<std::size_t>(t, "bytes", 0);
        row.trees.push_back(tf);
      }
      row.fcl_obbrss_build_ms = spread_from_json(m["fcl_obbrss_build_ms"]);
      row.fcl_rss_build_ms = spread_from_json(m["fcl_rss_build_ms"]);
      res.meshes.push_back(std::move(row));
    }
    for (const auto& p : j.value("plans", nlohmann::json::array())) {
      PlanRow pr;
      pr.scene = p.at("scene");
      pr.fitter = fitter_from(p.at("fitter"), f);
      pr.split = split_from(p.at("split"), f);
      pr.cpu_ms = spread_from_json(p["cpu_ms"]);
      pr.wall_ms = spread_from_json(p["wall_ms"]);
      pr.statuses = p.value("statuses", std::vector<std::string>{});
      pr.solved = get_or<int>(p, "solved", 0);
      pr.distance_queries = get_or<std::uint64_t>(p, "distance_queries", 0);
      pr.waypoints = get_or<std::size_t>(p, "waypoints", 0);
      pr.same_path = get_or<bool>(p, "same_path_every_run", true);
      res.plans.push_back(std::move(pr));
    }
    for (const auto& q : j.value("queries", nlohmann::json::array())) {
      QueryRow row(q.at("scene"), q.at("set"), q.at("engine"), get_or<std::size_t>(q, "poses", 0));
      row.collide_us = spread_from_json(q["collide_us"]);
      row.distance_us = spread_from_json(q["distance_us"]);
      res.queries.push_back(std::move(row));
    }
    const auto& om = j.value("ompl", nlohmann::json::object());
    const auto problems = om.value("problems", nlohmann::json::array());
    if (!problems.empty()) {
      res.ompl_status = get_or<std::string>(om, "status", "");
      res.ompl_time_limit = get_or<double>(om, "time_limit_s", 0.0);
      const double nan = std::numeric_limits<double>::quiet_NaN();
      for (const auto& w : problems) {
        OmplRow row;
        row.problem = w.at("problem");
        row.successes = get_or<int>(w, "successes", 0);
        row.runs = get_or<int>(w, "runs", 0);
        row.median_ms = get_or<double>(w, "median_ms", nan);
        row.min_ms = get_or<double>(w, "min_ms", nan);
        row.max_ms = get_or<double>(w, "max_ms", nan);
        row.fcl_build_ms = get_or<double>(w, "fcl_build_ms", nan);
        row.swept_ms = get_or<double>(w, "swept_inertia_ms", nan);
        row.swept_status = get_or<std::string>(w, "swept_status", "");
        res.ompl.push_back(row);
      }
    }
    for (const auto& n : j.value("notes", nlohmann::json::array())) res.notes.push_back(n.get<std::string>());
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(file.string() + ": not a results.json of `swept bench paper`: " + e.what());
  }
}

/// Writes results.json, report.md and the plots; returns the report. Called after every scene so

}  // namespace swept::bench
