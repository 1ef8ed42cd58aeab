// Tessellation, the deterministic deflection search and the files of a scene.
#include "swept/scenes/modeling.h"
#include "swept/scenes/scene_model.h"
#include "swept/scenes/scenes.h"
#include "swept/scenes/gearbox.h"
#include "swept/scenes/pin_in_bore.h"
#include "swept/scenes/planning_suite.h"
#include "swept/scenes/problem_toml.h"
#include "swept/io/file_write.h"
#include "swept/io/mesh_io.h"

#include <Standard_Failure.hxx>
#include <TopoDS_Shape.hxx>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <optional>
#include <stdexcept>

namespace swept::scenes {

bool parse_scale(const std::string& text, Scale& scale) {
  if (text == "test") {
    scale = Scale::test;
    return true;
  }
  if (text == "paper") {
    scale = Scale::paper;
    return true;
  }
  return false;
}

const std::vector<SceneInfo>& catalog() {
  // Triangle counts: the paper's Table I (rigid body †, obstacles ‡).
  static const std::vector<SceneInfo> scenes{
      {"air-cleaner",
       "air-cleaner subassembly (filleted housing, filter canister, bent hoses) inside a frame "
       "welded from round tubes; goal: outside the frame",
       1253476, 415378},
      {"cylinder-head",
       "cylinder head (ports, bolt holes, cooling fins, manifolds) lifted above a cylinder block "
       "with bores, inside a tube frame; goal: outside the frame",
       246584, 413742},
      {"tunnel-console",
       "car centre console between dashboard, gear selector, hand brake, seats and roof; goal: "
       "a pose outside the passenger door",
       73469, 300567},
  };
  return scenes;
}

namespace {

using detail::SceneModel;

// Test scale: the paper's body/obstacle proportions, 24,000 triangles in all, so that the
// ±8 % search tolerance keeps every scene under 30,000.
constexpr double kTestTotal = 24000.0;
constexpr double kSearchTolerance = 0.08;
constexpr int kMaxTessellations = 14;
// Deflection limits of the search, mm: coarser than kMaxDeflection the count is set by the
// angular deflection alone; finer than kMinDeflection float32 STL coordinates lose the detail.
constexpr double kMaxDeflection = 20.0;
constexpr double kMinDeflection = 1e-4;

struct SearchResult {
  double deflection = 0.0;
  std::size_t triangles = 0;
};

// Finds a linear deflection whose triangle count is within kSearchTolerance of `target`:
// a secant search on log(count) over log(deflection), bracketing once both sides are seen.
// Deterministic: BRepMesh runs serially and the iteration depends only on the counts.
// The shapes are left meshed at the returned deflection.
SearchResult search_deflection(const std::function<std::size_t(double)>& count, double target, double start,
                               int& tessellations) {
  struct Sample {
    double d;
    std::size_t n;
  };
  std::optional<Sample> fine, coarse;  // fine: too many triangles; coarse: too few
  std::optional<Sample> best;
  double d = start;
  auto error = [&](std::size_t n) { return std::abs(std::log(static_cast<double>(std::max<std::size_t>(n, 1)) / target)); };
  for (int it = 0; it < kMaxTessellations; ++it) {
    const std::size_t n = count(d);
    ++tessellations;
    const Sample s{d, n};
    if (!best || error(n) < error(best->n)) best = s;
    if (std::abs(static_cast<double>(n) / target - 1.0) <= kSearchTolerance) break;
    if (static_cast<double>(n) > target) {
      if (!fine || d > fine->d) fine = s;
    } else {
      if (!coarse || d < coarse->d) coarse = s;
    }
    double next;
    if (fine && coarse) {
      const double ln_f = std::log(static_cast<double>(fine->n)), ln_c = std::log(static_cast<double>(std::max<std::size_t>(coarse->n, 1)));
      double t = ln_f > ln_c ? (ln_f - std::log(target)) / (ln_f - ln_c) : 0.5;
      t = std::clamp(t, 0.15, 0.85);  // keep strictly inside the bracket
      next = std::exp(std::log(fine->d) + t * (std::log(coarse->d) - std::log(fine->d)));
    } else {
      // Counts grow about as 1/deflection on doubly curved faces: extrapolate with that slope.
      const double factor = std::clamp(static_cast<double>(std::max<std::size_t>(n, 1)) / target, 1.0 / 16.0, 16.0);
      next = d * factor;
    }
    next = std::clamp(next, kMinDeflection, kMaxDeflection);
    if (std::abs(next / d - 1.0) < 1e-4) break;  // at a limit, or the count no longer responds
    d = next;
  }
  if (best->d != d) {  // leave the shapes meshed at the best deflection seen
    count(best->d);
    ++tessellations;
  }
  return {best->d, best->n};
}

std::string fmt(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}
std::string problem_toml(const SceneModel& m, const SceneReport& r) {
  std::string comment = "swept scene " + r.name + " --scale " + (r.scale == Scale::paper ? "paper" : "test") + "\n" +
                        m.comment + "\nBRepMesh linear deflection: body " + fmt(r.body_deflection) +
                        " mm, obstacles " + fmt(r.obstacle_deflection) + " mm; angular " + fmt(r.angular_deflection) +
                        " rad.\nTriangles: body " + std::to_string(r.body_triangles) + ", obstacles " +
                        std::to_string(r.obstacle_triangles) + ".";
  Problem p;
  p.unit = "mm";
  for (const MeshFile& f : r.meshes) (f.body ? p.body : p.obstacles).push_back(mesh_ref(f.file, "mm"));
  p.start = m.start;
  p.goal_outside = m.goal_outside;
  if (m.goal_outside) p.goal_margin = m.goal_margin;
  else p.goal = m.goal;
  p.bounds = Aabb{m.bounds_min, m.bounds_max};
  p.rotation = RotationMode::free;
  p.clearance = m.clearance;
  p.time_limit = 60.0;
  p.threads = 2;
  return scenes::problem_toml(p, comment);
}

SceneModel build(const std::string& name) {
  if (name == "air-cleaner") return detail::build_air_cleaner();
  if (name == "cylinder-head") return detail::build_cylinder_head();
  return detail::build_tunnel_console();
}

}  // namespace

Result<SceneReport> generate_scene(const GenerateRequest& request) {
  // Not a planning problem of the paper's catalogue but an assembly (gearbox.h).
  if (request.name == "gearbox") return generate_gearbox(request);
  if (request.name == "pin-in-bore") return generate_pin_in_bore(request);
  const auto t0 = std::chrono::steady_clock::now();
  const auto& cat = catalog();
  const auto info = std::find_if(cat.begin(), cat.end(), [&](const SceneInfo& s) { return s.name == request.name; });
  if (info == cat.end()) {
    std::string names;
    for (const SceneInfo& s : cat) names.append(names.empty() ? "" : ", ").append(s.name);
    if (is_suite_problem(request.name))
      return Error{"'" + request.name + "' is a planner benchmark problem, not a CAD scene: write it with "
                   "write_suite_problem(suite_problem(name), dir), as `swept scene` does"};
    std::string suite;
    for (const SuiteInfo& s : suite_catalog()) suite.append(suite.empty() ? "" : ", ").append(s.name);
    return Error{"unknown scene '" + request.name + "' (known: " + names + "; planner benchmark problems: " + suite +
                 "; assemblies: gearbox, pin-in-bore)"};
  }
  std::error_code ec;
  std::filesystem::create_directories(request.output_dir, ec);
  if (ec) return Error{"cannot create directory " + request.output_dir.string() + ": " + ec.message()};

  SceneReport report;
  report.name = info->name;
  report.scale = request.scale;
  try {
    const SceneModel model = build(info->name);
    const double total = static_cast<double>(info->paper_body_triangles + info->paper_obstacle_triangles);
    const double k = request.scale == Scale::paper ? 1.0 : kTestTotal / total;
    report.target_body_triangles = static_cast<std::size_t>(std::llround(k * static_cast<double>(info->paper_body_triangles)));
    report.target_obstacle_triangles = static_cast<std::size_t>(std::llround(k * static_cast<double>(info->paper_obstacle_triangles)));
    report.angular_deflection = request.scale == Scale::paper ? 0.2 : 0.6;

    for (bool body : {true, false}) {
      std::vector<const TopoDS_Shape*> shapes;
      for (const detail::ScenePart& p : model.parts)
        if (p.body == body) shapes.push_back(&p.shape);
      const auto count = [&](double d) {
        std::size_t n = 0;
        for (const TopoDS_Shape* s : shapes) n += detail::mesh(*s, d, report.angular_deflection);
        return n;
      };
      const double target = static_cast<double>(body ? report.target_body_triangles : report.target_obstacle_triangles);
      // The search starts from the deflection measured for this scene and scale, so that it
      // usually needs one BRepMesh run; it still converges from any start.
      const auto& guess = request.scale == Scale::paper ? model.paper_deflection : model.test_deflection;
      const SearchResult found = search_deflection(count, target, body ? guess[0] : guess[1], report.tessellations);
      (body ? report.body_deflection : report.obstacle_deflection) = found.deflection;
      (body ? report.body_triangles : report.obstacle_triangles) = found.triangles;
    }
    for (const detail::ScenePart& p : model.parts) {
      const TriangleSoup soup = detail::triangles_of(p.shape, p.file);
      const std::filesystem::path path = request.output_dir / p.file;
      if (auto w = write_stl_binary(path, soup); !w) return w.error();
      report.meshes.push_back({p.file, p.body, soup.triangles.size()});
    }
    report.problem_file = request.output_dir / "problem.toml";
    if (auto w = write_file_atomically(report.problem_file, problem_toml(model, report)); !w) return w.error();
  } catch (const Standard_Failure& e) {
    return Error{"scene '" + info->name + "': OpenCASCADE " + e.DynamicType()->Name() + ": " + e.GetMessageString()};
  } catch (const std::exception& e) {
    return Error{"scene '" + info->name + "': " + e.what()};
  }
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return report;
}

}  // namespace swept::scenes
