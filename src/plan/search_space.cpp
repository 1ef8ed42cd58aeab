// The planner's search space and goal test (search_space.h): one definition, used by the
// planner's phases and by the OMPL comparison.
#include "swept/plan/search_space.h"

#include <algorithm>

namespace swept {

SearchSpace search_space(const Problem& problem, const PlanScene& scene) {
  SearchSpace space;
  space.reference = scene.reference;
  space.radius = std::max(scene.radius, 1e-12);
  space.rotation = problem.rotation;
  space.rotation_limits = problem.rotation_limits;
  const double size = std::max(scene.obstacle_box.extent(), 2 * space.radius);
  space.goal_box = scene.obstacle_box;
  space.goal_box.min.array() -= problem.goal_margin;
  space.goal_box.max.array() += problem.goal_margin;
  if (problem.bounds) {
    space.bounds = *problem.bounds;
  } else {
    // Room for the body beside the goal box on every side.
    space.bounds = space.goal_box;
    space.bounds.min.array() -= 2.2 * space.radius + 0.05 * size;
    space.bounds.max.array() += 2.2 * space.radius + 0.05 * size;
    space.bounds.extend(problem.start.apply(space.reference));
    if (problem.goal) space.bounds.extend(problem.goal->apply(space.reference));
  }
  return space;
}

bool in_bounds(const SearchSpace& space, const Vec3& point) {
  return (point.array() >= space.bounds.min.array()).all() && (point.array() <= space.bounds.max.array()).all();
}

bool outside_goal_box(const SearchSpace& space, const Vec3& point) {
  for (int i = 0; i < 3; ++i)
    if (point[i] - space.radius > space.goal_box.max[i] || point[i] + space.radius < space.goal_box.min[i]) return true;
  return false;
}

bool goal_reached(const SearchSpace& space, const Problem& problem, const Pose& pose) {
  if (problem.goal_outside) return outside_goal_box(space, pose.apply(space.reference));
  return problem.goal && pose.rotation == problem.goal->rotation && pose.translation == problem.goal->translation;
}

}  // namespace swept
