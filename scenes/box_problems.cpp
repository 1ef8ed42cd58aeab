// Box-made planning problems for tests and benchmarks.
#include "swept/scenes/box_problems.h"
#include "swept/scenes/problem_toml.h"

#include "swept/io/file_write.h"
#include "swept/io/mesh_io.h"

#include <filesystem>

namespace swept::scenes {

void add_hexahedron(std::vector<Triangle>& out, const std::array<Vec3, 8>& c) {
  const int f[12][3] = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                        {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  for (auto& t : f) out.push_back({c[t[0]], c[t[1]], c[t[2]]});
}

void add_box(std::vector<Triangle>& out, const Vec3& lo, const Vec3& hi) {
  std::array<Vec3, 8> c;
  for (int i = 0; i < 8; ++i) c[i] = Vec3(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(), i & 4 ? hi.z() : lo.z());
  add_hexahedron(out, c);
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

Result<bool> write_problem_files(const GeneratedProblem& g, const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) return Error{dir + ": cannot create: " + ec.message()};
  if (auto w = write_stl_binary(fs::path(dir) / "obstacles.stl", g.obstacles); !w) return w.error();
  if (auto w = write_stl_binary(fs::path(dir) / "body.stl", g.body); !w) return w.error();
  Problem p = g.problem;
  p.obstacles = {mesh_ref("obstacles.stl")};
  p.body = {mesh_ref("body.stl")};
  return write_file_atomically(fs::path(dir) / "problem.toml", problem_toml(p, g.name + " (generated by swept)"));
}

}  // namespace swept::scenes
