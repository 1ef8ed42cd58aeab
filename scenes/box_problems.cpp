// Box-made planning problems for tests and benchmarks.
#include "swept/scenes/box_problems.h"

#include "swept/io/file_write.h"
#include "swept/io/mesh_io.h"

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace swept::scenes {

void add_box(std::vector<Triangle>& out, const Vec3& lo, const Vec3& hi) {
  auto v = [&](int i) { return Vec3(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(), i & 4 ? hi.z() : lo.z()); };
  const int f[12][3] = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                        {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  for (auto& t : f) out.push_back({v(t[0]), v(t[1]), v(t[2])});
}

GeneratedProblem peg_in_hole(double w, double clearance_fraction) {
  GeneratedProblem g;
  g.name = __func__;
  const double c = clearance_fraction * w, depth = 2 * w, wall = w;
  const double h = w / 2 + c;  // half width of the hole
  auto& o = g.obstacles.triangles;
  add_box(o, Vec3(-h - wall, -h - wall, -depth - wall), Vec3(h + wall, h + wall, -depth));  // bottom
  add_box(o, Vec3(-h - wall, -h - wall, -depth), Vec3(-h, h + wall, 0));                 // four walls
  add_box(o, Vec3(h, -h - wall, -depth), Vec3(h + wall, h + wall, 0));
  add_box(o, Vec3(-h, -h - wall, -depth), Vec3(h, -h, 0));
  add_box(o, Vec3(-h, h, -depth), Vec3(h, h + wall, 0));
  const double len = 2.5 * w;
  add_box(g.body.triangles, Vec3(-w / 2, -w / 2, -len / 2), Vec3(w / 2, w / 2, len / 2));
  g.problem.start = Pose::from_translation(Vec3(0, 0, -depth + c + len / 2));
  g.problem.goal_outside = true;
  g.problem.goal_margin = 0.0;
  g.problem.clearance = c / 5;
  g.problem.time_limit = 60;
  return g;
}

GeneratedProblem t_slot() {
  GeneratedProblem g;
  g.name = __func__;
  auto& o = g.obstacles.triangles;
  // Block [−20, 20] × [−15, 15] × [−10, 0] with a T-slot along x: a narrow neck |y| < 3 for
  // z ∈ [−3, 0] and a wide channel |y| < 8 for z ∈ [−9, −3]; closed at x = −20 by an end wall.
  add_box(o, Vec3(-20, -15, -10), Vec3(20, 15, -9));  // floor
  add_box(o, Vec3(-20, -15, -9), Vec3(20, -8, 0));     // side walls
  add_box(o, Vec3(-20, 8, -9), Vec3(20, 15, 0));
  add_box(o, Vec3(-20, -8, -3), Vec3(20, -3, 0));      // lips
  add_box(o, Vec3(-20, 3, -3), Vec3(20, 8, 0));
  add_box(o, Vec3(-22, -15, -10), Vec3(-20, 15, 0));   // end wall
  auto& b = g.body.triangles;
  add_box(b, Vec3(-6, -7, -8.5), Vec3(6, 7, -3.5));  // head in the channel
  add_box(b, Vec3(-6, -2.5, -3.5), Vec3(6, 2.5, 4));  // stem through the neck, sticking out
  g.problem.start = Pose::from_translation(Vec3(0, 0, 0));
  g.problem.goal = Pose::from_translation(Vec3(35, 0, 25));
  g.problem.clearance = 0.05;
  g.problem.rotation = RotationMode::none;
  g.problem.time_limit = 60;
  return g;
}

GeneratedProblem l_tunnel() {
  GeneratedProblem g;
  g.name = __func__;
  auto& o = g.obstacles.triangles;
  // Solid block [0, 40] × [−10, 10] × [−10, 40] minus the tunnel: horizontal leg
  // x ∈ [0, 30], |y| < 5, z ∈ [−5, 5]; vertical leg x ∈ [20, 30], |y| < 5, z ∈ [−5, 40].
  add_box(o, Vec3(0, -10, -10), Vec3(40, 10, -5));   // floor
  add_box(o, Vec3(0, -10, -5), Vec3(40, -5, 40));    // sides
  add_box(o, Vec3(0, 5, -5), Vec3(40, 10, 40));
  add_box(o, Vec3(0, -5, 5), Vec3(20, 5, 40));       // roof of the horizontal leg
  add_box(o, Vec3(30, -5, -5), Vec3(40, 5, 40));     // far wall
  add_box(g.body.triangles, Vec3(-3.5, -3.5, -3.5), Vec3(3.5, 3.5, 3.5));
  g.problem.start = Pose::from_translation(Vec3(-8, 0, 0));  // in front of the entrance
  g.problem.goal = Pose::from_translation(Vec3(25, 0, 48));  // above the exit
  g.problem.clearance = 0.1;
  g.problem.rotation = RotationMode::none;
  g.problem.bounds = Aabb{Vec3(-12, -12, -12), Vec3(45, 12, 55)};
  g.problem.time_limit = 60;
  return g;
}

GeneratedProblem bar_through_slot() {
  GeneratedProblem g;
  g.name = __func__;
  auto& o = g.obstacles.triangles;
  // Wall x ∈ [−1, 1], y, z ∈ [−20, 20], with a slot |y| < 4, |z| < 2.
  add_box(o, Vec3(-1, -20, -20), Vec3(1, -4, 20));
  add_box(o, Vec3(-1, 4, -20), Vec3(1, 20, 20));
  add_box(o, Vec3(-1, -4, -20), Vec3(1, 4, -2));
  add_box(o, Vec3(-1, -4, 2), Vec3(1, 4, 20));
  add_box(g.body.triangles, Vec3(-0.75, -7, -0.75), Vec3(0.75, 7, 0.75));  // 14 long, along y
  g.problem.start = Pose::from_translation(Vec3(-10, 0, 0));
  g.problem.goal = Pose::from_translation(Vec3(10, 0, 0));
  g.problem.clearance = 0.05;
  g.problem.bounds = Aabb{Vec3(-14, -10, -10), Vec3(14, 10, 10)};
  g.problem.time_limit = 120;
  return g;
}

GeneratedProblem enclosed() {
  GeneratedProblem g;
  g.name = __func__;
  auto& o = g.obstacles.triangles;
  add_box(o, Vec3(-10, -10, -10), Vec3(10, 10, -8));
  add_box(o, Vec3(-10, -10, 8), Vec3(10, 10, 10));
  add_box(o, Vec3(-10, -10, -8), Vec3(-8, 10, 8));
  add_box(o, Vec3(8, -10, -8), Vec3(10, 10, 8));
  add_box(o, Vec3(-8, -10, -8), Vec3(8, -8, 8));
  add_box(o, Vec3(-8, 8, -8), Vec3(8, 10, 8));
  add_box(g.body.triangles, Vec3(-2, -2, -2), Vec3(2, 2, 2));
  g.problem.start = Pose{};
  g.problem.goal_outside = true;
  g.problem.clearance = 0.1;
  g.problem.rotation = RotationMode::none;
  g.problem.time_limit = 5;
  return g;
}

std::vector<GeneratedProblem> box_problems() {
  return {peg_in_hole(), t_slot(), l_tunnel(), bar_through_slot(), enclosed()};
}

namespace {
std::string vec(const Vec3& v) {
  std::ostringstream os;
  os << std::setprecision(17) << "[" << v.x() << ", " << v.y() << ", " << v.z() << "]";
  return os.str();
}
std::string pose_table(const Pose& p) {
  const Quat q = p.quaternion();
  std::ostringstream os;
  os << std::setprecision(17) << "translation = " << vec(p.translation) << "\nquaternion = [" << q.x() << ", " << q.y()
     << ", " << q.z() << ", " << q.w() << "]\n";
  return os.str();
}
}  // namespace

Result<bool> write_problem_files(const GeneratedProblem& g, const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) return Error{dir + ": cannot create: " + ec.message()};
  if (auto w = write_stl_binary(fs::path(dir) / "obstacles.stl", g.obstacles); !w) return w.error();
  if (auto w = write_stl_binary(fs::path(dir) / "body.stl", g.body); !w) return w.error();
  const Problem& p = g.problem;
  std::ostringstream out;
  out << std::setprecision(17) << "# " << g.name << " (generated by swept)\nunit = \"" << p.unit << "\"\n\n"
      << "[[obstacle]]\nfile = \"obstacles.stl\"\n\n[[body]]\nfile = \"body.stl\"\n\n";
  if (p.reference_point) out << "[body_frame]\nreference_point = " << vec(*p.reference_point) << "\n\n";
  out << "[start]\n" << pose_table(p.start) << "\n[goal]\n";
  if (p.goal_outside) out << "outside = true\nmargin = " << p.goal_margin << "\n\n";
  else out << pose_table(*p.goal) << "\n";
  if (p.bounds) out << "[bounds]\nmin = " << vec(p.bounds->min) << "\nmax = " << vec(p.bounds->max) << "\n\n";
  out << "[rotation]\nmode = \"" << (p.rotation == RotationMode::none ? "none" : p.rotation == RotationMode::free ? "free" : "limits")
      << "\"\n";
  if (p.rotation == RotationMode::limits) {
    out << "limits_deg = [";
    for (int i = 0; i < 3; ++i)
      out << (i ? ", " : "") << "[" << p.rotation_limits[i][0] * 180 / 3.141592653589793 << ", "
          << p.rotation_limits[i][1] * 180 / 3.141592653589793 << "]";
    out << "]\n";
  }
  out << "\n[planner]\nclearance = " << p.clearance << "\ncontact_tolerance = " << p.contact_tolerance
      << "\nfitter = \"" << to_string(p.build.fitter) << "\"\nsplit = \"" << to_string(p.build.split)
      << "\"\nleaf_size = " << p.build.leaf_size << "\ntime_limit = " << p.time_limit << "\n";
  return write_file_atomically(fs::path(dir) / "problem.toml", out.str());
}

}  // namespace swept::scenes
