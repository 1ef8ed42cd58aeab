// `swept bench paper`: the paper's Tables II–IV reproduced in one run, with the peers beside
// them. For each scene of `swept scene` (body † and obstacles ‡) and a handful of real CAD files
// of ../shared/data, for each fitter (pqp, rapid2, inertia) under both split rules (min-sa,
// largest):
// - Table II: total RSS surface area and volume of the tree;
// - Table III: planner wall time per scene (median of N runs, min–max), speed-up against pqp,
//   distance queries issued;
// - Table IV: tree build time (serial build, median of N runs);
// - peers: FCL's OBBRSS and RSS build times on the same meshes, collide/distance times on three
//   seeded pose sets per scene (overlapping, near contact, far), and OMPL RRTConnect + FCL on the
//   same problems (merged from the `bench_plan` program when it is built).
// Writes results.json, report.md and SVG plots (img/) into the output directory.
#include "seeded_rng.h"
#include "commands.h"
#include "fcl_peer.h"
#include "output.h"
#include "paper_verdicts.h"
#include "svg_plot.h"

#include "swept/bvh/bvh.h"
#include "swept/io/mesh_io.h"
#include "swept/plan/planner.h"
#include "swept/plan/problem.h"
#include "swept/query/query.h"
#include "swept/scenes/scenes.h"

#include <nlohmann/json.hpp>
#include <sys/utsname.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace swept::cli {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

/// CPU time of the whole process, ms. The benchmark times with it: on a shared machine the
/// wall clock also counts the time other processes hold the cores, the CPU time does not.
double cpu_ms() {
  timespec ts{};
  ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) * 1e-6;
}

struct PaperOptions {
  std::string scale = "test";
  int runs = 3;
  std::string out;
  std::string scenes_dir;  ///< pre-generated scenes (DIR/<name>/problem.toml); empty: generate
  std::string data_dir = "../shared/data";
  std::vector<std::string> only;  ///< scene names; empty: all
  bool no_scenes = false;
  bool no_cad = false;
  std::vector<std::string> merge;  ///< output directories of earlier runs whose results.json are merged in
  int poses = 0;             ///< per pose set; 0: 5 at test scale, 20 at paper scale
  int threads = 1;           ///< planner threads
  double time_limit = 0.0;   ///< planner time limit, s; 0: the problem's
  bool no_ompl = false;
  std::string bench_plan;    ///< path of the bench_plan program; empty: beside this build
  double ompl_time_limit = 0.0;  ///< s; 0: 10 at test scale, 60 at paper scale
};

// ---- statistics (Spread, Ratio and the rows are in paper_verdicts.h) --------------------------- --------------------------------------------------------------------------------

nlohmann::json to_json(const Spread& s) {
  return {{"median", s.median}, {"min", s.min}, {"max", s.max}, {"samples", s.samples}};
}

/// "12.3 (11.9–12.8)", or "12.3" for a single run.
std::string fmt_spread(const Spread& s, int digits) {
  if (!std::isfinite(s.median)) return "n/a";
  if (s.samples.size() <= 1) return fmt_fixed(s.median, digits);
  return fmt_fixed(s.median, digits) + " (" + fmt_fixed(s.min, digits) + "–" + fmt_fixed(s.max, digits) + ")";
}

std::string fmt_g(double v, int digits = 4) {
  if (!std::isfinite(v)) return "n/a";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

// ---- seeded pose sets --------------------------------------------------------------------------

using SplitMix = SeededRng;

struct PoseSet {
  std::string name;
  std::vector<Pose> poses;  ///< poses of the body; the obstacles stay at the identity
};

/// Three sets of body poses against the obstacles: overlapping (colliding), near contact
/// (0 < distance ≤ 1 % of the body's size) and far (bounding spheres apart).
std::vector<PoseSet> make_pose_sets(const PlanScene& scene, int count, std::uint64_t seed) {
  const Bvh& a = scene.obstacle_tree;
  const Bvh& b = scene.body_tree;
  const Aabb box_a = bounds(scene.obstacles.triangles);
  const Vec3 ca = box_a.center(), cb = bounds(scene.body.triangles).center();
  const Pose id;
  SplitMix rng{seed};
  auto place = [&](const Mat3& r, const Vec3& body_center) { return Pose{r, body_center - r * cb}; };
  std::vector<PoseSet> sets{{"overlapping", {}}, {"near", {}}, {"far", {}}};
  const int attempts = 400 * count;
  for (int k = 0; k < attempts && static_cast<int>(sets[0].poses.size()) < count; ++k) {
    const Mat3 r = rng.rotation();
    const Vec3 u(rng.uniform(), rng.uniform(), rng.uniform());
    const Vec3 target = box_a.min + u.cwiseProduct(box_a.max - box_a.min);
    const Pose p = place(r, target);
    if (collide(a, id, b, p).colliding) sets[0].poses.push_back(p);
  }
  // Near contact: from an overlapping pose, bisect a translation along a random direction until
  // 0 < distance ≤ limit. Moving the body by a.extent + b.extent separates the bounding spheres.
  const double limit = 0.01 * b.extent;
  const std::size_t n_overlap = sets[0].poses.size();
  for (int k = 0; n_overlap > 0 && k < 4 * count && static_cast<int>(sets[1].poses.size()) < count; ++k) {
    const Pose& p0 = sets[0].poses[static_cast<std::size_t>(k) % n_overlap];
    const Vec3 dir = rng.direction();
    auto moved = [&](double s) { return Pose{p0.rotation, p0.translation + s * dir}; };
    double lo = 0.0, hi = a.extent + b.extent;
    for (int it = 0; it < 80; ++it) {
      const double mid = 0.5 * (lo + hi);
      const double d = distance(a, id, b, moved(mid)).distance;
      if (d <= 0.0) {
        lo = mid;
      } else if (d > limit) {
        hi = mid;
      } else {
        sets[1].poses.push_back(moved(mid));
        break;
      }
    }
  }
  for (int k = 0; k < count; ++k) {
    const Mat3 r = rng.rotation();
    const double reach = 0.5 * (a.extent + b.extent) * (1.1 + 0.9 * rng.uniform());
    sets[2].poses.push_back(place(r, ca + reach * rng.direction()));
  }
  return sets;
}

/// CPU microseconds per call of `f` over the poses: one figure per run, each run repeating
/// passes over the poses for at least 20 ms of CPU time.
template <class F>
Spread time_queries(const std::vector<Pose>& poses, int runs, F&& f) {
  std::vector<double> per_run;
  if (poses.empty()) return spread_of(per_run);
  for (const Pose& p : poses) f(p);  // warm-up
  for (int r = 0; r < runs; ++r) {
    const double t0 = cpu_ms();
    std::size_t calls = 0;
    double elapsed = 0.0;
    do {
      for (const Pose& p : poses) f(p);
      calls += poses.size();
      elapsed = (cpu_ms() - t0) * 1e3;
    } while (elapsed < 2e4);
    per_run.push_back(elapsed / static_cast<double>(calls));
  }
  return spread_of(per_run);
}

// ---- results (MeshRow, PlanRow, QueryRow: paper_verdicts.h) ------------------------------------

struct SceneRun {
  std::string name;
  std::size_t body_triangles = 0, obstacle_triangles = 0;
  std::size_t paper_body = 0, paper_obstacles = 0;
  double load_ms = 0.0, generate_s = 0.0;
  std::string problem_file;
  std::string error;  ///< not run: why
};

struct OmplRow {
  std::string problem;
  int successes = 0, runs = 0;
  double median_ms = std::numeric_limits<double>::quiet_NaN();
  double min_ms = median_ms, max_ms = median_ms;
  double swept_ms = median_ms;  ///< bench_plan's own swept run (problem's fitter)
  std::string swept_status;
  double fcl_build_ms = median_ms;
};

struct Results {
  std::vector<SceneRun> scenes;
  std::vector<MeshRow> meshes;
  std::vector<PlanRow> plans;
  std::vector<QueryRow> queries;
  std::vector<std::string> notes;  ///< skipped inputs, peers not run
  std::vector<OmplRow> ompl;
  std::string ompl_status;  ///< how the OMPL column was obtained, or why it is absent
  double ompl_time_limit = 0.0;
};

// ---- measuring ---------------------------------------------------------------------------------

Bvh build_timed(const std::vector<Triangle>& tris, Fitter f, SplitRule s, int runs, const std::string& what,
                std::vector<double>& times) {
  std::optional<Bvh> kept;
  for (int r = 0; r < runs; ++r) {
    const double t0 = cpu_ms();
    Result<Bvh> bvh = build_bvh(tris, {.fitter = f, .split = s, .parallel = false});
    times.push_back(cpu_ms() - t0);
    if (!bvh) throw std::runtime_error(what + ": " + bvh.error().message);
    kept = std::move(bvh).value();
  }
  return std::move(*kept);
}

void fcl_builds(MeshRow& row, const std::vector<Triangle>& tris, int runs) {
  for (const FclVolume v : {FclVolume::obbrss, FclVolume::rss}) {
    std::vector<double> times;
    for (int r = 0; r < runs; ++r) {
      const double t0 = cpu_ms();
      FclMesh m(tris, v);
      times.push_back(cpu_ms() - t0);
    }
    (v == FclVolume::obbrss ? row.fcl_obbrss_build_ms : row.fcl_rss_build_ms) = spread_of(times);
  }
}

/// Tables II and IV for a mesh that is not planned with (the real CAD).
MeshRow measure_mesh(const std::string& name, const std::string& source, const std::vector<Triangle>& tris, int runs) {
  MeshRow row;
  row.name = name;
  row.source = source;
  row.kind = "cad";
  row.triangles = tris.size();
  for (const SplitRule s : kSplits)
    for (const Fitter f : kFitters) {
      std::vector<double> times;
      const Bvh bvh = build_timed(tris, f, s, runs, source, times);
      row.trees.push_back({f, s, stats(bvh), spread_of(times)});
    }
  fcl_builds(row, tris, runs);
  return row;
}

std::string status_name(PlanStatus s) {
  switch (s) {
    case PlanStatus::solved: return "solved";
    case PlanStatus::no_path_time: return "no path (time limit)";
    case PlanStatus::no_path_bounds: return "no path (bounds)";
    case PlanStatus::no_path_resolution: return "no path (resolution)";
    case PlanStatus::invalid_start: return "invalid start";
    case PlanStatus::invalid_goal: return "invalid goal";
    case PlanStatus::invalid_bounds: return "invalid bounds";
  }
  return "unknown";
}

void run_scene(const PaperOptions& o, const scenes::SceneInfo& info, const fs::path& problem_file, Results& res,
               int poses_per_set) {
  SceneRun& sr = res.scenes.back();
  auto problem = load_problem(problem_file);
  if (!problem) throw std::runtime_error(problem.error().message);
  const auto t0 = Clock::now();
  auto loaded = load_scene(*problem, BuildConfig{});
  if (!loaded) throw std::runtime_error(problem_file.string() + ": " + loaded.error().message);
  PlanScene scene = std::move(loaded).value();
  sr.load_ms = ms_since(t0);
  sr.body_triangles = scene.body.triangles.size();
  sr.obstacle_triangles = scene.obstacles.triangles.size();
  std::cerr << "bench paper: " << info.name << ": body " << sr.body_triangles << ", obstacles "
            << sr.obstacle_triangles << " triangles\n";

  const std::vector<PoseSet> sets = make_pose_sets(scene, poses_per_set, 0x5EED0000ull + res.scenes.size());
  for (const PoseSet& s : sets)
    if (static_cast<int>(s.poses.size()) < poses_per_set)
      res.notes.push_back(info.name + ": pose set '" + s.name + "' has " + std::to_string(s.poses.size()) + " of " +
                          std::to_string(poses_per_set) + " poses (not enough found within the attempt budget)");

  MeshRow body, obstacles;
  body.name = info.name + " †";
  body.source = "scene " + info.name + ", body";
  body.kind = "scene-body";
  body.triangles = sr.body_triangles;
  body.paper_triangles = info.paper_body_triangles;
  obstacles.name = info.name + " ‡";
  obstacles.source = "scene " + info.name + ", obstacles";
  obstacles.kind = "scene-obstacles";
  obstacles.triangles = sr.obstacle_triangles;
  obstacles.paper_triangles = info.paper_obstacle_triangles;
  PlanOptions popts;
  popts.threads = o.threads;
  if (o.time_limit > 0) popts.time_limit = o.time_limit;
  const Pose id;
  for (const SplitRule s : kSplits) {
    for (const Fitter f : kFitters) {
      const std::string cfg = config_name(f, s);
      std::vector<double> tb, to;
      scene.body_tree = build_timed(scene.body.triangles, f, s, o.runs, info.name + " body", tb);
      scene.obstacle_tree = build_timed(scene.obstacles.triangles, f, s, o.runs, info.name + " obstacles", to);
      body.trees.push_back({f, s, stats(scene.body_tree), spread_of(tb)});
      obstacles.trees.push_back({f, s, stats(scene.obstacle_tree), spread_of(to)});

      PlanRow pr;
      pr.scene = info.name;
      pr.fitter = f;
      pr.split = s;
      std::vector<double> times, cpu_times;
      std::optional<std::uint64_t> hash;
      for (int r = 0; r < o.runs; ++r) {
        const auto p0 = Clock::now();
        const double c0 = cpu_ms();
        const PlanResult result = plan(*problem, scene, popts);
        cpu_times.push_back(cpu_ms() - c0);
        times.push_back(ms_since(p0));
        pr.statuses.push_back(status_name(result.status));
        pr.solved += result.solved() ? 1 : 0;
        pr.distance_queries = result.queries.distance;
        pr.waypoints = result.path.poses.size();
        if (hash && *hash != result.path_hash) pr.same_path = false;
        hash = result.path_hash;
      }
      pr.wall_ms = spread_of(times);
      pr.cpu_ms = spread_of(cpu_times);
      std::cerr << "  " << cfg << ": build body " << fmt_fixed(body.trees.back().build_ms.median, 1)
                << " ms, obstacles " << fmt_fixed(obstacles.trees.back().build_ms.median, 1) << " ms; plan CPU "
                << fmt_spread(pr.cpu_ms, 1) << " ms, wall " << fmt_spread(pr.wall_ms, 1) << " ms, " << pr.statuses.back() << ", " << pr.distance_queries
                << " distance queries\n";
      res.plans.push_back(std::move(pr));

      volatile double sink = 0.0;
      for (const PoseSet& set : sets) {
        QueryRow q{info.name, set.name, "swept-" + cfg, set.poses.size()};
        q.collide_us = time_queries(set.poses, o.runs, [&](const Pose& p) {
          sink = sink + collide(scene.obstacle_tree, id, scene.body_tree, p).colliding;
        });
        q.distance_us = time_queries(set.poses, o.runs, [&](const Pose& p) {
          sink = sink + distance(scene.obstacle_tree, id, scene.body_tree, p).distance;
        });
        res.queries.push_back(std::move(q));
      }
    }
  }
  scene.body_tree = Bvh{};
  scene.obstacle_tree = Bvh{};
  // FCL: build times (Table IV's peer column) and the same pose sets.
  fcl_builds(body, scene.body.triangles, o.runs);
  fcl_builds(obstacles, scene.obstacles.triangles, o.runs);
  for (const FclVolume v : {FclVolume::obbrss, FclVolume::rss}) {
    const FclMesh fa(scene.obstacles.triangles, v), fb(scene.body.triangles, v);
    volatile double sink = 0.0;
    for (const PoseSet& set : sets) {
      QueryRow q{info.name, set.name, std::string(fcl_engine_name(v)), set.poses.size()};
      q.collide_us = time_queries(set.poses, o.runs, [&](const Pose& p) { sink = sink + fa.collide(id, fb, p); });
      q.distance_us = time_queries(set.poses, o.runs, [&](const Pose& p) { sink = sink + fa.distance(id, fb, p); });
      res.queries.push_back(std::move(q));
    }
  }
  res.meshes.push_back(std::move(body));
  res.meshes.push_back(std::move(obstacles));
}

struct CadInput {
  const char* path;       ///< relative to the data directory
  double deflection;      ///< BRepMesh linear deflection (mm) for CAD formats; 0: the importer's default
  bool paper_only;
  const char* file_unit;  ///< unit of a mesh file's coordinates; "": the importer's default (mm)
};

constexpr CadInput kCad[] = {
    {"ros_industrial/kuka_kr10r1420_visual_base_link.stl", 0.0, false, "m"},  // the vendor's meshes are in metres
    {"tessellated/engine_d0.05/engine_p01_CylinderHead_rle_brep.stl", 0.0, false, ""},
    {"occt/motor.stl", 0.0, true, ""},
    {"nist/nist_ctc_04_asme1_rd.stp", 0.05, true, ""},
    {"occt/hammer.brep", 0.05, true, ""},
};

void run_cad(const PaperOptions& o, bool paper, Results& res) {
  const fs::path data(o.data_dir);
  if (!fs::is_directory(data)) {
    res.notes.push_back("real CAD skipped: the data directory " + data.string() + " is absent");
    std::cerr << "bench paper: " << res.notes.back() << "\n";
    return;
  }
  for (const CadInput& c : kCad) {
    if (c.paper_only && !paper) continue;
    const fs::path file = data / c.path;
    if (!fs::exists(file)) {
      res.notes.push_back("real CAD " + file.string() + " skipped: absent");
      std::cerr << "bench paper: " << res.notes.back() << "\n";
      continue;
    }
    ImportOptions io;
    if (c.deflection > 0) io.linear_deflection = c.deflection;
    io.file_unit = c.file_unit;
    auto model = import_mesh(file, io);
    if (!model) throw std::runtime_error(model.error().message);
    const std::vector<Triangle> tris = model->merged().triangles;
    if (tris.empty()) throw std::runtime_error(file.string() + ": no triangles");
    std::string name = fs::path(c.path).filename().string();
    if (c.deflection > 0) name += " @" + fmt_g(c.deflection) + " mm";
    std::cerr << "bench paper: " << name << ": " << tris.size() << " triangles\n";
    res.meshes.push_back(measure_mesh(name, c.path, tris, o.runs));
  }
}

// ---- OMPL via bench_plan -----------------------------------------------------------------------

fs::path default_bench_plan() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  // <build>/apps/swept/swept → <build>/bench/bench_plan
  return exe.parent_path().parent_path().parent_path() / "bench" / "bench_plan";
}

std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

void run_ompl(const PaperOptions& o, bool paper, const fs::path& out, Results& res) {
  res.ompl_time_limit = o.ompl_time_limit > 0 ? o.ompl_time_limit : (paper ? 60.0 : 10.0);
  if (o.no_ompl) {
    res.ompl_status = "not run (--no-ompl)";
    return;
  }
  const fs::path prog = o.bench_plan.empty() ? default_bench_plan() : fs::path(o.bench_plan);
  if (prog.empty() || !fs::exists(prog)) {
    res.ompl_status = "not run: the bench_plan program (" + (prog.empty() ? std::string("?") : prog.string()) +
                      ") is not built; build it with `cmake --build <build> --target bench_plan` or name it with "
                      "--bench-plan";
    std::cerr << "bench paper: OMPL " << res.ompl_status << "\n";
    return;
  }
  // The scenes of this benchmark (bench_plan generates them itself, at test scale).
  std::string names;
  for (const scenes::SceneInfo& s : scenes::catalog()) {
    if (!o.only.empty() && std::find(o.only.begin(), o.only.end(), s.name) == o.only.end()) continue;
    names += (names.empty() ? "" : ",") + s.name;
  }
  if (names.empty()) {
    res.ompl_status = "not run: no scene";
    return;
  }
  const fs::path json = out / "bench_plan.json";
  const std::string cmd = shell_quote(prog.string()) + " --only " + names + " --seeds " + std::to_string(o.runs) +
                          " --time-limit " + fmt_g(res.ompl_time_limit, 6) + " --threads " + std::to_string(o.threads) +
                          " --json " + shell_quote(json.string()) + " > " + shell_quote((out / "bench_plan.txt").string()) +
                          " 2> " + shell_quote((out / "bench_plan.log").string());
  std::cerr << "bench paper: OMPL RRTConnect + FCL via " << prog.string() << " (test-scale scenes)\n";
  const int rc = std::system(cmd.c_str());
  std::ifstream in(json);
  if (rc != 0 || !in) {
    res.ompl_status = "bench_plan failed (exit " + std::to_string(rc) + "); see bench_plan.log";
    return;
  }
  nlohmann::json j;
  try {
    in >> j;
  } catch (const std::exception& e) {
    res.ompl_status = std::string("bench_plan wrote unreadable JSON: ") + e.what();
    return;
  }
  for (const auto& p : j.value("problems", nlohmann::json::array())) {
    OmplRow row;
    row.problem = p.value("name", "");
    if (p.contains("error")) {
      res.notes.push_back("bench_plan: " + row.problem + " not run: " + p.value("error", ""));
      continue;
    }
    std::vector<double> times;
    for (const auto& r : p.value("ompl", nlohmann::json::array())) {
      ++row.runs;
      if (r.value("solved", false)) ++row.successes;
      times.push_back(r.value("ms", 0.0));
    }
    const Spread sp = spread_of(times);
    row.median_ms = sp.median;
    row.min_ms = sp.min;
    row.max_ms = sp.max;
    row.fcl_build_ms = p.value("ompl_fcl_build_ms", std::numeric_limits<double>::quiet_NaN());
    for (const auto& s : p.value("swept", nlohmann::json::array())) {
      if (s.value("fitter", "") != "inertia") continue;
      row.swept_ms = s.value("plan_ms", std::numeric_limits<double>::quiet_NaN());
      row.swept_status = s.value("status", "");
      break;
    }
    res.ompl.push_back(row);
  }
  res.ompl_status = "bench_plan (" + prog.string() + "): OMPL RRTConnect + FCL OBBRSS, " + std::to_string(o.runs) +
                    " seeds, " + fmt_g(res.ompl_time_limit) +
                    " s limit per run (failed runs count as the limit in the median), on the scenes at test scale";
}

// ---- report ------------------------------------------------------------------------------------

std::string machine_description() {
  std::string cpu;
  std::ifstream info("/proc/cpuinfo");
  for (std::string line; std::getline(info, line);)
    if (line.rfind("model name", 0) == 0) {
      cpu = line.substr(line.find(':') + 2);
      break;
    }
  std::string mem;
  std::ifstream meminfo("/proc/meminfo");
  for (std::string line; std::getline(meminfo, line);)
    if (line.rfind("MemTotal:", 0) == 0) {
      std::istringstream ss(line.substr(9));
      double kb = 0;
      ss >> kb;
      mem = fmt_fixed(kb / (1024.0 * 1024.0), 1) + " GiB RAM";
      break;
    }
  utsname u{};
  std::string os;
  if (::uname(&u) == 0) os = std::string(u.sysname) + " " + u.release + " " + u.machine;
  std::string s = (cpu.empty() ? std::string("unknown CPU") : cpu) + ", " +
                  std::to_string(std::thread::hardware_concurrency()) + " hardware threads";
  if (!mem.empty()) s += ", " + mem;
  if (!os.empty()) s += ", " + os;
#ifdef __VERSION__
  s += ", compiler " + std::string(__VERSION__);
#endif
  return s;
}

std::string utc_now() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[64];
  std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M UTC", &tm);
  return buf;
}

std::string command_line(const PaperOptions& o) {
  std::string c = "swept bench paper --scale " + o.scale + " --runs " + std::to_string(o.runs) + " --out " + o.out;
  if (!o.scenes_dir.empty()) c += " --scenes " + o.scenes_dir;
  if (o.data_dir != "../shared/data") c += " --data " + o.data_dir;
  if (!o.only.empty()) {
    c += " --only ";
    for (std::size_t i = 0; i < o.only.size(); ++i) c += (i ? "," : "") + o.only[i];
  }
  if (o.no_scenes) c += " --no-scenes";
  if (o.no_cad) c += " --no-cad";
  if (!o.merge.empty()) {
    c += " --merge ";
    for (std::size_t i = 0; i < o.merge.size(); ++i) c += (i ? "," : "") + o.merge[i];
  }
  if (o.poses > 0) c += " --poses " + std::to_string(o.poses);
  if (o.threads != 1) c += " --threads " + std::to_string(o.threads);
  if (o.time_limit > 0) c += " --time-limit " + fmt_g(o.time_limit);
  if (o.no_ompl) c += " --no-ompl";
  if (!o.bench_plan.empty()) c += " --bench-plan " + o.bench_plan;
  if (o.ompl_time_limit > 0) c += " --ompl-time-limit " + fmt_g(o.ompl_time_limit);
  return c;
}

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

void write_plots(const Results& r, const fs::path& img, std::vector<std::string>& files) {
  fs::create_directories(img);
  const std::vector<std::string> sc = planned_scenes(r);
  if (!sc.empty()) {
    BarChart c;
    c.title = "Planning speed-up against PQP_FIT (median over runs, whiskers: min–max)";
    c.y_label = "speed-up (pqp time / time)";
    c.reference_line = 1.0;
    c.reference_label = "PQP_FIT";
    for (const SplitRule s : kSplits)
      for (const std::string& name : sc) c.groups.push_back(name + " (" + std::string(to_string(s)) + ")");
    for (const Fitter f : kFitters) {
      BarSeries ser{upper_name(f), {}, {}, {}};
      for (const SplitRule s : kSplits)
        for (const std::string& name : sc) {
          const PlanRow* p = find_plan(r, name, Fitter::pqp, s);
          const PlanRow* x = find_plan(r, name, f, s);
          const Ratio ra = p && x ? ratio_of(p->cpu_ms, x->cpu_ms) : Ratio{};
          ser.values.push_back(ra.value);
          ser.low.push_back(ra.low);
          ser.high.push_back(ra.high);
        }
      c.series.push_back(std::move(ser));
    }
    write_svg(c, (img / "paper-speedup.svg").string());
    files.push_back("paper-speedup.svg");

    for (const bool dist : {true, false}) {
      BarChart q;
      q.title = std::string(dist ? "Distance" : "Collide") +
                " query time per pose set: swept (min-sa split) vs FCL (median over runs, whiskers: min–max)";
      q.y_label = "µs per query";
      q.log_scale = true;
      std::vector<std::string> engines;
      for (const Fitter f : kFitters) engines.push_back("swept-" + config_name(f, SplitRule::min_sa));
      engines.push_back(std::string(fcl_engine_name(FclVolume::obbrss)));
      engines.push_back(std::string(fcl_engine_name(FclVolume::rss)));
      const char* set_names[] = {"overlapping", "near", "far"};
      for (const std::string& name : sc)
        for (const char* set : set_names) q.groups.push_back(name + " / " + set);
      for (const std::string& e : engines) {
        BarSeries ser{e, {}, {}, {}};
        for (const std::string& name : sc)
          for (const char* set : set_names) {
            const QueryRow* row = find_query(r, name, set, e);
            const Spread none;
            const Spread& sp = row ? (dist ? row->distance_us : row->collide_us) : none;
            ser.values.push_back(sp.median);
            ser.low.push_back(sp.min);
            ser.high.push_back(sp.max);
          }
        q.series.push_back(std::move(ser));
      }
      const std::string file = dist ? "paper-query-distance.svg" : "paper-query-collide.svg";
      bool any = false;
      for (const BarSeries& s : q.series)
        for (double v : s.values) any = any || (std::isfinite(v) && v > 0);
      if (!any) continue;
      write_svg(q, (img / file).string());
      files.push_back(file);
    }
  }
  if (!r.meshes.empty()) {
    BarChart t;
    t.title = "Total RSS surface area and build time relative to PQP_FIT (min-sa split)";
    t.y_label = "ratio to PQP_FIT";
    t.reference_line = 1.0;
    t.reference_label = "PQP_FIT";
    for (const MeshRow& m : r.meshes) t.groups.push_back(m.name);
    for (const Fitter f : {Fitter::rapid2, Fitter::inertia}) {
      BarSeries sa{upper_name(f) + " surface area", {}, {}, {}};
      BarSeries bt{upper_name(f) + " build time", {}, {}, {}};
      for (const MeshRow& m : r.meshes) {
        sa.values.push_back(m.tree(f, SplitRule::min_sa).stats.total_surface_area /
                            m.tree(Fitter::pqp, SplitRule::min_sa).stats.total_surface_area);
        const Ratio b = ratio_of(m.tree(f, SplitRule::min_sa).build_ms, m.tree(Fitter::pqp, SplitRule::min_sa).build_ms);
        bt.values.push_back(b.value);
        bt.low.push_back(b.low);
        bt.high.push_back(b.high);
      }
      t.series.push_back(std::move(sa));
      t.series.push_back(std::move(bt));
    }
    write_svg(t, (img / "paper-trees.svg").string());
    files.push_back("paper-trees.svg");
  }
}

/// Lengths are millimetres; the paper's Table II figures read as m² and m³.
constexpr double kMm2ToM2 = 1e-6, kMm3ToM3 = 1e-9;

std::string markdown_report(const Results& r, const PaperOptions& o, const std::string& date,
                            const std::string& machine, const std::vector<std::string>& plots) {
  std::ostringstream md;
  const bool spread = o.runs > 1;
  md << "# The paper's experiments, reproduced: Tables II–IV with FCL and OMPL beside them\n\n";
  md << "- Command: `" << command_line(o) << "`\n";
  md << "- Date: " << date << "\n";
  md << "- Machine: " << machine
     << ". The machine is shared: other processes (compilers, other benchmarks) may run at the same time, which "
        "widens the min–max ranges.\n";
  md << "- Scale: `" << o.scale << "`; " << o.runs << " run(s) per figure (median, min–max); planner on " << o.threads
     << " thread(s), trees built serially (`parallel = false`) so that build times compare fitters, not thread "
        "scheduling.\n";
  md << "- Times are CPU time of the process (`CLOCK_PROCESS_CPUTIME_ID`): on a shared machine the wall clock "
        "also counts the time other processes hold the cores. Table III gives the planner's wall time beside it. "
        "The planner's time limit is wall time.\n";
  md << "- Planner time is `plan()` — what `swept plan` runs — on trees built beforehand: mesh loading and "
        "the tree build are not in Table III (the build is Table IV).\n";
  md << "- Units: scenes and CAD are in millimetres; Table II gives m² and m³ as the paper's figures read.\n\n";

  md << "## Table I — the meshes\n\n| mesh | source | triangles | paper's Table I |\n|---|---|---:|---:|\n";
  for (const MeshRow& m : r.meshes)
    md << "| " << m.name << " | " << m.source << " | " << m.triangles << " | "
       << (m.paper_triangles ? std::to_string(m.paper_triangles) : std::string("—")) << " |\n";
  md << "\n† rigid body, ‡ obstacles (as in the paper).\n\n";

  for (const SplitRule s : kSplits) {
    md << "## Table II — total RSS surface area (m²) and volume (m³), split rule `" << to_string(s) << "`\n\n";
    md << "| mesh | PQP_FIT SA | PQP_FIT V | RAPID2_FIT SA | RAPID2_FIT V | INERTIA_FIT SA | INERTIA_FIT V | "
          "inertia/pqp SA | inertia/pqp V |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const MeshRow& m : r.meshes) {
      md << "| " << m.name;
      for (const Fitter f : kFitters) {
        const BvhStats& st = m.tree(f, s).stats;
        md << " | " << fmt_g(st.total_surface_area * kMm2ToM2) << " | " << fmt_g(st.total_volume * kMm3ToM3);
      }
      const BvhStats& i = m.tree(Fitter::inertia, s).stats;
      const BvhStats& p = m.tree(Fitter::pqp, s).stats;
      md << " | " << fmt_fixed(i.total_surface_area / p.total_surface_area, 3) << " | "
         << fmt_fixed(i.total_volume / p.total_volume, 3) << " |\n";
    }
    md << "\n";
  }

  const std::vector<std::string> sc = planned_scenes(r);
  for (const SplitRule s : kSplits) {
    md << "## Table III — planner time, split rule `" << to_string(s)
       << "`: CPU ms, median (min–max) over runs [speed-up against PQP_FIT]; wall ms; distance queries\n\n";
    md << "| scene | PQP_FIT | RAPID2_FIT | INERTIA_FIT | wall ms pqp / rapid2 / inertia (median) | distance queries "
          "pqp / rapid2 / inertia | status |\n"
          "|---|---:|---:|---:|---:|---:|---|\n";
    for (const std::string& name : sc) {
      const PlanRow* p = find_plan(r, name, Fitter::pqp, s);
      md << "| " << name;
      std::string queries, status, wall;
      for (const Fitter f : kFitters) {
        const PlanRow* x = find_plan(r, name, f, s);
        if (!x || !p) {
          md << " | n/a";
          continue;
        }
        md << " | " << fmt_spread(x->cpu_ms, 0) << " [" << fmt_ratio(ratio_of(p->cpu_ms, x->cpu_ms), spread) << "]";
        wall += (wall.empty() ? "" : " / ") + fmt_fixed(x->wall_ms.median, 0);
        queries += (queries.empty() ? "" : " / ") + std::to_string(x->distance_queries);
        status += (status.empty() ? "" : "; ") + std::string(to_string(f)) + " " + std::to_string(x->solved) + "/" +
                  std::to_string(x->statuses.size()) + " solved" + (x->same_path ? "" : ", paths differ");
      }
      md << " | " << wall << " | " << queries << " | " << status << " |\n";
    }
    md << "\nIn brackets: speed-up = PQP_FIT time / this fitter's time (range from the runs' extremes).\n\n";
  }

  for (const SplitRule s : kSplits) {
    md << "## Table IV — tree build time (CPU ms, serial build), split rule `" << to_string(s)
       << "`; FCL's builds beside them\n\n";
    md << "| mesh | triangles | PQP_FIT | RAPID2_FIT | INERTIA_FIT | inertia/pqp | rapid2/pqp | FCL OBBRSS | FCL RSS |\n"
          "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const MeshRow& m : r.meshes) {
      md << "| " << m.name << " | " << m.triangles;
      for (const Fitter f : kFitters) md << " | " << fmt_spread(m.tree(f, s).build_ms, 1);
      md << " | " << fmt_ratio(ratio_of(m.tree(Fitter::inertia, s).build_ms, m.tree(Fitter::pqp, s).build_ms), false)
         << " | " << fmt_ratio(ratio_of(m.tree(Fitter::rapid2, s).build_ms, m.tree(Fitter::pqp, s).build_ms), false)
         << " | " << fmt_spread(m.fcl_obbrss_build_ms, 1) << " | " << fmt_spread(m.fcl_rss_build_ms, 1) << " |\n";
    }
    md << "\n";
  }

  md << "## Peers: query times per pose set (CPU µs per query, median (min–max) over runs)\n\n"
        "Obstacles fixed, body posed: `overlapping` (colliding), `near` (0 < distance ≤ 1 % of the body's size), "
        "`far` (bounding spheres apart); seeded, the same poses for every engine. FCL: `fcl::collide` (first "
        "contact) and `fcl::distance` (nearest points) on OBBRSS and RSS trees.\n\n";
  md << "| scene | set | poses | engine | collide µs | distance µs | distance vs fcl-obbrss |\n"
        "|---|---|---:|---|---:|---:|---:|\n";
  for (const QueryRow& q : r.queries) {
    const QueryRow* f = find_query(r, q.scene, q.set, std::string(fcl_engine_name(FclVolume::obbrss)));
    md << "| " << q.scene << " | " << q.set << " | " << q.poses << " | " << q.engine << " | "
       << fmt_spread(q.collide_us, 1) << " | " << fmt_spread(q.distance_us, 1) << " | "
       << (f ? fmt_ratio(ratio_of(f->distance_us, q.distance_us), false) : std::string("n/a")) << " |\n";
  }
  md << "\n(ratio > 1: swept faster than FCL OBBRSS.)\n\n";

  md << "## Peers: OMPL RRTConnect + FCL on the same problems\n\n" << r.ompl_status << ".\n\n";
  if (!r.ompl.empty()) {
    md << "| problem | OMPL solved | OMPL median ms | OMPL min–max ms | FCL build ms | swept (inertia) ms in the "
          "same run | swept status |\n|---|---:|---:|---:|---:|---:|---|\n";
    for (const OmplRow& w : r.ompl)
      md << "| " << w.problem << " | " << w.successes << "/" << w.runs << " | " << fmt_fixed(w.median_ms, 1) << " | "
         << fmt_fixed(w.min_ms, 1) << "–" << fmt_fixed(w.max_ms, 1) << " | " << fmt_fixed(w.fcl_build_ms, 1) << " | "
         << fmt_fixed(w.swept_ms, 1) << " | " << w.swept_status << " |\n";
    md << "\n";
  }

  const PaperRows rows = rows_of(r);
  md << "## The paper's claims\n\n";
  for (const ClaimVerdict& c : assess_claims(rows, o.runs)) md << "- **" << c.claim << "** — " << c.text() << "\n";
  md << "\n";
  md << "## The peers in numbers\n\nRatios are FCL's time / swept's time (> 1: swept is faster), each range over every "
        "row it names.\n\n";
  for (const std::string& f : peer_findings(rows)) md << "- " << f << "\n";
  md << "\n";

  if (!plots.empty()) {
    md << "## Plots\n\n";
    for (const std::string& p : plots) md << "![" << p << "](img/" << p << ")\n\n";
  }
  if (!r.notes.empty()) {
    md << "## Notes\n\n";
    for (const std::string& n : r.notes) md << "- " << n << "\n";
    md << "\n";
  }
  return md.str();
}

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
    const PlanRow* base = find_plan(r, p.scene, Fitter::pqp, p.split);
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
                          {"tolerance_queries", p.tolerance_queries},
                          {"collide_queries", p.collide_queries},
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
      pr.tolerance_queries = get_or<std::uint64_t>(p, "tolerance_queries", 0);
      pr.collide_queries = get_or<std::uint64_t>(p, "collide_queries", 0);
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
    std::cerr << "bench paper: wrote " << (out / "results.json").string() << ", " << (out / "report.md").string()
              << " and " << plots.size() << " plots in " << (out / "img").string() << "\n";
  return md;
}

void run(const PaperOptions& o) {
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
      std::cerr << "bench paper: generating " << info.name << " at scale " << o.scale << "\n";
      const auto t0 = Clock::now();
      auto report = scenes::generate_scene({.name = info.name, .scale = scale, .output_dir = out / "scenes" / info.name});
      sr.generate_s = ms_since(t0) / 1e3;
      if (!report) {
        sr.error = report.error().message;
        res.notes.push_back(info.name + " not run: " + sr.error);
        std::cerr << "bench paper: " << res.notes.back() << "\n";
        continue;
      }
      problem = report->problem_file;
    }
    sr.problem_file = problem.string();
    run_scene(o, info, problem, res, poses);
    write_outputs(res, o, out, false);
  }
  if (!o.no_cad) {
    run_cad(o, paper, res);
    write_outputs(res, o, out, false);
  }
  run_ompl(o, paper, out, res);
  const bool ompl_measured = !res.ompl.empty();
  const std::string ompl_status = res.ompl_status;
  for (const std::string& d : o.merge) merge_results(d, o, res);
  if (ompl_measured) res.ompl_status = ompl_status;  // measured here: this run's OMPL wins
  if (res.ompl.empty() && !o.merge.empty() && o.no_ompl) res.ompl_status = "not run (--no-ompl) in any merged run";
  std::cout << write_outputs(res, o, out, true);
}

}  // namespace

void add_bench_paper_command(CLI::App& app) {
  // `bench` is created by add_bench_queries_command, registered before this one.
  CLI::App* bench = nullptr;
  try {
    bench = app.get_subcommand("bench");
  } catch (const CLI::OptionNotFound&) {
    bench = app.add_subcommand("bench", "Benchmarks against peer libraries");
    bench->require_subcommand(1);
  }
  auto o = std::make_shared<PaperOptions>();
  CLI::App* cmd = bench->add_subcommand(
      "paper",
      "The paper's Tables II-IV in one run: for each scene of `swept scene` and real CAD files, each fitter\n"
      "(pqp, rapid2, inertia) under both split rules: total RSS surface area and volume, planner wall time\n"
      "(median of N runs, min-max, speed-up against pqp, distance queries), build time; FCL's build and\n"
      "query times on the same meshes and pose sets, and OMPL RRTConnect + FCL via bench_plan. Writes\n"
      "results.json, report.md and SVG plots (img/) into --out.");
  cmd->add_option("--scale", o->scale, "test | paper")->capture_default_str();
  cmd->add_option("--runs", o->runs, "runs per figure (median, min-max)")->capture_default_str();
  cmd->add_option("--out", o->out, "output directory")->required();
  cmd->add_option("--scenes", o->scenes_dir, "use scenes generated earlier: DIR/<name>/problem.toml");
  cmd->add_option("--data", o->data_dir, "the real CAD data directory")->capture_default_str();
  cmd->add_option("--only", o->only, "only these scenes")->delimiter(',');
  cmd->add_flag("--no-scenes", o->no_scenes, "skip the scenes (e.g. a process for the real CAD only)");
  cmd->add_flag("--no-cad", o->no_cad, "skip the real CAD meshes");
  cmd->add_option("--merge", o->merge,
                  "merge the results.json of earlier runs' output directories into this report (a long run "
                  "split into processes)")
      ->delimiter(',');
  cmd->add_option("--poses", o->poses, "poses per query set (default 5 at test scale, 20 at paper scale)");
  cmd->add_option("--threads", o->threads, "planner threads (0: all cores)")->capture_default_str();
  cmd->add_option("--time-limit", o->time_limit, "planner time limit, s (default: the problem's)");
  cmd->add_flag("--no-ompl", o->no_ompl, "do not run OMPL (bench_plan)");
  cmd->add_option("--bench-plan", o->bench_plan, "the bench_plan program (default: <build>/bench/bench_plan)");
  cmd->add_option("--ompl-time-limit", o->ompl_time_limit, "OMPL time limit per run, s (default 10 test, 60 paper)");
  cmd->callback([o] { run(*o); });
}

}  // namespace swept::cli
