#include "swept/bench/search_space.h"

#include <algorithm>
#include <limits>

namespace swept::bench {

SearchSpace planner_search_space(const Problem& pb, const PlanScene& scene) {
  SearchSpace g;
  g.reference = scene.reference;
  g.radius = std::max(scene.radius, 1e-12);
  const double size = std::max(scene.obstacle_box.extent(), 2 * g.radius);
  g.goal_box = scene.obstacle_box;
  g.goal_box.min.array() -= pb.goal_margin;
  g.goal_box.max.array() += pb.goal_margin;
  if (pb.bounds) {
    g.bounds = *pb.bounds;
  } else {
    g.bounds = g.goal_box;
    g.bounds.min.array() -= 2.2 * g.radius + 0.05 * size;
    g.bounds.max.array() += 2.2 * g.radius + 0.05 * size;
    g.bounds.extend(pb.start.apply(g.reference));
    if (pb.goal) g.bounds.extend(pb.goal->apply(g.reference));
  }
  return g;
}

double distance_to_goal_region(const SearchSpace& space, const Vec3& p) {
  const Aabb& box = space.goal_box;
  const double r = space.radius;
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    best = std::min(best, std::max(0.0, box.max[i] + r - p[i]));
    best = std::min(best, std::max(0.0, p[i] - (box.min[i] - r)));
  }
  return best;
}

}  // namespace swept::bench
