// The box-made problems of the planner benchmark suite (see swept/scenes/planning_suite.h).
// Every coordinate below is chosen so that the witness path's clearances can be read off the
// numbers; the comments state them.
#include "swept/scenes/planning_suite.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace swept::scenes::suite {
namespace {

constexpr double kPi = std::numbers::pi;

Pose at(double x, double y, double z) { return Pose::from_translation(Vec3(x, y, z)); }
Pose turned(const Vec3& axis, double degrees, double x, double y, double z) {
  return Pose::from_axis_angle(axis, degrees * kPi / 180.0, Vec3(x, y, z));
}

void box(std::vector<Triangle>& out, double x0, double y0, double z0, double x1, double y1, double z1) {
  add_box(out, Vec3(x0, y0, z0), Vec3(x1, y1, z1));
}

SuiteProblem make(const std::string& name, double clearance, const Aabb& bounds) {
  SuiteProblem s;
  s.problem.name = name;
  Problem& p = s.problem.problem;
  p.unit = "mm";
  p.clearance = clearance;
  p.bounds = bounds;
  p.rotation = RotationMode::free;
  p.time_limit = 60.0;
  p.threads = 2;
  return s;
}

void finish(SuiteProblem& s) {
  s.problem.problem.start = s.witness.front();
  s.problem.problem.goal = s.witness.back();
  s.problem.obstacles.name = "obstacles";
  s.problem.body.name = "body";
}

}  // namespace

SuiteProblem twisty_slot() {
  // Two walls across x with 2-wide slots at right angles: a vertical one (|y| < 1, |z| < 6) in
  // x ∈ [−1, 1] and a horizontal one (|y| < 6, |z| < 1) in x ∈ [19, 21]. The slab (10 along x,
  // 1.6 thick along y, 8 wide along z) passes the first as it starts, must turn 90° about x in
  // the 18-long chamber between the walls (its half-diagonal across is 4.08, 4 from each wall
  // when centred at x = 10), and passes the second turned. The bounds keep the reference point
  // at |y|, |z| ≤ 13 inside walls 15 wide on each side, so going round a wall is impossible.
  SuiteProblem s = make("twisty-slot", 0.05, Aabb{Vec3(-14, -13, -13), Vec3(34, 13, 13)});
  auto& o = s.problem.obstacles.triangles;
  box(o, -1, -15, -15, 1, -1, 15);
  box(o, -1, 1, -15, 1, 15, 15);
  box(o, -1, -1, -15, 1, 1, -6);
  box(o, -1, -1, 6, 1, 1, 15);
  box(o, 19, -15, -15, 21, 15, -1);
  box(o, 19, -15, 1, 21, 15, 15);
  box(o, 19, -15, -1, 21, -6, 1);
  box(o, 19, 6, -1, 21, 15, 1);
  box(s.problem.body.triangles, -5, -0.8, -4, 5, 0.8, 4);
  s.witness = {at(-8, 0, 0), at(10, 0, 0), turned(Vec3::UnitX(), 90, 10, 0, 0), turned(Vec3::UnitX(), 90, 28, 0, 0)};
  s.passage_width = 2.0;
  s.body_width = 1.6;
  s.passage = "two 2 x 12 slots at right angles, 20 apart; the slab is 1.6 thick and must turn 90 deg between them";
  finish(s);
  return s;
}

SuiteProblem bug_trap() {
  // A closed cage, inside [−10, 10]³ with walls 1 thick, whose only opening is a 2 × 2 square
  // hole in the +x wall continued inwards by a funnel tube (walls 1 thick) from x = 2 to x = 10:
  // a 9-long channel |y|, |z| < 1 pointing into the cage, like a bug trap's neck. The rod
  // (5 long, 1.6 × 1.6) leaves only aligned with x: 0.2 of play on each side, and tilting it by
  // more than about 0.08 rad jams it. It starts across (along y) in the middle of the cage and
  // ends across outside the hole.
  SuiteProblem s = make("bug-trap", 0.05, Aabb{Vec3(-14, -14, -14), Vec3(26, 14, 14)});
  auto& o = s.problem.obstacles.triangles;
  box(o, -11, -11, -11, -10, 11, 11);   // −x wall
  box(o, -10, -11, -11, 10, -10, 11);   // ±y walls
  box(o, -10, 10, -11, 10, 11, 11);
  box(o, -10, -10, -11, 10, 10, -10);   // ±z walls
  box(o, -10, -10, 10, 10, 10, 11);
  box(o, 10, -11, -11, 11, -1, 11);     // +x wall round the 2 × 2 hole
  box(o, 10, 1, -11, 11, 11, 11);
  box(o, 10, -1, -11, 11, 1, -1);
  box(o, 10, -1, 1, 11, 1, 11);
  box(o, 2, 1, -2, 10, 2, 2);           // the funnel tube, inside the cage
  box(o, 2, -2, -2, 10, -1, 2);
  box(o, 2, -1, 1, 10, 1, 2);
  box(o, 2, -1, -2, 10, 1, -1);
  box(s.problem.body.triangles, -2.5, -0.8, -0.8, 2.5, 0.8, 0.8);
  // Turning in place at x = −4 sweeps x ∈ [−6.62, −1.38]: clear of the tube (x ≥ 2) and walls.
  s.witness = {turned(Vec3::UnitZ(), 90, -4, 0, 0), at(-4, 0, 0), at(18, 0, 0), turned(Vec3::UnitZ(), 90, 18, 0, 0)};
  s.passage_width = 2.0;
  s.body_width = 1.6;
  s.passage = "a 2 x 2 square channel 9 long (funnel tube x in [2, 10] and the wall) pointing into the cage";
  finish(s);
  return s;
}

SuiteProblem hooks(double gap_ratio) {
  // Two C-shaped hooks of square bar t = 2, linked like chain links. The fixed hook lies in
  // y ∈ [−1, 1]: a 20 × 20 frame (x, z ∈ [−10, 10]) whose top bar (z ∈ [8, 10]) is cut by a
  // slanted slit of width g: |x cos 30° + y sin 30°| < g/2, vertical walls at 30° to the bar's
  // cross-section. The moving hook lies in x ∈ [−1, 1]: a 16 × 22 frame (y ∈ [−8, 8],
  // z ∈ [0, 22]) with a gap |y| < g/2 in its top bar; its bottom bar runs along y through the
  // fixed hook's window, and the fixed hook's top bar runs through the moving hook's window
  // (z ∈ [2, 20]). They come apart when the moving hook, turned 30° about z to line its bottom
  // bar (2 wide) up with the slit, rises through it: (g − 2)/2 of play on each side, and a turn
  // or tilt of the 16-long bar off the slit's direction by more than about (g − 2)/16 rad jams it.
  // Unturned, the bar fits only when (g/2 − sin 30°)/cos 30° > 1, i.e. g/2 > 1.37: in hooks-1.5,
  // with 0.155 of play instead of 0.5.
  // Turning in place is free: the moving hook's side bars stay at |y| ≥ 5.9, the fixed hook's
  // top bar keeps |x_B| ≥ g/2 > 1 off the moving hook's plane where they could meet.
  // The moving hook's own gap is no way out: for the fixed top bar to reach it the moving bottom
  // bar would have to sink 12, and it has 8 of room.
  const double g = 2.0 * gap_ratio, h = g / 2;
  constexpr double kSlit = 30.0;
  const double c = std::cos(kSlit * kPi / 180), sn = std::sin(kSlit * kPi / 180);
  char name[32];
  std::snprintf(name, sizeof name, "hooks-%.1f", gap_ratio);
  SuiteProblem s = make(name, 0.02, Aabb{Vec3(-25, -25, -15), Vec3(25, 25, 45)});
  auto& o = s.problem.obstacles.triangles;
  box(o, -10, -1, -10, -8, 1, 10);
  box(o, 8, -1, -10, 10, 1, 10);
  box(o, -8, -1, -10, 8, 1, -8);
  // The top bar's two halves, x from −8 to the slit's wall x = (−h − y sin)/cos and from the
  // other wall x = (h − y sin)/cos to 8: hexahedra with one slanted side.
  for (const double side : {-1.0, 1.0}) {
    std::array<Vec3, 8> corners;
    for (int i = 0; i < 8; ++i) {
      const double y = i & 2 ? 1.0 : -1.0, z = i & 4 ? 10.0 : 8.0;
      const double wall = (side * h - y * sn) / c;
      const bool high_x = i & 1;
      const double x = side < 0 ? (high_x ? wall : -8.0) : (high_x ? 8.0 : wall);
      corners[static_cast<std::size_t>(i)] = Vec3(x, y, z);
    }
    add_hexahedron(o, corners);
  }
  auto& b = s.problem.body.triangles;
  box(b, -1, -8, 0, 1, -6, 22);
  box(b, -1, 6, 0, 1, 8, 22);
  box(b, -1, -6, 0, 1, 6, 2);
  box(b, -1, -6, 20, 1, -h, 22);
  box(b, -1, h, 20, 1, 6, 22);
  // Turned 30° about the vertical axis through the design origin (the witness turns about the
  // reference point, the vertex mean, which is on that axis); up 14 the bottom bar is at
  // z ∈ [14, 16], above the fixed hook (z ≤ 10): free to turn on to 90°.
  s.witness = {at(0, 0, 0), turned(Vec3::UnitZ(), kSlit, 0, 0, 0), turned(Vec3::UnitZ(), kSlit, 0, 0, 14),
               turned(Vec3::UnitZ(), 90, 0, 0, 14)};
  s.passage_width = g;
  s.body_width = 2.0;
  s.passage = "the fixed hook's slanted slit, " + std::string(name + 6) +
              " x the 2-thick bar, which must turn 30 deg to line up with it";
  finish(s);
  return s;
}

SuiteProblem house() {
  // A closed one-storey house, inside [0, 60] × [0, 40] × [0, 12]: a west room (x < 30), a wall
  // at x ∈ [30, 31] with a door y ∈ [8, 16] (10 high), and east of it a wall at y ∈ [20, 21] with
  // a door x ∈ [44, 52]; furniture in every room. The body is a table (6 × 4 top, four legs,
  // 3 high) carried from the west room to the north-east room, turned 90°. Lanes of the witness
  // (body boxes): x ∈ [5, 11] from y = 30 down to 12; y ∈ [10, 14] from x = 8 to 48 (door 1:
  // 2 of play each side); x ∈ [45, 51] from y = 12 up to 30 (door 2: 1 of play each side).
  SuiteProblem s = make("house", 0.1, Aabb{Vec3(0, 0, 0), Vec3(60, 40, 12)});
  auto& o = s.problem.obstacles.triangles;
  box(o, -1, -1, -1, 61, 41, 0);  // floor and ceiling
  box(o, -1, -1, 12, 61, 41, 13);
  box(o, -1, 0, 0, 0, 40, 12);    // outer walls
  box(o, 60, 0, 0, 61, 40, 12);
  box(o, 0, -1, 0, 60, 0, 12);
  box(o, 0, 40, 0, 60, 41, 12);
  box(o, 30, 0, 0, 31, 8, 12);    // west wall of the east rooms, door y ∈ [8, 16]
  box(o, 30, 16, 0, 31, 40, 12);
  box(o, 30, 8, 10, 31, 16, 12);
  box(o, 31, 20, 0, 44, 21, 12);  // wall between the east rooms, door x ∈ [44, 52]
  box(o, 52, 20, 0, 60, 21, 12);
  box(o, 44, 20, 10, 52, 21, 12);
  // West room: dining table with four legs, two chairs, a sideboard, an armchair.
  box(o, 16, 24, 3, 24, 32, 3.5);
  for (const double x : {16.0, 23.5})
    for (const double y : {24.0, 31.5}) box(o, x, y, 0, x + 0.5, y + 0.5, 3);
  box(o, 17, 21, 0, 19, 23, 2);
  box(o, 21, 33, 0, 23, 35, 2);
  box(o, 0, 20, 0, 2, 36, 4);
  box(o, 12, 1, 0, 15, 5, 3);
  // South-east room: sofa, coffee table, TV stand.
  box(o, 33, 0.5, 0, 42, 4.5, 3);
  box(o, 53, 2, 0, 59, 8, 2);
  box(o, 58, 10, 0, 60, 18, 5);
  // North-east room: bed with headboard, wardrobe, desk.
  box(o, 32, 28, 0, 42, 40, 2.5);
  box(o, 32, 39, 2.5, 42, 40, 5);
  box(o, 57, 22, 0, 60, 30, 10);
  box(o, 50, 37, 0, 59, 40, 3);
  auto& b = s.problem.body.triangles;
  box(b, -3, -2, 1, 3, 2, 1.5);  // table top, legs below it
  for (const double x : {-3.0, 2.5})
    for (const double y : {-2.0, 1.5}) box(b, x, y, -1.5, x + 0.5, y + 0.5, 1);
  // The last segment turns 90° about z while moving (2, 2): it sweeps within 3.61 of the
  // straight line from (48, 30) to (50, 32), clear of the wall (y ≤ 21), bed (x ≤ 42), desk
  // (y ≥ 37) and wardrobe (x ≥ 57).
  s.witness = {at(8, 30, 2), at(8, 12, 2), at(48, 12, 2), at(48, 30, 2), turned(Vec3::UnitZ(), 90, 50, 32, 2)};
  s.passage_width = 8.0;
  s.body_width = 6.0;
  s.passage = "the door between the east rooms, 8 wide, for the 6-long table";
  finish(s);
  return s;
}

SuiteProblem cubicles() {
  // A two-storey office, inside [0, 40]² × [0, 21]: the ground floor z ∈ [0, 10], a slab
  // z ∈ [10, 11] with an 8 × 8 stairwell x, y ∈ [30, 38], the upper floor z ∈ [11, 21]. On each
  // floor, three cubicles along the south wall (x ∈ [0, 10], [10.5, 20], [20.5, 30], y < 12)
  // with partitions 6 high, a front partition y ∈ [12, 12.5] with a 4-wide opening, and a desk;
  // a column and filing cabinets in the open space. An L-shaped robot (3 × 2.5 × 1) goes from
  // the first cubicle downstairs out (opening x ∈ [3, 7]: 0.5 of play each side), along the
  // corridor, up through the stairwell, and into the third cubicle upstairs (x ∈ [23, 27]).
  SuiteProblem s = make("cubicles", 0.05, Aabb{Vec3(0, 0, 0), Vec3(40, 40, 21)});
  auto& o = s.problem.obstacles.triangles;
  box(o, -1, -1, -1, 41, 41, 0);   // ground and roof
  box(o, -1, -1, 21, 41, 41, 22);
  box(o, -1, -1, 0, 0, 41, 21);    // outer walls
  box(o, 40, -1, 0, 41, 41, 21);
  box(o, 0, -1, 0, 40, 0, 21);
  box(o, 0, 40, 0, 40, 41, 21);
  box(o, 0, 0, 10, 40, 30, 11);    // the slab round the stairwell
  box(o, 0, 38, 10, 40, 40, 11);
  box(o, 0, 30, 10, 30, 38, 11);
  box(o, 38, 30, 10, 40, 38, 11);
  struct Cubicle {
    double x0, x1, door;  // extent along x, centre of the 4-wide opening
  };
  const Cubicle cubes[] = {{0, 10, 5}, {10.5, 20, 15.25}, {20.5, 30, 25}};
  for (const double z : {0.0, 11.0}) {
    for (const double x : {10.0, 20.0, 30.0}) box(o, x, 0, z, x + 0.5, 12.5, z + 6);  // side partitions
    for (const Cubicle& c : cubes) {
      box(o, c.x0, 12, z, c.door - 2, 12.5, z + 6);  // front partition, opening |x − door| < 2
      box(o, c.door + 2, 12, z, c.x1, 12.5, z + 6);
      box(o, c.x0 + 0.5, 0, z, c.x1 - 0.5, 3, z + 3);  // desk
    }
    box(o, 19, 24, z, 21, 26, z + 10);  // column
    box(o, 0, 36, z, 8, 40, z + 4);     // filing cabinets
  }
  auto& b = s.problem.body.triangles;
  box(b, -1.5, -0.5, -0.5, 1.5, 0.5, 0.5);
  box(b, -1.5, 0.5, -0.5, -0.5, 2, 0.5);
  // Lanes (body boxes): y ∈ [5.5, 18] through the openings; y ∈ [15.5, 18] along the
  // corridors (partitions y ≤ 12.5, column y ≥ 24); x ∈ [32.5, 35.5], y ∈ [33.5, 36] up the
  // stairwell (2 of room to its edges). The last segment turns 90° about z in place in the
  // cubicle: within 2.6 of (25, 6), clear of the desk (y ≤ 3) and the partitions.
  s.witness = {at(5, 6, 3),   at(5, 16, 3),   at(34, 16, 3), at(34, 34, 3), at(34, 34, 14),
               at(34, 16, 14), at(25, 16, 14), at(25, 6, 14), turned(Vec3::UnitZ(), 90, 25, 6, 14)};
  s.passage_width = 4.0;
  s.body_width = 3.0;
  s.passage = "the cubicles' 4-wide openings, for the 3-long robot";
  finish(s);
  return s;
}

}  // namespace swept::scenes::suite
