// Phase 2: lazy weighted A* on the multi-resolution grid (lazy_astar.h).
#include "lazy_astar.h"

#include "swept/geometry/assert.h"

#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>

namespace swept::detail {

LazyGridSearch::LazyGridSearch(PlanContext& context, const Grid& grid, const Pose& start, double start_distance)
    : context_(context), grid_(grid), start_(start) {
  SWEPT_ASSERT(context.problem.goal_outside || context.problem.goal, "a problem has a goal pose or a goal region");
  nodes_[GridKey{}] = NodeInfo{true, start_distance};
}

double LazyGridSearch::heuristic(const Pose& pose) const {
  const Problem& problem = context_.problem;
  if (!problem.goal_outside) return context_.check.length(pose, *problem.goal);
  const Vec3 p = context_.reference_at(pose);
  const Aabb& box = context_.space.goal_box;
  const double r = context_.space.radius;
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    best = std::min(best, std::max(0.0, box.max[i] + r - p[i]));
    best = std::min(best, std::max(0.0, p[i] - (box.min[i] - r)));
  }
  return best;
}

void LazyGridSearch::report_progress(int level) {
  if (!context_.options.progress) return;
  const double now = context_.elapsed_s();
  if (now - last_progress_s_ < 1.0) return;
  last_progress_s_ = now;
  context_.report({level, nodes_.size(), context_.check.distance_queries(), now});
}

// An entry is a (node, parent) pair; a node and the edge from its parent are checked only when
// the entry is popped (Cohen, Phillips, Likhachev 2014). A node's distance bound carries to its
// neighbours by the 1-Lipschitz property of the distance in the motion metric
// (D(q') ≥ D(q) − d(q, q')), so in open space most nodes and edges need no query at all.
std::optional<std::vector<GridKey>> LazyGridSearch::search_level(int level, std::size_t budget, bool& exhausted) {
  const Problem& problem = context_.problem;
  const double step = grid_.step(level);
  const double margin = context_.check.margin();
  constexpr double kWeight = 2.0;
  struct Entry {
    double f, g;
    GridKey key, parent;
    bool operator>(const Entry& o) const {
      if (f != o.f) return f > o.f;
      if (g != o.g) return g < o.g;  // deeper first among equals
      if (key != o.key) return key > o.key;
      return parent > o.parent;
    }
  };
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
  absl::flat_hash_map<GridKey, GridKey, GridKeyHash> closed;  // node → parent
  absl::flat_hash_map<GridKey, double, GridKeyHash> best_g;
  const GridKey start{};
  open.push({kWeight * heuristic(start_), 0.0, start, start});
  const double goal_connect = std::sqrt(static_cast<double>(grid_.dimensions())) * step * 1.01;
  std::size_t expansions = 0;
  exhausted = false;
  auto edge_of = [](const GridKey& a, const GridKey& b) {
    return b == kGoalKey ? GridEdge{a, kGoalKey} : GridEdge{std::min(a, b), std::max(a, b)};
  };
  while (!open.empty()) {
    const Entry e = open.top();
    open.pop();
    if (closed.count(e.key)) continue;
    ++expansions_;
    if ((++expansions & 255) == 0) {
      if (context_.out_of_time()) return std::nullopt;
      report_progress(level);
    }
    if (expansions > budget) return std::nullopt;
    if (context_.over_budget()) return std::nullopt;
    // The node.
    NodeInfo* node = nullptr;
    if (e.key != kGoalKey) {
      // Unknown, or known only by a bound too weak to carry on: query it.
      auto unknown = [&](const GridKey& key) {
        const auto it = nodes_.find(key);
        return it == nodes_.end() || (it->second.free && !it->second.queried && it->second.distance <= margin + step);
      };
      if (unknown(e.key)) {
        // The next entry's node, when it too is unknown, is queried at the same time on the other
        // core (it would be when popped). The search is the same: a node's freedom and an
        // edge's verdict do not depend on which bounds are known first, only the count of
        // queries does (a node queried ahead gets no bound from its parent's free ball).
        const Entry* ahead = open.empty() || !query_ahead_ ? nullptr : &open.top();
        if (ahead && (ahead->key == kGoalKey || ahead->key == e.key || closed.count(ahead->key) || !unknown(ahead->key)))
          ahead = nullptr;
        auto query = [&](const GridKey& key) {
          NodeInfo info;
          info.free = context_.free_at(grid_.pose_of(key), 4.0 * step, &info.distance);
          return info;
        };
        NodeInfo here, there;
        if (ahead) {
          tbb::parallel_invoke([&] { here = query(e.key); }, [&] { there = query(ahead->key); });
          nodes_.insert_or_assign(ahead->key, there);
        } else {
          here = query(e.key);
        }
        nodes_.insert_or_assign(e.key, here);
      }
      const auto it = nodes_.find(e.key);
      if (!it->second.free) continue;
      node = &it->second;
    }
    // The edge from its parent.
    if (e.key != start) {
      const GridEdge edge = edge_of(e.parent, e.key);
      auto known = edges_.find(edge);
      if (known == edges_.end()) {
        const Pose a = grid_.pose_of(e.parent);
        const Pose b = e.key == kGoalKey ? *problem.goal : grid_.pose_of(e.key);
        const double da = nodes_.at(e.parent).distance;
        const double db = node ? node->distance : -1.0;
        known = edges_.emplace(edge, context_.certify(a, da, b, db)).first;
      }
      if (!known->second) continue;
    }
    closed.emplace(e.key, e.parent);
    if (e.key == kGoalKey || (problem.goal_outside && goal_reached(context_.space, problem, grid_.pose_of(e.key)))) {
      std::vector<GridKey> path;
      for (GridKey k = e.key;; k = closed.at(k)) {
        path.push_back(k);
        if (k == start) break;
      }
      std::reverse(path.begin(), path.end());
      return path;
    }
    const Pose q = grid_.pose_of(e.key);
    auto push = [&](const GridKey& next, double cost) {
      const double g = e.g + cost;
      auto bg = best_g.find(next);
      if (bg != best_g.end() && bg->second <= g) return;
      best_g[next] = g;
      const double h = next == kGoalKey ? 0.0 : heuristic(grid_.pose_of(next));
      open.push({g + kWeight * h, g, next, e.key});
    };
    if (!problem.goal_outside && context_.check.length(q, *problem.goal) <= goal_connect) {
      auto known = edges_.find({e.key, kGoalKey});
      if (known == edges_.end() || known->second) push(kGoalKey, context_.check.length(q, *problem.goal));
    }
    const double inherited = node->distance - step;
    const GridNeighbours around = grid_.neighbours(e.key, level);
    for (int i = 0; i < around.count; ++i) {
      const GridKey& next = around.keys[i];
      if (closed.count(next)) continue;
      auto n = nodes_.find(next);
      if (n != nodes_.end() && !n->second.free) continue;
      // A neighbour well inside this node's free ball is free, and so is the edge to it.
      if (n == nodes_.end() && inherited > margin) {
        nodes_.emplace(next, NodeInfo{true, inherited, false});
        edges_.emplace(edge_of(e.key, next), true);
      }
      push(next, step);
    }
  }
  exhausted = true;
  return std::nullopt;
}

std::optional<std::vector<Pose>> LazyGridSearch::run(GridOutcome& outcome, std::size_t total_budget) {
  const bool bounded = total_budget != SIZE_MAX;
  bool all_exhausted = true;
  std::size_t unfinished = 0;  // expansions of levels that stopped at their budget
  for (int level = 0; level <= grid_.finest_level(); ++level) {
    std::size_t budget = std::size_t{4000} << level;
    if (level == grid_.finest_level() && !bounded) budget = std::numeric_limits<std::size_t>::max();
    if (bounded) {
      if (unfinished >= total_budget) break;
      budget = std::min(budget, total_budget - unfinished);
    }
    level_reached_ = level;
    const std::size_t before = expansions_;
    bool exhausted = false;
    if (const auto keys = search_level(level, budget, exhausted)) {
      std::vector<Pose> poses;
      for (const GridKey& k : *keys) poses.push_back(k == kGoalKey ? *context_.problem.goal : grid_.pose_of(k));
      outcome = GridOutcome::found;
      return poses;
    }
    if (context_.out_of_time()) {
      outcome = GridOutcome::time_limit;
      return std::nullopt;
    }
    if (context_.over_budget()) {
      outcome = GridOutcome::budget;
      return std::nullopt;
    }
    if (!exhausted) unfinished += expansions_ - before;
    all_exhausted = all_exhausted && exhausted;
  }
  outcome = all_exhausted && level_reached_ == grid_.finest_level() ? GridOutcome::exhausted : GridOutcome::resolution;
  return std::nullopt;
}

}  // namespace swept::detail
