// The multi-resolution grid (grid.h).
#include "grid.h"

#include "rotation_vector.h"
#include "swept/geometry/assert.h"

#include <numbers>

namespace swept::detail {

Grid::Grid(const SearchSpace& space, const Pose& problem_start, const Pose& anchor, double clearance,
           double scene_size)
    : space_(space) {
  SWEPT_ASSERT(space.radius > 0.0, "the search space's radius must be positive (search_space() makes it ≥ 1e-12)");
  SWEPT_ASSERT(!space.bounds.empty(), "the grid needs non-empty bounds");
  dimensions_ = space.rotation == RotationMode::none ? 3 : 6;
  anchor_point_ = anchor.apply(space.reference);
  anchor_rotation_ = anchor.rotation;
  const Eigen::AngleAxisd turn(anchor.rotation * problem_start.rotation.transpose());
  anchor_rotation_vector_ = turn.angle() * turn.axis();
  const double coarse_step = (space.bounds.max - space.bounds.min).maxCoeff() / 8.0;
  const double finest = std::max(clearance, 2e-3 * scene_size);
  while (finest_level_ < 7 && coarse_step / (1 << finest_level_) > finest) ++finest_level_;
  fine_step_ = coarse_step / (1 << finest_level_);
}

Pose Grid::pose_of(const GridKey& key) const {
  const Vec3 p = anchor_point_ + fine_step_ * Vec3(key[0], key[1], key[2]);
  Mat3 rotation = anchor_rotation_;
  if (dimensions_ == 6) {
    const Vec3 w = (fine_step_ / space_.radius) * Vec3(key[3], key[4], key[5]);
    rotation = exp_rotation(w) * anchor_rotation_;
  }
  return {rotation, p - rotation * space_.reference};
}

bool Grid::contains(const GridKey& key) const {
  const Vec3 p = anchor_point_ + fine_step_ * Vec3(key[0], key[1], key[2]);
  if (!in_bounds(space_, p)) return false;
  if (dimensions_ == 3) return true;
  const Vec3 w = (fine_step_ / space_.radius) * Vec3(key[3], key[4], key[5]) + anchor_rotation_vector_;
  if (space_.rotation == RotationMode::free) return w.norm() <= std::numbers::pi;
  for (int i = 0; i < 3; ++i)
    if (w[i] < space_.rotation_limits[i][0] || w[i] > space_.rotation_limits[i][1]) return false;
  return true;
}

GridNeighbours Grid::neighbours(const GridKey& key, int level) const {
  GridNeighbours out;
  const std::int32_t s = stride(level);
  for (int d = 0; d < dimensions_; ++d)
    for (std::int32_t sign : {-1, 1}) {
      GridKey k = key;
      k[d] += sign * s;
      if (contains(k)) out.keys[out.count++] = k;
    }
  return out;
}

}  // namespace swept::detail
