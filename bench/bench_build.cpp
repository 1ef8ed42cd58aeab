// Build speed of the RSS trees: every fitter and split rule, the paper's method (inertia +
// min-sa) also at leaf sizes 2, 4 and 8 (bytes per triangle as a counter), and FCL's
// BVHModel<RSS> build of the same mesh in the same run; prints the ratios at the end.
//   bench_build [--benchmark_filter=...]
// Mesh: SWEPT_BENCH_MESH (any format swept reads; SWEPT_BENCH_DEFLECTION for CAD, default 0.01),
// else occt/hammer.brep from the shared data at 0.01 mm deflection (≈1.3M triangles).
#include "swept/bench/fcl_model.h"
#include "swept/bvh/bvh.h"
#include "swept/io/mesh_io.h"

#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <string>

namespace {

using namespace swept;

const std::vector<Triangle>& mesh() {
  static const std::vector<Triangle> tris = [] {
    std::string file = SWEPT_SHARED_DATA "/occt/hammer.brep";
    if (const char* f = std::getenv("SWEPT_BENCH_MESH")) file = f;
    ImportOptions io;
    io.linear_deflection = 0.01;
    // The hammer at 0.01 mm makes 1.3 M triangles, but BRepMesh's estimate before meshing is
    // about 7.8 M: the default limit of 5 M would refuse it.
    io.max_triangles = 20'000'000;
    if (const char* d = std::getenv("SWEPT_BENCH_DEFLECTION")) io.linear_deflection = std::atof(d);
    auto m = import_mesh(file, io);
    if (!m) {
      std::cerr << "bench_build: " << m.error().message << "\n";
      std::exit(1);
    }
    std::cerr << "bench_build: " << file << ": " << m->triangle_count() << " triangles\n";
    return m->merged().triangles;
  }();
  return tris;
}

std::map<std::string, double>& seconds_per_build() {
  static std::map<std::string, double> m;
  return m;
}

// Leaf sizes the paper's method is also built at (docs/fitters.md, "Leaf size").
constexpr int kOtherLeafSizes[] = {2, 4, 8};

void BM_Swept(benchmark::State& state, Fitter fitter, SplitRule split, int leaf_size) {
  const auto& tris = mesh();
  const int threads = static_cast<int>(state.range(0));
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
  std::size_t bytes = 0;
  for (auto _ : state) {
    auto bvh = build_bvh(tris, {.fitter = fitter, .split = split, .leaf_size = leaf_size, .parallel = threads > 1});
    benchmark::DoNotOptimize(bvh);
    bytes = bvh->memory_bytes();
  }
  state.counters["Mtri/s"] = benchmark::Counter(static_cast<double>(tris.size()) * 1e-6 * state.iterations(),
                                                benchmark::Counter::kIsRate);
  state.counters["triangles"] = static_cast<double>(tris.size());
  state.counters["bytes/tri"] = static_cast<double>(bytes) / static_cast<double>(tris.size());
}

void BM_FclRss(benchmark::State& state) {
  const auto& tris = mesh();
  // As the paper benchmark times FCL: the model built from swept's triangles, conversion included.
  for (auto _ : state) benchmark::DoNotOptimize(swept::bench::fcl_model<fcl::RSSd>(tris));
  state.counters["Mtri/s"] = benchmark::Counter(static_cast<double>(tris.size()) * 1e-6 * state.iterations(),
                                                benchmark::Counter::kIsRate);
}

// Records seconds per build per benchmark name, to print the ratios after the run.
class RatioReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& r : runs)
      if (r.run_type == Run::RT_Iteration && r.iterations > 0)
        seconds_per_build()[r.benchmark_name()] = r.GetAdjustedRealTime() * 1e-3;  // ms → s
    ConsoleReporter::ReportRuns(runs);
  }
};

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  // Every fitter and split rule of the library's tables; ratios against the first fitter (PQP_FIT).
  const std::string base(all_fitters().front().name);
  for (const FitterInfo& f : all_fitters())
    for (const SplitRuleInfo& s : all_split_rules())
      benchmark::RegisterBenchmark(("swept/" + std::string(f.name) + "/" + std::string(s.name)).c_str(), BM_Swept,
                                   f.fitter, s.rule, kDefaultLeafSize)
          ->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
  for (const int leaf : kOtherLeafSizes)
    benchmark::RegisterBenchmark(("swept/inertia/min-sa/leaf" + std::to_string(leaf)).c_str(), BM_Swept, Fitter::inertia,
                                 SplitRule::min_sa, leaf)
        ->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
  benchmark::RegisterBenchmark("fcl/RSS", BM_FclRss)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
  RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  auto& t = seconds_per_build();
  const double n = static_cast<double>(mesh().size());
  std::printf("\nBuild speed, %.0f triangles (million triangles per second; ratio = time / time of the reference)\n", n);
  auto row = [&](const std::string& name, const std::string& ref) {
    if (!t.count(name)) return;
    std::printf("  %-34s %7.3f Mtri/s", name.c_str(), n / t[name] * 1e-6);
    if (t.count(ref)) std::printf("   %5.2fx the time of %s", t[name] / t[ref], ref.c_str());
    std::printf("\n");
  };
  for (const char* threads : {"1", "2"}) {
    for (const FitterInfo& f : all_fitters())
      for (const SplitRuleInfo& s : all_split_rules()) {
        const std::string suffix = "/" + std::string(s.name) + "/" + threads + "/iterations:3/real_time";
        row("swept/" + std::string(f.name) + suffix, "swept/" + base + suffix);
      }
  }
  for (const char* threads : {"1", "2"})
    for (const int leaf : kOtherLeafSizes) {
      const std::string suffix = std::string("/") + threads + "/iterations:3/real_time";
      row("swept/inertia/min-sa/leaf" + std::to_string(leaf) + suffix, "swept/inertia/min-sa" + suffix);
    }
  row("fcl/RSS/iterations:3/real_time", "");
  const std::string ours = "swept/inertia/min-sa/2/iterations:3/real_time";
  if (t.count(ours) && t.count("fcl/RSS/iterations:3/real_time"))
    std::printf("  FCL RSS build time / swept inertia+min-sa (2 threads): %.2fx\n", t["fcl/RSS/iterations:3/real_time"] / t[ours]);
  benchmark::Shutdown();
  return 0;
}
