// The oracle's box tree: median split on the longest axis of the centroids' box, leaves of at
// most four triangles, and depth-first dual-tree queries that visit the nearer child pair first.
#include "oracle/box_tree.h"

#include <algorithm>
#include <cmath>

namespace oracle::detail {
namespace {

constexpr int kLeafSize = 4;

double axis_gap_sq(const Box& a, const Box& b, int axis) {
  const double g = std::max({0.0, a.lo[axis] - b.hi[axis], b.lo[axis] - a.hi[axis]});
  return g * g;
}

bool is_leaf(const Node& n) { return n.count > 0; }

double size_of(const Box& b) { return (b.hi - b.lo).squaredNorm(); }

}  // namespace

Box box_of(const Tri& t) {
  Box b;
  for (const auto& v : t.v) b.grow(v);
  return b;
}

double box_gap_sq(const Box& a, const Box& b) {
  return axis_gap_sq(a, b, 0) + axis_gap_sq(a, b, 1) + axis_gap_sq(a, b, 2);
}

BoxTree build_tree(const std::vector<Tri>& tris) {
  BoxTree tree;
  const auto n = static_cast<std::int32_t>(tris.size());
  tree.tri_index.resize(tris.size());
  tree.tri_box.resize(tris.size());
  std::vector<Eigen::Vector3d> centroid(tris.size());
  for (std::int32_t i = 0; i < n; ++i) {
    tree.tri_index[i] = i;
    tree.tri_box[i] = box_of(tris[i]);
    centroid[i] = (tris[i].v[0] + tris[i].v[1] + tris[i].v[2]) / 3.0;
  }
  if (n == 0) return tree;
  struct Range {
    std::int32_t node, first, count;
  };
  tree.nodes.push_back({});
  std::vector<Range> todo{{0, 0, n}};
  while (!todo.empty()) {
    const Range r = todo.back();
    todo.pop_back();
    Box cbox;
    Box box;
    for (std::int32_t k = r.first; k < r.first + r.count; ++k) {
      box.grow(tree.tri_box[tree.tri_index[k]]);
      cbox.grow(centroid[tree.tri_index[k]]);
    }
    tree.nodes[r.node].box = box;
    const Eigen::Vector3d ext = cbox.hi - cbox.lo;
    if (r.count <= kLeafSize || !(ext.maxCoeff() > 0.0)) {  // small, or all centroids equal
      tree.nodes[r.node].first = r.first;
      tree.nodes[r.node].count = r.count;
      continue;
    }
    int axis = 0;
    ext.maxCoeff(&axis);
    const std::int32_t half = r.count / 2;
    auto begin = tree.tri_index.begin() + r.first;
    // A total order (ties by index): each half holds the same triangles with any standard library.
    std::nth_element(begin, begin + half, begin + r.count, [&](std::int32_t x, std::int32_t y) {
      const double cx = centroid[x][axis], cy = centroid[y][axis];
      return cx < cy || (cx == cy && x < y);
    });
    const auto left = static_cast<std::int32_t>(tree.nodes.size());
    tree.nodes[r.node].left = left;
    tree.nodes.push_back({});
    tree.nodes.push_back({});
    todo.push_back({left + 1, r.first + half, r.count - half});
    todo.push_back({left, r.first, half});
  }
  return tree;
}

void refit(BoxTree& tree, const std::vector<Tri>& moved) {
  for (std::size_t i = 0; i < moved.size(); ++i) tree.tri_box[i] = box_of(moved[i]);
  for (std::size_t k = tree.nodes.size(); k-- > 0;) {
    Node& node = tree.nodes[k];
    Box box;
    if (is_leaf(node)) {
      for (std::int32_t j = node.first; j < node.first + node.count; ++j) box.grow(tree.tri_box[tree.tri_index[j]]);
    } else {
      box = tree.nodes[node.left].box;
      box.grow(tree.nodes[node.left + 1].box);
    }
    node.box = box;
  }
}

namespace {

// Depth-first over node pairs, nearer pair first; `leaf` is called for every pair of leaves
// whose boxes are closer than `bound()` (squared), which the callback may lower.
template <class Bound, class Leaf>
void dual_traverse(const BoxTree& ta, const BoxTree& tb, Bound bound, Leaf leaf) {
  if (ta.nodes.empty() || tb.nodes.empty()) return;
  struct Item {
    std::int32_t a, b;
    double gap_sq;
  };
  std::vector<Item> stack;
  stack.reserve(256);
  stack.push_back({0, 0, box_gap_sq(ta.nodes[0].box, tb.nodes[0].box)});
  while (!stack.empty()) {
    const Item it = stack.back();
    stack.pop_back();
    if (!(it.gap_sq < bound())) continue;
    const Node& na = ta.nodes[it.a];
    const Node& nb = tb.nodes[it.b];
    if (is_leaf(na) && is_leaf(nb)) {
      leaf(na, nb);
      continue;
    }
    // Split the larger box (or the one that is not a leaf).
    const bool split_a = !is_leaf(na) && (is_leaf(nb) || size_of(na.box) >= size_of(nb.box));
    Item c0, c1;
    if (split_a) {
      c0 = {na.left, it.b, box_gap_sq(ta.nodes[na.left].box, nb.box)};
      c1 = {na.left + 1, it.b, box_gap_sq(ta.nodes[na.left + 1].box, nb.box)};
    } else {
      c0 = {it.a, nb.left, box_gap_sq(na.box, tb.nodes[nb.left].box)};
      c1 = {it.a, nb.left + 1, box_gap_sq(na.box, tb.nodes[nb.left + 1].box)};
    }
    if (c0.gap_sq < c1.gap_sq) std::swap(c0, c1);
    stack.push_back(c0);  // farther first, so the nearer is visited first
    stack.push_back(c1);
  }
}

}  // namespace

Closest closest_pair(const BoxTree& ta, const std::vector<Tri>& a, const BoxTree& tb, const std::vector<Tri>& b,
                     const std::vector<PairKey>* exclude) {
  Closest best;
  double best_sq = std::numeric_limits<double>::infinity();
  dual_traverse(
      ta, tb, [&] { return best_sq; },
      [&](const Node& na, const Node& nb) {
        for (std::int32_t i = na.first; i < na.first + na.count; ++i) {
          const std::int32_t ia = ta.tri_index[i];
          for (std::int32_t j = nb.first; j < nb.first + nb.count; ++j) {
            const std::int32_t ib = tb.tri_index[j];
            if (!(box_gap_sq(ta.tri_box[ia], tb.tri_box[ib]) < best_sq)) continue;
            if (exclude && std::binary_search(exclude->begin(), exclude->end(), pair_key(ia, ib))) continue;
            const double d = triangle_distance(a[ia], b[ib]);
            if (d < best.distance) {
              best = {d, ia, ib};
              best_sq = d * d;
            }
          }
        }
      });
  return best;
}

std::vector<PairKey> close_pairs(const BoxTree& ta, const std::vector<Tri>& a, const BoxTree& tb,
                                 const std::vector<Tri>& b, double threshold) {
  std::vector<PairKey> out;
  if (!(threshold > 0.0)) return out;
  const double t_sq = threshold * threshold;
  dual_traverse(
      ta, tb, [&] { return t_sq; },
      [&](const Node& na, const Node& nb) {
        for (std::int32_t i = na.first; i < na.first + na.count; ++i) {
          const std::int32_t ia = ta.tri_index[i];
          for (std::int32_t j = nb.first; j < nb.first + nb.count; ++j) {
            const std::int32_t ib = tb.tri_index[j];
            if (!(box_gap_sq(ta.tri_box[ia], tb.tri_box[ib]) < t_sq)) continue;
            if (triangle_distance(a[ia], b[ib]) < threshold) out.push_back(pair_key(ia, ib));
          }
        }
      });
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace oracle::detail
