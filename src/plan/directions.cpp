// Candidate directions of straight moves and the room along them (directions.h).
#include "directions.h"

#include "swept/bvh/fitter.h"

#include <algorithm>
#include <limits>

namespace swept::detail {

void add_direction(std::vector<Vec3>& list, const Vec3& d) {
  if (!(d.norm() > 1e-12)) return;
  const Vec3 u = d.normalized();
  for (const Vec3& e : list)
    if (e.dot(u) > 1.0 - 1e-9) return;
  list.push_back(u);
}

std::vector<Vec3> candidate_directions(const PlanContext& context, const Pose& start) {
  std::vector<Vec3> dirs;
  const Problem& problem = context.problem;
  if (problem.goal) add_direction(dirs, context.reference_at(*problem.goal) - context.reference_at(start));
  for (const Vec3& d : {Vec3(0, 0, 1), Vec3(0, 0, -1), Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0)})
    add_direction(dirs, d);
  // The axes the problem's own fitter gives the body's triangles (inertia by default).
  const Fit principal = fit(context.scene.body.triangles, problem.build.fitter);
  for (int i = 0; i < 3; ++i) {
    add_direction(dirs, start.rotation * principal.axes.col(i));
    add_direction(dirs, -(start.rotation * principal.axes.col(i)));
  }
  return dirs;
}

double room_along(const Aabb& box, const Vec3& p, const Vec3& u) {
  double t = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    if (u[i] > 1e-12) t = std::min(t, (box.max[i] - p[i]) / u[i]);
    if (u[i] < -1e-12) t = std::min(t, (box.min[i] - p[i]) / u[i]);
  }
  return std::max(t, 0.0);
}

double shortest_move_out(const PlanContext& context, const Mat3& rotation, const Vec3& p, const Vec3& u,
                         double room) {
  auto out = [&](double s) {
    return outside_goal_box(context.space, context.reference_at(context.pose_with_reference_at(rotation, p + s * u)));
  };
  if (!out(room)) return -1.0;
  double lo = 0, hi = room;
  for (int it = 0; it < 40; ++it) {
    const double mid = 0.5 * (lo + hi);
    (out(mid) ? hi : lo) = mid;
  }
  return hi;
}

}  // namespace swept::detail
