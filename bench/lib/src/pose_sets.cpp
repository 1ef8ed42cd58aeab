#include "swept/bench/pose_sets.h"

#include "swept/bench/seeded_rng.h"
#include "swept/query/query.h"

namespace swept::bench {

std::vector<PoseSet> make_pose_sets(const Bvh& a, const Bvh& b, const PoseSetRequest& request) {
  const int count = request.count;
  const Aabb box_a = bounds(a.triangles);
  const Vec3 ca = box_a.center(), cb = bounds(b.triangles).center();
  const Pose id;
  SeededRng rng{request.seed};
  auto place = [&](const Mat3& r, const Vec3& b_center) { return Pose{r, b_center - r * cb}; };
  std::vector<PoseSet> sets{{"overlapping", {}}, {"near", {}}, {"far", {}}};
  const int attempts = 400 * count;
  for (int k = 0; k < attempts && static_cast<int>(sets[0].poses.size()) < count; ++k) {
    const Mat3 r = rng.rotation();
    const Vec3 u(rng.uniform(), rng.uniform(), rng.uniform());
    const Vec3 target = box_a.min + u.cwiseProduct(box_a.max - box_a.min);
    const Pose p = place(r, target);
    if (collide(a, id, b, p).colliding) sets[0].poses.push_back(p);
  }
  // Near contact: from an overlapping pose, bisect a translation along a random direction until
  // 0 < distance ≤ limit. Moving B by a.extent + b.extent separates the bounding spheres.
  const double limit = request.near_fraction * b.extent;
  const std::size_t n_overlap = sets[0].poses.size();
  for (int k = 0; n_overlap > 0 && k < 4 * count && static_cast<int>(sets[1].poses.size()) < count; ++k) {
    const Pose& p0 = sets[0].poses[static_cast<std::size_t>(k) % n_overlap];
    const Vec3 dir = rng.direction();
    auto moved = [&](double s) { return Pose{p0.rotation, p0.translation + s * dir}; };
    double lo = 0.0, hi = a.extent + b.extent;
    for (int it = 0; it < 80; ++it) {
      const double mid = 0.5 * (lo + hi);
      const double d = distance(a, id, b, moved(mid)).distance;
      if (d <= 0.0) {
        lo = mid;
      } else if (d > limit) {
        hi = mid;
      } else {
        sets[1].poses.push_back(moved(mid));
        break;
      }
    }
  }
  for (int k = 0; k < count; ++k) {
    const Mat3 r = rng.rotation();
    const double reach = 0.5 * (a.extent + b.extent) * (1.1 + 0.9 * rng.uniform());
    sets[2].poses.push_back(place(r, ca + reach * rng.direction()));
  }
  return sets;
}

}  // namespace swept::bench
