#pragma once
/// Small planning problems made of boxes, each with a known character (a tight peg, a T-slot, an
/// L-shaped tunnel, a bar that must turn, a closed box): used by the planner tests and by the
/// side-by-side planner benchmark against OMPL.
#include "swept/plan/problem.h"

#include <array>
#include <string>
#include <vector>

namespace swept::scenes {

/// A problem with its meshes in memory (obstacles in the world, body in the body frame).
struct GeneratedProblem {
  std::string name;
  Problem problem;
  TriangleSoup obstacles, body;
};

/// Appends the 12 triangles of the box [lo, hi], normals outward.
void add_box(std::vector<Triangle>& out, const Vec3& lo, const Vec3& hi);
/// Appends the 12 triangles of a hexahedron: corner i is where add_box puts its corner i (bit 0:
/// high x, bit 1: high y, bit 2: high z). Normals point outward when the corners are a box's
/// moved without turning any face inside out (e.g. a box with slanted sides); each quadrilateral
/// face is split along one diagonal, so a non-planar face is two planar triangles.
void add_hexahedron(std::vector<Triangle>& out, const std::array<Vec3, 8>& corners);

/// A square peg of width w in a blind square hole with radial clearance
/// `clearance_fraction`·w, pulled out upwards (goal: outside the block).
GeneratedProblem peg_in_hole(double w = 10.0, double clearance_fraction = 1e-3);
/// A T-shaped slider in a T-slot open towards +x: slide out along x, then lift to the goal.
GeneratedProblem t_slot();
/// A cube through an L-shaped tunnel: in along +x, then up along +z.
GeneratedProblem l_tunnel();
/// A bar longer than a slot is wide: it must turn to pass through the wall.
GeneratedProblem bar_through_slot();
/// A body shut inside a closed box: no path exists.
GeneratedProblem enclosed();
/// All of the above, in that order.
std::vector<GeneratedProblem> box_problems();

/// Writes the problem as files: obstacles.stl, body.stl and problem.toml in `dir`.
Result<bool> write_problem_files(const GeneratedProblem& g, const std::string& dir);

}  // namespace swept::scenes
