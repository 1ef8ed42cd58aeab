#pragma once
/// Certifying a path against a problem: the planner's own final pass, for the paths it returns
/// and for paths users bring (ours, OMPL `.path`, other planners'). `swept check` runs it.
#include "swept/plan/planner.h"

#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace swept {

struct PathCheckOptions {
  std::optional<double> clearance;       ///< required distance; default: the problem's
  /// Body-frame point the motion between two waypoints interpolates about (its path is a
  /// straight line, the rotation a slerp about it); default: the scene's reference point. OMPL
  /// interpolates SE(3) states about the body frame's origin: pass (0, 0, 0) for its paths.
  std::optional<Vec3> reference_point;
  /// Called with (segments checked, segments) as the segments finish, one call at a time, from
  /// whichever thread checked the segment; for a progress line. Not called when empty.
  std::function<void(std::size_t done, std::size_t total)> progress;
};

/// One segment (waypoint i → i + 1).
struct SegmentCheck {
  bool certified = false;  ///< the distance stays above the clearance along the whole motion
  /// An end within the clearance: certified as a pull by the contact model (docs/planner.md, "The
  /// contact model"), not by the distance certificate.
  bool in_contact = false;
  double min_distance = std::numeric_limits<double>::infinity();  ///< smallest exact distance found, all pairs
  double t_min = 0.0;                                             ///< where (motion parameter in [0, 1])
  /// Not certified: where the certificate found the distance at or below the clearance, and
  /// that distance (t = −1: it gave up after its query cap without finding one).
  double t_blocked = -1.0;
  double distance_at_block = 0.0;
};

struct PathCheckResult {
  bool valid = false;    ///< every segment certified (and the path has a pose)
  std::string message;   ///< one sentence: valid, or the first segment that is not and why
  double clearance = 0;  ///< the clearance checked
  std::vector<SegmentCheck> segments;
  /// Smallest exact distance found along the whole path (every segment and pair), where.
  double min_clearance = std::numeric_limits<double>::infinity();
  std::size_t min_segment = 0;
  double min_t = 0.0;
  Pose min_pose;
  /// The first segment not certified, the pose where it was blocked and the distance there
  /// (0: in collision).
  std::optional<std::size_t> first_bad_segment;
  Pose first_bad_pose;
  double first_bad_distance = 0.0;
  /// Segments with an end within the clearance (problem.contact_tolerance > 0): each must be a
  /// pure translation that the contact model certifies as a pull from that end (from its start
  /// when both are): every pair keeps the clearance but the mates of the mate rule there, which
  /// reach at most the contact tolerance into each other.
  std::size_t contact_segments = 0;
  std::uint64_t distance_queries = 0;
  std::uint64_t sweeps = 0;  ///< exact sweeps: grazing pure translations and pulls in contact (docs/planner.md)
};

/// Certifies every segment of `path` in the problem's scene with the certificate the planner
/// uses (Schwarzer, Saha, Latombe 2005), and finds the smallest distance along it: exact at every
/// waypoint and at 15 samples inside each segment, refined by a golden-section search around the
/// smallest (the certificate guarantees the clearance in between). Segments run in parallel;
/// the result is the same at any thread count (tested at 1, 2, 4 and 8).
PathCheckResult check_path(const Problem& problem, const PlanScene& scene, const Path& path,
                           const PathCheckOptions& options = {});

}  // namespace swept
