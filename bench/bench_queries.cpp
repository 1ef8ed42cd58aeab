// Micro-benchmarks of the proximity queries against FCL 0.7 (OBBRSS) in the same run:
// collide and distance on a CAD mesh pair at near-contact and far poses, and distance along
// straight motions with and without coherence (each query hinted with the previous one's
// closest pair: DistanceRequest::hint; or told its own answer, the ceiling of any warm start),
// and pure translations certified step by step against checked exactly in one traversal
// (sweep_translation).
//   bench_queries [--benchmark_filter=...]      (mesh pair: SWEPT_BENCH_A / SWEPT_BENCH_B,
//                                                default occt/motor.stl against itself)
#include "swept/bench/fcl_model.h"
#include "swept/bench/pose_sets.h"
#include "swept/io/mesh_io.h"
#include "swept/query/motion.h"
#include "swept/query/query.h"

#include <benchmark/benchmark.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/distance.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace {

using namespace swept;
using bench::fcl_model;
using bench::to_fcl;

/// The mesh pair, its trees and two pose sets, built once.
struct Fixture {
  Bvh a, b;
  std::shared_ptr<fcl::BVHModel<fcl::OBBRSSd>> fa, fb;
  std::vector<Pose> near, far;
  /// Straight motions, 32 poses each, from each far pose to a near-contact one (the reference
  /// point linear, the rotation slerped): the poses a motion check or a path query visits.
  std::vector<Pose> path;

  static const Fixture& get() {
    static const Fixture f = make();
    return f;
  }
  static Fixture make() {
    const char* ea = std::getenv("SWEPT_BENCH_A");
    const char* eb = std::getenv("SWEPT_BENCH_B");
    const std::string pa = ea ? ea : std::string(SWEPT_SHARED_DATA) + "/occt/motor.stl";
    const std::string pb = eb ? eb : pa;
    auto load = [](const std::string& p) {
      Result<ImportedModel> m = import_mesh(p);
      if (!m) {
        std::cerr << m.error().message << "\n";
        std::exit(1);
      }
      return m->merged().triangles;
    };
    const auto ta = load(pa), tb = load(pb);
    Fixture f{build_bvh(ta).value(), build_bvh(tb).value(), fcl_model<fcl::OBBRSSd>(ta), fcl_model<fcl::OBBRSSd>(tb), {}, {}};
    // The benchmarks' one pose-set generator (swept/bench/pose_sets.h), 64 poses per set.
    auto sets = bench::make_pose_sets(f.a, f.b, {.count = 64, .seed = 42});
    f.near = std::move(sets[1].poses);
    f.far = std::move(sets[2].poses);
    if (f.near.empty() || f.far.empty()) {
      std::cerr << "bench_queries: no near-contact or far poses found for " << pa << " and " << pb << "\n";
      std::exit(1);
    }
    for (std::size_t k = 0; k < std::min(f.near.size(), f.far.size()); ++k) {
      const Quat q0 = f.far[k].quaternion(), q1 = f.near[k].quaternion();
      for (int i = 0; i < 32; ++i) {
        const double t = i / 31.0;
        f.path.push_back({q0.slerp(t, q1).toRotationMatrix(), (1 - t) * f.far[k].translation + t * f.near[k].translation});
      }
    }
    return f;
  }
};

const std::vector<Pose>& poses(const Fixture& f, int set) { return set == 0 ? f.near : f.far; }

void BM_SweptDistance(benchmark::State& state) {
  const Fixture& f = Fixture::get();
  const auto& ps = poses(f, static_cast<int>(state.range(0)));
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(distance(f.a, {}, f.b, ps[i++ % ps.size()]).distance);
}
void BM_FclDistance(benchmark::State& state) {
  const Fixture& f = Fixture::get();
  const auto& ps = poses(f, static_cast<int>(state.range(0)));
  std::size_t i = 0;
  fcl::DistanceRequestd req;
  req.enable_nearest_points = true;
  for (auto _ : state) {
    fcl::DistanceResultd res;
    fcl::distance(f.fa.get(), fcl::Transform3d::Identity(), f.fb.get(), to_fcl(ps[i++ % ps.size()]), req, res);
    benchmark::DoNotOptimize(res.min_distance);
  }
}
void BM_SweptCollide(benchmark::State& state) {
  const Fixture& f = Fixture::get();
  const auto& ps = poses(f, static_cast<int>(state.range(0)));
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(collide(f.a, {}, f.b, ps[i++ % ps.size()]).colliding);
}
void BM_FclCollide(benchmark::State& state) {
  const Fixture& f = Fixture::get();
  const auto& ps = poses(f, static_cast<int>(state.range(0)));
  std::size_t i = 0;
  fcl::CollisionRequestd req;
  for (auto _ : state) {
    fcl::CollisionResultd res;
    fcl::collide(f.fa.get(), fcl::Transform3d::Identity(), f.fb.get(), to_fcl(ps[i++ % ps.size()]), req, res);
    benchmark::DoNotOptimize(res.isCollision());
  }
}

// Along the motions, pose after pose. Argument 0: each query cold; 1: hinted with the previous
// query's closest pair (DistanceRequest::hint); 2: the ceiling of any warm start, each query told
// its own answer in advance (upper_bound = the next double above the exact distance, measured
// before the timing), so that all it does is prove it. Counter `rss_tests`: RSS pair tests per
// query (the same on every run).
void BM_SweptDistancePath(benchmark::State& state) {
  const Fixture& f = Fixture::get();
  const int mode = static_cast<int>(state.range(0));
  std::vector<double> known;
  if (mode == 2)
    for (const Pose& p : f.path) known.push_back(std::nextafter(distance(f.a, {}, f.b, p).distance, std::numeric_limits<double>::infinity()));
  std::uint64_t tests = 0;
  for (auto _ : state) {
    DistanceRequest request;
    double sum = 0;
    tests = 0;
    for (std::size_t i = 0; i < f.path.size(); ++i) {
      if (mode == 2) request.upper_bound = known[i];
      const DistanceResult d = distance(f.a, {}, f.b, f.path[i], request);
      if (mode == 1) request.hint = d.hint;
      sum += d.distance;
      tests += d.stats.bv_tests;
    }
    benchmark::DoNotOptimize(sum);
  }
  state.counters["rss_tests"] = static_cast<double>(tests) / static_cast<double>(f.path.size());
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * f.path.size()));
}
void BM_FclDistancePath(benchmark::State& state) {
  const Fixture& f = Fixture::get();
  fcl::DistanceRequestd req;
  req.enable_nearest_points = true;
  for (auto _ : state) {
    double sum = 0;
    for (const Pose& p : f.path) {
      fcl::DistanceResultd res;
      fcl::distance(f.fa.get(), fcl::Transform3d::Identity(), f.fb.get(), to_fcl(p), req, res);
      sum += res.min_distance;
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * f.path.size()));
}
// Pure translations from each far pose to its near-contact pose's position (the far rotation
// kept), clear by more than 0: argument 0 certifies each with the certificate alone
// (motion_clearance without its sweep of grazing translations),
// 1 checks it exactly with sweep_translation. Counter `clear`: motions found clear (the same for
// both; the benchmark stops with an error if they differ).
void BM_SweptTranslation(benchmark::State& state) {
  const Fixture& f = Fixture::get();
  const bool sweep = state.range(0) == 1;
  const std::size_t n = std::min(f.near.size(), f.far.size());
  const Vec3 reference = Vec3::Zero();
  const double radius = motion_radius(f.b, reference);
  auto clear_by = [&](std::size_t k, bool use_sweep) {
    const Pose from = f.far[k];
    const Vec3 shift = f.near[k].translation - from.translation;
    if (use_sweep) return sweep_translation(f.a, {}, f.b, from, {.translation = shift}).clear;
    const Pose to{from.rotation, from.translation + shift};
    return motion_clearance(f.a, {}, f.b, {from, to, reference, radius}, {.sweep_after = -1}).clear();
  };
  for (std::size_t k = 0; k < n; ++k)
    if (clear_by(k, true) != clear_by(k, false)) {
      state.SkipWithError("the sweep and the certificate disagree");
      return;
    }
  std::size_t clear = 0;
  for (auto _ : state) {
    clear = 0;
    for (std::size_t k = 0; k < n; ++k) clear += clear_by(k, sweep) ? 1 : 0;
  }
  state.counters["clear"] = static_cast<double>(clear);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * n));
}
BENCHMARK(BM_SweptTranslation)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

BENCHMARK(BM_SweptDistancePath)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FclDistancePath)->Unit(benchmark::kMillisecond);

// Argument: 0 = near contact, 1 = far.
BENCHMARK(BM_SweptDistance)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_FclDistance)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SweptCollide)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_FclCollide)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
