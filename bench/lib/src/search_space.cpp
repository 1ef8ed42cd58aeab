#include "swept/bench/search_space.h"

#include <algorithm>
#include <limits>

namespace swept::bench {

double distance_to_goal_region(const SearchSpace& space, const Vec3& p) {
  if (outside_goal_box(space, p)) return 0.0;  // the planner's goal test, boundary rules included
  const Aabb& box = space.goal_box;
  const double r = space.radius;
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    best = std::min(best, box.max[i] + r - p[i]);
    best = std::min(best, p[i] - (box.min[i] - r));
  }
  // Inside on every axis: the move to the boundary is positive (a point on it is not yet outside).
  return std::max(best, std::numeric_limits<double>::min());
}

}  // namespace swept::bench
