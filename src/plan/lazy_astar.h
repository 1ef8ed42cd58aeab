#pragma once
// Phase 2 of the search (internal to src/plan): lazy weighted A* on the multi-resolution grid
// (Bohlin & Kavraki 2000, "Path planning using lazy PRM": check nodes and edges only when a
// search reaches them; Bohlin 2001: the grid refined level by level). Every edge is certified
// (Schwarzer, Saha & Latombe 2005) before the search moves along it.
#include "grid.h"
#include "plan_context.h"

#include <absl/container/flat_hash_map.h>

#include <cstdint>
#include <optional>
#include <vector>

namespace swept::detail {

/// What the search knows about a grid node.
struct NodeInfo {
  bool free = false;      ///< the distance bound exceeds the margin
  double distance = 0.0;  ///< lower bound on the distance at the node
  bool queried = true;    ///< from a distance query (else inherited from a neighbour's bound)
};

/// An edge between two nodes (or a node and kGoalKey), the smaller key first.
struct GridEdge {
  GridKey a, b;
  bool operator==(const GridEdge&) const = default;
};
struct GridEdgeHash {
  std::size_t operator()(const GridEdge& e) const { return GridKeyHash{}(e.a) * 31u ^ GridKeyHash{}(e.b); }
};

/// How a grid search ended without a path.
enum class GridOutcome {
  found,
  time_limit,   ///< the time limit was reached
  budget,       ///< PlanOptions::max_queries was reached
  exhausted,    ///< every level ran out of nodes inside the bounds and rotation limits
  resolution,   ///< some level stopped at its budget, and the finest level found no path
};

/// The search over the levels of one grid. Node and edge knowledge (the open-addressing tables:
/// millions of entries on a long search, looked up at every expansion and freed in one piece)
/// carries from level to level.
class LazyGridSearch {
 public:
  LazyGridSearch(PlanContext& context, const Grid& grid, const Pose& start, double start_distance);

  /// Lazy weighted A* (weight 2) on one level, with a budget of expansions. Returns the keys of
  /// the path (start {0,…} first; the last kGoalKey for a goal pose); `exhausted` is set when
  /// the open list ran empty.
  std::optional<std::vector<GridKey>> search_level(int level, std::size_t budget, bool& exhausted);

  /// Every level from the coarsest: coarse levels get 4000·2^level expansions, so that a level
  /// too coarse for a narrow passage does not eat the time limit; the finest runs to the time
  /// limit. With a `total_budget`, the finest level too stops at its budget, and the search
  /// stops (outcome `resolution`) once the levels that stopped at their budget (not those whose
  /// open list ran empty) have taken `total_budget` expansions. The path's poses (the last is
  /// the goal pose, or a pose in the goal region).
  std::optional<std::vector<Pose>> run(GridOutcome& outcome, std::size_t total_budget = SIZE_MAX);

  /// Expansions of every level so far.
  std::size_t expansions() const { return expansions_; }

  /// Lower bound of the metric distance from `pose` to the goal (pose, or leaving the goal box).
  double heuristic(const Pose& pose) const;

  int level_reached() const { return level_reached_; }
  /// While on (the default), an expansion that queries its node also queries the next entry's
  /// node when that one is unknown too, on the other core. Off only to test that it changes no
  /// decision.
  void set_query_ahead(bool on) { query_ahead_ = on; }
  std::size_t nodes_known() const { return nodes_.size(); }

 private:
  void report_progress(int level);

  PlanContext& context_;
  const Grid& grid_;
  Pose start_;
  absl::flat_hash_map<GridKey, NodeInfo, GridKeyHash> nodes_;
  absl::flat_hash_map<GridEdge, bool, GridEdgeHash> edges_;  ///< certified clear?
  int level_reached_ = 0;
  std::size_t expansions_ = 0;
  bool query_ahead_ = true;
  double last_progress_s_ = -1.0;
};

}  // namespace swept::detail
