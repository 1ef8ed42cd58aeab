// Phase 3: trees from both ends toward a Halton sequence (tree_search.h).
#include "tree_search.h"

#include "rotation_vector.h"
#include "swept/geometry/assert.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <numbers>

namespace swept::detail {
namespace {

double radical_inverse(std::uint64_t i, std::uint64_t base) {
  double inverse = 1.0 / static_cast<double>(base), scale = inverse, out = 0.0;
  for (; i > 0; i /= base, scale *= inverse) out += static_cast<double>(i % base) * scale;
  return out;
}


// Coordinate `d` of seed `seed`'s offset, in [0, 1): SplitMix64 (Steele, Lea & Flood 2014) of
// the pair, its top 53 bits.
double seed_offset(std::uint64_t seed, std::size_t d) {
  std::uint64_t z = seed * 6 + d + 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * 0x1.0p-53;
}

// Rounds in which the other tree reaches for a new node take at most this many steps.
constexpr int kConnectSteps = 64;
// A new node's distance is measured exactly only up to the margin + this share of the step: it
// serves as the end bound of its edges' certificates, where a larger one saves little (the same
// paths on the suite and the scenes at 1, 0.25 and 0.1; 0.1 against 1: house, cubicles, bug trap,
// twisty slot and tunnel console 3-17 % less search time, 0-1.3 % more queries). 0.03 against
// 0.1, instructions of a whole one-thread plan: house -5 %, cubicles -1 %, the rest within 1 %;
// the same paths, but for the tunnel console's and the cylinder head's, whose waypoints moved by
// rounding (lengths equal to 13 digits). docs/lab/bench-plan-history.md.
constexpr double kNodeReach = 0.03;
// A lazy step (past its start's free ball) is taken when its end is free and so are these points
// of its interior: its middle, and on a step longer than kLazyLong of the longest, its quarters
// too (each only where neither end's free ball holds it). One point lets the trees join through
// thin walls, whose lazy edges then fail when a path needs them. Over seeds 0-39 on both sides
// (bench_plan --swept-seeds, two threads), swept's median: house 23.3 -> 17.9 ms, cubicles
// 36.1 -> 26.9 ms (2.66x -> 3.56x RRTConnect's); three points on every step: 17.4 and 29.0 in
// a scratch run. docs/lab/bench-plan-history.md, "A long lazy step's quarters checked".
constexpr std::array<double, 3> kLazyPoints{0.5, 0.25, 0.75};
constexpr double kLazyLong = 0.75;

// The longest step beyond a node's free ball, as a share of the bounds' diagonal; the tries of a
// step (the first, then halved toward its start); slides along the obstacles after a blocked step
// of the growing tree; the other tree reaches for the new node straight until blocked, without
// slides (RRTConnect's connect). Chosen together against 0.1, 6, 8 and 8 (each alone had moved
// little): together they halve the time or better on OMPL.app's cubicles, Home and Twistycool,
// the suite's cubicles and two of the CAD scenes, and slow no problem of the suite
// (docs/lab/bench-plan-history.md, "Fewer tries per step").
constexpr double kStepShare = 0.2;
constexpr int kStepTries = 2;
constexpr int kSlides = 2;
constexpr int kReachSlides = 0;
// Roots of a goal region's tree.
constexpr std::size_t kGoalRoots = 16;

}  // namespace

Mat3 lattice_rotation(std::uint64_t k) {
  // The 24 rotations that map the axes onto the axes: a signed permutation of determinant +1.
  static const std::array<Mat3, 24> kCube = [] {
    std::array<Mat3, 24> out;
    const std::array<std::array<int, 3>, 6> perms{{{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}}};
    std::size_t n = 0;
    for (std::size_t p = 0; p < perms.size(); ++p)
      for (int signs = 0; signs < 8; ++signs) {
        Mat3 m = Mat3::Zero();
        for (int row = 0; row < 3; ++row) m(row, perms[p][row]) = (signs >> row) & 1 ? -1.0 : 1.0;
        if (m.determinant() > 0) out[n++] = m;
      }
    return out;
  }();
  return kCube[k % 24];
}

std::array<double, 6> Halton::point(std::uint64_t i) {
  static constexpr std::array<std::uint64_t, 6> kBases{2, 3, 5, 7, 11, 13};
  std::array<double, 6> out{};
  for (std::size_t d = 0; d < kBases.size(); ++d) out[d] = radical_inverse(i, kBases[d]);
  return out;
}

// What one sample did, computed from the trees as they stood at the start of its round.
struct TreeSearch::Attempt {
  /// New nodes of the growing tree and the other tree's steps toward the last of them. In each
  /// chain the first node's parent is a node of the trees as they stood at the round's start,
  /// and a parent −2 − k is the chain's own node k.
  std::vector<TreeNode> grown;
  std::vector<TreeNode> chain;
  bool connected = false;         ///< the chain reached the new node, or the new node is in the goal region
  std::int32_t meet = -1;         ///< connected with an empty chain: the other tree's node at the new node
  std::optional<TreeNode> root;   ///< a goal region's sample, free: a new root of the goal tree
  bool in_region = false;         ///< a new node of the start's tree is in the goal region
  std::size_t edges = 0;          ///< motions certified
};

TreeSearch::TreeSearch(PlanContext& context, const Pose& start, double start_distance, double goal_distance)
    : context_(context),
      nearest_radius_(kNearestTurnWeight * context.space.radius),
      index_{NearestIndex(nearest_radius_), NearestIndex(nearest_radius_)} {
  const Problem& problem = context.problem;
  const SearchSpace& space = context.space;
  region_ = problem.goal_outside || !problem.goal;
  start_rotation_ = problem.start.rotation;
  goal_rotation_ = problem.goal ? problem.goal->rotation : start.rotation;
  start_rotation_vector_ = rotation_vector(start.rotation * problem.start.rotation.transpose());
  if (problem.seed != 0)
    for (std::size_t d = 0; d < shift_.size(); ++d) shift_[d] = seed_offset(problem.seed, d);
  const double size = context.scene_size();
  step_ = kStepShare * (space.bounds.max - space.bounds.min).norm();
  min_step_ = std::max(context.check.margin(), 1e-3 * size);
  step_ = std::max(step_, 2 * min_step_);
  add_node(0, make_node(start, start_distance, -1));
  if (!region_) add_node(1, make_node(*problem.goal, goal_distance, -1));
}

TreeNode TreeSearch::make_node(const Pose& pose, double distance, std::int32_t parent) const {
  return {pose, context_.reference_at(pose), pose.quaternion(), distance, parent};
}

TreeNode TreeSearch::make_node(const Pose& pose, const DistanceResult& d) const {
  TreeNode node = make_node(pose, d.distance, -1);
  node.hint = d.hint;
  if (d.exact) {
    node.near_known = true;
    node.near_obstacle = d.point_a;
    node.near_body = d.point_b;
  }
  return node;
}

Pose TreeSearch::sample(std::uint64_t i) const {
  std::array<double, 6> u = Halton::point(i);
  for (std::size_t d = 0; d < u.size(); ++d)
    if (shift_[d] > 0.0 && (u[d] += shift_[d]) >= 1.0) u[d] -= 1.0;
  const Aabb& bounds = context_.space.bounds;
  const Vec3 point = bounds.min + Vec3(u[0], u[1], u[2]).cwiseProduct(bounds.max - bounds.min);
  Mat3 rotation = trees_[0].front().pose.rotation;
  switch (context_.space.rotation) {
    case RotationMode::none: break;
    case RotationMode::free: {
      if (i % 4 == 3) {  // every fourth sample: a quarter-turn lattice orientation
        // Lattice samples alternate a move and a turn (i / 4 % 2): each turn sees all 24 of the
        // start's orientations, then all 24 of the goal's.
        const std::uint64_t k = i / 8;
        rotation = lattice_rotation(k) * ((k / 24) % 2 == 0 ? start_rotation_ : goal_rotation_);
        break;
      }
      const double a = std::sqrt(1.0 - u[3]), b = std::sqrt(u[3]);
      const double s = 2 * std::numbers::pi * u[4], t = 2 * std::numbers::pi * u[5];
      rotation = Quat(b * std::cos(t), a * std::sin(s), a * std::cos(s), b * std::sin(t)).normalized().toRotationMatrix();
      break;
    }
    case RotationMode::limits: {
      const auto& limits = context_.space.rotation_limits;
      Vec3 w;
      for (int k = 0; k < 3; ++k) w[k] = limits[k][0] + u[3 + k] * (limits[k][1] - limits[k][0]);
      rotation = exp_rotation(w) * start_rotation_;
      break;
    }
  }
  return context_.pose_with_reference_at(rotation, point);
}

Pose TreeSearch::lattice_move(const TreeNode& from, const Pose& target, bool turn) const {
  if (turn && context_.space.rotation != RotationMode::none) return context_.pose_with_reference_at(target.rotation, from.point);
  const Vec3 d = context_.reference_at(target) - from.point;
  int axis = 0;
  d.cwiseAbs().maxCoeff(&axis);
  Vec3 p = from.point;
  p[axis] += d[axis];
  return context_.pose_with_reference_at(from.pose.rotation, p);
}

bool TreeSearch::inside(const Pose& pose) const {
  const SearchSpace& space = context_.space;
  if (!in_bounds(space, context_.reference_at(pose))) return false;
  if (space.rotation != RotationMode::limits) return true;
  const Vec3 w = rotation_vector(pose.rotation * start_rotation_.transpose());
  for (int k = 0; k < 3; ++k)
    if (w[k] < space.rotation_limits[k][0] || w[k] > space.rotation_limits[k][1]) return false;
  return true;
}

std::int32_t TreeSearch::nearest(const std::vector<TreeNode>& tree, const Pose& pose) const {
  // Every node in order (the index answers the same: nearest_index.h).
  const Vec3 point = context_.reference_at(pose);
  const Quat q = pose.quaternion();
  std::int32_t best = -1;
  double best_length = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < tree.size(); ++i) {
    if (tree[i].dead) continue;
    const double length = motion_metric(point, q, tree[i].point, tree[i].rotation, nearest_radius_);
    if (length < best_length) {
      best_length = length;
      best = static_cast<std::int32_t>(i);
    }
  }
  return best;
}

std::int32_t TreeSearch::nearest(int tree, const Pose& pose) const {
  const std::vector<TreeNode>& nodes = trees_[tree];
  return index_[tree].nearest(context_.reference_at(pose), pose.quaternion(), [&](std::size_t i) { return !nodes[i].dead; });
}

void TreeSearch::add_node(int tree, const TreeNode& node) {
  trees_[tree].push_back(node);
  index_[tree].add(node.point, node.rotation);
}

std::optional<TreeNode> TreeSearch::step_toward(const TreeNode& from, const Pose& target, bool& reached,
                                                Suspects& suspects) const {
  reached = false;
  const Checker& check = context_.check;
  const double margin = check.margin();
  const Motion motion = check.motion(from.pose, target);
  const double length = motion.length();
  if (length <= 0.0) {
    reached = true;
    return std::nullopt;
  }
  const double bubble = 0.9 * (from.distance - margin);  // certified without a query
  double s = std::min(length, std::max(step_, bubble));
  // The pairs found closest or blocking at the node and at the poses this attempt tried
  // before are tried first.
  suspects.add(from.hint);
  for (int attempt = 0; attempt < kStepTries && s > 0.0; ++attempt) {
    const bool whole = s >= length;
    const Pose q = whole ? target : motion.at(s / length);
    if (inside(q)) {
      const DistanceResult mq = check.measure(q, margin + kNodeReach * step_, &suspects);
      const double dq = mq.distance;
      if (dq > margin && s > bubble) {
        // Past the free ball: the edge is certified later, if a path uses it. Points of its
        // interior are checked now (a step across a thin wall has free ends), the middle first,
        // unless either end's free ball holds them (the distance at f·s is at least
        // D(from) − f·s and D(end) − (1 − f)·s).
        const std::size_t points = s > kLazyLong * step_ ? kLazyPoints.size() : 1;
        bool interior_free = true;
        for (std::size_t k = 0; k < points && interior_free; ++k) {
          const double f = kLazyPoints[k];
          const bool held = f * s < from.distance - margin || (1.0 - f) * s < dq - margin;
          interior_free = held || check.free(motion.at(f * s / length));
        }
        if (interior_free) {
          reached = whole;
          TreeNode node = make_node(q, mq);
          node.certified = false;
          return node;
        }
        s *= 0.5;
      } else if (dq > margin) {
        const Certificate c = check.certify(from.pose, from.distance, q, dq);
        if (c.clear()) {
          reached = whole;
          return make_node(q, mq);
        }
        if (c.status != MotionStatus::blocked) return std::nullopt;  // deadline or cap
        s *= std::max(0.05, 0.5 * c.t_blocked);
      } else {
        s *= 0.5;
      }
    } else {
      s *= 0.5;
    }
    if (s < min_step_) {
      if (bubble <= min_step_) return std::nullopt;
      s = bubble;  // the free ball's step is certain
    }
  }
  return std::nullopt;
}

bool TreeSearch::extend(const TreeNode& from, std::int32_t parent, const Pose& target, std::vector<TreeNode>& chain,
                        bool& reached, std::size_t& edges, Suspects& suspects, int slides) const {
  std::optional<TreeNode> next = step_toward(from, target, reached, suspects);
  if (next) {
    edges += next->certified;
    next->parent = parent;
    chain.push_back(*next);
    return true;
  }
  if (reached) return false;
  // Blocked: slide along the obstacles toward the target (retraction, Zhang & Manocha 2008).
  const std::size_t before = chain.size();
  TreeNode at = from;
  for (int k = 0; k < slides && !stopped(); ++k) {
    std::optional<TreeNode> slid = slide(at, target, suspects);
    if (!slid) break;
    edges += slid->certified;
    slid->parent = parent;
    parent = -2 - static_cast<std::int32_t>(chain.size());
    chain.push_back(*slid);
    at = *slid;
    // Free again toward the target?
    if (std::optional<TreeNode> direct = step_toward(at, target, reached, suspects)) {
      edges += direct->certified;
      direct->parent = parent;
      chain.push_back(*direct);
      return true;
    }
    if (reached) return true;
  }
  return chain.size() > before;
}

std::optional<TreeNode> TreeSearch::slide(const TreeNode& from, const Pose& target, Suspects& suspects) const {
  const Checker& check = context_.check;
  const double margin = check.margin();
  // The closest points: the node's own query's when it was exact, else a query exact up to a step.
  Vec3 obstacle = from.near_obstacle, body = from.near_body;
  if (!from.near_known) {
    const DistanceResult w = check.nearest(from.pose, margin + step_);
    if (!w.exact) return std::nullopt;
    obstacle = w.point_a;
    body = w.point_b;
  }
  Vec3 n = body - obstacle;  // from the obstacle toward the body
  if (!(n.norm() > 0.0)) return std::nullopt;
  n.normalize();
  const double radius = context_.space.radius;
  const Vec3 r = body - from.point;
  // The motion toward the target as (Δc, r_max·ω); the body's witness point moves by
  // Δc + ω × r, whose component along −n closes the gap: project it out.
  Eigen::Matrix<double, 6, 1> u, j;
  u << context_.reference_at(target) - from.point, radius * rotation_vector(target.rotation * from.pose.rotation.transpose());
  if (context_.space.rotation == RotationMode::none) u.tail<3>().setZero();
  j << n, (context_.space.rotation == RotationMode::none ? Vec3::Zero() : Vec3(r.cross(n) / radius));
  const double closing = j.dot(u);
  if (closing < 0.0) u -= closing / j.squaredNorm() * j;
  double length = u.head<3>().norm() + u.tail<3>().norm();
  if (!(length > 0.0)) return std::nullopt;
  double s = std::min(length, std::max(0.25 * step_, 0.9 * (from.distance - margin)));
  suspects.add(from.hint);  // as in step_toward
  for (int attempt = 0; attempt < 4 && s >= min_step_; ++attempt, s *= 0.5) {
    const double f = s / length;
    Vec3 move = f * u.head<3>() + 0.1 * s * n;  // and a little away from the obstacle
    const Mat3 rotation = exp_rotation(f * u.tail<3>() / radius) * from.pose.rotation;
    const Pose q = context_.pose_with_reference_at(rotation, from.point + move);
    if (!inside(q)) continue;
    const DistanceResult mq = check.measure(q, margin + kNodeReach * step_, &suspects);
    const double dq = mq.distance;
    if (dq <= margin) continue;
    if (s > 0.9 * (from.distance - margin)) {  // past the free ball: certified lazily
      TreeNode node = make_node(q, mq);
      node.certified = false;
      return node;
    }
    if (check.certify(from.pose, from.distance, q, dq).clear()) return make_node(q, mq);
  }
  return std::nullopt;
}

TreeSearch::Attempt TreeSearch::attempt(int grow, const Pose& target, std::uint64_t index) const {
  Attempt out;
  // A goal region's tree grows from free samples in the region, the first kGoalRoots of them.
  if (region_ && trees_[1].size() < kGoalRoots && goal_reached(context_.space, context_.problem, target)) {
    const double d = context_.check.clearance(target, context_.check.margin() + step_);
    if (d > context_.check.margin()) out.root = make_node(target, d, -1);
  }
  if (trees_[grow].empty()) return out;
  const std::vector<TreeNode>& mine = trees_[grow];
  const std::int32_t from = nearest(grow, target);
  bool reached = false;
  // Every fourth sample moves along one axis or turns in place (`lattice_move`).
  const Pose aim = index % 4 == 3 ? lattice_move(mine[from], target, index / 4 % 2 == 1) : target;
  Suspects suspects;  // this attempt's
  if (!extend(mine[from], from, aim, out.grown, reached, out.edges, suspects, kSlides)) return out;
  reach_for(grow, out, kConnectSteps, suspects);
  return out;
}

// Steps from `at` (index `parent`, encoded as in Attempt) toward `leg` along its line (no
// slides), appending the nodes to `chain`; true when the leg's end is reached.
bool TreeSearch::leg(TreeNode at, std::int32_t parent, const Pose& leg, std::vector<TreeNode>& chain,
                     std::size_t& edges, Suspects& suspects) const {
  for (int k = 0; k < kConnectSteps && !stopped(); ++k) {
    bool reached = false;
    std::optional<TreeNode> next = step_toward(at, leg, reached, suspects);
    if (!next) return reached;
    edges += next->certified;
    next->parent = parent;
    parent = -2 - static_cast<std::int32_t>(chain.size());
    chain.push_back(*next);
    at = *next;
    if (reached) return true;
  }
  return false;
}

TreeSearch::Turn TreeSearch::turn(int grow, int orientation) const {
  Turn out;
  const TreeNode& root = trees_[grow].front();
  const Pose turned = context_.pose_with_reference_at(lattice_rotation(static_cast<std::uint64_t>(orientation)) * root.pose.rotation, root.point);
  out.rotation = turned.rotation;
  Suspects suspects;
  out.done = leg(root, 0, turned, out.nodes, out.edges, suspects);
  return out;
}

TreeSearch::Attempt TreeSearch::seed_attempt(int grow, const Turn& turn, int axis) const {
  // From the root: the turn in place to a lattice orientation of the root's, then a pull along
  // a world axis toward the bounds, step after step (no slides: the move stays on its line).
  Attempt out;
  Suspects suspects;  // this seed's
  out.grown = turn.nodes;
  out.edges = turn.edges;
  if (turn.done) {  // else the turn stopped short: what grew stays
    const TreeNode& root = trees_[grow].front();
    const TreeNode& at = out.grown.empty() ? root : out.grown.back();
    Vec3 u = Vec3::Zero();
    u[axis / 2] = axis % 2 == 0 ? 1.0 : -1.0;
    const Aabb& bounds = context_.space.bounds;
    const double room = u[axis / 2] > 0 ? bounds.max[axis / 2] - root.point[axis / 2] : root.point[axis / 2] - bounds.min[axis / 2];
    const Pose pulled = context_.pose_with_reference_at(turn.rotation, root.point + room * u);
    const std::int32_t parent = out.grown.empty() ? 0 : -2 - static_cast<std::int32_t>(out.grown.size() - 1);
    leg(at, parent, pulled, out.grown, out.edges, suspects);
  }
  // The other tree does not reach for a seed: the seeds of both trees lie on the same few lines,
  // and the samples' reaching connects them (reaching for every seed cost the house and the
  // cubicles 2–3 times the search time).
  if (!out.grown.empty()) reach_for(grow, out, 0, suspects);
  return out;
}

void TreeSearch::reach_for(int grow, Attempt& out, int max_steps, Suspects& suspects) const {
  bool reached = false;
  const TreeNode& grown = out.grown.back();
  if (region_ && grow == 0) {
    for (const TreeNode& n : out.grown) out.in_region = out.in_region || goal_reached(context_.space, context_.problem, n.pose);
    if (out.in_region) return;
  }
  // The other tree reaches for the new node, step after step, until it gets there or is blocked.
  const std::vector<TreeNode>& other = trees_[1 - grow];
  if (other.empty()) return;
  std::int32_t parent = nearest(1 - grow, grown.pose);
  TreeNode at = other[parent];
  for (int k = 0; k < max_steps && !stopped(); ++k) {
    const std::size_t before = out.chain.size();
    const bool moved = extend(at, parent, grown.pose, out.chain, reached, out.edges, suspects, kReachSlides);
    if (reached) {
      out.connected = true;
      if (out.chain.empty()) out.meet = parent;  // the other tree's node is at the new node already
      break;
    }
    if (!moved || out.chain.size() == before) break;
    parent = -2 - static_cast<std::int32_t>(out.chain.size() - 1);
    at = out.chain.back();
  }
}

std::int32_t TreeSearch::append(int tree, const std::vector<TreeNode>& chain) {
  const auto base = static_cast<std::int32_t>(trees_[tree].size());
  for (TreeNode n : chain) {
    if (n.parent <= -2) n.parent = base + (-2 - n.parent);
    add_node(tree, n);
  }
  return static_cast<std::int32_t>(trees_[tree].size() - 1);
}

std::vector<TreeSearch::Waypoint> TreeSearch::waypoints(int tree_a, std::int32_t node_a, int tree_b, std::int32_t node_b) const {
  // Root of tree 0 (the start's) … its node, then the goal tree's node … its root. A node's
  // `certified` flag is that of its edge to its parent: in the start's tree the motion to it from
  // the waypoint before, in the goal's tree the motion from it to the next waypoint.
  auto up = [&](int tree, std::int32_t node) {
    std::vector<const TreeNode*> chain;
    for (std::int32_t i = node; i >= 0; i = trees_[tree][i].parent) chain.push_back(&trees_[tree][i]);
    return chain;
  };
  const std::vector<const TreeNode*> from_start = tree_a == 0 ? up(tree_a, node_a) : up(tree_b, node_b);
  std::vector<const TreeNode*> to_goal;
  if (node_b >= 0) to_goal = tree_a == 0 ? up(tree_b, node_b) : up(tree_a, node_a);
  std::vector<Waypoint> way;
  for (auto it = from_start.rbegin(); it != from_start.rend(); ++it) {
    if (!way.empty()) way.back().edge = *it;
    way.push_back({*it});
  }
  for (std::size_t k = 0; k < to_goal.size(); ++k) {
    const TreeNode* n = to_goal[k];
    // The two halves meet at the same pose: kept once (otherwise they differ by rounding only,
    // a motion of length 0 in the metric — reach_for's `reached` — with no edge of its own).
    const bool same = k == 0 && !way.empty() && way.back().node->pose.rotation == n->pose.rotation &&
                      way.back().node->pose.translation == n->pose.translation;
    if (!same) way.push_back({n});
    way.back().edge = n->parent >= 0 ? n : nullptr;  // the goal tree's root: no motion after it
  }
  return way;
}

std::vector<Pose> TreeSearch::path_through(int tree_a, std::int32_t node_a, int tree_b, std::int32_t node_b) const {
  std::vector<Pose> path;
  for (const Waypoint& w : waypoints(tree_a, node_a, tree_b, node_b)) path.push_back(w.node->pose);
  return path;
}

void TreeSearch::propagate_dead(std::vector<TreeNode>& tree, std::size_t first) {
  // A parent's index is below its children's: one pass in index order.
  for (std::size_t i = first; i < tree.size(); ++i)
    if (!tree[i].dead && tree[i].parent >= 0 && tree[tree[i].parent].dead) tree[i].dead = true;
}

bool TreeSearch::alive_path(const std::vector<TreeNode>& tree, std::int32_t node) {
  for (std::int32_t i = node; i >= 0; i = tree[i].parent)
    if (tree[i].dead) return false;
  return true;
}

bool TreeSearch::certify_path(int tree_a, std::int32_t node_a, int tree_b, std::int32_t node_b) {
  struct Edge {
    int tree;
    std::int32_t node;
    MotionStatus status = MotionStatus::refused_cap;
  };
  std::vector<Edge> edges;
  for (std::int32_t i = node_a; i >= 0 && trees_[tree_a][i].parent >= 0; i = trees_[tree_a][i].parent)
    if (!trees_[tree_a][i].certified) edges.push_back({tree_a, i});
  if (node_b >= 0)
    for (std::int32_t i = node_b; i >= 0 && trees_[tree_b][i].parent >= 0; i = trees_[tree_b][i].parent)
      if (!trees_[tree_b][i].certified) edges.push_back({tree_b, i});
  const Checker& check = context_.check;
  tbb::parallel_for(std::size_t{0}, edges.size(), [&](std::size_t k) {
    const std::vector<TreeNode>& tree = trees_[edges[k].tree];
    const TreeNode& child = tree[edges[k].node];
    const TreeNode& parent = tree[child.parent];
    edges[k].status = check.certify(parent.pose, parent.distance, child.pose, child.distance, kMaxCertificateQueries,
                                    Pieces::two_earliest, {cancel_, nullptr}).status;
  });
  bool all = true;
  for (const Edge& e : edges) {
    TreeNode& child = trees_[e.tree][e.node];
    ++context_.edges_checked;
    ++lazy_certified_;
    if (e.status == MotionStatus::clear) {
      child.certified = true;
    } else {
      all = false;
      // Not known: the time is up, or another phase has decided the plan; the search ends anyway.
      if (e.status == MotionStatus::deadline || e.status == MotionStatus::cancelled) continue;
      child.dead = true;  // blocked, or too close to certify: cut
      ++lazy_cut_;
    }
  }
  // The subtrees below the cut edges die with them.
  if (!all)
    for (auto& tree : trees_) propagate_dead(tree, 1);
  return all;
}

std::size_t TreeSearch::first_bridge(const std::vector<Waypoint>& way, std::size_t i,
                                     const std::vector<std::pair<std::size_t, std::size_t>>& bridges, bool& stopped) {
  // The candidates are handed out in order, one at a time, to as many workers as there are
  // cores; a worker takes no candidate past the first success known. Every candidate before the
  // first success is tried whatever the timing, so the bridge taken is the serial loop's: the
  // same at any thread count. Under a query budget the count must not depend on the timing:
  // one worker, which is that loop.
  // A candidate still being tried when an earlier one succeeds is cancelled: its answer is no
  // longer needed, and the join would otherwise wait for it.
  const std::size_t n = bridges.size();
  SWEPT_ASSERT(n <= kBridges.size(), "at most kBridges.size() bridges are tried round one motion");
  std::array<std::atomic<bool>, kBridges.size()> cancel{};
  std::atomic<std::size_t> next{0}, first{n};
  std::atomic<std::uint64_t> tried{0};
  std::atomic<bool> stop{false};  // the time is up, or the query budget spent
  auto worker = [&] {
    for (std::size_t k = next++; k < n && k < first.load() && !stop.load(); k = next++) {
      const auto [back, ahead] = bridges[k];
      const TreeNode& a = *way[i - back].node;
      const TreeNode& b = *way[i + ahead].node;
      ++tried;
      if (context_.certify(a.pose, a.distance, b.pose, b.distance, kBridgeQueries, {&cancel[k], cancel_},
                             Pieces::earliest_and_latest)) {
        for (std::size_t f = first.load(); k < f && !first.compare_exchange_weak(f, k);) {
        }
        for (std::size_t later = k + 1; later < n; ++later) cancel[later] = true;
      } else if (context_.out_of_time() || context_.over_budget() || (cancel_ && cancel_->load())) {
        stop = true;
      }
    }
  };
  const int workers = context_.options.max_queries ? 1 : std::min<int>(static_cast<int>(n), tbb::this_task_arena::max_concurrency());
  tbb::task_group group;
  for (int w = 1; w < workers; ++w) group.run(worker);
  worker();
  group.wait();
  bridges_tried_ += tried;
  context_.edges_checked += tried;
  stopped = stop;
  return first;
}

std::optional<std::vector<Pose>> TreeSearch::join(int tree_a, std::int32_t node_a, int tree_b, std::int32_t node_b) {
  if (on_join_) on_join_();
  if (certify_path(tree_a, node_a, tree_b, node_b)) return path_through(tree_a, node_a, tree_b, node_b);
  if (stopped() || context_.over_budget() || bridge_misses_ >= kBridgeMisses) return std::nullopt;
  const std::vector<Waypoint> way = waypoints(tree_a, node_a, tree_b, node_b);
  auto clear = [&](std::size_t i) { return way[i].edge == nullptr || way[i].edge->certified; };

  // Each failed motion (i, i+1) is bridged by the first certified motion in kBridges from a
  // waypoint a ≤ i to one b ≥ i + 1 (not before the end of the last bridge): the path then skips
  // the waypoints in between. The lazy edges a path crosses fail at a wall's corner, which a
  // motion from one waypoint further back or on usually clears.
  std::vector<std::size_t> kept{0};
  std::size_t floor = 0;
  std::size_t i = 0;
  while (i + 1 < way.size()) {
    if (clear(i)) {
      kept.push_back(++i);
      continue;
    }
    std::vector<std::pair<std::size_t, std::size_t>> bridges;
    for (const auto& [back, ahead] : kBridges)
      if (back <= i - floor && i + ahead < way.size()) bridges.emplace_back(back, ahead);
    bool stopped = false;
    const std::size_t first = first_bridge(way, i, bridges, stopped);
    if (first == bridges.size()) {
      if (!stopped) ++bridge_misses_;
      return std::nullopt;
    }
    const auto [back, ahead] = bridges[first];
    kept.resize(kept.size() - back);
    i += ahead;
    kept.push_back(i);
    floor = i;
    ++bridges_;
  }
  std::vector<Pose> path;
  path.reserve(kept.size());
  for (std::size_t k : kept) path.push_back(way[k].node->pose);
  return path;
}

std::optional<std::vector<Pose>> TreeSearch::run(TreeOutcome& outcome, std::uint64_t max_rounds) {
  std::vector<Attempt> attempts(kRound);
  std::vector<Pose> targets(kRound);
  double last_progress_s = -1.0;
  for (std::uint64_t round = 0; round < max_rounds; ++round) {
    if (context_.out_of_time()) {
      outcome = TreeOutcome::time_limit;
      return std::nullopt;
    }
    if (context_.over_budget()) {  // between rounds: the same count at any thread count
      outcome = TreeOutcome::budget;
      return std::nullopt;
    }
    if (cancel_ && cancel_->load()) {
      outcome = TreeOutcome::cancelled;
      return std::nullopt;
    }
    if (context_.options.progress && context_.elapsed_s() - last_progress_s >= 1.0) {
      last_progress_s = context_.elapsed_s();
      context_.report({kTreeLevel, nodes(), context_.check.distance_queries(), last_progress_s});
    }
    const int grow = trees_[1].empty() ? 0 : static_cast<int>(round % 2);
    // The first rounds are half seeds (turn and pull from a root), in a fixed order.
    const bool rooted = grow == 0 || !region_;  // a goal region's tree has many roots: no seeds
    const int seeds = rooted ? static_cast<int>(std::min<std::uint64_t>(kRound / 2, kSeeds - std::min(kSeeds, seed_index_[grow]))) : 0;
    const std::uint64_t first = sample_index_ + 1;
    for (int i = seeds; i < kRound; ++i) targets[i] = sample(++sample_index_);
    const std::uint64_t seed_first = seed_index_[grow];
    seed_index_[grow] += static_cast<std::uint64_t>(seeds);
    // Seed k turns to orientation k / 6 and pulls along axis k % 6: the turns this round's
    // seeds need and no earlier one made, first (each depends on the root alone).
    std::vector<int> new_turns;
    for (int i = 0; i < seeds; ++i) {
      const int o = static_cast<int>((seed_first + static_cast<std::uint64_t>(i)) / 6 % 24);
      if (!turns_[grow][o] && std::find(new_turns.begin(), new_turns.end(), o) == new_turns.end()) new_turns.push_back(o);
    }
    std::vector<Turn> made(new_turns.size());
    tbb::parallel_for(std::size_t{0}, new_turns.size(), [&](std::size_t j) { made[j] = turn(grow, new_turns[j]); });
    for (std::size_t j = 0; j < new_turns.size(); ++j) turns_[grow][new_turns[j]] = std::move(made[j]);
    tbb::parallel_for(0, kRound, [&](int i) {
      if (i < seeds) {
        const std::uint64_t k = seed_first + static_cast<std::uint64_t>(i);  // orientation, axis
        attempts[i] = seed_attempt(grow, *turns_[grow][k / 6 % 24], static_cast<int>(k % 6));
      } else {
        attempts[i] = attempt(grow, targets[i], first + static_cast<std::uint64_t>(i - seeds));
      }
    });
    if (cancel_ && cancel_->load()) {  // the round's attempts may have stopped short: not added
      outcome = TreeOutcome::cancelled;
      return std::nullopt;
    }
    // Added in sample order: the same trees at any thread count. A path that joins the ends
    // has its lazy edges certified here, in order; the edges that fail are cut.
    for (Attempt& a : attempts) {
      context_.edges_checked += a.edges;
      if (a.root && trees_[1].size() < kGoalRoots) add_node(1, *a.root);
      if (a.grown.empty()) continue;
      const std::size_t grown_first = trees_[grow].size();
      const std::int32_t grown = append(grow, a.grown);
      propagate_dead(trees_[grow], grown_first);  // a parent may have died earlier in this round
      if (a.in_region) {
        // The first of the new nodes in the goal region (each is the next one's parent) ends the path.
        std::int32_t end = grown - static_cast<std::int32_t>(a.grown.size()) + 1;
        while (!goal_reached(context_.space, context_.problem, trees_[0][end].pose)) ++end;
        if (alive_path(trees_[0], end)) {
          if (auto path = join(0, end, 0, -1)) {
            outcome = TreeOutcome::found;
            return path;
          }
        }
        if (stopped()) break;
        continue;
      }
      if (a.chain.empty() && !a.connected) continue;
      const std::size_t chain_first = trees_[1 - grow].size();
      const std::int32_t reach = a.chain.empty() ? a.meet : append(1 - grow, a.chain);
      propagate_dead(trees_[1 - grow], chain_first);
      if (a.connected && alive_path(trees_[grow], grown) && alive_path(trees_[1 - grow], reach)) {
        if (auto path = join(grow, grown, 1 - grow, reach)) {
          outcome = TreeOutcome::found;
          return path;
        }
        if (stopped()) break;
      }
    }
  }
  outcome = TreeOutcome::round_limit;
  return std::nullopt;
}

}  // namespace swept::detail
