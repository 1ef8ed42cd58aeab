#pragma once
// Internal pieces shared by the query implementations: B's placement in A's frame, node-pair
// bounds and the fixed-capacity traversal stack.
#include "swept/bvh/bvh.h"
#include "swept/geometry/assert.h"
#include "swept/geometry/distance.h"
#include "swept/geometry/pose.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

namespace swept::detail {

/// m·x and mᵀ·x, written out: every column of a pair's frame is formed by the same arithmetic,
/// whichever of them a test asks for first.
[[gnu::always_inline]] inline Vec3 times(const Mat3& m, const Vec3& x) {
  return {m(0, 0) * x.x() + m(0, 1) * x.y() + m(0, 2) * x.z(), m(1, 0) * x.x() + m(1, 1) * x.y() + m(1, 2) * x.z(),
          m(2, 0) * x.x() + m(2, 1) * x.y() + m(2, 2) * x.z()};
}
[[gnu::always_inline]] inline Vec3 transpose_times(const Mat3& m, const Vec3& x) {
  return {m(0, 0) * x.x() + m(1, 0) * x.y() + m(2, 0) * x.z(), m(0, 1) * x.x() + m(1, 1) * x.y() + m(2, 1) * x.z(),
          m(0, 2) * x.x() + m(1, 2) * x.y() + m(2, 2) * x.z()};
}

/// Model B's frame expressed in model A's frame, computed once per query: `relative(pose_a,
/// pose_b)` written out column by column (the same sums in the same order, without the
/// transposed copy and the temporaries Eigen makes of it).
struct Relative {
  Mat3 rotation;
  Vec3 translation;

  Relative(const Pose& pose_a, const Pose& pose_b) {
    const Mat3& ra = pose_a.rotation;
    rotation.col(0) = transpose_times(ra, pose_b.rotation.col(0));
    rotation.col(1) = transpose_times(ra, pose_b.rotation.col(1));
    rotation.col(2) = transpose_times(ra, pose_b.rotation.col(2));
    translation = transpose_times(ra, pose_b.translation) + -transpose_times(ra, pose_a.translation);
  }
  Triangle apply(const Triangle& t) const {
    return {rotation * t.p + translation, rotation * t.q + translation, rotation * t.r + translation};
  }
};

/// A node of B decoded (Node stores it compactly) and placed in A's model frame: its center at
/// once, its axes on first use (a bounding-sphere test often settles a pair from the centers
/// alone), and the normal only when a test needs it (the distance search's first projection
/// step uses the first two axes alone, and almost always decides).
struct PlacedRss {
  Rss rss;  ///< in B's model frame
  const Relative* rel = nullptr;
  Vec3 center;
  Mat3 axes_;
  int placed_axes = 0;  ///< columns of axes_ computed: 0, 2 or 3

  PlacedRss() = default;
  /// Copies the axes computed so far, and only those (the others hold nothing yet).
  PlacedRss(const PlacedRss& o) : rss(o.rss), rel(o.rel), center(o.center), placed_axes(o.placed_axes) {
    for (int c = 0; c < placed_axes; ++c) axes_.col(c) = o.axes_.col(c);
  }
  PlacedRss& operator=(const PlacedRss& o) {
    rss = o.rss;
    rel = o.rel;
    center = o.center;
    placed_axes = o.placed_axes;
    for (int c = 0; c < placed_axes; ++c) axes_.col(c) = o.axes_.col(c);
    return *this;
  }

  /// The first two axes (columns 0 and 1 of the result; column 2 may not be set).
  const Mat3& first_axes() {
    if (placed_axes < 2) {
      axes_.col(0) = times(rel->rotation, rss.axes.col(0));
      axes_.col(1) = times(rel->rotation, rss.axes.col(1));
      placed_axes = 2;
    }
    return axes_;
  }
  const Mat3& axes() {
    if (placed_axes < 3) {
      first_axes();
      axes_.col(2) = times(rel->rotation, rss.axes.col(2));
      placed_axes = 3;
    }
    return axes_;
  }
};

inline PlacedRss place(const Rss& nb, const Relative& rel) {
  PlacedRss p;
  p.rss = nb;
  p.rel = &rel;
  p.center.noalias() = rel.rotation * nb.center;
  p.center += rel.translation;
  return p;
}

/// Node `i` of B, decoded and placed in A's frame.
inline PlacedRss place(const Bvh& b, std::int32_t i, const Relative& rel) {
  return place(b.bv(static_cast<std::size_t>(i)), rel);
}

/// Rectangles of node `na` of A and node `nb` of B (placed in A's frame), in na's frame.
[[gnu::always_inline]] inline RectanglePair node_pair(const Rss& na, const Rss& nb, PlacedRss& placed) {
  RectanglePair p;
  const Mat3& axes = placed.axes();
  p.rotation.col(0) = transpose_times(na.axes, axes.col(0));
  p.rotation.col(1) = transpose_times(na.axes, axes.col(1));
  p.rotation.col(2) = transpose_times(na.axes, axes.col(2));
  p.translation = transpose_times(na.axes, placed.center - na.center);
  p.a[0] = na.half_length[0];
  p.a[1] = na.half_length[1];
  p.b[0] = nb.half_length[0];
  p.b[1] = nb.half_length[1];
  return p;
}

/// Rectangles of node `na` of A and node `nb` of B (B placed by `rel`), in na's frame.
inline RectanglePair node_pair(const Rss& na, const Rss& nb, const Relative& rel) {
  PlacedRss placed = place(nb, rel);
  return node_pair(na, nb, placed);
}

/// The pair of `node_pair(na, pb.rss, pb)` completed from B's first two axes `u`, `v` and center
/// `t` already formed in na's frame: only B's normal is added.
[[gnu::always_inline]] inline RectanglePair complete_pair(const Rss& na, PlacedRss& pb, const Vec3& u, const Vec3& v,
                                                          const Vec3& t) {
  RectanglePair pair;
  pair.rotation.col(0) = u;
  pair.rotation.col(1) = v;
  pair.rotation.col(2) = transpose_times(na.axes, pb.axes().col(2));
  pair.translation = t;
  pair.a[0] = na.half_length[0];
  pair.a[1] = na.half_length[1];
  pair.b[0] = pb.rss.half_length[0];
  pair.b[1] = pb.rss.half_length[1];
  return pair;
}

/// `rectangle_lower_bound(node_pair(na, pb.rss, pb), stop_at)`, to the bit, in its two steps:
/// the first, which decides almost every node pair of a distance search, needs neither B's
/// normal nor the pair's full frame. `value_past_stop` false: a bound that surely reaches
/// `stop_at` may come back as +∞ (projection_gap), for callers that only compare it with
/// `stop_at`.
[[gnu::always_inline]] inline double lower_bound(const Rss& na, PlacedRss& pb, double stop_at,
                                                 bool value_past_stop = true) {
  const double a0 = na.half_length[0], a1 = na.half_length[1], b0 = pb.rss.half_length[0], b1 = pb.rss.half_length[1];
  const Mat3& placed = pb.first_axes();
  const Vec3 u = transpose_times(na.axes, placed.col(0));
  const Vec3 v = transpose_times(na.axes, placed.col(1));
  const Vec3 t = transpose_times(na.axes, pb.center - na.center);
  const double slack = rectangle_slack(t, a0, a1, b0, b1);
  stop_at += slack;
  const ProjectionGap first = projection_gap(u, v, t, a0, a1, b0, b1, stop_at, slack, value_past_stop);
  if (first.decided) return first.bound(slack);
  return rectangle_axes_gap(complete_pair(na, pb, u, v, t), stop_at, first.gap, slack);
}

/// True when the balls around A's node `na` and B's node `pb` placed in A's frame (each
/// rectangle's circumscribed disc grown by its radius) are more than `limit` apart: the centers
/// settle a far-apart pair without the axes. The allowance for rounding is the rectangle tests'
/// (kRectangleSlack), on the centers' coordinates as well as the lengths.
[[gnu::always_inline]] inline bool balls_apart(const Rss& na, const PlacedRss& pb, double limit) {
  const double a0 = na.half_length[0], a1 = na.half_length[1];
  const double b0 = pb.rss.half_length[0], b1 = pb.rss.half_length[1];
  const double reach = std::sqrt(a0 * a0 + a1 * a1) + std::sqrt(b0 * b0 + b1 * b1) + na.radius + pb.rss.radius;
  const double slack = kRectangleSlack * (na.center.cwiseAbs().sum() + pb.center.cwiseAbs().sum() + a0 + a1 + b0 + b1 +
                                          na.radius + pb.rss.radius);
  const double clear = reach + limit + slack;
  return (pb.center - na.center).squaredNorm() > clear * clear;
}

/// `rectangle_gap(node_pair(na, pb.rss, pb), limit) > limit`, to the bit: A's normal, the first
/// axis, is tested from B's first two axes and center alone (it separates many pairs before B's
/// normal and the pair's full frame are formed); the rest runs on the completed pair.
[[gnu::always_inline]] inline bool separated(const Rss& na, PlacedRss& pb, double limit) {
  const double b0 = pb.rss.half_length[0], b1 = pb.rss.half_length[1];
  const Mat3& placed = pb.first_axes();
  const Vec3 u = transpose_times(na.axes, placed.col(0));
  const Vec3 v = transpose_times(na.axes, placed.col(1));
  const Vec3 t = transpose_times(na.axes, pb.center - na.center);
  const double slack = rectangle_slack(t, na.half_length[0], na.half_length[1], b0, b1);
  const double normal_gap = std::abs(t.z()) - b0 * std::abs(u.z()) - b1 * std::abs(v.z());
  if (normal_gap >= limit + slack) return normal_gap - slack > limit;
  return rectangle_axes_gap(complete_pair(na, pb, u, v, t), limit + slack,
                            -std::numeric_limits<double>::infinity(), slack) > limit;
}

/// A bound on |coordinate| of every vertex of A and of B placed in A's frame, from the two
/// roots (A's in its model frame, B's placed); 1e-12 of it bounds every `touch_tolerance` the
/// triangle tests will use.
inline double coordinate_bound(const Rss& root_a, const PlacedRss& root_b) {
  auto bound = [](const Rss& v, const Vec3& c) {
    return c.cwiseAbs().maxCoeff() + v.half_length[0] + v.half_length[1] + v.radius;
  };
  return std::max(bound(root_a, root_a.center), bound(root_b.rss, root_b.center));
}

/// The roots of a query's two trees, each decoded once: A's in its model frame, B's placed in
/// A's frame.
struct Roots {
  Rss a;
  PlacedRss b;
  Roots(const Bvh& tree_a, const Bvh& tree_b, const Relative& rel) : a(tree_a.root), b(place(tree_b.root, rel)) {}

  double coordinate_bound() const { return detail::coordinate_bound(a, b); }
};

/// Nodes of A decoded and nodes of B placed in A's frame by one traversal, by node index: each
/// decoded once however many of its pairs the traversal meets (far apart on the KUKA pair a
/// distance query met each node of A it decoded 3.7 times and each node of B it placed 5.5
/// times). Direct-mapped slots (a node whose slot another node took is decoded again: the same
/// arithmetic, so the same values), the thread's, reused from traversal to traversal (each
/// numbers its slots, so none outlives it) and taken out while in use, so that a traversal
/// started inside another on the same thread gets slots of its own.
class DecodedNodes {
 public:
  DecodedNodes(const Bvh& a, const Bvh& b, const Relative& rel) : a_(a), b_(b), rel_(rel), slots_(take()) {
    traversal_ = ++slots_->traversals;
  }
  ~DecodedNodes() { spare() = std::move(slots_); }
  DecodedNodes(const DecodedNodes&) = delete;
  DecodedNodes& operator=(const DecodedNodes&) = delete;

  /// The roots, already decoded (Roots).
  void seed(const Rss& root_a, const PlacedRss& root_b) {
    slots_->a[0] = {traversal_, 0, root_a};
    slots_->b[0] = {traversal_, 0, root_b};
  }
  /// Node i of A (two adjacent nodes never share a slot).
  const Rss& a(std::int32_t i) {
    SlotA& slot = slots_->a[static_cast<std::size_t>(i) & (kSlots - 1)];
    if (slot.traversal != traversal_ || slot.node != i) slot = {traversal_, i, a_.bv(static_cast<std::size_t>(i))};
    return slot.rss;
  }
  /// Node i of B, placed in A's frame.
  PlacedRss& b(std::int32_t i) {
    SlotB& slot = slots_->b[static_cast<std::size_t>(i) & (kSlots - 1)];
    if (slot.traversal != traversal_ || slot.node != i) slot = {traversal_, i, place(b_, i, rel_)};
    return slot.placed;
  }

 private:
  static constexpr std::size_t kSlots = 256;
  struct SlotA {
    std::uint64_t traversal = 0;
    std::int32_t node = -1;
    Rss rss;
  };
  struct SlotB {
    std::uint64_t traversal = 0;
    std::int32_t node = -1;
    PlacedRss placed;
  };
  struct Slots {
    std::uint64_t traversals = 0;
    std::array<SlotA, kSlots> a;
    std::array<SlotB, kSlots> b;
  };
  static std::unique_ptr<Slots>& spare() {
    thread_local std::unique_ptr<Slots> slots;
    return slots;
  }
  static std::unique_ptr<Slots> take() {
    std::unique_ptr<Slots> slots = std::move(spare());
    return slots ? std::move(slots) : std::make_unique<Slots>();
  }

  const Bvh& a_;
  const Bvh& b_;
  const Relative& rel_;
  std::unique_ptr<Slots> slots_;
  std::uint64_t traversal_ = 0;
};

/// True when node a (rather than node b) should be split: the one of larger surface area
/// (Node::area).
inline bool descend_a(const Node& a, const Node& b) {
  if (b.is_leaf()) return true;
  if (a.is_leaf()) return false;
  return a.area() >= b.area();
}

/// A node pair waiting on the traversal stack, with its lower bound.
struct PairEntry {
  std::int32_t a = 0;
  std::int32_t b = 0;
  double bound = 0.0;
};

/// Fixed-capacity LIFO of node pairs. Depth-first traversal of two trees keeps at most one
/// pending sibling per level, so depth(A) + depth(B) + 2 entries always suffice; deeper trees
/// than the inline capacity use one heap block sized once per query.
class PairStack {
 public:
  PairStack(const Bvh& a, const Bvh& b) {
    const std::size_t need = static_cast<std::size_t>(a.depth + b.depth) + 4;
    if (need > inline_.size()) {
      heap_.resize(need);
      data_ = heap_.data();
      capacity_ = need;
    } else {
      data_ = inline_.data();
      capacity_ = inline_.size();
    }
  }
  PairStack(const PairStack&) = delete;
  PairStack& operator=(const PairStack&) = delete;

  bool empty() const { return size_ == 0; }
  void push(std::int32_t a, std::int32_t b, double bound) {
    SWEPT_ASSERT(size_ < capacity_, "traversal stack overflow: a tree deeper than its recorded depth");
    data_[size_++] = {a, b, bound};
  }
  PairEntry pop() {
    SWEPT_ASSERT(size_ > 0, "pop from an empty traversal stack");
    return data_[--size_];
  }

 private:
  std::array<PairEntry, 192> inline_;
  std::vector<PairEntry> heap_;
  PairEntry* data_ = nullptr;
  std::size_t capacity_ = 0;
  std::size_t size_ = 0;
};

/// The overlap traversal shared by collide, proximity_pairs and sweep_translation: node pairs
/// depth first from a fixed-capacity stack, the larger node of a pair split (descend_a), its
/// first child visited first. `keep(ia, ib, ra, pb)` decides whether the pair of nodes ia of A
/// and ib of B can hold a reported triangle pair (the root pair included), given ia's RSS `ra`
/// and ib's placed in A's frame `pb` (each decoded once for both children of a split);
/// `leaves(na, nb)` visits every kept pair of leaves and returns false to stop the traversal.
/// (The distance search orders its pairs by their bounds instead and keeps its own loop,
/// query.cpp.)
/// `roots` are the two trees' roots (Roots); the overload without them decodes them.
template <class Keep, class Leaves>
void for_each_leaf_pair(const Bvh& a, const Bvh& b, const Relative& rel, const Roots& roots, Keep&& keep,
                        Leaves&& leaves) {
  if (a.empty() || b.empty()) return;
  const Rss root_a = roots.a;
  PlacedRss root_b = roots.b;
  if (!keep(0, 0, root_a, root_b)) return;
  DecodedNodes nodes(a, b, rel);
  nodes.seed(root_a, root_b);
  PairStack stack(a, b);
  stack.push(0, 0, 0.0);
  while (!stack.empty()) {
    const PairEntry e = stack.pop();
    const Node& na = a.nodes[e.a];
    const Node& nb = b.nodes[e.b];
    if (na.is_leaf() && nb.is_leaf()) {
      if (!leaves(na, nb)) return;
      continue;
    }
    // Pushed second child first, so that the first child is visited first.
    if (descend_a(na, nb)) {
      PlacedRss& placed = nodes.b(e.b);
      for (std::int32_t c = na.first + 1; c >= na.first; --c)
        if (keep(c, e.b, nodes.a(c), placed)) stack.push(c, e.b, 0.0);
    } else {
      const Rss& ra = nodes.a(e.a);
      for (std::int32_t c = nb.first + 1; c >= nb.first; --c)
        if (keep(e.a, c, ra, nodes.b(c))) stack.push(e.a, c, 0.0);
    }
  }
}

template <class Keep, class Leaves>
void for_each_leaf_pair(const Bvh& a, const Bvh& b, const Relative& rel, Keep&& keep, Leaves&& leaves) {
  if (a.empty() || b.empty()) return;
  for_each_leaf_pair(a, b, rel, Roots(a, b, rel), keep, leaves);
}

}  // namespace swept::detail
