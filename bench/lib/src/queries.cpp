// `swept bench queries A B`: see swept/bench/queries.h.
#include "swept/bench/queries.h"

#include "swept/bench/fcl_peer.h"
#include "swept/bench/output.h"
#include "swept/bench/pose_sets.h"

#include "swept/bvh/bvh.h"
#include "swept/io/mesh_io.h"
#include "swept/query/query.h"

#include <nlohmann/json.hpp>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace swept::bench {
namespace {

std::vector<Triangle> load(const std::string& file) {
  Result<ImportedModel> m = import_mesh(file);
  if (!m) throw std::runtime_error(m.error().message);
  std::vector<Triangle> tris = m->merged().triangles;
  if (tris.empty()) throw std::runtime_error(file + ": no triangles");
  return tris;
}


/// CPU time of the calling thread in microseconds: the comparison stays fair when other
/// processes share the machine (wall time would charge their time to whoever runs then).
double thread_cpu_us() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) * 1e6 + static_cast<double>(ts.tv_nsec) * 1e-3;
}

/// Mean microseconds (thread CPU time) per call of `f` over all poses, repeating passes for
/// at least 50 ms.
template <class F>
double mean_us(const std::vector<Pose>& poses, F&& f) {
  const double start = thread_cpu_us();
  std::size_t calls = 0;
  double elapsed = 0.0;
  do {
    for (const Pose& p : poses) f(p);
    calls += poses.size();
    elapsed = thread_cpu_us() - start;
  } while (elapsed < 5e4);
  return elapsed / static_cast<double>(calls);
}

struct EngineResult {
  std::string engine;
  double collide_us = 0, distance_us = 0, tolerance_us = 0;
  double bv_tests = -1;  ///< mean BV tests per distance query; < 0: not reported by the engine
  double collide_bv_tests = -1;  ///< mean BV tests per collide query; < 0: not reported by the engine
  double bytes_per_triangle = -1;  ///< both trees' memory over both meshes' triangles; < 0: not reported
};

}  // namespace

void run_queries_benchmark(const QueriesOptions& o, std::ostream& out, std::ostream& log) {
  if (o.poses < 1) throw std::runtime_error("--poses must be at least 1");
  const std::vector<Triangle> ta = load(o.file_a);
  const std::vector<Triangle> tb = o.file_b == o.file_a ? ta : load(o.file_b);

  struct SweptEngine {
    std::string name;
    Bvh a, b;
  };
  if (o.leaf_sizes.empty()) throw std::runtime_error("--leaf-size needs at least one size");
  std::vector<SweptEngine> swept_engines;
  // The paper's method first: its trees draw the pose sets and are the reference of the distance
  // comparison and the batch; then the rest of the fitter table, in its order; each fitter at
  // every leaf size asked for (named with its leaf size when there are several).
  std::vector<Fitter> fitters{Fitter::inertia};
  for (const FitterInfo& f : all_fitters())
    if (f.fitter != Fitter::inertia) fitters.push_back(f.fitter);
  for (const int leaf : o.leaf_sizes) {
    for (const Fitter f : fitters) {
      const BuildConfig config{.fitter = f, .split = o.split, .leaf_size = leaf};
      Result<Bvh> a = build_bvh(ta, config);
      if (!a) throw std::runtime_error(o.file_a + ": " + a.error().message);
      Result<Bvh> b = build_bvh(tb, config);
      if (!b) throw std::runtime_error(o.file_b + ": " + b.error().message);
      std::string name = "swept-" + std::string(to_string(f));
      if (o.leaf_sizes.size() > 1) name += "/leaf" + std::to_string(leaf);
      swept_engines.push_back({std::move(name), std::move(a).value(), std::move(b).value()});
    }
  }
  struct FclEngine {
    FclVolume volume;
    std::unique_ptr<FclMesh> a, b;
  };
  std::vector<FclEngine> fcl_engines;
  for (const FclVolume v : {FclVolume::obbrss, FclVolume::rss})
    fcl_engines.push_back({v, std::make_unique<FclMesh>(ta, v), std::make_unique<FclMesh>(tb, v)});

  const Bvh& ref_a = swept_engines[0].a;
  const Bvh& ref_b = swept_engines[0].b;
  const std::vector<PoseSet> sets = make_pose_sets(ref_a, ref_b, {.count = o.poses, .seed = o.seed});
  for (const PoseSet& set : sets) {
    if (set.poses.empty())
      throw std::runtime_error("could not find " + set.name + " poses for these models");
    if (static_cast<int>(set.poses.size()) < o.poses)
      log << "bench queries: pose set '" << set.name << "' has " << set.poses.size() << " of " << o.poses
          << " poses (not enough found within the attempt budget)\n";
  }
  const double size = std::max(ref_a.extent, ref_b.extent);
  const double tol = 0.01 * size;
  const Pose id;

  double max_rel_diff = 0.0;
  std::size_t collide_disagreements = 0;  ///< poses where swept's collide answer is not FCL OBBRSS's
  std::size_t collide_compared = 0;
  std::vector<std::vector<EngineResult>> all;
  for (const PoseSet& set : sets) {
    std::vector<EngineResult> results;
    volatile double sink = 0.0;
    for (const SweptEngine& e : swept_engines) {
      EngineResult r{e.name};
      r.collide_us = mean_us(set.poses, [&](const Pose& p) { sink = sink + collide(e.a, id, e.b, p).colliding; });
      r.distance_us = mean_us(set.poses, [&](const Pose& p) { sink = sink + distance(e.a, id, e.b, p).distance; });
      r.tolerance_us = mean_us(set.poses, [&](const Pose& p) { sink = sink + tolerance(e.a, id, e.b, p, {.tolerance = tol}).within; });
      double bv = 0, collide_bv = 0;
      for (const Pose& p : set.poses) {
        bv += static_cast<double>(distance(e.a, id, e.b, p).stats.bv_tests);
        collide_bv += static_cast<double>(collide(e.a, id, e.b, p).stats.bv_tests);
      }
      r.bv_tests = bv / static_cast<double>(set.poses.size());
      r.collide_bv_tests = collide_bv / static_cast<double>(set.poses.size());
      r.bytes_per_triangle = static_cast<double>(e.a.memory_bytes() + e.b.memory_bytes()) /
                             static_cast<double>(e.a.triangles.size() + e.b.triangles.size());
      results.push_back(r);
    }
    for (const FclEngine& e : fcl_engines) {
      EngineResult r{std::string(fcl_engine_name(e.volume))};
      r.collide_us = mean_us(set.poses, [&](const Pose& p) { sink = sink + e.a->collide(id, *e.b, p); });
      r.distance_us = mean_us(set.poses, [&](const Pose& p) { sink = sink + e.a->distance(id, *e.b, p); });
      // FCL has no tolerance query: its nearest equivalent is a distance query and a comparison.
      r.tolerance_us = mean_us(set.poses, [&](const Pose& p) { sink = sink + (e.a->distance(id, *e.b, p) < tol); });
      // One untimed pass: FCL's node-pair counter, and the answers against swept's reference.
      double bv = 0, collide_bv = 0;
      bool collide_counted = true;
      for (const Pose& p : set.poses) {
        // Collide: FCL's counter where its collide runs a traversal of the models as they are,
        // and its answer against swept's (on the first row's trees, like the distances).
        if (const std::optional<FclCollideStats> c = e.a->collide_stats(id, *e.b, p)) {
          if (c->colliding != e.a->collide(id, *e.b, p))
            throw std::runtime_error("FCL's counted collide query differs from fcl::collide");
          collide_bv += static_cast<double>(c->bv_tests);
          ++collide_compared;
          if (c->colliding != collide(ref_a, id, ref_b, p).colliding) ++collide_disagreements;
        } else {
          collide_counted = false;
        }
        const double theirs = e.a->distance(id, *e.b, p);
        const FclDistanceStats st = e.a->distance_stats(id, *e.b, p);
        if (st.distance != theirs) throw std::runtime_error("FCL's counted distance query differs from fcl::distance");
        bv += static_cast<double>(st.bv_tests);
        const double ours = distance(ref_a, id, ref_b, p).distance;
        if (ours <= 0.0 && theirs <= 0.0) continue;  // both in contact (FCL may report −1)
        const double diff = std::abs(ours - theirs) / std::max({std::abs(theirs), std::abs(ours), 1e-12 * size});
        max_rel_diff = std::max(max_rel_diff, diff);
      }
      r.bv_tests = bv / static_cast<double>(set.poses.size());
      if (collide_counted) r.collide_bv_tests = collide_bv / static_cast<double>(set.poses.size());
      results.push_back(r);
    }
    all.push_back(std::move(results));
  }

  // Batch: 10k distance queries (near and far poses) on 1 thread and on 2.
  std::vector<Pose> batch;
  for (std::size_t i = 0; batch.size() < 10000; ++i)
    batch.push_back(sets[1 + i % 2].poses[(i / 2) % sets[1 + i % 2].poses.size()]);
  // The thread count is this call's own arena, not a process-wide limit.
  auto time_batch = [&](int threads) {
    tbb::task_arena arena(threads);
    const auto t0 = std::chrono::steady_clock::now();
    const auto res = arena.execute([&] { return distance_batch(ref_a, id, ref_b, batch); });
    const auto t1 = std::chrono::steady_clock::now();
    if (res.size() != batch.size()) throw std::runtime_error("batch size mismatch");
    return std::chrono::duration<double>(t1 - t0).count();
  };
  time_batch(2);  // warm-up
  const double t1 = time_batch(1), t2 = time_batch(2);

  if (o.json) {
    nlohmann::ordered_json j;
    j["sets"] = nlohmann::ordered_json::array();
    for (std::size_t s = 0; s < sets.size(); ++s) {
      nlohmann::ordered_json results = nlohmann::ordered_json::array();
      for (const EngineResult& r : all[s]) {
        results.push_back({{"engine", r.engine},
                           {"collide_us", r.collide_us},
                           {"distance_us", r.distance_us},
                           {"tolerance_us", r.tolerance_us},
                           {"bv_tests_per_distance", r.bv_tests >= 0 ? nlohmann::ordered_json(r.bv_tests) : nlohmann::ordered_json()},
                           {"bv_tests_per_collide", r.collide_bv_tests >= 0 ? nlohmann::ordered_json(r.collide_bv_tests) : nlohmann::ordered_json()},
                           {"bytes_per_triangle", r.bytes_per_triangle >= 0 ? nlohmann::ordered_json(r.bytes_per_triangle) : nlohmann::ordered_json()}});
      }
      j["sets"].push_back({{"name", sets[s].name}, {"poses", sets[s].poses.size()}, {"results", results}});
    }
    j["max_rel_distance_diff_vs_fcl"] = max_rel_diff;
    j["collide_answers_differing_from_fcl"] = collide_disagreements;
    j["collide_answers_compared_with_fcl"] = collide_compared;
    out << json_text(j, 2) << "\n";
    log << "batch of " << batch.size() << " distance queries: " << fmt_fixed(t1 * 1e3, 1) << " ms on 1 thread, "
              << fmt_fixed(t2 * 1e3, 1) << " ms on 2 threads, speedup " << fmt_fixed(t1 / t2, 2) << "x\n";
    return;
  }
  out << "A: " << o.file_a << " (" << ta.size() << " triangles)\nB: " << o.file_b << " (" << tb.size()
            << " triangles)\nmodel size " << fmt_sci(size) << ", tolerance " << fmt_sci(tol) << ", " << o.poses
            << " poses per set, seed " << o.seed << ", split rule " << to_string(o.split) << "\n\n";
  Table table({"set", "engine", "collide us", "distance us", "tolerance us", "BV tests/collide", "BV tests/distance", "bytes/tri",
               "collide x vs fcl-obbrss", "distance x vs fcl-obbrss"});
  for (std::size_t s = 0; s < sets.size(); ++s) {
    const EngineResult* fcl = nullptr;
    for (const EngineResult& r : all[s])
      if (r.engine == "fcl-obbrss") fcl = &r;
    for (const EngineResult& r : all[s]) {
      table.add({sets[s].name, r.engine, fmt_fixed(r.collide_us, 2), fmt_fixed(r.distance_us, 2),
                 fmt_fixed(r.tolerance_us, 2), r.collide_bv_tests >= 0 ? fmt_fixed(r.collide_bv_tests, 1) : "n/a",
                 r.bv_tests >= 0 ? fmt_fixed(r.bv_tests, 1) : "n/a",
                 r.bytes_per_triangle >= 0 ? fmt_fixed(r.bytes_per_triangle, 0) : "n/a",
                 fmt_fixed(fcl->collide_us / r.collide_us, 2), fmt_fixed(fcl->distance_us / r.distance_us, 2)});
    }
  }
  table.print(out);
  out << "\n(Times are the mean thread CPU time per query. FCL has no tolerance query: its column is\n"
               " a distance query and a comparison. BV tests: swept counts every RSS pair test of the query;\n"
               " FCL its traversal node's num_bv_tests, the same query run as fcl::distance (or\n"
               " fcl::collide) runs it. FCL's RSS collide copies both models and\n"
               " transforms their vertices on every call, hence its time; its node pairs are not counted.)\n"
            << "largest relative distance difference vs FCL: " << fmt_sci(max_rel_diff) << "\n"
            << "collide answers that differ from FCL OBBRSS's: " << collide_disagreements << " of "
            << collide_compared << " poses\n"
            << "batch of " << batch.size() << " distance queries (swept-inertia): " << fmt_fixed(t1 * 1e3, 1)
            << " ms on 1 thread, " << fmt_fixed(t2 * 1e3, 1) << " ms on 2 threads, speedup "
            << fmt_fixed(t1 / t2, 2) << "x\n";
}


}  // namespace swept::bench
