// The escape from a start in contact (escape.h).
#include "escape.h"

#include "directions.h"
#include "swept/geometry/distance.h"

#include <cmath>
#include <limits>

namespace swept::detail {

std::vector<Vec3> separating_directions(const PlanScene& scene, const Pose& start, const TrianglePairs& pairs) {
  std::vector<Vec3> normals;
  const Vec3 body_center = start.apply(scene.reference);
  for (const ContactPair& p : pairs.pairs) {
    if (normals.size() >= 12) break;
    const Triangle& o = scene.obstacles.triangles[p.triangle_a];
    const Triangle& t = scene.body.triangles[p.triangle_b];
    Vec3 n = (o.q - o.p).cross(o.r - o.p);
    if (!(n.norm() > 0.0)) continue;
    n.normalize();
    const Vec3 toward = start.apply(centroid(t)) - centroid(o);
    const double side = n.dot(toward);
    const double scale = std::max(toward.norm(), 1e-300);
    const double s = std::abs(side) > 1e-9 * scale ? side : n.dot(body_center - centroid(o));
    if (s == 0.0) continue;
    add_direction(normals, s > 0 ? n : Vec3(-n));
  }
  // A peg resting on the bottom of its hole and against a wall leaves diagonally.
  std::vector<Vec3> out = normals;
  for (std::size_t i = 0; i < normals.size(); ++i)
    for (std::size_t j = i + 1; j < normals.size(); ++j) add_direction(out, normals[i] + normals[j]);
  return out;
}

std::optional<Pose> escape_from_contact(PlanContext& context, const Pose& start) {
  const double size = context.scene_size();
  const Vec3 from = context.reference_at(start);
  std::vector<Vec3> candidates = candidate_directions(context, start);
  for (const Vec3& d : separating_directions(context.scene, start, context.check.exempt())) {
    bool seen = false;
    for (const Vec3& e : candidates) seen = seen || e.dot(d) > 1.0 - 1e-9;
    if (!seen) candidates.push_back(d);
  }
  double best = std::numeric_limits<double>::infinity();
  std::optional<Pose> escape;
  for (const Vec3& u : candidates) {
    const double room = room_along(context.space.bounds, from, u);
    for (double s = 1e-3 * size; s <= room && s < best; s *= 1.5) {
      if (context.out_of_time()) return std::nullopt;
      const Pose q = context.pose_with_reference_at(start.rotation, from + s * u);
      if (!context.free_at(q, s)) continue;
      if (context.check.clear(start, -1, q, -1, /*relaxed=*/true)) {
        best = s;
        escape = q;
      }
      break;  // the first free pose along u decides this direction
    }
  }
  return escape;
}

}  // namespace swept::detail
