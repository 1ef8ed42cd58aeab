// Micro-benchmarks of the proximity queries against FCL 0.7 (OBBRSS) in the same run:
// collide and distance on a CAD mesh pair at near-contact and far poses.
//   bench_queries [--benchmark_filter=...]      (mesh pair: SWEPT_BENCH_A / SWEPT_BENCH_B,
//                                                default occt/motor.stl against itself)
#include "../apps/swept/seeded_rng.h"
#include "swept/io/mesh_io.h"
#include "swept/query/query.h"

#include <benchmark/benchmark.h>
#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/math/bv/OBBRSS.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/distance.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

namespace {

using namespace swept;

using Rng = swept::cli::SeededRng;

std::shared_ptr<fcl::BVHModel<fcl::OBBRSSd>> fcl_model(const std::vector<Triangle>& tris) {
  auto m = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
  std::vector<fcl::Vector3d> v;
  std::vector<fcl::Triangle> f;
  for (const Triangle& t : tris) {
    const std::size_t base = v.size();
    v.push_back(t.p);
    v.push_back(t.q);
    v.push_back(t.r);
    f.emplace_back(base, base + 1, base + 2);
  }
  m->beginModel();
  m->addSubModel(v, f);
  m->endModel();
  return m;
}

fcl::Transform3d to_fcl(const Pose& p) {
  fcl::Transform3d t = fcl::Transform3d::Identity();
  t.linear() = p.rotation;
  t.translation() = p.translation;
  return t;
}

/// The mesh pair, its trees and two pose sets, built once.
struct Fixture {
  Bvh a, b;
  std::shared_ptr<fcl::BVHModel<fcl::OBBRSSd>> fa, fb;
  std::vector<Pose> near, far;

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
    Fixture f{build_bvh(ta).value(), build_bvh(tb).value(), fcl_model(ta), fcl_model(tb), {}, {}};
    const Vec3 ca = bounds(ta).center(), cb = bounds(tb).center();
    const double size = std::max(f.a.extent, f.b.extent);
    Rng rng{42};
    while (f.near.size() < 64) {
      const Mat3 r = rng.rotation();
      const Vec3 u = rng.direction();
      auto place = [&](double s) { return Pose{r, ca + s * u - r * cb}; };
      auto dist = [&](double s) { return distance(f.a, {}, f.b, place(s)).distance; };
      double lo = 0, hi = size;
      while (dist(hi) <= 0.01 * size) hi *= 2;
      for (int it = 0; it < 80; ++it) {
        const double mid = 0.5 * (lo + hi), d = dist(mid);
        if (d <= 0) {
          lo = mid;
        } else if (d > 0.01 * size) {
          hi = mid;
        } else {
          f.near.push_back(place(mid));
          break;
        }
      }
      f.far.push_back(place(size * (1.1 + 0.9 * rng.uniform())));
    }
    f.far.resize(64);
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

// Argument: 0 = near contact, 1 = far.
BENCHMARK(BM_SweptDistance)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_FclDistance)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SweptCollide)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_FclCollide)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
