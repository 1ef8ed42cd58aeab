// The pin-in-bore assembly (pin_in_bore.h): a headed pin in a through bore of its radius, on a
// tilted axis, written as .brep files that keep their cylinders.
#include "swept/scenes/pin_in_bore.h"

#include "swept/scenes/modeling.h"
#include "swept/io/file_write.h"

#include <BRepTools.hxx>
#include <Standard_Failure.hxx>
#include <TopoDS_Shape.hxx>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>
#include <string>
#include <tuple>

namespace swept::scenes {

Pose PinInBore::pose() {
  return Pose::from_axis_angle(Vec3(1, 2, 0).normalized(), 35.0 * std::numbers::pi / 180.0, Vec3(10, -5, 3));
}

Result<SceneReport> generate_pin_in_bore(const GenerateRequest& request) {
  using P = PinInBore;
  const auto t0 = std::chrono::steady_clock::now();
  std::error_code ec;
  std::filesystem::create_directories(request.output_dir, ec);
  if (ec) return Error{"cannot create directory " + request.output_dir.string() + ": " + ec.message()};
  SceneReport report;
  report.name = "pin-in-bore";
  report.scale = request.scale;
  report.body_deflection = report.obstacle_deflection = P::kDeflection;
  report.angular_deflection = 0.5;  // ImportOptions' default
  try {
    using detail::box;
    using detail::cut;
    using detail::cylinder;
    using detail::fuse;
    const Vec3 z = Vec3::UnitZ();
    const TopoDS_Shape block =
        cut(box(Vec3(-P::kBlockHalf, -P::kBlockHalf, 0), Vec3(P::kBlockHalf, P::kBlockHalf, P::kBlockHeight)),
            {cylinder(Vec3(0, 0, -1), z, P::kRadius, P::kBlockHeight + 2)});
    // The pin turned about its axis by 0.2 rad, so that its facets do not line up with the bore's.
    const TopoDS_Shape pin = detail::placed(
        fuse({cylinder(Vec3(0, 0, P::kShaftBottom), z, P::kRadius, P::kBlockHeight - P::kShaftBottom),
              cylinder(Vec3(0, 0, P::kBlockHeight), z, P::kHeadRadius, P::kHeadTop - P::kBlockHeight)}),
        Pose::from_axis_angle(z, 0.2, Vec3::Zero()));
    const Pose pose = P::pose();
    const Eigen::AngleAxisd turn(pose.rotation);
    char placement[256];
    std::snprintf(placement, sizeof placement,
                  "pose = { translation = [%.17g, %.17g, %.17g], axis = [%.17g, %.17g, %.17g], angle_deg = %.17g }\n",
                  pose.translation.x(), pose.translation.y(), pose.translation.z(), turn.axis().x(), turn.axis().y(),
                  turn.axis().z(), turn.angle() * 180.0 / std::numbers::pi);
    std::string toml =
        "# swept scene pin-in-bore\n# An assembly for swept disassemble (docs/assembly-format.md): a headed pin in a "
        "through bore of\n# its radius, meshed coarsely; the pin leaves along its axis, away from its head.\n"
        "unit = \"mm\"\ndeflection = " +
        std::to_string(P::kDeflection) + "\n";
    for (const auto& [name, shape, fixed] : {std::tuple{"block", block, true}, std::tuple{"pin", pin, false}}) {
      std::ostringstream out;
      BRepTools::Write(shape, out);
      const std::string file = std::string(name) + ".brep";
      if (auto w = write_file_atomically(request.output_dir / file, out.str()); !w) return w.error();
      // Counted after writing, so that the files carry no triangulation of their own.
      const std::size_t n = detail::mesh(shape, P::kDeflection, report.angular_deflection);
      ++report.tessellations;
      report.meshes.push_back({file, !fixed, n});
      (fixed ? report.obstacle_triangles : report.body_triangles) += n;
      toml += "\n[[part]]\nname = \"" + std::string(name) + "\"\nfile = \"" + file + "\"\n" + placement;
      if (fixed) toml += "fixed = true\n";
    }
    // No deflection search: the fixed deflection's counts are the targets.
    report.target_body_triangles = report.body_triangles;
    report.target_obstacle_triangles = report.obstacle_triangles;
    report.problem_file = request.output_dir / "assembly.toml";
    if (auto w = write_file_atomically(report.problem_file, toml); !w) return w.error();
  } catch (const Standard_Failure& e) {
    return Error{"scene 'pin-in-bore': OpenCASCADE " + std::string(e.DynamicType()->Name()) + ": " + e.GetMessageString()};
  } catch (const std::exception& e) {
    return Error{"scene 'pin-in-bore': " + std::string(e.what())};
  }
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return report;
}

}  // namespace swept::scenes
