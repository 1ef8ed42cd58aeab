// Top-down RSS tree construction (SPEC §2), level by level.
//
// Each level's nodes are processed in parallel (oneTBB); each node's work depends only on its
// own triangles, kept in input order by stable partitions, and node indices are handed out
// serially in level order afterwards, so the tree is the same node for node at any thread count.
#include "fit_internal.h"
#include "swept/bvh/bvh.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numbers>
#include <numeric>
#include <string>

namespace swept {

std::size_t Bvh::memory_bytes() const {
  // What the arrays hold, not only what they use (a build reserves for 2n − 1 nodes).
  return nodes.capacity() * sizeof(Node) + triangles.memory_bytes() +
         triangle_ids.capacity() * sizeof(std::uint32_t) + sizeof(Bvh);
}

BvhStats stats(const Bvh& bvh) {
  BvhStats s;
  s.triangles = bvh.triangles.size();
  s.nodes = bvh.nodes.size();
  s.depth = bvh.depth;
  for (std::size_t i = 0; i < bvh.nodes.size(); ++i) {
    const Rss v = bvh.bv(i);
    s.total_surface_area += surface_area(v);
    s.total_volume += volume(v);
  }
  s.bytes = bvh.memory_bytes();
  return s;
}

Aabb bounds(const IndexedTriangles& triangles) {
  Aabb box;
  for (const Vec3& v : triangles.vertices) box.extend(v);
  return box;
}

namespace {

// x rounded to a float, the rounding kept: GCC 12's SLP vectorizer (-O2 and up) drops a
// double → float → double round trip of Eigen vector components (found here: a center stored as
// floats decoded back bit for bit equal to the unrounded one, so no error was measured and the
// stored RSS missed vertices). A volatile float is a value the compiler cannot see through.
float to_float(double x) {
  volatile float f = static_cast<float>(x);
  return f;
}

// The float nearest to x that is not below it (x finite, |x| below FLT_MAX).
float round_up(double x) {
  float f = to_float(x);
  if (static_cast<double>(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
  return f;
}

}  // namespace

void encode_rss(const Rss& rss, const Vec3& origin, Node& node) {
  // The axes as a quaternion rounded to floats, and the center relative to `origin` rounded to
  // floats. The stored RSS uses what they decode to (decode_rss, shared with every query).
  const Eigen::Quaterniond q(rss.axes);
  Node out;
  out.rotation = {to_float(q.w()), to_float(q.x()), to_float(q.y()), to_float(q.z())};
  const Vec3 local = rss.center - origin;
  out.center = {to_float(local.x()), to_float(local.y()), to_float(local.z())};
  const Rss stored = decode_rss(out, origin);
  // A point c + s·e1 + t·e2 + u of the RSS (|s| ≤ a, |t| ≤ b, ‖u‖ ≤ r) is within
  // ‖δc‖ + a‖δ1‖ + b‖δ2‖ + r of the stored rectangle's point c' + s·e1' + t·e2'.
  const double a = rss.half_length[0], b = rss.half_length[1];
  const double grow = (stored.center - rss.center).norm() + a * (stored.axes.col(0) - rss.axes.col(0)).norm() +
                      b * (stored.axes.col(1) - rss.axes.col(1)).norm();
  // The relative slack covers the rounding of the sums above (a few units in the last place).
  node.rotation = out.rotation;
  node.center = out.center;
  node.half_length = {round_up(a), round_up(b)};
  node.radius = round_up((rss.radius + grow) * (1.0 + 1e-12));
}

namespace {

using detail::TriInfo;

// Maps the pages of [data, data + bytes) in, on every core: the kernel's first-touch work
// (a fault and a cleared page per 4 KiB) is otherwise done by whichever thread first writes
// the memory, and for the builder's largest buffers that was a serial loop. Best effort: a
// kernel without MADV_POPULATE_WRITE (before Linux 5.14) leaves the pages to the first write.
void prefault([[maybe_unused]] const void* data, [[maybe_unused]] std::size_t bytes, [[maybe_unused]] bool parallel) {
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
  constexpr std::size_t kMin = std::size_t{8} << 20;  // smaller buffers: not worth the calls
  if (!parallel || data == nullptr || bytes < kMin) return;
  const auto page = static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
  const auto begin = (reinterpret_cast<std::uintptr_t>(data) + page - 1) / page * page;
  const auto end = (reinterpret_cast<std::uintptr_t>(data) + bytes) / page * page;
  if (end <= begin) return;
  constexpr std::uintptr_t kChunk = std::uintptr_t{2} << 20;
  const std::size_t chunks = (end - begin + kChunk - 1) / kChunk;
  tbb::parallel_for(std::size_t{0}, chunks, [&](std::size_t c) {
    const std::uintptr_t from = begin + c * kChunk, to = std::min(end, from + kChunk);
    madvise(reinterpret_cast<void*>(from), to - from, MADV_POPULATE_WRITE);
  });
#endif
}

// Room for `capacity` elements in `v`, the pages of its first `mapped` mapped in (prefault).
template <class T>
void reserve_mapped(std::vector<T>& v, std::size_t capacity, std::size_t mapped, bool parallel) {
  v.reserve(capacity);
  prefault(v.data(), std::min(mapped, v.capacity()) * sizeof(T), parallel);
}

// Interleaves the low 21 bits of x, y and z (clamped cell coordinates) into a 63-bit Morton code.
std::uint64_t morton_code(const Vec3& cell) {
  auto spread = [](double v) {
    std::uint64_t x = static_cast<std::uint64_t>(std::clamp(v, 0.0, 2097151.0));
    x = (x | x << 32) & 0x1f00000000ffffULL;
    x = (x | x << 16) & 0x1f0000ff0000ffULL;
    x = (x | x << 8) & 0x100f00f00f00f00fULL;
    x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
    x = (x | x << 2) & 0x1249249249249249ULL;
    return x;
  };
  return spread(cell.x()) | spread(cell.y()) << 1 | spread(cell.z()) << 2;
}

// A node waiting to be processed: its index and its triangle range in `ids`; with min-sa, also
// its own fit, made already when its parent weighed the split that made it.
struct Pending {
  std::int32_t node = 0;
  std::uint32_t begin = 0, end = 0;
  bool fitted = false;
  Fit fit;
};

// What processing a node produced besides its RSS: where its triangles split (or a leaf), or
// that its whole subtree is done (small nodes, see build_subtree).
struct Outcome {
  bool leaf = true;
  bool subtree = false;
  int subtree_depth = 0;     // levels of the finished subtree, its root included
  std::uint32_t middle = 0;  // children: [begin, middle) and [middle, end)
  bool child_fits = false;   // min-sa fitted both children to cost the split: their fits
  Fit child_fit[2];
};

// With one triangle per leaf, a node of n triangles has exactly 2n − 1 nodes below and
// including it, so a small node's subtree can be given its block of indices in advance and
// built depth first while its triangles are in cache, instead of one level per pass over all
// triangles (the deep levels of a large mesh are mostly cache misses otherwise).
constexpr std::uint32_t kSubtreeTriangles = 2048;

struct Scratch {
  std::vector<Vec3> projected;
  std::vector<std::uint32_t> outside;  // projected vertices that may sit at an RSS corner
  std::vector<std::uint32_t> ids[2];
  std::vector<std::uint8_t> side[3];
  std::vector<Vec3> child_projected;        // min-sa's candidate children
  std::vector<std::uint32_t> child_outside;
  struct StackItem {
    Pending p;
    int depth;
  };
  std::vector<StackItem> stack;  // build_subtree's walk
};

// Completes a processed node: its RSS (`rss`, in the builder's frame) to the model frame and
// stored, then either its leaf range or its
// two children at indices `next`, `next + 1` (taken from `next`), returned as pending work.
// Returns false for a leaf.
bool link_node(Node& node, const Pending& p, const Outcome& o, Rss rss, const Vec3& offset, std::size_t& next,
               Pending children[2]) {
  rss.center += offset;
  encode_rss(rss, offset, node);
  if (o.leaf) {
    node.first = static_cast<std::int32_t>(p.begin);
    node.count = static_cast<std::int32_t>(p.end - p.begin);
    return false;
  }
  const auto child = static_cast<std::int32_t>(next);
  next += 2;
  node.first = child;
  node.count = 0;
  children[0] = {child, p.begin, o.middle};
  children[1] = {child + 1, o.middle, p.end};
  if (o.child_fits)
    for (int k = 0; k < 2; ++k) {
      children[k].fitted = true;
      children[k].fit = o.child_fit[k];
    }
  return true;
}

struct Builder {
  const BuildConfig& config;
  const std::vector<TriInfo>& info;  // local frame
  std::vector<std::uint32_t>& ids;
  tbb::enumerable_thread_specific<Scratch> scratch;

  // Stable partition of the node's ids by `side` (left first), in place.
  std::uint32_t apply(const Pending& node, const std::vector<std::uint8_t>& side, Scratch& s) {
    const std::size_t n = node.end - node.begin;
    s.ids[0].clear();
    s.ids[1].clear();
    for (std::size_t j = 0; j < n; ++j) s.ids[side[j]].push_back(ids[node.begin + j]);
    std::copy(s.ids[0].begin(), s.ids[0].end(), ids.begin() + node.begin);
    std::copy(s.ids[1].begin(), s.ids[1].end(), ids.begin() + node.begin + s.ids[0].size());
    return node.begin + static_cast<std::uint32_t>(s.ids[0].size());
  }

  // Builds the whole subtree of `root` (leaf size 1) depth first: the root into nodes[root.node],
  // its descendants into nodes[base, base + 2n − 2), siblings adjacent, in the order a depth-
  // first walk (left child first) reaches them. Centres are moved to the model frame.
  Outcome build_subtree(const Pending& root, std::size_t base, std::vector<Node>& nodes, const Vec3& offset,
                        Scratch& s) {
    using Item = Scratch::StackItem;
    Outcome result;
    result.subtree = true;
    std::vector<Item>& stack = s.stack;
    stack.clear();
    stack.push_back({root, 1});
    std::size_t next = base;
    while (!stack.empty()) {
      const Item it = stack.back();
      stack.pop_back();
      result.subtree_depth = std::max(result.subtree_depth, it.depth);
      Node& node = nodes[static_cast<std::size_t>(it.p.node)];
      Pending children[2];
      Rss rss;
      const Outcome o = process(it.p, rss, s);
      if (!link_node(node, it.p, o, rss, offset, next, children)) continue;
      stack.push_back({children[1], it.depth + 1});
      stack.push_back({children[0], it.depth + 1});  // the left child first
    }
    return result;
  }

  // The RSS that process() gives a node of these triangles (the one-triangle closed form, else
  // the node's own fit orients it): min-sa's cost of a candidate child, exactly as the child
  // would be built. `accumulated` holds the subset's fit, passes done; it is finished into `fit`
  // only when used (a one-triangle child takes the closed form and needs none).
  Rss subset_rss(const std::uint32_t* subset, std::size_t n, Scratch& s, detail::FitAccumulator& accumulated,
                 Fit& fit) const {
    const Vec3 origin = info[subset[0]].t.p;
    Mat3 axes;
    if (n == 1 && detail::single_triangle_axes(info[subset[0]].t, axes)) {
      detail::project_vertices(info.data(), subset, n, axes, origin, s.child_projected);
      return detail::make_rss(detail::rss_extents(s.child_projected.data(), s.child_projected.size()), axes, origin);
    }
    fit = accumulated.finish();
    axes = fit.axes;
    Vec3 lo, hi;
    detail::project_vertices(info.data(), subset, n, axes, origin, s.child_projected, &lo, &hi);
    detail::RssEdges edges(lo, hi);
    s.child_outside.clear();
    for (std::size_t k = 0; k < s.child_projected.size(); ++k)
      if (edges.add(s.child_projected[k])) s.child_outside.push_back(static_cast<std::uint32_t>(k));
    return detail::make_rss(edges.finish(s.child_projected.data(), s.child_outside.data(), s.child_outside.size()),
                            axes, origin);
  }

  // min-sa's SA(L) + SA(R) of every candidate `a` that leaves no side empty (`valid`): each side
  // fitted as its own node (the paper's eq. (4) with each child's RSS, SPEC §2.2), exactly as
  // fit_ids and subset_rss would fit it alone — the six sides' fits accumulated in the same two
  // passes over the node's triangles instead of two passes over each side. Their fits go to
  // `fits`: the chosen candidate's are its children's own.
  void min_sa_costs(const std::uint32_t* node_ids, std::size_t n, int candidates, const bool valid[3], double cost[3],
                    Fit fits[3][2], Scratch& s) const {
    detail::FitAccumulator acc[3][2];
    for (std::size_t j = 0; j < n; ++j) {
      if (j + detail::kPrefetchAhead < n) detail::prefetch(info.data() + node_ids[j + detail::kPrefetchAhead]);
      const TriInfo& t = info[node_ids[j]];
      for (int a = 0; a < candidates; ++a)
        if (valid[a]) acc[a][s.side[a][j]].first(t);
    }
    for (int a = 0; a < candidates; ++a)
      if (valid[a])
        for (auto& side : acc[a]) side.middle(config.fitter);
    for (std::size_t j = 0; j < n; ++j) {
      if (j + detail::kPrefetchAhead < n) detail::prefetch(info.data() + node_ids[j + detail::kPrefetchAhead]);
      const TriInfo& t = info[node_ids[j]];
      const detail::TriMoments mo = detail::tri_moments(t);
      for (int a = 0; a < candidates; ++a)
        if (valid[a]) acc[a][s.side[a][j]].second(t, mo);
    }
    for (int a = 0; a < candidates; ++a) {
      if (!valid[a]) continue;
      // A candidate that splits the triangles as an earlier one did (or with the sides swapped)
      // costs the same, and ties keep the earlier axis: it cannot be chosen. (Every candidate
      // of a two-triangle node is such a repeat.)
      bool repeat = false;
      for (int e = 0; e < a && !repeat; ++e) {
        if (!valid[e]) continue;
        const bool swapped = s.side[e][0] != s.side[a][0];
        repeat = std::equal(s.side[a].begin(), s.side[a].begin() + static_cast<std::ptrdiff_t>(n), s.side[e].begin(),
                            [swapped](std::uint8_t x, std::uint8_t y) { return (x != y) == swapped; });
      }
      if (repeat) {
        cost[a] = std::numeric_limits<double>::infinity();
        continue;
      }
      s.ids[0].clear();
      s.ids[1].clear();
      for (std::size_t j = 0; j < n; ++j) s.ids[s.side[a][j]].push_back(node_ids[j]);
      cost[a] = 0.0;
      for (int k = 0; k < 2; ++k)
        cost[a] += surface_area(subset_rss(s.ids[k].data(), s.ids[k].size(), s, acc[a][k], fits[a][k]));
    }
  }

  // SA(L) + SA(R) of a candidate for min-sa-box: the RSS around each side's bounding box in the
  // node's frame, from the one pass (cheaper, not the paper's rule).
  static double box_cost(const Vec3 lo[2], const Vec3 hi[2]) {
    double cost = 0.0;
    for (int k = 0; k < 2; ++k) {
      const Vec3 ext = hi[k] - lo[k];
      const double w = ext.x(), h = ext.y(), r = 0.5 * ext.z();
      cost += 2.0 * w * h + 2.0 * std::numbers::pi * (w + h) * r + 4.0 * std::numbers::pi * r * r;
    }
    return cost;
  }

  // Fits the node's RSS (in the local frame) into `rss` and decides its split.
  Outcome process(const Pending& node, Rss& rss, Scratch& s) {
    Outcome out;
    const std::size_t n = node.end - node.begin;
    const std::uint32_t* node_ids = ids.data() + node.begin;
    const Vec3 origin = info[node_ids[0]].t.p;
    Mat3 leaf_axes;
    if (n == 1 && detail::single_triangle_axes(info[node_ids[0]].t, leaf_axes)) {
      // A one-triangle leaf: the fitters' axes in closed form.
      detail::project_vertices(info.data(), node_ids, n, leaf_axes, origin, s.projected);
      rss = detail::make_rss(detail::rss_extents(s.projected.data(), s.projected.size()), leaf_axes, origin);
      return out;
    }
    // The node's own fit orients its RSS (SPEC §2.3) and gives the split candidates (§2.2).
    const Fit f = node.fitted ? node.fit : detail::fit_ids(info.data(), node_ids, n, config.fitter);
    Vec3 box_lo, box_hi;
    detail::project_vertices(info.data(), node_ids, n, f.axes, origin, s.projected, &box_lo, &box_hi);
    detail::RssEdges edges(box_lo, box_hi);
    s.outside.clear();

    // Candidate planes through the split position, across e1, e2, e3 (min-sa, min-sa-box) or e1
    // only (largest), each costed by split_cost(). The sides, and min-sa-box's boxes (rectangle:
    // a side's e1 × e2 extent in the node's frame; radius: half its e3 extent), come from the
    // same pass over the projections as the edges of the node's own RSS.
    const bool leaf = n <= static_cast<std::size_t>(config.leaf_size);
    const Vec3 split = f.axes.transpose() * (f.split_point - origin);
    const int candidates = leaf ? 0 : config.split == SplitRule::largest ? 1 : 3;
    constexpr double inf = std::numeric_limits<double>::infinity();
    Vec3 lo[3][2], hi[3][2];
    std::size_t left[3] = {0, 0, 0};
    for (int a = 0; a < candidates; ++a) {
      s.side[a].resize(n);
      lo[a][0] = lo[a][1] = Vec3::Constant(inf);
      hi[a][0] = hi[a][1] = Vec3::Constant(-inf);
    }
    for (std::size_t j = 0; j < n; ++j) {
      const Vec3& p0 = s.projected[3 * j];
      const Vec3& p1 = s.projected[3 * j + 1];
      const Vec3& p2 = s.projected[3 * j + 2];
      const auto k = static_cast<std::uint32_t>(3 * j);
      if (edges.add(p0)) s.outside.push_back(k);
      if (edges.add(p1)) s.outside.push_back(k + 1);
      if (edges.add(p2)) s.outside.push_back(k + 2);
      if (candidates == 0) continue;
      const Vec3 tlo = p0.cwiseMin(p1).cwiseMin(p2), thi = p0.cwiseMax(p1).cwiseMax(p2);
      const Vec3 centre = (p0 + p1 + p2) / 3.0;
      for (int a = 0; a < candidates; ++a) {
        const int right = centre[a] - split[a] >= 0.0 ? 1 : 0;
        s.side[a][j] = static_cast<std::uint8_t>(right);
        left[a] += 1 - right;
        lo[a][right] = lo[a][right].cwiseMin(tlo);
        hi[a][right] = hi[a][right].cwiseMax(thi);
      }
    }
    rss = detail::make_rss(edges.finish(s.projected.data(), s.outside.data(), s.outside.size()), f.axes, origin);
    if (leaf) return out;
    out.leaf = false;

    bool valid[3] = {false, false, false};  // a candidate that leaves one side empty is none
    for (int a = 0; a < candidates; ++a) valid[a] = left[a] != 0 && left[a] != n;
    const bool fit_sides = candidates > 1 && config.split == SplitRule::min_sa;
    double min_sa_cost[3];
    Fit side_fits[3][2];
    if (fit_sides) min_sa_costs(node_ids, n, candidates, valid, min_sa_cost, side_fits, s);
    double best_cost = inf;
    int best = -1;
    for (int a = 0; a < candidates; ++a) {
      if (!valid[a]) continue;
      // With one candidate (largest) there is nothing to compare.
      const double cost = candidates == 1 ? 0.0 : fit_sides ? min_sa_cost[a] : box_cost(lo[a], hi[a]);
      if (cost < best_cost) {  // ties keep the earlier axis
        best_cost = cost;
        best = a;
      }
    }
    if (best >= 0) {
      out.middle = apply(node, s.side[best], s);
      if (fit_sides) {
        out.child_fits = true;
        out.child_fit[0] = side_fits[best][0];
        out.child_fit[1] = side_fits[best][1];
      }
      return out;
    }
    // Every axis leaves a side empty (e.g. coincident centroids): split at the median of the
    // projections on e1, ties broken by the builder's (Morton) order.
    const Vec3 e1 = f.axes.col(0);
    auto first = ids.begin() + node.begin, last = ids.begin() + node.end;
    const std::size_t half = n / 2;
    std::nth_element(first, first + half, last, [&](std::uint32_t x, std::uint32_t y) {
      const double px = info[x].centroid().dot(e1), py = info[y].centroid().dot(e1);
      return px < py || (px == py && x < y);
    });
    std::sort(first, first + half);
    std::sort(first + half, last);
    out.middle = node.begin + static_cast<std::uint32_t>(half);
    return out;
  }
};

}  // namespace

namespace {

constexpr double kMaxCoordinate = 1e30;

// The triangles `ids` (in that order) as indices into shared vertices: a vertex is shared when
// its coordinates are equal bit for bit, so every triangle reads back exactly. Vertices are
// numbered in order of first use, so the vertices of neighbouring leaves lie close in memory.
// An open-addressing table of vertex indices, keyed by a hash of the coordinates' bits.
void weld(std::span<const Triangle> triangles, const std::vector<std::uint32_t>& ids, IndexedTriangles& out,
          bool parallel) {
  const std::size_t n = ids.size();
  out.vertices.clear();
  out.corners.clear();
  reserve_mapped(out.corners, n, n, parallel);
  out.corners.resize(n);
  // Closed meshes have about n / 2 vertices: the table starts with room for them at half load
  // and doubles when it is half full (a table for the worst case, 3n, spent its time in cache
  // misses).
  std::size_t slots = 64;
  while (slots < n) slots *= 2;
  constexpr std::uint32_t kEmpty = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> table(slots, kEmpty);
  std::vector<Vec3> vertices;
  reserve_mapped(vertices, n, n / 2, parallel);  // closed meshes have about n / 2
  auto hash = [](const Vec3& v) {
    std::uint64_t k[3];
    std::memcpy(k, v.data(), sizeof(k));
    std::uint64_t h = k[0] * 0x9E3779B97F4A7C15ULL;
    h = (h ^ (h >> 29) ^ k[1]) * 0xBF58476D1CE4E5B9ULL;
    h = (h ^ (h >> 32) ^ k[2]) * 0x94D049BB133111EBULL;
    return h ^ (h >> 31);
  };
  auto grow = [&] {
    slots *= 2;
    table.assign(slots, kEmpty);
    for (std::uint32_t idx = 0; idx < vertices.size(); ++idx) {
      std::size_t slot = hash(vertices[idx]) & (slots - 1);
      while (table[slot] != kEmpty) slot = (slot + 1) & (slots - 1);
      table[slot] = idx;
    }
  };
  auto table_index = [&](const Vec3& v, std::uint64_t h) -> std::uint32_t {
    for (std::size_t slot = h & (slots - 1);; slot = (slot + 1) & (slots - 1)) {
      const std::uint32_t idx = table[slot];
      if (idx == kEmpty) {
        const auto added = static_cast<std::uint32_t>(vertices.size());
        table[slot] = added;
        vertices.push_back(v);
        if (2 * vertices.size() >= slots) grow();
        return added;
      }
      if (std::memcmp(vertices[idx].data(), v.data(), sizeof(Vec3)) == 0) return idx;
    }
  };
  // In leaf order a vertex is mostly met again soon after it was first met (its triangles are
  // neighbours): a small direct-mapped cache of the last vertex per hash bucket, in cache, answers
  // those, and the table (mostly cache misses) only the rest.
  constexpr std::size_t kRecent = 4096;
  std::vector<std::uint32_t> recent(kRecent, kEmpty);
  auto index_of = [&](const Vec3& v) {
    const std::uint64_t h = hash(v);
    std::uint32_t& r = recent[(h >> 40) & (kRecent - 1)];
    if (r != kEmpty && std::memcmp(vertices[r].data(), v.data(), sizeof(Vec3)) == 0) return r;
    r = table_index(v, h);
    return r;
  };
  // Both are read far apart in memory, so they are fetched ahead: the triangle (in the input's
  // order, not the leaves') 2·kAhead triangles ahead, the table slots of its corners kAhead ahead.
  constexpr std::size_t kAhead = 8;
  for (std::size_t i = 0; i < n; ++i) {
#if defined(__GNUC__)
    if (i + 2 * kAhead < n) {
      const char* record = reinterpret_cast<const char*>(&triangles[ids[i + 2 * kAhead]]);
      __builtin_prefetch(record);
      __builtin_prefetch(record + sizeof(Triangle) - 1);
    }
    if (i + kAhead < n) {
      const Triangle& ahead = triangles[ids[i + kAhead]];
      for (int c = 0; c < 3; ++c) __builtin_prefetch(table.data() + (hash(ahead[c]) & (slots - 1)));
    }
#endif
    const Triangle& t = triangles[ids[i]];
    out.corners[i] = {index_of(t.p), index_of(t.q), index_of(t.r)};
  }
  std::vector<std::uint32_t>().swap(table);
  // Exactly as many as used (the working array grew by doubling).
  reserve_mapped(out.vertices, vertices.size(), vertices.size(), parallel);
  out.vertices.assign(vertices.begin(), vertices.end());
}

}  // namespace

Result<Bvh> build_bvh(std::span<const Triangle> triangles, const BuildConfig& config) {
  if (triangles.empty()) return Error{"cannot build a tree of an empty mesh (0 triangles)"};
  if (triangles.size() > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max() / 2))
    return Error{"mesh too large: " + std::to_string(triangles.size()) + " triangles"};
  if (config.leaf_size < 1 || config.leaf_size > kMaxLeafSize)
    return Error{"leaf size must be between 1 and " + std::to_string(kMaxLeafSize) + " (got " +
                 std::to_string(config.leaf_size) + ")"};
  Aabb box;
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    const Triangle& t = triangles[i];
    if (!(t.p.allFinite() && t.q.allFinite() && t.r.allFinite()))
      return Error{"triangle " + std::to_string(i) + " has a NaN or infinite coordinate"};
    // Nodes are stored in single precision (Node): lengths up to 2e30 stay far from its limit.
    if (std::max({t.p.cwiseAbs().maxCoeff(), t.q.cwiseAbs().maxCoeff(), t.r.cwiseAbs().maxCoeff()}) > kMaxCoordinate)
      return Error{"triangle " + std::to_string(i) + " has a coordinate beyond ±1e30, which trees do not support"};
    box.extend(t.p);
    box.extend(t.q);
    box.extend(t.r);
  }
  const Vec3 offset = box.center();
  const std::size_t n = triangles.size();
  auto for_each_index = [&](auto&& body) {
    if (config.parallel) {
      tbb::parallel_for(std::size_t{0}, n, body);
    } else {
      for (std::size_t i = 0; i < n; ++i) body(i);
    }
  };

  // The builder works on copies in Morton order of the centroids, so that a node's triangles
  // lie close together in memory (on a 1.3M-triangle CAD mesh this alone makes the build about
  // a quarter faster than in the file's order). The order is a total one (ties by input index),
  // so the tree is still a function of the input alone.
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed;
  reserve_mapped(keyed, n, n, config.parallel);
  keyed.resize(n);
  const Vec3 size = box.max - box.min;
  const Vec3 cells = Vec3::NullaryExpr([&](Eigen::Index k) { return size[k] > 0.0 ? 2097151.0 / size[k] : 0.0; });
  for_each_index([&](std::size_t i) {
    const Triangle& t = triangles[i];
    const Vec3 c = ((t.p + t.q + t.r) / 3.0 - box.min).cwiseProduct(cells);
    keyed[i] = {morton_code(c), static_cast<std::uint32_t>(i)};
  });
  if (config.parallel) {
    tbb::parallel_sort(keyed.begin(), keyed.end());
  } else {
    std::sort(keyed.begin(), keyed.end());
  }
  std::vector<std::uint32_t> order(n);
  std::vector<TriInfo> info;
  reserve_mapped(info, n, n, config.parallel);
  info.resize(n);
  for_each_index([&](std::size_t i) {
    order[i] = keyed[i].second;
    const Triangle& t = triangles[order[i]];
    info[i] = detail::make_tri_info(Triangle{t.p - offset, t.q - offset, t.r - offset});
  });
  std::vector<std::pair<std::uint64_t, std::uint32_t>>().swap(keyed);
  std::vector<std::uint32_t> ids(n);
  std::iota(ids.begin(), ids.end(), 0u);

  Builder builder{config, info, ids, {}};
  Bvh bvh;
  bvh.config = config;
  bvh.extent = box.extent();
  // Every split leaves both sides non-empty, so there are at most n leaves and 2n − 1 nodes:
  // reserved once, so that each level's nodes are written in place, in parallel.
  reserve_mapped(bvh.nodes, 2 * n - 1, 2 * n - 1, config.parallel);
  std::size_t used = 1;

  std::vector<Pending> level{Pending{0, 0, static_cast<std::uint32_t>(n)}};
  std::vector<Outcome> outcomes;
  std::vector<Rss> level_rss;  // the level's RSSs, in the builder's frame, until linked
  std::vector<Pending> next;
  std::vector<std::size_t> subtree_base;  // 0: not a subtree root (index 0 is the tree's root)
  int max_depth = 0;
  {
    // The root, one node, is processed on this thread: its projections' buffers mapped in on
    // every core (min-sa's candidate sides too: a candidate's larger side has at least half).
    Scratch& s = builder.scratch.local();
    reserve_mapped(s.projected, 3 * n, 3 * n, config.parallel);
    if (config.split == SplitRule::min_sa) reserve_mapped(s.child_projected, 3 * n, 3 * n / 2, config.parallel);
  }
  while (!level.empty()) {
    ++bvh.depth;
    // Small nodes get their subtree's block of indices now, in level order.
    subtree_base.assign(level.size(), 0);
    if (config.leaf_size == 1) {
      for (std::size_t i = 0; i < level.size(); ++i) {
        const std::uint32_t m = level[i].end - level[i].begin;
        if (m < 2 || m > kSubtreeTriangles) continue;
        subtree_base[i] = used;
        used += 2 * static_cast<std::size_t>(m) - 2;
      }
    }
    bvh.nodes.resize(used);
    outcomes.assign(level.size(), Outcome{});
    level_rss.resize(level.size());
    auto run = [&](const tbb::blocked_range<std::size_t>& range) {
      Scratch& s = builder.scratch.local();
      for (std::size_t i = range.begin(); i != range.end(); ++i) {
        if (subtree_base[i] != 0) {
          outcomes[i] = builder.build_subtree(level[i], subtree_base[i], bvh.nodes, offset, s);
        } else {
          outcomes[i] = builder.process(level[i], level_rss[i], s);
        }
      }
    };
    if (config.parallel && level.size() > 1) {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, level.size()), run);
    } else {
      run(tbb::blocked_range<std::size_t>(0, level.size()));
    }
    // Children are numbered serially, in level order: the same tree at any thread count.
    next.clear();
    for (std::size_t i = 0; i < level.size(); ++i) {
      const Pending& p = level[i];
      const Outcome& o = outcomes[i];
      if (o.subtree) {
        max_depth = std::max(max_depth, bvh.depth - 1 + o.subtree_depth);
        continue;
      }
      Pending children[2];
      if (link_node(bvh.nodes[static_cast<std::size_t>(p.node)], p, o, level_rss[i], offset, used, children))
        next.insert(next.end(), children, children + 2);
    }
    std::swap(level, next);
  }
  bvh.depth = std::max(bvh.depth, max_depth);
  if (bvh.nodes.capacity() > used + used / 4) bvh.nodes.shrink_to_fit();  // large leaves

  bvh.origin = offset;
  bvh.root = bvh.bv(0);
  bvh.triangle_ids.resize(n);
  for_each_index([&](std::size_t i) { bvh.triangle_ids[i] = order[ids[i]]; });
  weld(triangles, bvh.triangle_ids, bvh.triangles, config.parallel);
  return bvh;
}

}  // namespace swept
