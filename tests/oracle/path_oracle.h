#pragma once
/// An independent checker of planned paths for the test suite. It shares no code with swept:
/// only Eigen (and oneTBB inside), its own exact triangle–triangle distance, its own box trees,
/// its own motion and its own certificate. Agreement between this and the planner is evidence
/// that neither is wrong in the same way.
///
/// Units are whatever the caller's coordinates are in; frames are named on every field.
#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace oracle {

/// A triangle by its three corners. Zero-area and sliver triangles are allowed.
struct Tri {
  Eigen::Vector3d v[3];
};

/// A rigid placement: x_world = R · x_body + t. R must be a rotation matrix.
struct RigidPose {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
};

struct PathCheckInput {
  std::vector<Tri> obstacles;  ///< world frame
  std::vector<Tri> body;       ///< body frame
  std::vector<RigidPose> poses;  ///< the path's waypoints, in order
  /// Body-frame point that moves on a straight line between waypoints; the rotation is the
  /// shortest slerp about it.
  Eigen::Vector3d reference = Eigen::Vector3d::Zero();
  double clearance = 0;  ///< distance required along the whole continuous motion
  /// > 0: a segment with an end closer than `clearance` is a motion in contact: a pure
  /// translation along which no two triangles reach more than this into each other.
  double contact_tolerance = 0;
  /// Total dense samples, spread over the segments by length (at least 16 intervals each).
  int dense_samples = 2000;
  /// Safety caps of one segment's certificate: exceeded → "not certified".
  int max_certificate_queries = 200000;
  int max_certificate_depth = 60;
};

struct PathCheckReport {
  bool valid = false;  ///< every segment certified (the contact rule where it applies)
  std::string why;     ///< when not valid: segment, t, distance found, triangle pair
  int bad_segment = -1;
  double bad_t = -1;
  /// Smallest exact distance over all triangle pairs at the dense samples (motions in contact included).
  double dense_min = std::numeric_limits<double>::infinity();
  /// Largest motion-metric length between consecutive dense samples: the true minimum along
  /// the path is at least dense_min − dense_spacing/2.
  double dense_spacing = 0;
  double max_segment_length = 0;  ///< longest segment in the motion metric ‖Δc‖ + r·θ
  std::size_t contact_segments = 0;  ///< segments checked by the contact rule
  /// The deepest any two triangles reach into each other at the contact segments' samples.
  double max_penetration = 0;
  std::size_t certificate_queries = 0;  ///< exact distance queries spent on certificates
};

/// Checks a path: the Schwarzer–Saha–Latombe (2005) certificate of every segment with exact
/// distances, and dense exact distances. The contact rule (docs/planner.md, "The contact
/// model"), checked by its consequence, not by the planner's mate rule: when contact_tolerance > 0,
/// a segment with an end at distance ≤ clearance must be a pure translation along which, at
/// samples no farther apart than a quarter of the tolerance, no two intersecting triangles
/// overlap by more than the tolerance along every separating axis of the pair
/// (triangle_penetration); every other segment is certified with all pairs.
PathCheckReport check_path(const PathCheckInput& input);

/// How deep two triangles reach into each other: 0 when they do not intersect, else the
/// smallest overlap of their projections over the candidate separating axes (both normals, the
/// nine edge cross products, and for coplanar triangles the six in-plane edge normals): the
/// shortest translation along those axes that separates them.
double triangle_penetration(const Tri& a, const Tri& b);

/// Exact distance between two triangles: 0 when they intersect (including coplanar overlap),
/// else the smallest of the vertex–triangle and edge–edge distances. Never NaN for finite input.
double triangle_distance(const Tri& a, const Tri& b);

/// The smallest triangle_distance between `a` and `b` moved by t·sweep over t ∈ [0, 1]: golden
/// section on the distance, which is convex in a translation of one convex set, plus both ends.
double translation_minimum(const Tri& a, const Tri& b, const Eigen::Vector3d& sweep);

/// Exact smallest distance between two triangle sets in the same frame (+∞ if one is empty).
double exact_distance(const std::vector<Tri>& obstacles_world, const std::vector<Tri>& body_world);

/// Where the body is at parameter s ∈ [0, 1] of the motion from `a` to `b`: the reference
/// point moves linearly, the rotation is the shortest slerp.
RigidPose interpolate_pose(const RigidPose& a, const RigidPose& b, double s, const Eigen::Vector3d& reference);

/// Rotation angle between two orientations, in [0, π].
double rotation_angle(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b);

}  // namespace oracle
