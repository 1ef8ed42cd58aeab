#pragma once
// The oracle's own acceleration: an axis-aligned box tree (median split) over a triangle set,
// and closest-pair / close-pairs queries between two trees. Internal to the oracle.
#include "oracle/path_oracle.h"

#include <cstdint>
#include <limits>
#include <vector>

namespace oracle::detail {

struct Box {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = Eigen::Vector3d::Constant(-std::numeric_limits<double>::infinity());
  void grow(const Eigen::Vector3d& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  void grow(const Box& b) {
    lo = lo.cwiseMin(b.lo);
    hi = hi.cwiseMax(b.hi);
  }
};

Box box_of(const Tri& t);

/// Squared gap between two boxes (0 when they overlap).
double box_gap_sq(const Box& a, const Box& b);

/// Children of node k are nodes `left` and `left + 1`, both after k; leaves have count > 0 and
/// hold tri_index[first, first + count).
struct Node {
  Box box;
  std::int32_t left = -1;
  std::int32_t first = 0;
  std::int32_t count = 0;
};

/// A tree over a triangle set. Its topology can be reused for the same triangles moved
/// rigidly: `refit` recomputes every box from the moved triangles.
struct BoxTree {
  std::vector<Node> nodes;
  std::vector<std::int32_t> tri_index;
  std::vector<Box> tri_box;  ///< per triangle (by original index), matching the last build/refit
};

BoxTree build_tree(const std::vector<Tri>& tris);
void refit(BoxTree& tree, const std::vector<Tri>& moved);

/// A pair (triangle a of the first set, triangle b of the second) as a·2^32 + b; sorted vectors
/// of them name the pairs a query leaves out.
using PairKey = std::uint64_t;
inline PairKey pair_key(std::int32_t a, std::int32_t b) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

struct Closest {
  double distance = std::numeric_limits<double>::infinity();
  std::int32_t a = -1;  ///< triangle of the first set
  std::int32_t b = -1;  ///< triangle of the second set
};

/// Smallest exact distance between the two sets, leaving out the pairs in `exclude` (sorted
/// keys; may be null). Serial and deterministic.
Closest closest_pair(const BoxTree& ta, const std::vector<Tri>& a, const BoxTree& tb, const std::vector<Tri>& b,
                     const std::vector<PairKey>* exclude = nullptr);

/// Every pair at exact distance < threshold, as sorted keys.
std::vector<PairKey> close_pairs(const BoxTree& ta, const std::vector<Tri>& a, const BoxTree& tb,
                                 const std::vector<Tri>& b, double threshold);

}  // namespace oracle::detail
