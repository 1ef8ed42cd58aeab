#pragma once
// The multi-resolution grid of the search (internal to src/plan; Bohlin 2001, "Path planning
// in practice; lazy evaluation on a multi-resolution grid"). Anchored at the search start:
// translation in steps of the reference point, rotation as a rotation vector (world axes)
// applied before the start orientation, in steps of the same arc length for the farthest body
// point, so that one step moves body points about equally either way.
#include "swept/plan/search_space.h"

#include <array>
#include <climits>
#include <cstdint>

namespace swept::detail {

/// Integer coordinates of a grid node at the finest level (translation x, y, z, then rotation
/// vector x, y, z; the rotation ones stay 0 without rotation). Level k uses multiples of
/// 2^(finest − k).
using GridKey = std::array<std::int32_t, 6>;

struct GridKeyHash {
  std::size_t operator()(const GridKey& k) const {
    std::uint64_t h = 0x9E3779B97F4A7C15ull;
    for (std::int32_t v : k)
      h ^= static_cast<std::uint64_t>(static_cast<std::uint32_t>(v)) + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
    return static_cast<std::size_t>(h);
  }
};

/// The goal pose as a node of the search (not a grid point).
inline constexpr GridKey kGoalKey = {INT_MIN, INT_MIN, INT_MIN, INT_MIN, INT_MIN, INT_MIN};

/// Up to 12 neighbours of a node, in a fixed order.
struct GridNeighbours {
  std::array<GridKey, 12> keys;
  int count = 0;
};

class Grid {
 public:
  /// The grid anchored at `anchor` (the search start, reached from the problem's start, whose
  /// rotation the rotation limits are relative to). Level 0 steps an eighth of the bounds'
  /// largest side; the finest level is the first at or below max(clearance, 2·10^-3·size), at
  /// most level 7.
  Grid(const SearchSpace& space, const Pose& problem_start, const Pose& anchor, double clearance, double scene_size);

  int dimensions() const { return dimensions_; }  ///< 3 (translation) or 6
  int finest_level() const { return finest_level_; }
  double fine_step() const { return fine_step_; }
  /// Key stride and step length (translation units; arc length r_max·Δθ) at `level`.
  std::int32_t stride(int level) const { return std::int32_t{1} << (finest_level_ - level); }
  double step(int level) const { return fine_step_ * stride(level); }

  /// The pose of a node (the key {0,…} is the anchor).
  Pose pose_of(const GridKey& key) const;
  /// Inside the bounds of the reference point and the rotation limits (|rotation vector| ≤ π
  /// for free rotation).
  bool contains(const GridKey& key) const;
  /// The neighbours of `key` at `level` inside the space: −, + along each dimension in turn.
  GridNeighbours neighbours(const GridKey& key, int level) const;

 private:
  const SearchSpace& space_;
  int dimensions_ = 6;
  int finest_level_ = 0;
  double fine_step_ = 1.0;
  Vec3 anchor_point_ = Vec3::Zero();        ///< reference point at the anchor (world)
  Mat3 anchor_rotation_ = Mat3::Identity();
  Vec3 anchor_rotation_vector_ = Vec3::Zero();  ///< of the anchor relative to the problem's start
};

}  // namespace swept::detail
