// Collide, distance and tolerance queries over two RSS trees (Larsen et al. 1999; PQP's
// traversal scheme): B is placed in A's frame once per query and the node of larger surface area
// split. Collide and proximity visit node pairs depth first from a fixed-capacity stack; the
// distance search takes the pending pair of smallest bound first for its first dives, then
// goes on depth first, nearer child pair first (DistanceSearch::run).
#include "swept/query/query.h"

#include "traversal.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace swept {
namespace {

using detail::descend_a;
using detail::node_pair;
using detail::Relative;

constexpr double kInf = std::numeric_limits<double>::infinity();

bool pair_less(const ContactPair& x, const ContactPair& y) {
  return x.triangle_a != y.triangle_a ? x.triangle_a < y.triangle_a : x.triangle_b < y.triangle_b;
}
void sort_pairs(std::vector<ContactPair>& pairs) { std::sort(pairs.begin(), pairs.end(), pair_less); }

/// Collision traversal: separated when some projection gap exceeds the radii (+ contact
/// tolerance), exactly like an OBB separating-axis test.
CollideResult collide_relative(const Bvh& a, const Bvh& b, const Relative& rel, const CollideRequest& request) {
  CollideResult out;
  if (a.empty() || b.empty()) return out;
  const detail::Roots roots(a, b, rel);
  const double touch = 1e-12 * roots.coordinate_bound();
  // Far apart, the balls around the two roots settle the query from their centers (counted as
  // the root pair's test).
  if (detail::balls_apart(roots.a, roots.b, touch)) {
    out.stats.bv_tests = 1;
    return out;
  }
  auto overlapping = [&](std::int32_t, std::int32_t, const Rss& na, detail::PlacedRss& pb) {
    ++out.stats.bv_tests;
    const double limit = na.radius + pb.rss.radius + touch;
    return !detail::separated(na, pb, limit);
  };
  auto leaves = [&](const Node& na, const Node& nb) {
    for (std::int32_t j = nb.first; j < nb.first + nb.count; ++j) {
      const Triangle tb = rel.apply(b.triangles[j]);
      for (std::int32_t i = na.first; i < na.first + na.count; ++i) {
        ++out.stats.triangle_tests;
        if (!triangles_intersect(a.triangles[i], tb)) continue;
        out.colliding = true;
        out.contacts.push_back({a.triangle_ids[i], b.triangle_ids[j]});
        if (!request.all_contacts) return false;
      }
    }
    return true;
  };
  detail::for_each_leaf_pair(a, b, rel, roots, overlapping, leaves);
  sort_pairs(out.contacts);
  return out;
}

/// Distance traversal in A's frame; points are returned in A's frame.
struct DistanceSearch {
  const Bvh& a;
  const Bvh& b;
  const Relative& rel;
  double rel_err, abs_err, enough;
  const TrianglePairs* exclude = nullptr;  ///< pairs left out (the planner's contact exemption)
  /// pairs left out by a rule (the assembly's mates)
  const std::function<bool(std::uint32_t, std::uint32_t)>* exclude_if = nullptr;

  DistanceSearch(const Bvh& a_, const Bvh& b_, const Relative& rel_, double rel_err_,
                 double abs_err_, double enough_, const TrianglePairs* exclude_ = nullptr,
                 const std::function<bool(std::uint32_t, std::uint32_t)>* exclude_if_ = nullptr)
      : a(a_), b(b_), rel(rel_), rel_err(rel_err_), abs_err(abs_err_), enough(enough_), exclude(exclude_),
        exclude_if(exclude_if_) {}

  double best = kInf;
  bool have_witness = false;
  Vec3 point_a = Vec3::Zero(), point_b = Vec3::Zero();
  std::uint32_t tri_a = 0, tri_b = 0;
  std::uint32_t pos_a = UINT32_MAX, pos_b = UINT32_MAX;  ///< the witness's positions in the trees
  double pruned_enough = kInf;  ///< smallest bound of a pair dropped because it reached `enough`
  bool stop_at_first = false;   ///< tolerance queries: stop at the first pair below `best`
  double stop_below = -kInf;    ///< stop once the answer so far is below this (DistanceRequest::stop_below)
  QueryStats stats;

  /// The bound at which a pair cannot improve the answer (PQP's error semantics), kept up to
  /// date whenever `best` changes.
  double best_level = kInf;
  void set_best(double d) {
    best = d;
    best_level = std::min(best / (1.0 + rel_err), best - abs_err);
  }
  double prune_level() const { return std::min(best_level, enough); }
  /// Pairs (tree positions) left out by `exclude` or `exclude_if`.
  bool excluded(std::size_t i, std::size_t j) const {
    return (exclude && exclude->contains(a.triangle_ids[i], b.triangle_ids[j])) ||
           (exclude_if && (*exclude_if)(a.triangle_ids[i], b.triangle_ids[j]));
  }
  /// The pair at tree positions (i, j), at distance `d`, is the answer so far.
  void take(const TriangleDistance& d, std::size_t i, std::size_t j) {
    set_best(d.distance);
    have_witness = true;
    point_a = d.point_a;
    point_b = d.point_b;
    tri_a = a.triangle_ids[i];
    tri_b = b.triangle_ids[j];
    pos_a = static_cast<std::uint32_t>(i);
    pos_b = static_cast<std::uint32_t>(j);
    have_axis = d.distance > 0.0;
    if (have_axis) axis = (d.point_b - d.point_a) / d.distance;
  }
  /// The direction from the answer's point on A to its point on B, once the answer is a
  /// positive distance: the leaf pairs first try the gap along it (triangle_distance_below).
  /// Far apart it settles about half of the triangle pairs that would otherwise be evaluated in
  /// full only to end above the answer (counted on the shared CAD and robot pairs,
  /// docs/lab/fitters-history.md "The gap along the answer's direction").
  bool have_axis = false;
  Vec3 axis = Vec3::Zero();
  double scale = 0.0;  ///< bounds every coordinate a triangle test sees (A's frame), set by run()
  /// True when a pair with this lower bound is dropped.
  bool prune(double bound) {
    if (bound >= best_level) return true;
    if (bound >= enough) {
      pruned_enough = std::min(pruned_enough, bound);
      return true;
    }
    return false;
  }
  /// Lower bound for a node of A (`na`) against a node of B placed in A's frame (`pb`); the
  /// bound computation stops as soon as it reaches the prune level.
  double bound(const Rss& na, detail::PlacedRss& pb) {
    ++stats.bv_tests;
    const double radii = na.radius + pb.rss.radius;
    // A bound at or past the prune level is compared with `best_level` alone, unless the level
    // is `enough`, whose smallest pruned bound is reported (pruned_enough): only then its value.
    return detail::lower_bound(na, pb, prune_level() + radii, enough < best_level) - radii;
  }

  /// The nodes this search decoded (detail::DecodedNodes), set by run().
  detail::DecodedNodes* decoded = nullptr;
  const Rss& node_of_a(std::int32_t i) { return decoded->a(i); }
  detail::PlacedRss& placed_of_b(std::int32_t i) { return decoded->b(i); }

  void leaves(const Node& na, const Node& nb) {
    for (std::int32_t j = nb.first; j < nb.first + nb.count; ++j) {
      const Triangle tb = rel.apply(b.triangles[j]);
      for (std::int32_t i = na.first; i < na.first + na.count; ++i) {
        if (excluded(i, j)) continue;
        ++stats.triangle_tests;
        TriangleDistance d;
        const bool below = have_axis ? triangle_distance_below(a.triangles[i], tb, best, d, axis, scale)
                                     : triangle_distance_below(a.triangles[i], tb, best, d);
        if (below && d.distance < best) take(d, i, j);
      }
    }
  }

  // The order of the node pairs. A pair is expanded into its two child pairs; the nearer one is
  // taken next at once (a dive toward the leaves), the other waits. For the first kBestFirstDives
  // dives the waiting pair of smallest bound starts the next dive (best first, a binary heap):
  // in near contact this finds a close pair before the depth-first order would, and the answer
  // then prunes everything else (measured on two CAD pairs: 20-31 % fewer node pairs and 27-41 %
  // less time near contact, 9-23 % and 5-20 % far apart; docs/lab/fitters-history.md "Traversal order").
  // After that the waiting pairs are sorted, the smallest bound on top, and the search goes on
  // depth first: a heap over a whole far-apart query costs more than the pairs it saves (best
  // first throughout was 5-24 % slower than depth first far apart). Ties are broken by node
  // indices, so the order, and with it the witness of a tie, is the same on every run.
  // Tolerance queries (stop_at_first) want any pair below the threshold, not the nearest: depth
  // first throughout. A popped pair is dropped when the answer has since dropped to its bound.
  static constexpr int kBestFirstDives = 64;

  void run() {
    if (a.empty() || b.empty()) return;
    const Rss& root_a = a.root;  // the roots, decoded when the trees were built
    detail::PlacedRss root_b = detail::place(b.root, rel);
    scale = detail::coordinate_bound(root_a, root_b);
    const double root = bound(root_a, root_b);
    if (prune(root)) return;
    // The waiting pairs: a heap while best first, then a stack (its back on top). The buffer is
    // the thread's, reused from query to query; taken out while in use, so a nested search on
    // the same thread gets its own (as do the decoded nodes).
    thread_local std::vector<detail::PairEntry> spare;
    std::vector<detail::PairEntry> waiting = std::exchange(spare, {});
    detail::DecodedNodes nodes(a, b, rel);
    nodes.seed(root_a, root_b);
    decoded = &nodes;
    waiting.clear();
    run(root, waiting);
    decoded = nullptr;
    spare = std::move(waiting);
  }

  void run(double root, std::vector<detail::PairEntry>& waiting) {
    auto later = [](const detail::PairEntry& x, const detail::PairEntry& y) {
      if (x.bound != y.bound) return x.bound > y.bound;
      return x.a != y.a ? x.a > y.a : x.b > y.b;
    };
    int dives = stop_at_first ? kBestFirstDives : 0;
    bool best_first = dives < kBestFirstDives;
    bool diving = true;  // `next` holds the pair to expand
    detail::PairEntry next{0, 0, root};
    auto wait = [&](const detail::PairEntry& e) {
      waiting.push_back(e);
      if (best_first) std::push_heap(waiting.begin(), waiting.end(), later);
    };
    while (diving || !waiting.empty()) {
      // A touching pair ends every search: nothing is closer than 0 (the pairs left would only
      // confirm it), and the witness is the first such pair found.
      if (have_witness && (stop_at_first || best < stop_below || !(best > 0.0))) return;
      detail::PairEntry e = next;
      if (!diving) {
        if (best_first && ++dives > kBestFirstDives) {
          best_first = false;
          std::sort(waiting.begin(), waiting.end(), later);  // the smallest bound last: on top
        }
        if (best_first) {
          std::pop_heap(waiting.begin(), waiting.end(), later);
          e = waiting.back();
          waiting.pop_back();
          // Every waiting pair's bound is at least this one's: all are dropped with it (and the
          // smallest bound dropped for `enough`, if any, is this one).
          if (prune(e.bound)) return;
        } else {
          e = waiting.back();
          waiting.pop_back();
        }
      }
      diving = false;
      if (prune(e.bound)) continue;
      const Node& na = a.nodes[e.a];
      const Node& nb = b.nodes[e.b];
      if (na.is_leaf() && nb.is_leaf()) {
        leaves(na, nb);
        continue;
      }
      std::int32_t a0 = e.a, b0 = e.b, a1 = e.a, b1 = e.b;
      const bool split_a = descend_a(na, nb);
      if (split_a) {
        a0 = na.first;
        a1 = na.first + 1;
      } else {
        b0 = nb.first;
        b1 = nb.first + 1;
      }
      // A child pair of two leaves goes straight to the triangle test: its own cheap rejection
      // (the gap along the centroid line) costs about as much as an RSS test, and when it
      // does not reject, the RSS test would rarely have.
      const bool leaf0 = a.nodes[a0].is_leaf() && b.nodes[b0].is_leaf();
      const bool leaf1 = a.nodes[a1].is_leaf() && b.nodes[b1].is_leaf();
      if (leaf0) leaves(a.nodes[a0], b.nodes[b0]);
      if (leaf1) leaves(a.nodes[a1], b.nodes[b1]);
      if (leaf0 && leaf1) continue;
      if (leaf0 || leaf1) {
        const std::int32_t ca = leaf0 ? a1 : a0, cb = leaf0 ? b1 : b0;
        const double d = bound(node_of_a(ca), placed_of_b(cb));
        if (!prune(d)) {
          next = {ca, cb, d};
          diving = true;
        }
        continue;
      }
      // Each test decodes only the child it is about, and only if this search has not yet
      // (detail::DecodedNodes).
      double d0, d1;
      if (split_a) {
        detail::PlacedRss& placed = placed_of_b(e.b);
        d0 = bound(node_of_a(a0), placed);  // a0, a1 adjacent: never in one slot
        d1 = bound(node_of_a(a1), placed);
      } else {
        const Rss& ra = node_of_a(e.a);
        d0 = bound(ra, placed_of_b(b0));
        d1 = bound(ra, placed_of_b(b1));
      }
      // The nearer pair next; ties keep the first child first (deterministic).
      if (d1 < d0) {
        std::swap(a0, a1);
        std::swap(b0, b1);
        std::swap(d0, d1);
      }
      if (!prune(d1)) wait({a1, b1, d1});
      if (!prune(d0)) {
        next = {a0, b0, d0};
        diving = true;
      }
    }
  }
};

DistanceResult distance_relative(const Bvh& a, const Pose& pose_a, const Bvh& b,
                                 const Relative& rel, const DistanceRequest& request) {
  const double rel_err = std::max(0.0, request.rel_err), abs_err = std::max(0.0, request.abs_err);
  DistanceSearch warm(a, b, rel, rel_err, abs_err, request.enough, request.exclude, request.exclude_if);
  DistanceSearch cold(a, b, rel, rel_err, abs_err, request.enough, request.exclude, request.exclude_if);
  const DistanceSearch* used = &cold;

  // Suspects: the first pair below stop_below ends the query, as the search would end at it.
  // (No distance is below a stop_below of 0 or less.)
  if (request.stop_below > 0.0) {
    for (const DistanceHint& s : request.suspects) {
      if (!s.valid() || s.a >= a.triangles.size() || s.b >= b.triangles.size() || warm.excluded(s.a, s.b)) continue;
      ++warm.stats.triangle_tests;
      TriangleDistance d;
      if (!triangle_distance_below(a.triangles[s.a], rel.apply(b.triangles[s.b]), request.stop_below, d) ||
          !(d.distance < request.stop_below))
        continue;
      DistanceResult out;
      out.stats = warm.stats;
      out.distance = d.distance;
      out.exact = false;
      out.point_a = pose_a.apply(d.point_a);
      out.point_b = pose_a.apply(d.point_b);
      out.triangle_a = a.triangle_ids[s.a];
      out.triangle_b = b.triangle_ids[s.b];
      out.hint = s;
      return out;
    }
  }

  // Coherence: the previous query's closest pair, measured at these poses, is the answer so far.
  const DistanceHint h = request.hint;
  if (h.valid() && h.a < a.triangles.size() && h.b < b.triangles.size() && !warm.excluded(h.a, h.b)) {
    const TriangleDistance d = triangle_distance(a.triangles[h.a], rel.apply(b.triangles[h.b]));
    ++warm.stats.triangle_tests;
    if (d.distance < request.upper_bound) warm.take(d, h.a, h.b);
  }

  // No first-contact search before the distance search: the search ends at its first touching
  // pair, and near contact the contact search's node pairs (every pair of overlapping RSSs) are
  // ones the distance search must open anyway, so running it first only doubled them (a third of
  // a near-contact query's time; docs/lab/fitters-history.md, "No contact search first").
  warm.stop_below = cold.stop_below = request.stop_below;
  if (warm.have_witness && warm.best == 0.0) {
    used = &warm;  // nothing is closer than 0
  } else if (warm.have_witness || request.upper_bound < kInf) {
    if (!warm.have_witness) warm.set_best(request.upper_bound);
    warm.run();
    used = &warm;
    if (!warm.have_witness && !(warm.pruned_enough < warm.best)) {
      // The warm bound pruned everything: nothing is closer than it. Find the witness pair.
      cold.stats = warm.stats;
      cold.run();
      used = &cold;
    }
  } else {
    cold.stats = warm.stats;
    cold.run();
  }
  const DistanceSearch& s = *used;
  DistanceResult out;
  out.stats = s.stats;
  if (s.pruned_enough < s.best) {
    out.distance = s.pruned_enough;  // a lower bound ≥ enough
    out.exact = false;
  } else if (s.have_witness && s.best < request.stop_below) {
    out.distance = s.best;  // a pair below stop_below: an upper bound
    out.exact = false;
  } else {
    out.distance = s.best;
    out.exact = true;
  }
  if (s.have_witness) {
    out.point_a = pose_a.apply(s.point_a);
    out.point_b = pose_a.apply(s.point_b);
    out.triangle_a = s.tri_a;
    out.triangle_b = s.tri_b;
    out.hint = {s.pos_a, s.pos_b};
  }
  return out;
}

// Every triangle pair (positions i of A, j of B) closer than the threshold, to `near(i, j)`;
// node pairs with `skip_nodes(ia, ib)` and triangle pairs with `skip(i, j)` are not looked at.
// A node pair whose RSS lower bound reaches the threshold holds no such pair.
template <class SkipNodes, class Skip, class Near>
void for_each_near_pair(const Bvh& a, const Bvh& b, const Relative& rel, double threshold, QueryStats& stats,
                        SkipNodes&& skip_nodes, Skip&& skip, Near&& near) {
  auto keep = [&](std::int32_t ia, std::int32_t ib, const Rss& na, detail::PlacedRss& pb) {
    if (skip_nodes(ia, ib)) return false;
    ++stats.bv_tests;
    const double radii = na.radius + pb.rss.radius;
    return detail::lower_bound(na, pb, threshold + radii, false) - radii < threshold;
  };
  auto leaves = [&](const Node& na, const Node& nb) {
    for (std::int32_t j = nb.first; j < nb.first + nb.count; ++j) {
      const Triangle tb = rel.apply(b.triangles[j]);
      for (std::int32_t i = na.first; i < na.first + na.count; ++i) {
        if (skip(i, j)) continue;
        ++stats.triangle_tests;
        TriangleDistance d;
        if (triangle_distance_below(a.triangles[i], tb, threshold, d) && d.distance < threshold) near(i, j);
      }
    }
    return true;
  };
  detail::for_each_leaf_pair(a, b, rel, keep, leaves);
}

}  // namespace

bool TrianglePairs::contains(std::uint32_t triangle_a, std::uint32_t triangle_b) const {
  const ContactPair key{triangle_a, triangle_b};
  return std::binary_search(pairs.begin(), pairs.end(), key, pair_less);
}

ProximityResult proximity_pairs(const Bvh& a, const Pose& pose_a, const Bvh& b, const Pose& pose_b,
                                const ProximityRequest& request) {
  ProximityResult out;
  const double threshold = request.threshold;
  if (a.empty() || b.empty() || !(threshold > 0.0)) return out;
  for_each_near_pair(
      a, b, Relative(pose_a, pose_b), threshold, out.stats, [](std::int32_t, std::int32_t) { return false; },
      [](std::int32_t, std::int32_t) { return false; },
      [&](std::int32_t i, std::int32_t j) { out.pairs.pairs.push_back({a.triangle_ids[i], b.triangle_ids[j]}); });
  auto& v = out.pairs.pairs;
  sort_pairs(v);
  v.erase(std::unique(v.begin(), v.end(), [](const ContactPair& x, const ContactPair& y) {
            return x.triangle_a == y.triangle_a && x.triangle_b == y.triangle_b;
          }), v.end());
  return out;
}

namespace {

// Which triangles of a tree are known to be near: a flag per triangle (by position), and a node
// is `done` once every triangle under it is flagged. A leaf counts its unflagged triangles; a
// flagged leaf marks its ancestors done while both children of each are.
class NearMarks {
 public:
  explicit NearMarks(const Bvh& t)
      : tree_(t), flagged_(t.triangles.size(), 0), done_(t.nodes.size(), 0), parent_(t.nodes.size(), -1),
        leaf_of_(t.triangles.size(), 0), left_(t.nodes.size(), 0) {
    for (std::size_t n = 0; n < t.nodes.size(); ++n) {
      const Node& node = t.nodes[n];
      if (node.is_leaf()) {
        left_[n] = node.count;
        for (std::int32_t i = node.first; i < node.first + node.count; ++i) leaf_of_[i] = static_cast<std::int32_t>(n);
      } else {
        parent_[node.first] = parent_[node.first + 1] = static_cast<std::int32_t>(n);
      }
    }
  }
  bool flagged(std::int32_t i) const { return flagged_[i] != 0; }
  bool done(std::int32_t n) const { return done_[n] != 0; }
  void flag(std::int32_t i) {
    if (flagged_[i]) return;
    flagged_[i] = 1;
    std::int32_t n = leaf_of_[i];
    if (--left_[n] > 0) return;
    done_[n] = 1;
    for (std::int32_t p = parent_[n]; p >= 0; p = parent_[p]) {
      const std::int32_t c = tree_.nodes[p].first;
      if (!done_[c] || !done_[c + 1]) break;
      done_[p] = 1;
    }
  }
  std::vector<std::uint32_t> ids() const {
    std::vector<std::uint32_t> out;
    for (std::size_t i = 0; i < flagged_.size(); ++i)
      if (flagged_[i]) out.push_back(tree_.triangle_ids[i]);
    std::sort(out.begin(), out.end());
    return out;
  }

 private:
  const Bvh& tree_;
  std::vector<char> flagged_, done_;
  std::vector<std::int32_t> parent_, leaf_of_, left_;
};

}  // namespace

ProximityTrianglesResult proximity_triangles(const Bvh& a, const Pose& pose_a, const Bvh& b, const Pose& pose_b,
                                             const ProximityRequest& request) {
  ProximityTrianglesResult out;
  const double threshold = request.threshold;
  if (a.empty() || b.empty() || !(threshold > 0.0)) return out;
  NearMarks ma(a), mb(b);
  for_each_near_pair(
      a, b, Relative(pose_a, pose_b), threshold, out.stats,
      [&](std::int32_t ia, std::int32_t ib) { return ma.done(ia) && mb.done(ib); },
      [&](std::int32_t i, std::int32_t j) { return ma.flagged(i) && mb.flagged(j); },
      [&](std::int32_t i, std::int32_t j) {
        ma.flag(i);
        mb.flag(j);
      });
  out.a = ma.ids();
  out.b = mb.ids();
  return out;
}

CollideResult collide(const Bvh& a, const Pose& pose_a, const Bvh& b, const Pose& pose_b,
                      const CollideRequest& request) {
  const Relative rel(pose_a, pose_b);
  return collide_relative(a, b, rel, request);
}

DistanceResult distance(const Bvh& a, const Pose& pose_a, const Bvh& b, const Pose& pose_b,
                        const DistanceRequest& request) {
  const Relative rel(pose_a, pose_b);
  return distance_relative(a, pose_a, b, rel, request);
}

ToleranceResult tolerance(const Bvh& a, const Pose& pose_a, const Bvh& b, const Pose& pose_b,
                          const ToleranceRequest& request) {
  ToleranceResult out;
  if (a.empty() || b.empty() || !(request.tolerance > 0.0)) return out;
  const Relative rel(pose_a, pose_b);
  const double tol = request.tolerance;
  // The distance search, pruning at the tolerance and stopping at the first triangle pair closer
  // than it (depth first). No first-contact search before it, as in distance(): overlapping
  // RSSs bound 0, below any tolerance, so it would only visit pairs this search visits too.
  DistanceSearch s(a, b, rel, 0.0, 0.0, kInf);
  s.set_best(tol);
  s.stop_at_first = true;
  s.run();
  out.stats = s.stats;
  if (s.have_witness) {
    out.within = true;
    out.distance = s.best;
    out.point_a = pose_a.apply(s.point_a);
    out.point_b = pose_a.apply(s.point_b);
    out.triangle_a = s.tri_a;
    out.triangle_b = s.tri_b;
  }
  return out;
}

std::vector<DistanceResult> distance_batch(const Bvh& a, const Pose& pose_a, const Bvh& b,
                                           std::span<const Pose> poses_b,
                                           const DistanceRequest& request, bool along_path) {
  std::vector<DistanceResult> out(poses_b.size());
  if (along_path) {
    // Fixed blocks, each in order with the previous pose's pair as the hint.
    constexpr std::size_t kBlock = 64;
    const std::size_t blocks = (poses_b.size() + kBlock - 1) / kBlock;
    tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t k) {
      DistanceRequest r = request;
      r.hint = {};
      for (std::size_t i = k * kBlock; i < std::min(poses_b.size(), (k + 1) * kBlock); ++i) {
        out[i] = distance(a, pose_a, b, poses_b[i], r);
        r.hint = out[i].hint;
      }
    });
    return out;
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, poses_b.size(), 8),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t i = r.begin(); i != r.end(); ++i)
                        out[i] = distance(a, pose_a, b, poses_b[i], request);
                    });
  return out;
}

std::vector<CollideResult> collide_batch(const Bvh& a, const Pose& pose_a, const Bvh& b,
                                         std::span<const Pose> poses_b,
                                         const CollideRequest& request) {
  std::vector<CollideResult> out(poses_b.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, poses_b.size(), 8),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t i = r.begin(); i != r.end(); ++i)
                        out[i] = collide(a, pose_a, b, poses_b[i], request);
                    });
  return out;
}

}  // namespace swept
