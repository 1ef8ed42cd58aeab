#pragma once
/// What the planner-vs-OMPL benchmark gives OMPL about a problem so that both planners solve the
/// same one: the planner's own search space (swept::search_space(): reference point, r_max,
/// bounds of the reference point, goal box) and its goal test (swept::outside_goal_box()), plus
/// the distance to the goal region that OMPL's goal interface asks for.
#include "swept/plan/search_space.h"

namespace swept::bench {

using swept::SearchSpace;

/// The planner's search space of a problem: swept::search_space() itself.
inline SearchSpace planner_search_space(const Problem& problem, const PlanScene& scene) {
  return swept::search_space(problem, scene);
}

/// How far the reference point `p` (world frame) is from the goal region of a `goal outside`
/// problem: 0 exactly when the planner's goal test holds (swept::outside_goal_box: the sphere of
/// radius r_max about `p` lies outside the goal box), else the shortest move along one axis
/// that gets it there.
double distance_to_goal_region(const SearchSpace& space, const Vec3& p);

}  // namespace swept::bench
