// `swept bench paper`, the scenes: Tables II–IV and the FCL peer rows of one planning scene.
#include "swept/bench/fcl_peer.h"
#include "swept/bench/output.h"
#include "swept/bench/paper.h"
#include "swept/bench/pose_sets.h"
#include "swept/bench/timing.h"

#include "swept/plan/planner.h"
#include "swept/plan/problem.h"
#include "swept/query/query.h"

#include <optional>
#include <stdexcept>

namespace swept::bench {

namespace fs = std::filesystem;

namespace {

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

/// Builds the tree `runs` times, serially (build times compare fitters, not thread scheduling);
/// appends each build's CPU ms to `times` and returns the figures of the tree.
BvhStats build_timed(const std::vector<Triangle>& tris, Fitter f, SplitRule s, int runs, const std::string& what,
                std::vector<double>& times) {
  std::optional<BvhStats> figures;
  for (int r = 0; r < runs; ++r) {
    const double t0 = cpu_ms();
    Result<Bvh> bvh = build_bvh(tris, {.fitter = f, .split = s, .parallel = false});
    times.push_back(cpu_ms() - t0);
    if (!bvh) throw std::runtime_error(what + ": " + bvh.error().message);
    figures = stats(*bvh);
  }
  return *figures;
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

}  // namespace

MeshRow measure_mesh(const std::string& name, const std::string& source, const std::vector<Triangle>& tris, int runs) {
  MeshRow row;
  row.name = name;
  row.source = source;
  row.kind = "cad";
  row.triangles = tris.size();
  for (const SplitRule s : split_rules())
    for (const Fitter f : fitters()) {
      std::vector<double> times;
      const BvhStats st = build_timed(tris, f, s, runs, source, times);
      row.trees.push_back({f, s, st, spread_of(times)});
    }
  fcl_builds(row, tris, runs);
  return row;
}

std::size_t scene_steps() { return split_rules().size() * fitters().size(); }

void run_scene(const PaperOptions& o, const scenes::SceneInfo& info, const fs::path& problem_file, Results& res,
               int poses_per_set, PaperSteps& steps) {
  SceneRun& sr = res.scenes.back();
  auto problem = load_problem(problem_file);
  if (!problem) throw std::runtime_error(problem.error().message);
  const auto t0 = Clock::now();
  auto loaded = load_scene(*problem, problem->build);
  if (!loaded) throw std::runtime_error(problem_file.string() + ": " + loaded.error().message);
  PlanScene scene = std::move(loaded).value();
  sr.load_ms = ms_since(t0);
  sr.body_triangles = scene.body.triangles.size();
  sr.obstacle_triangles = scene.obstacles.triangles.size();
  log_line(o, std::string("bench paper: ") + info.name + ": body " + std::to_string(sr.body_triangles) + ", obstacles " + std::to_string(sr.obstacle_triangles) + " triangles");

  // The poses are drawn with the problem's trees (the fitter does not change what collides).
  const std::vector<PoseSet> sets = make_pose_sets(
      scene.obstacle_tree, scene.body_tree,
      {.count = poses_per_set, .seed = 0x5EED0000ull + res.scenes.size()});
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
  for (const SplitRule s : split_rules()) {
    for (const Fitter f : fitters()) {
      const std::string cfg = config_name(f, s);
      std::vector<double> tb, to;
      const BvhStats body_stats = build_timed(scene.body.triangles, f, s, o.runs, info.name + " body", tb);
      const BvhStats obstacle_stats =
          build_timed(scene.obstacles.triangles, f, s, o.runs, info.name + " obstacles", to);
      body.trees.push_back({f, s, body_stats, spread_of(tb)});
      obstacles.trees.push_back({f, s, obstacle_stats, spread_of(to)});
      // The scene this configuration plans in: the loaded meshes, trees built with its config.
      BuildConfig config = problem->build;
      config.fitter = f;
      config.split = s;
      auto made = make_scene(scene.obstacles, scene.body, config, problem->reference_point);
      if (!made) throw std::runtime_error(problem_file.string() + ": " + made.error().message);
      const PlanScene& cfg_scene = *made;

      PlanRow pr;
      pr.scene = info.name;
      pr.fitter = f;
      pr.split = s;
      std::vector<double> times, cpu_times;
      std::optional<std::uint64_t> hash;
      for (int r = 0; r < o.runs; ++r) {
        const auto p0 = Clock::now();
        const double c0 = cpu_ms();
        const PlanResult result = plan(*problem, cfg_scene, popts);
        cpu_times.push_back(cpu_ms() - c0);
        times.push_back(ms_since(p0));
        pr.statuses.emplace_back(status_name(result.status));
        pr.solved += result.solved() ? 1 : 0;
        pr.distance_queries = result.queries.distance;
        pr.waypoints = result.path.poses.size();
        if (hash && *hash != result.path_hash) pr.same_path = false;
        hash = result.path_hash;
      }
      pr.wall_ms = spread_of(times);
      pr.cpu_ms = spread_of(cpu_times);
      log_line(o, "  " + cfg + ": build body " + fmt_fixed(body.trees.back().build_ms.median, 1) + " ms, obstacles " +
                      fmt_fixed(obstacles.trees.back().build_ms.median, 1) + " ms; plan CPU " + fmt_spread(pr.cpu_ms, 1) +
                      " ms, wall " + fmt_spread(pr.wall_ms, 1) + " ms, " + pr.statuses.back() + ", " +
                      std::to_string(pr.distance_queries) + " distance queries");
      steps.step(info.name + " " + cfg);
      res.plans.push_back(std::move(pr));

      volatile double sink = 0.0;
      for (const PoseSet& set : sets) {
        QueryRow q{info.name, set.name, "swept-" + cfg, set.poses.size()};
        q.collide_us = time_queries(set.poses, o.runs, [&](const Pose& p) {
          sink = sink + collide(cfg_scene.obstacle_tree, id, cfg_scene.body_tree, p).colliding;
        });
        q.distance_us = time_queries(set.poses, o.runs, [&](const Pose& p) {
          sink = sink + distance(cfg_scene.obstacle_tree, id, cfg_scene.body_tree, p).distance;
        });
        res.queries.push_back(std::move(q));
      }
    }
  }
  scene.body_tree = Bvh{};  // FCL's models next: do not hold both libraries' trees at once
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

}  // namespace swept::bench
