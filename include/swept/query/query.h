#pragma once
/// Proximity queries between two RSS trees placed in the world (SPEC §3): collide, distance,
/// tolerance and proximity pairs (certified motion clearance: motion.h, included at the end).
/// Trees are immutable; every function here is safe to call concurrently from many threads on
/// the same trees (no locks, no shared mutable state).
///
/// Frames: `pose_a` / `pose_b` place model A / B in the world; all returned points are in the
/// world frame; returned triangle ids are the input indices (`Bvh::triangle_ids`).
#include "swept/bvh/bvh.h"
#include "swept/geometry/pose.h"

#include <cstdint>
#include <functional>
#include <limits>
#include <span>
#include <vector>

namespace swept {

/// Work counters carried by every result.
struct QueryStats {
  std::uint64_t bv_tests = 0;        ///< RSS-pair tests
  std::uint64_t triangle_tests = 0;  ///< triangle-pair tests
};

// ---- collide -----------------------------------------------------------------------------------
struct CollideRequest {
  bool all_contacts = false;  ///< false: stop at the first intersecting triangle pair
};
struct ContactPair {
  std::uint32_t triangle_a = 0;
  std::uint32_t triangle_b = 0;
};
/// A set of triangle pairs (A's id, B's id, as in `Bvh::triangle_ids`), sorted by
/// (triangle_a, triangle_b) without repeats.
struct TrianglePairs {
  std::vector<ContactPair> pairs;
  bool contains(std::uint32_t triangle_a, std::uint32_t triangle_b) const;
  std::size_t size() const { return pairs.size(); }
};
struct CollideResult {
  bool colliding = false;
  std::vector<ContactPair> contacts;  ///< all pairs (all_contacts) or the first one; sorted
  QueryStats stats;
};
CollideResult collide(const Bvh& a, const Pose& pose_a, const Bvh& b, const Pose& pose_b,
                      const CollideRequest& request = {});

// ---- distance ----------------------------------------------------------------------------------
/// Coherence along a motion: the closest triangle pair of a previous query, as positions in the
/// two trees' triangle arrays (opaque: take it from DistanceResult::hint). The next query starts
/// from that pair's exact distance as its answer so far, so that it prunes from the first node
/// pair on; on a tie it keeps that pair as the witness.
struct DistanceHint {
  std::uint32_t a = UINT32_MAX;
  std::uint32_t b = UINT32_MAX;
  bool valid() const { return a != UINT32_MAX && b != UINT32_MAX; }
};

struct DistanceRequest {
  double rel_err = 0.0;  ///< stop when the answer is provably within this relative error
  double abs_err = 0.0;  ///< ... or within this absolute error (PQP semantics)
  /// Warm start: a known upper bound on the distance (e.g. from a previous query).
  double upper_bound = std::numeric_limits<double>::infinity();
  /// Early exit for callers that only need to know the distance is at least this much:
  /// as soon as the distance is proven ≥ `enough`, stop; then `distance` is a lower bound
  /// (≥ enough) and `exact` is false.
  double enough = std::numeric_limits<double>::infinity();
  /// Triangle pairs left out (not owned; null: none). The result is then the distance over
  /// every other pair of triangles, which can be larger than the distance between the models:
  /// this is the contact exemption of the planner's escape from a start in contact.
  const TrianglePairs* exclude = nullptr;
  /// Triangle pairs left out by a rule (not owned; null: none): pairs (A's id, B's id) for which
  /// it returns true are skipped like `exclude`'s. It must be safe to call from many threads and
  /// give the same answer for the same pair (the assembly's mate rule, swept/contact/mate_rule.h).
  const std::function<bool(std::uint32_t triangle_a, std::uint32_t triangle_b)>* exclude_if = nullptr;
  /// The previous query's `hint` (same two trees), or none. The distance does not depend on
  /// it (only the work does, and on a tie which closest pair is reported); a hint out of range
  /// or naming a pair left out is ignored.
  DistanceHint hint{};
  /// Early exit for callers that only need to know the distance is below this much: as soon as
  /// a triangle pair closer than `stop_below` is found, stop; then `distance` is that pair's
  /// distance (< stop_below, and ≥ the true distance) and `exact` is false. (With a stop_below
  /// of 0 or less, which no distance is below, the answer is exact, as without it; the search
  /// still ends at its first touching pair, as every distance search does.)
  double stop_below = -std::numeric_limits<double>::infinity();
  /// With `stop_below`: triangle pairs (positions in the trees, as `DistanceResult::hint`) tried
  /// before anything else, for instance the pairs that blocked nearby poses. The first one closer
  /// than `stop_below` ends the query as the search would have ended at it; the others change
  /// nothing (unlike `hint`, they never seed the search), so a query that finds none of them
  /// below `stop_below` answers exactly as without them. Pairs out of range or left out are
  /// ignored. Not owned.
  std::span<const DistanceHint> suspects{};
};
struct DistanceResult {
  double distance = std::numeric_limits<double>::infinity();
  bool exact = true;           ///< false after an early exit (DistanceRequest::enough, ::stop_below)
  Vec3 point_a = Vec3::Zero(); ///< closest point on A (world)
  Vec3 point_b = Vec3::Zero(); ///< closest point on B (world)
  std::uint32_t triangle_a = 0;
  std::uint32_t triangle_b = 0;
  DistanceHint hint{};         ///< the witness pair, for the next query's DistanceRequest::hint
  QueryStats stats;
};
DistanceResult distance(const Bvh& a, const Pose& pose_a, const Bvh& b, const Pose& pose_b,
                        const DistanceRequest& request = {});

// ---- proximity pairs ----------------------------------------------------------------------------
struct ProximityRequest {
  double threshold = 0.0;  ///< in the model unit; pairs at distance < threshold are reported
};
struct ProximityResult {
  TrianglePairs pairs;  ///< every triangle pair closer than the threshold (ids as triangle_ids)
  QueryStats stats;
};
/// Every pair of triangles (one of A, one of B) whose exact distance is below the threshold:
/// the contacts of a part at its mounted pose. Threshold ≤ 0 gives no pairs.
ProximityResult proximity_pairs(const Bvh& a, const Pose& pose_a, const Bvh& b, const Pose& pose_b,
                                const ProximityRequest& request);

/// The triangles of each tree closer than the threshold to some triangle of the other: the same
/// triangles as the pairs of proximity_pairs name, without enumerating the pairs (a node pair is
/// skipped once every triangle under both nodes is known to be near, a triangle pair once both
/// are). What a contact's facets need on fine mates, where each triangle has many near partners.
struct ProximityTrianglesResult {
  std::vector<std::uint32_t> a;  ///< input indices of A's near triangles, ascending
  std::vector<std::uint32_t> b;  ///< input indices of B's near triangles, ascending
  QueryStats stats;
};
ProximityTrianglesResult proximity_triangles(const Bvh& a, const Pose& pose_a, const Bvh& b, const Pose& pose_b,
                                             const ProximityRequest& request);

// ---- tolerance ---------------------------------------------------------------------------------
struct ToleranceRequest {
  double tolerance = 0.0;  ///< in the model unit
};
struct ToleranceResult {
  bool within = false;   ///< distance < tolerance
  double distance = std::numeric_limits<double>::infinity();  ///< witness pair's distance when within
  Vec3 point_a = Vec3::Zero();
  Vec3 point_b = Vec3::Zero();
  std::uint32_t triangle_a = 0;
  std::uint32_t triangle_b = 0;
  QueryStats stats;
};
ToleranceResult tolerance(const Bvh& a, const Pose& pose_a, const Bvh& b, const Pose& pose_b,
                          const ToleranceRequest& request);

// ---- batches -----------------------------------------------------------------------------------
/// Many poses of B against A, answered in parallel (oneTBB); results in input order.
/// `along_path`: the poses follow each other along a motion; each query takes the previous
/// one's closest pair as its hint, in fixed blocks of 64 poses (the first of a block has
/// none), so the results do not depend on the number of threads. The distances are the same
/// either way; on a tie the pair reported may differ.
std::vector<DistanceResult> distance_batch(const Bvh& a, const Pose& pose_a, const Bvh& b,
                                           std::span<const Pose> poses_b,
                                           const DistanceRequest& request = {}, bool along_path = false);
std::vector<CollideResult> collide_batch(const Bvh& a, const Pose& pose_a, const Bvh& b,
                                         std::span<const Pose> poses_b,
                                         const CollideRequest& request = {});

}  // namespace swept

#include "swept/query/motion.h"  // IWYU pragma: export
