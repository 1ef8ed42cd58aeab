// The gearbox assembly (gearbox.h), modelled with OpenCASCADE.
#include "swept/scenes/gearbox.h"
#include "swept/scenes/modeling.h"

#include "swept/io/file_write.h"
#include "swept/io/mesh_io.h"

#include <Standard_Failure.hxx>
#include <TopoDS_Shape.hxx>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

namespace swept::scenes {
namespace {

using namespace detail;

struct GearboxPart {
  std::string name;
  bool fixed = false;
  TopoDS_Shape shape;
};

// Dimensions, mm. The shaft's axis is z; the housing's floor top is at z = 10, its walls' top
// at z = 100, the cover on them up to z = 110.
constexpr double kShaftR = 8, kBearingR = 16, kScrewR = 3, kHeadR = 6;
constexpr double kScrewXY = 52;

TopoDS_Shape ring(double z0, double z1, double inner, double outer) {
  return tube(Vec3(0, 0, z0), Vec3(0, 0, z1), outer, inner);
}

std::vector<GearboxPart> build_gearbox() {
  std::vector<GearboxPart> parts;
  // Housing: an open box, walls 15 thick, a blind bearing seat in its floor, blind screw holes in
  // its walls' top.
  std::vector<TopoDS_Shape> housing_cuts{box(Vec3(-45, -45, 10), Vec3(45, 45, 101)),
                                         cylinder(Vec3(0, 0, 4), Vec3(0, 0, 1), kBearingR, 7)};
  for (double sx : {-1.0, 1.0})
    for (double sy : {-1.0, 1.0})
      housing_cuts.push_back(cylinder(Vec3(sx * kScrewXY, sy * kScrewXY, 80), Vec3(0, 0, 1), kScrewR, 21));
  parts.push_back({"housing", true, cut(box(Vec3(-60, -60, 0), Vec3(60, 60, 100)), housing_cuts)});
  // Cover: a plate on the walls, a recess for the upper bearing from below, a hole for the shaft
  // (1 mm radial clearance), four screw holes.
  std::vector<TopoDS_Shape> cover_cuts{cylinder(Vec3(0, 0, 99), Vec3(0, 0, 1), kBearingR, 7),
                                       cylinder(Vec3(0, 0, 99), Vec3(0, 0, 1), kShaftR + 1, 12)};
  for (double sx : {-1.0, 1.0})
    for (double sy : {-1.0, 1.0})
      cover_cuts.push_back(cylinder(Vec3(sx * kScrewXY, sy * kScrewXY, 99), Vec3(0, 0, 1), kScrewR, 12));
  parts.push_back({"cover", false, cut(box(Vec3(-60, -60, 100), Vec3(60, 60, 110)), cover_cuts)});
  // Screws: a shank in the holes (same radius: zero clearance) and a head on the cover.
  int k = 0;
  for (double sx : {-1.0, 1.0})
    for (double sy : {-1.0, 1.0}) {
      const Vec3 at(sx * kScrewXY, sy * kScrewXY, 0);
      parts.push_back({"screw-" + std::to_string(++k), false,
                       fuse({cylinder(at + Vec3(0, 0, 80), Vec3(0, 0, 1), kScrewR, 30),
                             cylinder(at + Vec3(0, 0, 110), Vec3(0, 0, 1), kHeadR, 4)})});
    }
  // Shaft: standing in the lower bearing, a collar above it, up through the cover.
  parts.push_back({"shaft", false,
                   fuse({cylinder(Vec3(0, 0, 4), Vec3(0, 0, 1), kShaftR, 121),
                         cylinder(Vec3(0, 0, 14), Vec3(0, 0, 1), 14, 6)})});
  // Gear: a hub on the collar and 24 teeth round a rim of radius 36.
  std::vector<TopoDS_Shape> gear{ring(20, 35, kShaftR, 36)};
  for (int t = 0; t < 24; ++t) {
    const double a = 2.0 * std::numbers::pi * t / 24;
    const Pose turn = Pose::from_axis_angle(Vec3::UnitZ(), a, Vec3::Zero());
    gear.push_back(placed(box(Vec3(35, -2.5, 20), Vec3(41, 2.5, 35)), turn));
  }
  parts.push_back({"gear", false, fuse(gear)});
  // Bearings: rings on the shaft (inner radius = the shaft's), in the floor's seat and the
  // cover's recess (outer radius = the seat's).
  parts.push_back({"bearing-lower", false, ring(4, 14, kShaftR, kBearingR)});
  parts.push_back({"bearing-upper", false, ring(96, 106, kShaftR, kBearingR)});
  return parts;
}

std::string fmt(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

}  // namespace

Result<SceneReport> generate_gearbox(const GenerateRequest& request) {
  const auto t0 = std::chrono::steady_clock::now();
  std::error_code ec;
  std::filesystem::create_directories(request.output_dir, ec);
  if (ec) return Error{"cannot create directory " + request.output_dir.string() + ": " + ec.message()};
  SceneReport report;
  report.name = "gearbox";
  report.scale = request.scale;
  // The deflection: from a measured start, scaled until the count is within [target, 1.3 target]
  // (curved faces' counts grow about as 1/sqrt(deflection)); deterministic.
  const bool paper = request.scale == Scale::paper;
  const double target = paper ? 520000.0 : 16000.0;
  report.angular_deflection = paper ? 0.05 : 0.35;
  report.target_obstacle_triangles = static_cast<std::size_t>(target);
  try {
    const std::vector<GearboxPart> parts = build_gearbox();
    auto count = [&](double d) {
      std::size_t n = 0;
      for (const GearboxPart& p : parts) n += mesh(p.shape, d, report.angular_deflection);
      ++report.tessellations;
      return static_cast<double>(n);
    };
    double deflection = paper ? 2e-4 : 0.08;
    for (int it = 0; it < 8; ++it) {
      const double n = count(deflection);
      if (n >= target && n <= 1.3 * target) break;
      deflection *= std::clamp((n / (1.15 * target)) * (n / (1.15 * target)), 1.0 / 64, 64.0);
      if (it == 7) count(deflection);
    }
    report.body_deflection = report.obstacle_deflection = deflection;
    std::string toml = "# swept scene gearbox --scale " + std::string(paper ? "paper" : "test") +
                       "\n# An assembly for swept disassemble (docs/assembly-format.md). BRepMesh linear deflection " +
                       fmt(deflection) + " mm, angular " + fmt(report.angular_deflection) + " rad.\nunit = \"mm\"\n";
    for (const GearboxPart& p : parts) {
      const TriangleSoup soup = triangles_of(p.shape, p.name);
      const std::string file = p.name + ".stl";
      if (auto w = write_stl_binary(request.output_dir / file, soup); !w) return w.error();
      report.meshes.push_back({file, false, soup.triangles.size()});
      report.obstacle_triangles += soup.triangles.size();
      toml += "\n[[part]]\nname = \"" + p.name + "\"\nfile = \"" + file + "\"\n";
      if (p.fixed) toml += "fixed = true\n";
    }
    report.problem_file = request.output_dir / "assembly.toml";
    if (auto w = write_file_atomically(report.problem_file, toml); !w) return w.error();
  } catch (const Standard_Failure& e) {
    return Error{"scene 'gearbox': OpenCASCADE " + std::string(e.DynamicType()->Name()) + ": " + e.GetMessageString()};
  } catch (const std::exception& e) {
    return Error{"scene 'gearbox': " + std::string(e.what())};
  }
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return report;
}

}  // namespace swept::scenes
