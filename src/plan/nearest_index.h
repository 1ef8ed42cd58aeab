// The trees' nearest-node query (tree_search.h): exact, in the motion metric, over a k-d tree
// of the nodes' reference points and rotations with the newest nodes scanned apart.
#pragma once

#include "swept/geometry/types.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace swept::detail {

/// The trees' motion length between two poses given by reference point and unit quaternion:
/// |p − p'| + r·2·acos|⟨q, q'⟩| (r: the search space's radius; the angle of the rotation
/// between them, times r). Every nearest-node answer is by this one formula.
inline double motion_metric(const Vec3& p, const Quat& q, const Vec3& p2, const Quat& q2, double r) {
  return (p - p2).norm() + r * 2.0 * std::acos(std::min(1.0, std::abs(q.dot(q2))));
}

/// The nodes' points and rotations, in the order added (the index of a node is its tree's), and
/// the index of the node with the smallest motion_metric to a query among those a predicate
/// keeps, the lowest index on ties: exactly the answer of a scan of every node in order, so
/// the trees do not depend on the index (tests/plan/nearest_index_test.cpp: against that scan).
///
/// The older nodes are in a k-d tree over 7 coordinates (the point, and the quaternion scaled by
/// 2r), split at the median of the widest coordinate, each cell with its bounding box; the
/// newest, up to a sixteenth of all, are scanned. A cell is skipped when a lower bound of the
/// metric over its box is above the best so far: |p − p'| is at least the box's distance in the
/// point's coordinates, and 2r·acos|⟨q, q'⟩| ≥ 2r·min(|q − q'|, |q + q'|) (1 − cos θ ≤ θ²/2),
/// at least the box's distance from q or from −q in the quaternion's. add() rebuilds the tree
/// when the scanned nodes pass the sixteenth: its cost, n·log n, is paid once every n/16
/// additions. Not thread-safe to add while querying; queries may run concurrently.
class NearestIndex {
 public:
  explicit NearestIndex(double radius) : radius_(radius) {}

  void add(const Vec3& point, const Quat& rotation);
  std::size_t size() const { return keys_.size(); }

  /// The index of the nearest node for which `keep(index)` holds (−1 when none does).
  template <class Keep>
  std::int32_t nearest(const Vec3& point, const Quat& rotation, const Keep& keep) const;

 private:
  using Key = std::array<double, 7>;  ///< the point, then the quaternion (w, x, y, z; w ≥ 0) times 2r
  struct Cell {
    Key lo, hi;                ///< the bounding box of the cell's keys
    std::uint32_t begin, end;  ///< the cell's range of order_
    std::int32_t left = -1, right = -1;
  };
  struct Query;
  std::int32_t build(std::uint32_t begin, std::uint32_t end);
  void rebuild();

  double radius_;
  std::vector<Key> keys_;         ///< the points exactly, as the metric reads them
  std::vector<Quat> rotations_;  ///< the rotations as given (the keys' are scaled and signed)
  std::vector<std::uint32_t> order_;  ///< the indexed nodes, cell by cell
  std::vector<Cell> cells_;           ///< cells_[0] the root, when there is one
  std::size_t indexed_ = 0;           ///< nodes [0, indexed_) are in the k-d tree
};

struct NearestIndex::Query {
  const NearestIndex& index;
  Vec3 point;
  Quat rotation;
  Key key, flipped;  ///< the query's key, and with the quaternion negated
  std::int32_t best = -1;
  double best_length = std::numeric_limits<double>::infinity();

  // Lower bounds scaled down a little (1e-9, and 1e-7 of the quaternion's distance) so that
  // rounding cannot lift them above a metric that the formula rounds down (acos near 1): a
  // cell or node is skipped only when the exact answer would not take it.
  template <class Keep>
  void consider(std::uint32_t i, const Keep& keep) {
    const Key& k = index.keys_[i];
    const Vec3 p(k[0], k[1], k[2]);
    const double moved_sq = (p - point).squaredNorm();
    if (moved_sq > best_length * best_length * (1.0 + 1e-9)) return;
    const double c = std::min(1.0, std::abs(rotation.dot(index.rotations_[i])));
    if ((std::sqrt(moved_sq) + index.radius_ * 2.0 * std::sqrt(2.0 * (1.0 - c))) * (1.0 - 1e-9) > best_length) return;
    const double length = motion_metric(point, rotation, p, index.rotations_[i], index.radius_);
    if ((length < best_length || (length == best_length && static_cast<std::int32_t>(i) < best)) && keep(i)) {
      best_length = length;
      best = static_cast<std::int32_t>(i);
    }
  }
  double cell_bound(const Cell& c) const {
    auto gap = [&](const Key& k, int from, int to) {
      double sq = 0.0;
      for (int d = from; d < to; ++d) {
        const double g = std::max({0.0, c.lo[d] - k[d], k[d] - c.hi[d]});
        sq += g * g;
      }
      return std::sqrt(sq);
    };
    const double turn = std::max(0.0, std::min(gap(key, 3, 7), gap(flipped, 3, 7)) - 1e-7 * 2.0 * index.radius_);
    return (gap(key, 0, 3) + turn) * (1.0 - 1e-9);
  }
  template <class Keep>
  void search(std::int32_t cell, const Keep& keep) {
    const Cell& c = index.cells_[cell];
    if (c.left < 0) {
      for (std::uint32_t k = c.begin; k < c.end; ++k) consider(index.order_[k], keep);
      return;
    }
    const double l = cell_bound(index.cells_[c.left]), r = cell_bound(index.cells_[c.right]);
    const std::int32_t first = l <= r ? c.left : c.right, second = l <= r ? c.right : c.left;
    if (std::min(l, r) <= best_length) search(first, keep);
    if (std::max(l, r) <= best_length) search(second, keep);
  }
};

template <class Keep>
std::int32_t NearestIndex::nearest(const Vec3& point, const Quat& rotation, const Keep& keep) const {
  Query q{*this, point, rotation, {}, {}};
  const double s = 2.0 * radius_;
  q.key = {point.x(), point.y(), point.z(), s * rotation.w(), s * rotation.x(), s * rotation.y(), s * rotation.z()};
  q.flipped = q.key;
  for (int d = 3; d < 7; ++d) q.flipped[d] = -q.flipped[d];
  if (!cells_.empty()) q.search(0, keep);
  for (std::size_t i = indexed_; i < keys_.size(); ++i) q.consider(static_cast<std::uint32_t>(i), keep);
  return q.best;
}

}  // namespace swept::detail
