#pragma once
/// What the planner-vs-OMPL benchmark gives OMPL about a problem so that both planners solve the
/// same one: the reference point and r_max, the bounds of the reference point, and the goal
/// region of `goal outside` problems. One function computes it (planner_search_space), and it is
/// the only place in the benchmarks that knows how the planner derives it.
#include "swept/plan/planner.h"
#include "swept/plan/problem.h"

namespace swept::bench {

/// The planner's search space of a problem, as the planner computes it.
struct SearchSpace {
  Vec3 reference = Vec3::Zero();  ///< body-frame point the motions interpolate about
  double radius = 0.0;            ///< r_max: farthest body vertex from `reference`
  Aabb bounds;                    ///< where the reference point may go (world frame)
  Aabb goal_box;                  ///< the obstacles' box grown by the problem's goal margin
};

/// The problem's bounds, else the obstacles' box grown by 2.2·r_max + 0.05·size and extended to
/// the start and goal; the goal box for `goal outside`.
// TODO(merge): use swept::search_space() (include/swept/plan/search_space.h) once the planner
// exports it; this re-types src/plan/planner.cpp's computation until then.
SearchSpace planner_search_space(const Problem& problem, const PlanScene& scene);

/// How far the reference point `p` (world frame) is from the goal region of a `goal outside`
/// problem: 0 when the sphere of radius r_max about it lies outside the goal box, as the
/// planner's goal test requires; else the shortest move along one axis that gets it there.
// TODO(merge): goal test via swept::goal_reached(space, problem, pose) once exported.
double distance_to_goal_region(const SearchSpace& space, const Vec3& p);

}  // namespace swept::bench
