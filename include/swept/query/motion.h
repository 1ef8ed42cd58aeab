#pragma once
/// Certified clearance of a straight motion (Schwarzer, Saha, Latombe 2005): the one certificate
/// of the library. `certify_motion` is the core, over any distance function (the planner's
/// passes its contact exemption); `motion_clearance` is the same certificate against a tree.
#include "swept/bvh/bvh.h"
#include "swept/geometry/pose.h"
#include "swept/query/query.h"

#include <array>
#include <atomic>
#include <chrono>
#include <functional>
#include <limits>
#include <optional>

namespace swept {

/// Max distance from `reference` to any vertex of the tree's triangles (model frame).
double motion_radius(const Bvh& b, const Vec3& reference);

/// Motion metric of SPEC §4: ‖Δ reference point‖ + radius · angle(R0, R1). No body point
/// moves farther than this along the interpolated motion.
double motion_length(const Pose& from, const Pose& to, const Vec3& reference, double radius);

/// A straight motion of a body (see `interpolate`): the body-frame `reference` point moves on a
/// line from `from` to `to` while the rotation slerps about it.
struct Motion {
  Pose from = Pose{};
  Pose to = Pose{};
  Vec3 reference = Vec3::Zero();  ///< body frame
  /// Max distance from `reference` to any vertex of the body (body frame; `motion_radius`).
  /// Required: it bounds how far body points move, and a radius of 0 would certify a pure
  /// rotation from its end distances alone. NaN means "not given": certifying such a motion is
  /// a programmer error (asserted; the certificate answers `invalid_motion` when asserts are off).
  double radius = std::numeric_limits<double>::quiet_NaN();

  /// ‖Δ reference point‖ + radius · angle: no body point moves farther (`motion_length`).
  double length() const { return motion_length(from, to, reference, radius); }
  /// The pose at parameter t ∈ [0, 1]: `from` and `to` exactly at the ends.
  Pose at(double t) const;
};

/// How a certificate ended.
enum class MotionStatus {
  clear,           ///< certified: the distance stays above the margin along the whole motion
  blocked,         ///< a pose at distance ≤ margin was found (t_blocked, distance_at_block)
  refused_cap,     ///< gave up: more bisection queries than the cap, or pieces shorter than the
                   ///< parameter resolution (1e-9): the motion grazes the margin
  deadline,        ///< gave up: the deadline passed
  cancelled,       ///< gave up: the caller's cancel flag was set (CertificateOptions::cancel)
  invalid_motion,  ///< the motion's radius is not given or negative (a programmer error)
};

/// The default cap on the bisection queries of one certificate.
inline constexpr int kMaxCertificateQueries = 200000;
/// The default number of bisection queries after which a certificate asks its exact second
/// opinion (CertificateOptions::decide_after, MotionRequest::sweep_after, the planner's
/// certificates): past it, the motion grazes the margin and a sweep is the cheaper answer.
inline constexpr int kSweepAfterQueries = 64;

/// A lower bound on the distance at `pose`, exact when below `enough` (any value ≥ `enough`
/// otherwise, like `DistanceRequest::enough`).
using DistanceBound = std::function<double(const Pose& pose, double enough)>;
/// The same for a certificate that asks two midpoints at once (`certify_motion_paired`): `lane`
/// (0 or 1) says which of the two; calls on different lanes may run at the same time, calls on
/// one lane never do, and the lanes are assigned by the certificate's own order, whatever the
/// number of threads.
using LaneDistanceBound = std::function<double(const Pose& pose, double enough, int lane)>;

struct CertificateOptions {
  double margin = 0.0;  ///< required distance (≥ 0); a pose at distance ≤ margin blocks
  int max_queries = kMaxCertificateQueries;  ///< cap on the bisection (midpoint) queries
  /// Past this time the certificate gives up (checked every 64 bisection queries).
  std::optional<std::chrono::steady_clock::time_point> deadline = std::nullopt;
  /// Once either flag is set (by another thread, say, when the answer is no longer needed) the
  /// certificate gives up before its next query (status `cancelled`). Two, so that one can be
  /// this certificate's own and the other its whole search's. Not owned; null: never.
  std::array<const std::atomic<bool>*, 2> cancel{};
  /// Known lower bounds on the distance at `from` / `to` (negative: unknown, queried).
  double from_bound = -1.0;
  double to_bound = -1.0;
  /// An exact second opinion for motions that graze the margin (`sweep_translation` for a pure
  /// translation): asked once, when the bisection passes `decide_after` queries or is about to
  /// give up, whichever comes first, with the smallest distance bound seen so far (> margin).
  /// true ends the certificate clear; false lets the bisection go on from where it is, to find
  /// where the motion is blocked. Empty: never asked.
  std::function<bool(double smallest)> decide;
  int decide_after = kSweepAfterQueries;
  /// For `certify_motion_paired`: the two pieces asked at once are the earliest and the latest
  /// not yet certified, instead of the two earliest. A motion blocked near its end is found
  /// blocked without certifying all that comes before (a long bridge round a failed edge); a
  /// free motion is cut into the same pieces when the distances returned are the same.
  bool from_both_ends = false;
};

struct Certificate {
  MotionStatus status = MotionStatus::refused_cap;
  double t_blocked = -1.0;        ///< blocked: the motion parameter of the pose found
  double distance_at_block = 0.0; ///< blocked: the distance there (≤ margin)
  double min_distance = std::numeric_limits<double>::infinity();  ///< smallest bound seen
  int distance_queries = 0;       ///< calls of the distance function, ends included
  bool decided = false;           ///< CertificateOptions::decide was asked

  bool clear() const { return status == MotionStatus::clear; }
};

/// A straight motion seen as a pure translation: B kept at `from`'s rotation and moved by its
/// reference point's displacement. `slack` bounds how far any body point of the real motion
/// strays from there: radius × turn angle (‖R − I‖ ≤ angle), 0 when the rotations are equal (the
/// translation is then `to.translation − from.translation`, exactly). When the translation keeps
/// more than margin + slack (`sweep_translation`), the motion keeps more than the margin.
struct TranslationBound {
  Vec3 translation = Vec3::Zero();
  double slack = 0.0;
};
TranslationBound as_translation(const Motion& motion);

/// Schwarzer–Saha–Latombe certificate of `motion` with the distance function `distance_at`.
/// With D a lower bound on the distance, the piece [t0, t1] is free when
/// (t1 − t0)·length < (D(t0) − margin) + (D(t1) − margin): no body point moves far enough to
/// close the gap. Otherwise its midpoint is queried (blocked when D ≤ margin there) and both
/// halves are certified, depth first, earliest first. Distances are asked only as exactly as
/// needed: margin + length at the ends, margin + half the piece's length at a midpoint.
/// Never answers `clear` for a motion that comes within the margin.
Certificate certify_motion(const Motion& motion, const DistanceBound& distance_at,
                           const CertificateOptions& options);
/// The same certificate, two pieces at a time: the two earliest pieces that need a query have
/// their midpoints asked at once, in parallel (lane 0 the earlier, lane 1 the later), and the
/// earlier one's halves come next. A free motion is cut into the same pieces as by
/// `certify_motion` when the distances returned are the same, so it takes the same queries in
/// about half the time on two cores; a blocked one stops at the first blocked midpoint in this
/// order (the earlier of the two when both block), which may be another one than
/// `certify_motion` finds. With `from_both_ends` lane 1 works from the motion's end backwards
/// instead. For callers whose own work leaves a core idle (the planner's
/// shortcuts, straight moves, grid edges, a joined path's lazy edges and the final check).
Certificate certify_motion_paired(const Motion& motion, const LaneDistanceBound& distance_at,
                                  const CertificateOptions& options);

// ---- motion clearance against a tree --------------------------------------------------------
struct MotionRequest {
  double margin = 0.0;  ///< required distance along the whole motion
  int max_queries = kMaxCertificateQueries;  ///< cap on the bisection queries (then refused)
  /// A translation whose certificate passes this many bisection queries (it grazes the margin)
  /// is decided by `sweep_translation` in one traversal — a pure one, or one that turns by less
  /// than half its gap allows (`as_translation`: its ends' rotations differ by rounding); when
  /// the sweep is not clear the bisection goes on. Negative: never.
  int sweep_after = kSweepAfterQueries;
};
struct MotionResult {
  MotionStatus status = MotionStatus::refused_cap;
  double t_blocked = -1.0;  ///< blocked: parameter where the distance was found ≤ margin
  double distance_at_block = 0.0;
  double min_distance = std::numeric_limits<double>::infinity();  ///< smallest distance bound seen
  int distance_queries = 0;
  int sweeps = 0;  ///< exact sweeps of the translation run (0 or 1)
  QueryStats stats;

  /// Certified: distance > margin on the whole continuous motion.
  bool clear() const { return status == MotionStatus::clear; }
};
/// Is the motion of B (`motion`, see `interpolate`) against A at `pose_a` clear of A by more
/// than the margin everywhere? `certify_motion` with the tree distance; a grazing translation
/// is decided by `sweep_translation` (MotionRequest::sweep_after). Contact (distance 0)
/// always blocks, so margin 0 asks for a collision-free motion. Distances are between the
/// triangle surfaces (a body wholly inside a closed mesh is not in contact).
MotionResult motion_clearance(const Bvh& a, const Pose& pose_a, const Bvh& b, const Motion& motion,
                              const MotionRequest& request = {});

// ---- exact sweep of a translation -----------------------------------------------------------
struct SweepRequest {
  Vec3 translation = Vec3::Zero();  ///< B moves from pose_b to pose_b moved by this (world frame)
  double margin = 0.0;              ///< a pair at distance ≤ margin anywhere along the motion blocks
  /// Triangle pairs (A's id, B's id) that never block (not owned; null: none), as
  /// `DistanceRequest::exclude_if`: the assembly's mate rule.
  const std::function<bool(std::uint32_t triangle_a, std::uint32_t triangle_b)>* exclude_if = nullptr;
  /// Node pairs (A's node index, B's node index in `Bvh::nodes`) whose every triangle pair
  /// `exclude_if` leaves out (not owned; null: none): a rule proven for whole subtrees at once,
  /// so that a large face sliding along another is not visited triangle pair by triangle pair.
  const std::function<bool(std::int32_t node_a, std::int32_t node_b)>* exclude_nodes_if = nullptr;
};
struct SweepResult {
  bool clear = true;             ///< every pair not left out keeps more than the margin along the whole motion
  std::uint32_t triangle_a = 0;  ///< not clear: a blocking pair (input ids)
  std::uint32_t triangle_b = 0;
  QueryStats stats;
};
/// Is the pure translation of B against A clear by more than the margin? Exact, in one
/// traversal: no steps along the motion, no certificate — each node pair is bounded against
/// B's node swept along the whole translation (`swept_rectangle_lower_bound`), each leaf pair
/// tested with `triangle_sweep_within`. The answer a `certify_motion` of the same translation
/// gives with distances that leave the same pairs out, without its parameter resolution; stops
/// at the first blocking pair. Deterministic.
SweepResult sweep_translation(const Bvh& a, const Pose& pose_a, const Bvh& b, const Pose& pose_b,
                              const SweepRequest& request);

/// The exact second opinion on a grazing motion (CertificateOptions::decide): the sweep of
/// `as_translation(motion)` with the margin raised by its slack, pairs left out by `exclude_if`
/// as in SweepRequest; nullopt, and no sweep, when the slack is not under half the gap
/// `smallest` − margin (a turn that large would not be cleared).
std::optional<SweepResult> sweep_as_translation(
    const Bvh& a, const Pose& pose_a, const Bvh& b, const Motion& motion, double margin, double smallest,
    const std::function<bool(std::uint32_t triangle_a, std::uint32_t triangle_b)>* exclude_if = nullptr);

}  // namespace swept
