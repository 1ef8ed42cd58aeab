#pragma once
// Phase 3 of the search (internal to src/plan): trees grown from both ends toward a
// deterministic low-dispersion sequence, for what the grid does not solve within its budget —
// detours round walls, traps, coordinated twists.
//
// Trees grow from the search start and from the goal pose (for a goal region, from free samples
// in it) in the manner of RRT-Connect (Kuffner & LaValle 2000): each sample extends one tree,
// and the other tree then reaches for the new node. The samples are a Halton sequence, not
// random numbers (Janson, Ichter & Pavone 2018: deterministic low-dispersion sampling keeps the
// guarantees of random sampling). Each step uses what an exact distance gives: a node's
// distance bound D is a free ball of radius D − margin in the motion metric (Quinlan's bubbles),
// so a step inside it is certified without a query, and longer steps are certified by the
// adaptive certificate (Schwarzer, Saha & Latombe 2005). A step whose end is blocked is retried
// once, shorter, toward the last free part of the motion; the growing tree then slides along the
// obstacles, while the other tree reaches straight until blocked.
//
// Determinism on every core: samples are drawn in rounds of a fixed count; every extension of
// a round is computed from the trees as they stood at the start of the round, in parallel, and
// the results are added in sample order, so the trees are the same at any thread count.
#include "nearest_index.h"
#include "plan_context.h"

#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

namespace swept::detail {

/// The Halton sequence in up to 6 dimensions (bases 2, 3, 5, 7, 11, 13), from index 1.
class Halton {
 public:
  /// The point of index `i` (≥ 1), each coordinate in [0, 1).
  static std::array<double, 6> point(std::uint64_t i);
};

/// The k-th (mod 24) of the rotations that map the coordinate axes onto themselves.
Mat3 lattice_rotation(std::uint64_t k);

/// A node of a search tree.
struct TreeNode {
  Pose pose;
  Vec3 point = Vec3::Zero();   ///< the reference point (world)
  Quat rotation = Quat::Identity();  ///< of pose.rotation
  double distance = 0.0;       ///< lower bound on the distance at `pose`
  std::int32_t parent = -1;    ///< in the same tree; −1 for the root
  /// The motion from the parent is certified (inside the parent's free ball, or checked). Edges
  /// past the free ball are certified lazily, only when they lie on a path that joins the ends
  /// (SBL, Sánchez & Latombe 2001).
  bool certified = true;
  bool dead = false;           ///< its edge, or an ancestor's, failed its certificate: ignored
  /// The closest points (world) of the obstacles and the body when `distance` is exact: the
  /// node's own query found them, and a slide from the node starts from them.
  bool near_known = false;
  Vec3 near_obstacle = Vec3::Zero();
  Vec3 near_body = Vec3::Zero();
  /// The witness pair of the node's own query (DistanceResult::hint): the steps from the node
  /// try it first.
  DistanceHint hint{};
};

/// How the tree phase ended without a path.
enum class TreeOutcome { found, time_limit, budget, round_limit, cancelled };

class TreeSearch {
 public:
  /// Trees from `start` (its distance bound `start_distance`) and from the goal pose
  /// (`goal_distance`); for a goal region, from the first 16 free samples in the region.
  TreeSearch(PlanContext& context, const Pose& start, double start_distance, double goal_distance);

  /// Grows the trees, `kRound` samples a round, until they meet, a node of the start's tree
  /// reaches the goal region, the time is up, or `max_rounds` rounds have run. The path's poses, start
  /// first, goal pose (or a pose in the goal region) last.
  std::optional<std::vector<Pose>> run(TreeOutcome& outcome, std::uint64_t max_rounds = UINT64_MAX);

  /// Once `*cancel` is set, run() stops (outcome `cancelled`): another phase has decided the
  /// plan. Checked before each round, at each step, and by every certificate of a join (its
  /// lazy edges and its bridges), so the trees stop within a query or two.
  void set_cancel(const std::atomic<bool>* cancel) { cancel_ = cancel; }
  /// Called as each join begins, before its certificates (tests: to raise the cancel flag there).
  void set_on_join(std::function<void()> on_join) { on_join_ = std::move(on_join); }

  /// Samples per round: fixed, so that the trees do not depend on the number of threads.
  static constexpr int kRound = 8;
  /// The bridges tried round a failed edge (i, i+1), in order: from waypoint i − back to
  /// waypoint i + ahead.
  static constexpr std::array<std::pair<std::size_t, std::size_t>, 8> kBridges{
      {{1, 1}, {0, 2}, {1, 2}, {2, 1}, {0, 3}, {2, 2}, {1, 3}, {3, 1}}};
  /// A bridge that needs more bisection queries than this grazes the margin: not taken.
  static constexpr int kBridgeQueries = 256;
  /// Joins with an edge no bridge clears, after which no more bridges are tried: where joins
  /// keep failing, their edges cross whole walls (the cubicles, the spiral tube), and the tries
  /// only cost (the spiral tube: 6 % more queries and 26 % more time with no limit).
  static constexpr int kBridgeMisses = 4;

  std::size_t nodes() const { return trees_[0].size() + trees_[1].size(); }
  std::uint64_t samples() const { return sample_index_; }
  /// Edges certified when a path joined the ends, and those cut (their certificate failed).
  std::uint64_t lazy_certified() const { return lazy_certified_; }
  std::uint64_t lazy_cut() const { return lazy_cut_; }
  /// Bridges round failed edges taken, and tried.
  std::uint64_t bridges() const { return bridges_; }
  std::uint64_t bridges_tried() const { return bridges_tried_; }
  /// Joins that had an edge no bridge cleared (no more bridges after kBridgeMisses of them).
  int bridge_misses() const { return bridge_misses_; }

  /// The configuration of sample `i` (≥ 1), from the Halton point of index i shifted by the
  /// problem's seed (Problem::seed): the reference point uniform in the bounds, the
  /// rotation uniform over SO(3) (Shoemake's map) — except every fourth sample, whose rotation
  /// is a quarter-turn lattice orientation (`lattice_rotation`) of the start's or the goal's
  /// rotation, so that parts and passages aligned with each other meet aligned — uniform in the
  /// rotation limits about the start's rotation, or the start's rotation when the problem fixes
  /// it.
  Pose sample(std::uint64_t i) const;

  /// The nearest node is by the motion metric with its rotation's part weighted by this: by
  /// r/2, about the mean displacement of the body's points in a turn, not r, its farthest
  /// point's, so that the trees extend from nearby places more than from nearby orientations.
  /// Chosen over 1, 0.7 and 0.35 by medians over seeds (docs/lab/planner-history.md).
  static constexpr double kNearestTurnWeight = 0.5;
  /// Index of the node of `tree` nearest to `pose` in the motion metric, the rotation's part
  /// weighted by kNearestTurnWeight (ties: the lowest index).
  std::int32_t nearest(const std::vector<TreeNode>& tree, const Pose& pose) const;

 private:
  /// nearest() over trees_[tree], by its index (the same answer).
  std::int32_t nearest(int tree, const Pose& pose) const;
  /// Appends `node` to trees_[tree], and to its index.
  void add_node(int tree, const TreeNode& node);
  struct Step;
  struct Attempt;
  TreeNode make_node(const Pose& pose, double distance, std::int32_t parent) const;
  /// A node at a free pose measured by `d` (Checker::measure), with its closest points if exact.
  TreeNode make_node(const Pose& pose, const DistanceResult& d) const;
  /// One step from `from` toward `target`: the new node (parent unset), or nullopt when even the
  /// shortest step is blocked. `reached` is set when the node is `target` itself.
  std::optional<TreeNode> step_toward(const TreeNode& from, const Pose& target, bool& reached, Suspects& suspects) const;
  /// Extends from `from` (index `parent`) toward `target`: one step, or after a blocked step
  /// up to `slides` slides along the obstacles (retraction: the motion's component into the
  /// nearest obstacle taken out). Appends the new nodes to `chain` (parents encoded as in
  /// Attempt); false when none. `reached`: the target itself was reached (or `from` is at it).
  bool extend(const TreeNode& from, std::int32_t parent, const Pose& target, std::vector<TreeNode>& chain,
              bool& reached, std::size_t& edges, Suspects& suspects, int slides) const;
  /// One slide from `from` toward `target` along the nearest obstacle, certified.
  std::optional<TreeNode> slide(const TreeNode& from, const Pose& target, Suspects& suspects) const;
  /// Grows tree `grow` toward sample `index` (`target`), and the other tree toward what grew.
  Attempt attempt(int grow, const Pose& target, std::uint64_t index) const;
  /// The turn in place of tree `grow`'s root to lattice orientation `orientation`
  /// (`lattice_rotation`) of its rotation, step after step, as far as it is free: the first leg
  /// of the six seeds of that orientation, computed once for all six.
  struct Turn {
    std::vector<TreeNode> nodes;  ///< parents encoded as in Attempt (the first one's: the root)
    std::size_t edges = 0;        ///< motions certified
    bool done = false;            ///< the turn reached the orientation
    Mat3 rotation = Mat3::Identity();  ///< the orientation
  };
  Turn turn(int grow, int orientation) const;
  /// A seed of tree `grow`: from its root, the `turn` in place, then a pull along world axis
  /// `axis` (+x, −x, +y, −y, +z, −z) toward the bounds, as far as it is free.
  Attempt seed_attempt(int grow, const Turn& turn, int axis) const;
  /// Steps from `at` (index `parent`, encoded as in Attempt) toward `leg` along its line, no
  /// slides, appending the nodes to `chain`; true when the leg's end is reached.
  bool leg(TreeNode at, std::int32_t parent, const Pose& leg, std::vector<TreeNode>& chain, std::size_t& edges,
           Suspects& suspects) const;
  /// The other tree reaches for the last node `out` grew, step after step (at most `max_steps`),
  /// without slides: until it gets there or a step is blocked.
  void reach_for(int grow, Attempt& out, int max_steps, Suspects& suspects) const;
  /// Seeds per tree with a root of its own: 24 orientations × 6 axes.
  static constexpr std::uint64_t kSeeds = 144;
  /// Where a lattice move from `from` toward `target` aims: the same reference point turned to
  /// the target's rotation (`turn`), or the same rotation moved along the one world axis of the
  /// largest displacement toward the target. Aligned parts pass aligned passages so.
  Pose lattice_move(const TreeNode& from, const Pose& target, bool turn) const;
  /// Appends an attempt's chain to `tree`; the index of its last node.
  std::int32_t append(int tree, const std::vector<TreeNode>& chain);
  bool inside(const Pose& pose) const;
  /// Out of time, or cancelled: a step loop stops (the round's results are then not used,
  /// or the search is over).
  bool stopped() const { return context_.out_of_time() || (cancel_ && cancel_->load(std::memory_order_relaxed)); }
  /// A waypoint of the path through two trees' nodes, and the node whose `certified` flag is the
  /// motion from it to the next waypoint (none: the last waypoint, or where the trees meet).
  struct Waypoint {
    const TreeNode* node = nullptr;
    const TreeNode* edge = nullptr;
  };
  /// The path through node_a of tree_a and node_b of tree_b (node_b −1: none), start first.
  std::vector<Waypoint> waypoints(int tree_a, std::int32_t node_a, int tree_b, std::int32_t node_b) const;
  std::vector<Pose> path_through(int tree_a, std::int32_t node_a, int tree_b, std::int32_t node_b) const;
  /// Certifies the uncertified edges of the path through node_a of tree_a and node_b of tree_b
  /// (node_b −1: none), in parallel; edges that fail are cut (their nodes and the subtrees below
  /// them die). True when every edge of the path is certified.
  bool certify_path(int tree_a, std::int32_t node_a, int tree_b, std::int32_t node_b);
  /// The path through node_a of tree_a and node_b of tree_b (as certify_path), start first, once
  /// every motion of it is certified: its lazy edges by certify_path, and each edge that fails
  /// (cut all the same) bridged by a certified motion between the waypoints around it, until
  /// kBridgeMisses joins have had an edge without one. Nullopt when an edge that failed has no
  /// bridge.
  std::optional<std::vector<Pose>> join(int tree_a, std::int32_t node_a, int tree_b, std::int32_t node_b);
  /// The index of the first of `bridges` (back, ahead) round the failed motion (i, i+1) of
  /// `way` that is certified, or bridges.size() when none is; `stopped` when the time limit, the
  /// query budget or the cancel flag (set_cancel) cut the tries short. Tried on every core in order: the answer is the serial
  /// loop's at any thread count.
  std::size_t first_bridge(const std::vector<Waypoint>& way, std::size_t i,
                           const std::vector<std::pair<std::size_t, std::size_t>>& bridges, bool& stopped);
  /// Marks dead the nodes of `tree` from index `first` on whose parent is dead.
  void propagate_dead(std::vector<TreeNode>& tree, std::size_t first);
  static bool alive_path(const std::vector<TreeNode>& tree, std::int32_t node);

  PlanContext& context_;
  bool region_ = false;  ///< the goal is a region: the goal tree's roots are samples in it
  Mat3 start_rotation_ = Mat3::Identity();   ///< the problem's (rotation limits are about it)
  Mat3 goal_rotation_ = Mat3::Identity();    ///< the goal pose's (else the search start's)
  Vec3 start_rotation_vector_ = Vec3::Zero(); ///< of the search start relative to it
  std::array<double, 6> shift_{};  ///< the seed's offset of every sample (Problem::seed)
  double step_ = 1.0;       ///< longest step beyond a node's free ball
  double min_step_ = 1e-3;  ///< shortest step tried
  std::array<std::vector<TreeNode>, 2> trees_;
  double nearest_radius_;  ///< kNearestTurnWeight × the search space's radius
  std::array<NearestIndex, 2> index_;  ///< of trees_[t]'s points and rotations
  std::uint64_t sample_index_ = 0;
  std::array<std::uint64_t, 2> seed_index_{};  ///< seeds done, per tree
  std::array<std::array<std::optional<Turn>, 24>, 2> turns_;  ///< per tree and orientation, once computed
  std::uint64_t lazy_certified_ = 0, lazy_cut_ = 0, bridges_ = 0, bridges_tried_ = 0;
  int bridge_misses_ = 0;  ///< joins with an edge that no bridge cleared
  const std::atomic<bool>* cancel_ = nullptr;
  std::function<void()> on_join_;
};

}  // namespace swept::detail
