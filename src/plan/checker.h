#pragma once
// The planner's certificate (internal to src/plan): distance bounds against the obstacles and
// the Schwarzer–Saha–Latombe bisection over a straight motion, with query counters, a query cap
// and a deadline. Used by the search (lazy edges, smoothing, escapes) and by `check_path`, the
// final certification of every path the planner returns and of paths users bring.
#include "swept/plan/planner.h"
#include "swept/query/query.h"

#include <atomic>
#include <chrono>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

namespace swept::detail {

using Clock = std::chrono::steady_clock;

/// Where a certificate stopped: the motion parameter and the distance found there (the distance
/// is ≤ the margin), or t = −1 when it gave up (query cap, parameter resolution or deadline).
struct Blocked {
  double t = -1.0;
  double distance = 0.0;
};

// Distance bounds and motion certificates against the obstacles, with query counters. In
// `relaxed` mode (the escape from a start in contact) the triangle pairs that were closer than
// clearance + contact tolerance at the start are left out, pair by pair; every other pair of
// triangles is checked.
class Checker {
 public:
  /// Motions interpolate about the scene's reference point.
  Checker(const PlanScene& scene, double margin)
      : s_(scene), margin_(margin), reference_(scene.reference), radius_(scene.radius) {}
  /// Motions interpolate about `reference` (body frame), e.g. a path file's own.
  Checker(const PlanScene& scene, double margin, const Vec3& reference)
      : s_(scene), margin_(margin), reference_(reference), radius_(motion_radius(scene.body_tree, reference)) {}

  /// The pairs (obstacle triangle, body triangle) that relaxed queries leave out.
  void set_exempt(TrianglePairs pairs) { exempt_ = std::move(pairs); }
  const TrianglePairs& exempt() const { return exempt_; }

  /// A lower bound on the distance at `pose`, exact below `enough`.
  double clearance(const Pose& pose, double enough, bool relaxed = false) const {
    ++distance_queries;
    const DistanceRequest req{.enough = enough, .exclude = relaxed ? &exempt_ : nullptr};
    return distance(s_.obstacle_tree, Pose{}, s_.body_tree, pose, req).distance;
  }

  /// Exact distance at `pose`, or +∞ once the query has proved it is not below `bound`.
  double below(const Pose& pose, double bound, bool relaxed = false) const {
    ++distance_queries;
    const DistanceRequest req{.enough = bound, .exclude = relaxed ? &exempt_ : nullptr};
    const DistanceResult d = distance(s_.obstacle_tree, Pose{}, s_.body_tree, pose, req);
    return d.exact ? d.distance : std::numeric_limits<double>::infinity();
  }

  /// Exact distance at `pose` (for reporting clearance).
  double exact(const Pose& pose, bool relaxed = false) const {
    return below(pose, std::numeric_limits<double>::infinity(), relaxed);
  }

  double length(const Pose& a, const Pose& b) const {
    return motion_length(a, b, reference_, radius_);
  }

  /// Is the straight motion a → b free with distance > margin everywhere? `da`, `db` are known
  /// lower bounds at the ends (negative: unknown). Schwarzer–Saha–Latombe bisection.
  bool certify(const Pose& a, double da, const Pose& b, double db, bool relaxed = false,
               Blocked* blocked = nullptr) const {
    struct Piece {
      double t0, d0, t1, d1;
    };
    // The allowance covers rounding in the interpolated poses (as motion_clearance does).
    const double total = length(a, b) * (1.0 + 1e-9);
    if (total == 0.0) return true;
    auto at = [&](double t) { return interpolate(a, b, t, reference_); };
    if (da < 0) da = clearance(a, margin_ + total, relaxed);
    if (db < 0) db = clearance(b, margin_ + total, relaxed);
    if (da <= margin_ || db <= margin_) {
      if (blocked) *blocked = da <= margin_ ? Blocked{0.0, da} : Blocked{1.0, db};
      return false;
    }
    std::vector<Piece> stack{{0.0, da, 1.0, db}};
    int queries = 0;
    while (!stack.empty()) {
      const Piece p = stack.back();
      stack.pop_back();
      const double len = total * (p.t1 - p.t0);
      if (len < (p.d0 - margin_) + (p.d1 - margin_)) continue;
      // The certificate needs this piece split: too many pieces means the motion grazes the
      // margin; refuse rather than loop.
      if (++queries > kMaxQueriesPerEdge || p.t1 - p.t0 < 1e-9) {
        ++cap_refusals;
        return false;
      }
      // Past the search's deadline a long certificate gives up (conservatively: not free).
      if ((queries & 63) == 0 && deadline_ && Clock::now() > *deadline_) return false;
      const double tm = 0.5 * (p.t0 + p.t1);
      const double dm = clearance(at(tm), margin_ + 0.5 * len, relaxed);
      if (dm <= margin_) {
        if (blocked) *blocked = {tm, dm};
        return false;
      }
      stack.push_back({tm, dm, p.t1, p.d1});
      stack.push_back({p.t0, p.d0, tm, dm});
    }
    return true;
  }

  double margin() const { return margin_; }
  const Vec3& reference() const { return reference_; }
  /// While set, certificates that run past this time give up (not free).
  void set_deadline(std::optional<Clock::time_point> t) { deadline_ = t; }

  mutable std::atomic<std::uint64_t> distance_queries{0};
  /// Motions refused because certifying them needed more than kMaxQueriesPerEdge queries (or
  /// pieces below the parameter resolution): they graze the margin.
  mutable std::atomic<std::uint64_t> cap_refusals{0};
  static constexpr int kMaxQueriesPerEdge = 200000;

 private:
  const PlanScene& s_;
  double margin_;
  Vec3 reference_;
  double radius_;
  TrianglePairs exempt_;
  std::optional<Clock::time_point> deadline_;
};

}  // namespace swept::detail
