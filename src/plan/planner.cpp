// The planner (SPEC §4): straight-line disassembly moves first, then lazy A* over a
// multi-resolution grid of SE(3) anchored at the start, every edge certified by distance bounds,
// then deterministic shortcut smoothing and a final certification of the whole path.
//
// Determinism: no randomness, no clocks or addresses in decisions, ordered containers where
// order matters; work done in parallel (batches of node and edge checks) is the same set of work
// at any thread count and its results are consumed in path order.
#include "swept/plan/planner.h"

#include "checker.h"
#include "swept/bvh/fitter.h"
#include "swept/plan/check.h"
#include "swept/geometry/distance.h"
#include "swept/query/query.h"

#include <absl/container/flat_hash_map.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <climits>
#include <cmath>
#include <memory>
#include <numbers>
#include <queue>
#include <sstream>
#include <vector>

namespace swept {
namespace {

using Clock = std::chrono::steady_clock;
using detail::Checker;

Mat3 exp_rotation(const Vec3& w) {
  const double angle = w.norm();
  if (angle == 0.0) return Mat3::Identity();
  return Eigen::AngleAxisd(angle, w / angle).toRotationMatrix();
}

// ---- the grid ---------------------------------------------------------------------------------

constexpr int kMaxDims = 6;
using Key = std::array<std::int32_t, kMaxDims>;

struct KeyHash {
  std::size_t operator()(const Key& k) const {
    std::uint64_t h = 0x9E3779B97F4A7C15ull;
    for (std::int32_t v : k) {
      h ^= static_cast<std::uint64_t>(static_cast<std::uint32_t>(v)) + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
    }
    return static_cast<std::size_t>(h);
  }
};

struct EdgeKey {
  Key a, b;
  bool operator==(const EdgeKey&) const = default;
};
struct EdgeHash {
  std::size_t operator()(const EdgeKey& e) const { return KeyHash{}(e.a) * 31u ^ KeyHash{}(e.b); }
};

const Key kGoalKey = {INT_MIN, INT_MIN, INT_MIN, INT_MIN, INT_MIN, INT_MIN};

struct NodeInfo {
  bool valid = false;
  double distance = 0.0;  ///< lower bound on the distance at the node
  bool exact = true;      ///< from a query (else inherited from a neighbour's bound)
};

class Planner {
 public:
  Planner(const Problem& p, const PlanScene& s, const PlanOptions& o)
      : pb_(p), sc_(s), opt_(o), check_(s, p.clearance), t_start_(Clock::now()) {
    time_limit_ = o.time_limit.value_or(p.time_limit);
    c_ = s.reference;
    rmax_ = std::max(s.radius, 1e-12);
  }

  PlanResult run();

 private:
  // Reference point of a pose in the world.
  Vec3 ref(const Pose& q) const { return q.apply(c_); }
  Pose with_ref(const Mat3& rot, const Vec3& p) const { return {rot, p - rot * c_}; }
  double elapsed_s() const { return std::chrono::duration<double>(Clock::now() - t_start_).count(); }
  bool out_of_time() const { return elapsed_s() > time_limit_; }

  bool in_bounds(const Vec3& p) const {
    return (p.array() >= bounds_.min.array()).all() && (p.array() <= bounds_.max.array()).all();
  }
  bool in_goal_region(const Pose& q) const {
    const Vec3 p = ref(q);
    for (int i = 0; i < 3; ++i)
      if (p[i] - rmax_ > goal_box_.max[i] || p[i] + rmax_ < goal_box_.min[i]) return true;
    return false;
  }
  bool is_goal(const Pose& q) const { return pb_.goal_outside ? in_goal_region(q) : false; }
  // Lower bound of the metric distance to the goal.
  double heuristic(const Pose& q) const {
    if (!pb_.goal_outside) return check_.length(q, *pb_.goal);
    const Vec3 p = ref(q);
    double best = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 3; ++i) {
      best = std::min(best, std::max(0.0, goal_box_.max[i] + rmax_ - p[i]));
      best = std::min(best, std::max(0.0, p[i] - (goal_box_.min[i] - rmax_)));
    }
    return best;
  }

  // Grid: node coordinates are integers at the finest level; level k uses multiples of
  // 2^(kmax − k). Translation in units of step_fine_, rotation (a rotation vector, world axes,
  // applied before the anchor orientation) in units of step_fine_ / r_max radians.
  Pose pose_of(const Key& k) const {
    const Vec3 p = anchor_p_ + step_fine_ * Vec3(k[0], k[1], k[2]);
    if (dims_ == 3) return with_ref(anchor_r_, p);
    const Vec3 w = (step_fine_ / rmax_) * Vec3(k[3], k[4], k[5]);
    return with_ref(exp_rotation(w) * anchor_r_, p);
  }
  bool key_in_bounds(const Key& k) const {
    const Vec3 p = anchor_p_ + step_fine_ * Vec3(k[0], k[1], k[2]);
    if (!in_bounds(p)) return false;
    if (dims_ == 3) return true;
    const Vec3 w = (step_fine_ / rmax_) * Vec3(k[3], k[4], k[5]) + anchor_w_;
    if (pb_.rotation == RotationMode::free) return w.norm() <= std::numbers::pi;
    for (int i = 0; i < 3; ++i)
      if (w[i] < pb_.rotation_limits[i][0] || w[i] > pb_.rotation_limits[i][1]) return false;
    return true;
  }

  NodeInfo check_node(const Pose& q, double reach) const {
    NodeInfo n;
    n.distance = check_.clearance(q, check_.margin() + reach);
    n.valid = n.distance > check_.margin();
    return n;
  }

  bool straight_line_phase(std::vector<Pose>& out);
  bool grid_phase(std::vector<Pose>& out, PlanStatus& why);
  bool search_level(int level, std::size_t budget, std::vector<Key>& path, bool& exhausted);
  void smooth(std::vector<Pose>& path, std::size_t fixed_prefix);
  void report_progress(int level);

  std::vector<Vec3> directions() const;
  bool find_escape(Pose& escape);

  const Problem& pb_;
  const PlanScene& sc_;
  const PlanOptions& opt_;
  Checker check_;
  Clock::time_point t_start_;
  double time_limit_ = 60.0;
  Vec3 c_;
  double rmax_ = 1.0;
  Aabb bounds_;    // for the reference point
  Aabb goal_box_;  // the obstacles' box grown by the goal margin
  Pose start_;     // where the search starts (after an escape from contact)
  double start_distance_ = 0.0;
  int dims_ = 6;
  int kmax_ = 6;
  double step0_ = 1.0, step_fine_ = 1.0;
  Vec3 anchor_p_ = Vec3::Zero();
  Mat3 anchor_r_ = Mat3::Identity();
  Vec3 anchor_w_ = Vec3::Zero();  // rotation vector of the anchor relative to the problem start
  // Open-addressing tables (abseil): millions of entries on a long search, looked up at every
  // expansion, and let go in one piece (std::unordered_map freed them entry by entry, which
  // took seconds past the time limit).
  absl::flat_hash_map<Key, NodeInfo, KeyHash> nodes_;
  absl::flat_hash_map<EdgeKey, bool, EdgeHash> edges_;
  std::size_t edges_checked_ = 0;
  int level_reached_ = 0;
  double last_progress_ = -1.0;
};

std::vector<Vec3> Planner::directions() const {
  std::vector<Vec3> dirs;
  auto add = [&](const Vec3& d) {
    if (d.norm() < 1e-12) return;
    const Vec3 u = d.normalized();
    for (const Vec3& e : dirs)
      if (e.dot(u) > 1.0 - 1e-9) return;
    dirs.push_back(u);
  };
  // Toward the goal first, then the world axes (+z first: most parts come out upwards), then
  // the body's principal axes.
  if (pb_.goal) add(ref(*pb_.goal) - ref(start_));
  for (const Vec3& d : {Vec3(0, 0, 1), Vec3(0, 0, -1), Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0)})
    add(d);
  const Fit f = fit(sc_.body.triangles, Fitter::inertia);
  for (int i = 0; i < 3; ++i) {
    add(start_.rotation * f.axes.col(i));
    add(-(start_.rotation * f.axes.col(i)));
  }
  return dirs;
}

// How far the reference point can travel from `p` along `u` inside the bounds.
double room_along(const Aabb& box, const Vec3& p, const Vec3& u) {
  double t = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    if (u[i] > 1e-12) t = std::min(t, (box.max[i] - p[i]) / u[i]);
    if (u[i] < -1e-12) t = std::min(t, (box.min[i] - p[i]) / u[i]);
  }
  return std::max(t, 0.0);
}

// Directions that separate the body from the obstacle faces it touches at `start`: each
// touched face's normal, oriented toward the body (toward the touching body triangle, or toward
// the body's reference point when the two are coplanar), and the normalised sum of every two of
// them (a peg resting on the bottom of its hole and against a wall leaves diagonally). At most
// 12 distinct normals are used, in the order of the pairs (sorted by triangle ids).
std::vector<Vec3> separating_directions(const PlanScene& scene, const Pose& start, const TrianglePairs& pairs) {
  std::vector<Vec3> normals;
  auto add_unique = [](std::vector<Vec3>& list, const Vec3& d) {
    if (!(d.norm() > 1e-12)) return;
    const Vec3 u = d.normalized();
    for (const Vec3& e : list)
      if (e.dot(u) > 1.0 - 1e-9) return;
    list.push_back(u);
  };
  const Vec3 body_center = start.apply(scene.reference);
  for (const ContactPair& p : pairs.pairs) {
    if (normals.size() >= 12) break;
    const Triangle& o = scene.obstacles.triangles[p.triangle_a];
    const Triangle& t = scene.body.triangles[p.triangle_b];
    Vec3 n = (o.q - o.p).cross(o.r - o.p);
    if (!(n.norm() > 0.0)) continue;
    n.normalize();
    const Vec3 toward = start.apply(centroid(t)) - centroid(o);
    const double side = n.dot(toward);
    const double scale = std::max(toward.norm(), 1e-300);
    const double s = std::abs(side) > 1e-9 * scale ? side : n.dot(body_center - centroid(o));
    if (s == 0.0) continue;
    add_unique(normals, s > 0 ? n : Vec3(-n));
  }
  std::vector<Vec3> out = normals;
  for (std::size_t i = 0; i < normals.size(); ++i)
    for (std::size_t j = i + 1; j < normals.size(); ++j) add_unique(out, normals[i] + normals[j]);
  return out;
}

// Start in contact: a translation along one of the candidate directions (then the directions
// that separate the body from what it touches), certified with the contact pairs exempt, to the
// nearest pose where the full clearance holds.
bool Planner::find_escape(Pose& escape) {
  const double size = std::max(sc_.obstacle_box.extent(), 2 * rmax_);
  double best = std::numeric_limits<double>::infinity();
  std::vector<Vec3> candidates = directions();
  for (const Vec3& d : separating_directions(sc_, start_, check_.exempt())) {
    bool seen = false;
    for (const Vec3& e : candidates) seen = seen || e.dot(d) > 1.0 - 1e-9;
    if (!seen) candidates.push_back(d);
  }
  for (const Vec3& u : candidates) {
    const double room = room_along(bounds_, ref(start_), u);
    for (double s = 1e-3 * size; s <= room && s < best; s *= 1.5) {
      if (out_of_time()) return false;
      const Pose q = with_ref(start_.rotation, ref(start_) + s * u);
      const NodeInfo n = check_node(q, s);
      if (!n.valid) continue;
      if (check_.clear(start_, -1, q, -1, /*relaxed=*/true)) {
        best = s;
        escape = q;
      }
      break;  // the first valid pose along u decides this direction
    }
  }
  return std::isfinite(best);
}

bool Planner::straight_line_phase(std::vector<Pose>& out) {
  const Pose& s = start_;
  auto try_path = [&](std::vector<Pose> poses) {
    for (std::size_t i = 0; i + 1 < poses.size(); ++i) {
      if (out_of_time()) return false;
      ++edges_checked_;
      if (!check_.clear(poses[i], i == 0 ? start_distance_ : -1, poses[i + 1], -1)) return false;
    }
    out = std::move(poses);
    return true;
  };
  if (pb_.goal) {
    if (try_path({s, *pb_.goal})) return true;
  }
  const std::vector<Vec3> dirs = directions();
  // One straight move out (region goal), or out and then to the goal pose.
  for (const Vec3& u : dirs) {
    const double room = room_along(bounds_, ref(s), u);
    if (pb_.goal_outside) {
      // The shortest move along u that reaches the region, if the bounds allow it.
      double lo = 0, hi = room;
      if (!in_goal_region(with_ref(s.rotation, ref(s) + hi * u))) continue;
      for (int it = 0; it < 40; ++it) {
        const double mid = 0.5 * (lo + hi);
        (in_goal_region(with_ref(s.rotation, ref(s) + mid * u)) ? hi : lo) = mid;
      }
      if (try_path({s, with_ref(s.rotation, ref(s) + hi * u)})) return true;
    } else {
      for (double f : {0.25, 0.5, 1.0}) {
        const Pose q = with_ref(s.rotation, ref(s) + f * room * u);
        if (try_path({s, q, *pb_.goal})) return true;
      }
    }
  }
  // Two moves for a region goal: slide along u1, then out along u2 ⟂ u1 (a slider in a slot).
  if (pb_.goal_outside) {
    for (const Vec3& u1 : dirs) {
      const double room1 = room_along(bounds_, ref(s), u1);
      for (double f : {0.125, 0.25, 0.5, 0.75}) {
        const Pose q1 = with_ref(s.rotation, ref(s) + f * room1 * u1);
        const NodeInfo n1 = check_node(q1, f * room1);
        if (!n1.valid) continue;
        for (const Vec3& u2 : dirs) {
          if (std::abs(u2.dot(u1)) > 0.5) continue;
          const double room2 = room_along(bounds_, ref(q1), u2);
          if (!in_goal_region(with_ref(s.rotation, ref(q1) + room2 * u2))) continue;
          double lo = 0, hi = room2;
          for (int it = 0; it < 40; ++it) {
            const double mid = 0.5 * (lo + hi);
            (in_goal_region(with_ref(s.rotation, ref(q1) + mid * u2)) ? hi : lo) = mid;
          }
          if (try_path({s, q1, with_ref(s.rotation, ref(q1) + hi * u2)})) return true;
          if (out_of_time()) return false;
        }
      }
    }
  }
  return false;
}

void Planner::report_progress(int level) {
  if (!opt_.progress) return;
  const double now = elapsed_s();
  if (now - last_progress_ < 1.0) return;
  last_progress_ = now;
  opt_.progress({level, nodes_.size(), check_.distance_queries(), now});
}

// Lazy weighted A* (Cohen, Phillips, Likhachev 2014) on the grid of one level: an entry is a
// (node, parent) pair; a node and the edge from its parent are checked only when the entry is
// popped. A node's distance bound carries to its neighbours by the 1-Lipschitz property of the
// distance in the motion metric (D(q') ≥ D(q) − d(q, q')), so in open space most nodes and edges
// need no query at all.
bool Planner::search_level(int level, std::size_t budget, std::vector<Key>& path, bool& exhausted) {
  const std::int32_t stride = 1 << (kmax_ - level);
  const double step = step_fine_ * stride;
  const double margin = check_.margin();
  constexpr double kWeight = 2.0;
  struct Entry {
    double f, g;
    Key key, parent;
    bool operator>(const Entry& o) const {
      if (f != o.f) return f > o.f;
      if (g != o.g) return g < o.g;  // deeper first among equals
      if (key != o.key) return key > o.key;
      return parent > o.parent;
    }
  };
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
  absl::flat_hash_map<Key, Key, KeyHash> closed;  // node → parent
  absl::flat_hash_map<Key, double, KeyHash> best_g;
  const Key start{};
  open.push({kWeight * heuristic(start_), 0.0, start, start});
  const double goal_connect = std::sqrt(static_cast<double>(dims_)) * step * 1.01;
  std::size_t expansions = 0;
  exhausted = false;
  auto edge_key = [](const Key& a, const Key& b) {
    return b == kGoalKey ? EdgeKey{a, kGoalKey} : EdgeKey{std::min(a, b), std::max(a, b)};
  };
  while (!open.empty()) {
    const Entry e = open.top();
    open.pop();
    if (closed.count(e.key)) continue;
    if ((++expansions & 255) == 0) {
      if (out_of_time()) return false;
      report_progress(level);
    }
    if (expansions > budget) return false;
    // The node.
    NodeInfo* node = nullptr;
    if (e.key != kGoalKey) {
      auto it = nodes_.find(e.key);
      if (it == nodes_.end() || (it->second.valid && !it->second.exact && it->second.distance <= margin + step)) {
        // Unknown, or known only by a bound too weak to carry on: query it.
        it = nodes_.insert_or_assign(e.key, check_node(pose_of(e.key), 4.0 * step)).first;
      }
      if (!it->second.valid) continue;
      node = &it->second;
    }
    // The edge from its parent.
    if (e.key != start) {
      const EdgeKey ek = edge_key(e.parent, e.key);
      auto ed = edges_.find(ek);
      if (ed == edges_.end()) {
        const Pose a = pose_of(e.parent);
        const Pose b = e.key == kGoalKey ? *pb_.goal : pose_of(e.key);
        const double da = nodes_.at(e.parent).distance;
        const double db = node ? node->distance : -1.0;
        ++edges_checked_;
        ed = edges_.emplace(ek, check_.clear(a, da, b, db)).first;
      }
      if (!ed->second) continue;
    }
    closed.emplace(e.key, e.parent);
    if (e.key == kGoalKey || (pb_.goal_outside && in_goal_region(pose_of(e.key)))) {
      path.clear();
      for (Key k = e.key;; k = closed.at(k)) {
        path.push_back(k);
        if (k == start) break;
      }
      std::reverse(path.begin(), path.end());
      return true;
    }
    const Pose q = pose_of(e.key);
    auto push = [&](const Key& nk, double cost) {
      const double ng = e.g + cost;
      auto bg = best_g.find(nk);
      if (bg != best_g.end() && bg->second <= ng) return;
      best_g[nk] = ng;
      const double h = nk == kGoalKey ? 0.0 : heuristic(pose_of(nk));
      open.push({ng + kWeight * h, ng, nk, e.key});
    };
    if (!pb_.goal_outside && check_.length(q, *pb_.goal) <= goal_connect) {
      auto ed = edges_.find({e.key, kGoalKey});
      if (ed == edges_.end() || ed->second) push(kGoalKey, check_.length(q, *pb_.goal));
    }
    const double inherited = node->distance - step;
    for (int d = 0; d < dims_; ++d)
      for (int sign : {-1, 1}) {
        Key nk = e.key;
        nk[d] += sign * stride;
        if (closed.count(nk) || !key_in_bounds(nk)) continue;
        auto n = nodes_.find(nk);
        if (n != nodes_.end() && !n->second.valid) continue;
        // A neighbour well inside this node's free ball is free, and so is the edge to it.
        if (n == nodes_.end() && inherited > margin) {
          nodes_.emplace(nk, NodeInfo{true, inherited, false});
          edges_.emplace(edge_key(e.key, nk), true);
        }
        push(nk, step);
      }
  }
  exhausted = true;
  return false;
}

bool Planner::grid_phase(std::vector<Pose>& out, PlanStatus& why) {
  bool all_exhausted = true;
  // Coarse levels get a budget of expansions, so that a level too coarse for a narrow passage
  // does not eat the time limit; the finest level runs until the time limit.
  for (int level = 0; level <= kmax_; ++level) {
    level_reached_ = level;
    const std::size_t budget = level == kmax_ ? std::numeric_limits<std::size_t>::max() : std::size_t{4000} << level;
    std::vector<Key> keys;
    bool exhausted = false;
    if (search_level(level, budget, keys, exhausted)) {
      out.clear();
      for (const Key& k : keys) out.push_back(k == kGoalKey ? *pb_.goal : pose_of(k));
      return true;
    }
    if (out_of_time()) {
      why = PlanStatus::no_path_time;
      return false;
    }
    all_exhausted = all_exhausted && exhausted;
  }
  why = all_exhausted ? PlanStatus::no_path_bounds : PlanStatus::no_path_resolution;
  return false;
}

void Planner::smooth(std::vector<Pose>& path, std::size_t fixed) {
  // Greedy shortcuts: from each waypoint, the farthest later waypoint one certified segment
  // reaches (binary search), twice over.
  for (int round = 0; round < 2 && path.size() > fixed + 2; ++round) {
    std::vector<Pose> out(path.begin(), path.begin() + static_cast<std::ptrdiff_t>(fixed + 1));
    std::size_t i = fixed;
    while (i + 1 < path.size()) {
      if (out_of_time()) return;
      std::size_t lo = i + 1, hi = path.size() - 1;  // lo: known reachable (an edge of the path)
      while (lo < hi) {
        const std::size_t mid = (lo + hi + 1) / 2;
        ++edges_checked_;
        if (check_.clear(path[i], -1, path[mid], -1)) lo = mid;
        else hi = mid - 1;
      }
      out.push_back(path[lo]);
      i = lo;
    }
    path = std::move(out);
  }
}

PlanResult Planner::run() {
  PlanResult r;
  const double size = std::max(sc_.obstacle_box.extent(), 2 * rmax_);
  // Bounds of the reference point: given, or the obstacles' box grown so that the body fits
  // beside it on every side.
  goal_box_ = sc_.obstacle_box;
  goal_box_.min.array() -= pb_.goal_margin;
  goal_box_.max.array() += pb_.goal_margin;
  if (pb_.bounds) {
    bounds_ = *pb_.bounds;
  } else {
    bounds_ = goal_box_;
    bounds_.min.array() -= 2.2 * rmax_ + 0.05 * size;
    bounds_.max.array() += 2.2 * rmax_ + 0.05 * size;
    bounds_.extend(ref(pb_.start));
    if (pb_.goal) bounds_.extend(ref(*pb_.goal));
  }
  auto fail = [&](PlanStatus s, std::string msg) {
    r.status = s;
    r.message = std::move(msg);
    r.nodes_checked = nodes_.size();
    r.edges_checked = edges_checked_;
    r.queries.distance = check_.distance_queries();
    r.time_ms.total = elapsed_s() * 1e3;
    if (r.time_ms.search == 0.0) r.time_ms.search = r.time_ms.total;
    return r;
  };
  // Coordinates far beyond the scene lose the precision the distance bounds rely on (a query at
  // 1e100 visits every pair and takes seconds, so no time limit holds): the bounds, the start,
  // the goal and the goal region must stay within 10^6 scene sizes.
  {
    Aabb reach = bounds_;
    reach.extend(sc_.obstacle_box);
    reach.extend(goal_box_);
    reach.extend(ref(pb_.start));
    if (pb_.goal) reach.extend(ref(*pb_.goal));
    const double across = (reach.max - reach.min).maxCoeff();
    if (!(across <= 1e6 * size)) {
      std::ostringstream os;
      os << "the bounds, start, goal and goal margin span " << across << " " << pb_.unit << ", more than 10^6 times the scene's size ("
         << size << " " << pb_.unit << "): coordinates that far apart lose the precision the certificate needs; check [bounds], "
         << "[start], [goal] and goal.margin";
      return fail(PlanStatus::invalid_bounds, os.str());
    }
  }
  if (!in_bounds(ref(pb_.start))) return fail(PlanStatus::invalid_start, "the start's reference point is outside the bounds");
  if (pb_.goal && !in_bounds(ref(*pb_.goal))) return fail(PlanStatus::invalid_goal, "the goal's reference point is outside the bounds");
  if (pb_.goal_outside) {
    // The region must be reachable inside the bounds.
    bool reachable = false;
    for (int i = 0; i < 3; ++i)
      reachable = reachable || bounds_.max[i] - rmax_ > goal_box_.max[i] || bounds_.min[i] + rmax_ < goal_box_.min[i];
    if (!reachable) return fail(PlanStatus::invalid_goal, "the goal region (outside the obstacles' box) lies outside the bounds");
  }
  const double margin = pb_.clearance;
  check_.set_deadline(t_start_ + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(time_limit_)));
  start_ = pb_.start;
  std::vector<Pose> prefix{pb_.start};
  start_distance_ = check_.clearance(start_, margin + 0.05 * size);
  if (pb_.goal) {
    const double dg = check_.clearance(*pb_.goal, margin);
    if (dg <= margin) {
      std::ostringstream os;
      os << "the goal pose is closer than the clearance " << margin << " to the obstacles (distance " << dg << ")";
      return fail(PlanStatus::invalid_goal, os.str());
    }
    if (auto inside = enclosure_at(sc_, *pb_.goal)) return fail(PlanStatus::invalid_goal, "the goal pose is in collision: " + *inside);
  }
  if (start_distance_ > margin) {
    if (auto inside = enclosure_at(sc_, start_)) return fail(PlanStatus::invalid_start, "the start pose is in collision: " + *inside);
  }
  if (start_distance_ <= margin) {
    if (pb_.contact_tolerance <= 0.0) {
      std::ostringstream os;
      os << "the start pose is " << (start_distance_ <= 0 ? "in collision with" : "closer than the clearance to")
         << " the obstacles (distance " << start_distance_ << ", clearance " << margin
         << "); set planner.contact_tolerance for a part that starts in contact";
      return fail(PlanStatus::invalid_start, os.str());
    }
    check_.set_exempt(proximity_pairs(sc_.obstacle_tree, Pose{}, sc_.body_tree, start_,
                                      {.threshold = margin + pb_.contact_tolerance})
                          .pairs);
    Pose escape;
    if (!find_escape(escape)) {
      return fail(out_of_time() && check_.cap_refusals() == 0 ? PlanStatus::no_path_time : PlanStatus::no_path_resolution,
                  "the body starts in contact and no straight escape (along the world axes, the body's axes "
                  "or toward the goal) reaches a pose with the full clearance");
    }
    start_ = escape;
    prefix.push_back(escape);
    start_distance_ = check_.clearance(start_, margin + 0.05 * size);
  }

  // Grid set-up, anchored at the search start.
  dims_ = pb_.rotation == RotationMode::none ? 3 : 6;
  anchor_p_ = ref(start_);
  anchor_r_ = start_.rotation;
  anchor_w_ = Eigen::AngleAxisd(start_.rotation * pb_.start.rotation.transpose()).angle() *
              Eigen::AngleAxisd(start_.rotation * pb_.start.rotation.transpose()).axis();
  step0_ = (bounds_.max - bounds_.min).maxCoeff() / 8.0;
  kmax_ = 0;
  const double finest = std::max(margin, 2e-3 * size);
  while (kmax_ < 7 && step0_ / (1 << kmax_) > finest) ++kmax_;
  step_fine_ = step0_ / (1 << kmax_);
  nodes_[Key{}] = NodeInfo{true, start_distance_};

  std::vector<Pose> path;
  bool found = false;
  if (is_goal(start_)) {
    path = {start_};
    found = true;
    r.level = -1;
  }
  if (!found && straight_line_phase(path)) {
    found = true;
    r.level = -1;
  }
  PlanStatus why = PlanStatus::no_path_resolution;
  if (!found && !out_of_time()) {
    found = grid_phase(path, why);
    r.level = level_reached_;
  }
  const double t_search = elapsed_s();
  r.time_ms.search = t_search * 1e3;
  r.nodes_checked = nodes_.size();
  if (!found) {
    if (out_of_time()) why = PlanStatus::no_path_time;
    std::ostringstream os;
    if (const std::uint64_t refused = check_.cap_refusals(); refused > 0) {
      // The limiting factor was the resolution of the certificate, whatever the clock says.
      os << "no path found: " << refused << " motion" << (refused == 1 ? " grazes" : "s graze")
         << " the clearance too closely to certify (more than " << kMaxCertificateQueries
         << " distance queries each; a smaller clearance or a wider passage helps)";
      if (why == PlanStatus::no_path_time) os << ", and the search then reached the time limit of " << time_limit_ << " s";
      return fail(PlanStatus::no_path_resolution, os.str());
    }
    switch (why) {
      case PlanStatus::no_path_time: os << "no path found within the time limit of " << time_limit_ << " s"; break;
      case PlanStatus::no_path_bounds:
        os << "no path exists inside the bounds and rotation limits at the grid resolutions searched (finest step "
           << step_fine_ << " " << pb_.unit << ")";
        break;
      default: os << "no path found down to the finest grid resolution (step " << step_fine_ << " " << pb_.unit << ")"; break;
    }
    return fail(why, os.str());
  }
  // Smoothing after the escape prefix (which stays as it is).
  std::vector<Pose> full = prefix;
  full.insert(full.end(), path.begin() + 1, path.end());
  const std::size_t fixed = prefix.size() - 1;
  smooth(full, fixed);
  const double t_smooth = elapsed_s();
  r.time_ms.smooth = (t_smooth - t_search) * 1e3;

  // Final certification of every segment and the smallest distance along the path, by the
  // same function `swept check` runs (check_path.cpp), whatever the time.
  const PathCheckResult final_check = check_path(pb_, sc_, Path{full});
  if (!final_check.valid)
    return fail(PlanStatus::no_path_resolution,
                "internal: the found path failed its final certification: " + final_check.message);
  if (final_check.escape_segments != fixed)
    return fail(PlanStatus::no_path_resolution, "internal: the final certification disagrees on the escape from contact");
  const double min_d = final_check.min_clearance;
  r.escape_segments = final_check.escape_segments;
  r.exempt_pairs = final_check.exempt_pairs;
  r.escape_clearance = final_check.escape_clearance;
  r.status = PlanStatus::solved;
  r.path.poses = std::move(full);
  for (std::size_t i = 0; i + 1 < r.path.poses.size(); ++i) {
    const Pose& a = r.path.poses[i];
    const Pose& b = r.path.poses[i + 1];
    r.translation_length += (ref(b) - ref(a)).norm();
    r.rotation_length += rotation_angle(a.rotation, b.rotation);
    r.path_length += check_.length(a, b);
  }
  r.min_clearance = min_d;
  r.path_hash = path_hash(r.path);
  r.edges_checked = edges_checked_;
  r.queries.distance = check_.distance_queries() + final_check.distance_queries;
  r.time_ms.total = elapsed_s() * 1e3;
  std::ostringstream os;
  os << "solved" << (r.level < 0 ? " by straight moves" : " on the grid at level " + std::to_string(r.level)) << ": "
     << r.path.poses.size() << " waypoints";
  r.message = os.str();
  return r;
}

}  // namespace

PlanResult plan(const Problem& problem, const PlanScene& scene, const PlanOptions& options) {
  const int threads = options.threads.value_or(problem.threads);
  std::unique_ptr<tbb::global_control> limit;
  if (threads > 0) limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, threads);
  Planner planner(problem, scene, options);
  PlanResult r = planner.run();
  r.time_ms.build = scene.build_ms;
  r.time_ms.total += scene.build_ms;
  return r;
}

}  // namespace swept
