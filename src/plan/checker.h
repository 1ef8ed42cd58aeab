#pragma once
// The planner's view of the certificate (internal to src/plan): distance bounds of the body
// against the obstacles and the certificate of a straight motion (`certify_motion`, the query
// layer's one certificate), with query counters, the query cap and a deadline. Every pair of
// triangles counts: a motion with an end in contact is certified by the contact layer
// (contact.h), never here. Used by every phase of the search and by `check_path`.
#include "swept/plan/planner.h"
#include "swept/query/motion.h"
#include "swept/query/query.h"

#include <array>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>

namespace swept::detail {

using Clock = std::chrono::steady_clock;

/// Triangle pairs (positions in the obstacles' and the body's trees, as DistanceResult::hint)
/// that blocked, or were closest at, the poses a search step tried last, most recent first: a
/// pose shortened from a blocked one, or reached from a node near a wall, is most often blocked
/// by one of them (on the house, about 70 % of the trees' blocked steps).
struct Suspects {
  static constexpr std::size_t kSize = 4;
  std::array<DistanceHint, kSize> pairs{};
  /// `pair` first (moved up if it is there already); the oldest drops out.
  void add(DistanceHint pair) {
    if (!pair.valid()) return;
    std::size_t k = 0;
    while (k + 1 < kSize && !(pairs[k].a == pair.a && pairs[k].b == pair.b)) ++k;
    for (; k > 0; --k) pairs[k] = pairs[k - 1];
    pairs[0] = pair;
  }
};

/// How a motion certificate asks for its midpoints (Checker::certify).
enum class Pieces {
  one,                  ///< one at a time (`certify_motion`): for callers that run in parallel
  two_earliest,         ///< two at a time, in parallel (`certify_motion_paired`): serial callers
  earliest_and_latest,  ///< two at a time, one from each end (`from_both_ends`): a long motion
                        ///< likely blocked near its end, as a bridge round a failed edge
};

// Distance bounds and motion certificates against the obstacles, with query counters. The const
// queries are safe to run from many threads at once.
class Checker {
 public:
  /// Motions interpolate about the scene's reference point.
  Checker(const PlanScene& scene, double margin)
      : scene_(scene), margin_(margin), reference_(scene.reference), radius_(scene.radius) {}
  /// Motions interpolate about `reference` (body frame), e.g. a path file's own.
  Checker(const PlanScene& scene, double margin, const Vec3& reference)
      : scene_(scene), margin_(margin), reference_(reference), radius_(motion_radius(scene.body_tree, reference)) {}

  /// A lower bound on the distance at `pose`, exact below `enough`.
  double clearance(const Pose& pose, double enough) const;
  /// The same query with its result: when exact (and above the margin), its witness points
  /// are the closest pair.
  /// With `suspects` (the pairs that blocked, or were closest at, the poses a search step tried
  /// before) while set_decide_blocked is on: each is tried first (DistanceRequest::suspects), and
  /// one closer than the margin decides the pose blocked in a triangle test; otherwise the query
  /// runs as without them, so a free pose's result never depends on them. The query's witness
  /// joins the suspects.
  DistanceResult measure(const Pose& pose, double enough, Suspects* suspects = nullptr) const;
  /// Is the distance at `pose` above the margin? The cheapest query: it stops as soon as every
  /// pair left is proved farther than the margin (nothing else is asked of it).
  bool free(const Pose& pose) const;
  /// Exact distance at `pose`, or +∞ once the query has proved it is not below `bound`.
  double below(const Pose& pose, double bound) const;
  /// The distance at `pose`, known free (a tree node), with its witness points (world), exact
  /// below `enough` (counted).
  DistanceResult nearest(const Pose& pose, double enough) const;
  /// Exact distance at `pose` (for reporting clearance).
  double exact(const Pose& pose) const {
    return below(pose, std::numeric_limits<double>::infinity());
  }

  /// The straight motion a → b about the checker's reference point.
  Motion motion(const Pose& a, const Pose& b) const { return {a, b, reference_, radius_}; }
  /// Its metric length (‖Δc‖ + r_max·θ).
  double length(const Pose& a, const Pose& b) const { return motion_length(a, b, reference_, radius_); }

  /// Certificate of the straight motion a → b (distance > margin everywhere). `da`, `db` are
  /// known lower bounds at the ends (negative: unknown). A translation whose certificate runs
  /// past kSweepAfter queries (it grazes the margin: its pieces get short) is decided by the
  /// exact sweep of the translation instead (`sweep_translation`), in one traversal — a motion
  /// that turns by a hair too, with the margin raised by how far the turn strays
  /// (`as_translation`); for a blocked one the certificate goes on from where it was, to find
  /// where it is blocked. Refusals for the query cap are counted (`cap_refusals`) when the cap
  /// is the default one; a lower `max_queries` is a caller's
  /// "not worth more than this" (smoothing's shortcuts), not a limit of the planner.
  /// `pieces`: how the midpoints are asked (Pieces). `cancel`: CertificateOptions::cancel.
  Certificate certify(const Pose& a, double da, const Pose& b, double db,
                      int max_queries = kMaxCertificateQueries, Pieces pieces = Pieces::one,
                      std::array<const std::atomic<bool>*, 2> cancel = {}) const;
  /// A cheap refusal before a long motion's certificate: true when one of the poses at
  /// t = 1/2, 1/4, 3/4, 1/8, …, 7/8 of the motion a → b (in that order, stopping at the first)
  /// is within the margin (`free`), so the certificate, which asks for more than the margin
  /// everywhere, would not clear it. False says nothing: the motion may still be blocked
  /// between the samples. A free sample costs a query that stops once every pair is proved
  /// farther than the margin, where the certificate's ask for an exact distance up to half
  /// the motion's length.
  bool blocked_at_samples(const Pose& a, const Pose& b) const;
  /// Certified clear?
  bool clear(const Pose& a, double da, const Pose& b, double db) const {
    return certify(a, da, b, db).clear();
  }

  double margin() const { return margin_; }
  const Vec3& reference() const { return reference_; }
  double radius() const { return radius_; }
  /// While set, a query stops as soon as it finds a pair closer than the margin: a blocked pose
  /// is decided, not measured (its distance is then some pair's, ≤ the margin, not the
  /// smallest), which is all the search asks of it; free poses are measured as before. Only for
  /// clearance(), free() and certify(): nearest(), below() and exact() stay exact. Off by
  /// default: `swept check` reports the exact distance where a path is blocked.
  void set_decide_blocked(bool on) { decide_blocked_ = on; }
  /// While set, certificates that run past this time give up (not clear).
  void set_deadline(std::optional<Clock::time_point> t) { deadline_ = t; }

  std::uint64_t distance_queries() const { return distance_queries_.load(); }
  /// Exact sweeps of pure translations run by certify().
  std::uint64_t sweeps() const { return sweeps_.load(); }
  /// Queries of a pure translation's certificate before the exact sweep decides it.
  static constexpr int kSweepAfter = kSweepAfterQueries;
  /// Motions refused because certifying them needed more than kMaxCertificateQueries queries
  /// (or pieces below the parameter resolution): they graze the margin.
  std::uint64_t cap_refusals() const { return cap_refusals_.load(); }

 private:
  /// One counted distance query against the obstacles (`decide`: a blocked pose is decided, not
  /// measured, while set_decide_blocked is on).
  DistanceResult query(const Pose& pose, double enough, DistanceHint hint = {}, bool decide = true,
                       std::span<const DistanceHint> suspects = {}) const;

  const PlanScene& scene_;
  double margin_;
  Vec3 reference_;
  double radius_;
  std::optional<Clock::time_point> deadline_;
  bool decide_blocked_ = false;
  mutable std::atomic<std::uint64_t> distance_queries_{0};
  mutable std::atomic<std::uint64_t> cap_refusals_{0};
  mutable std::atomic<std::uint64_t> sweeps_{0};
};

}  // namespace swept::detail
