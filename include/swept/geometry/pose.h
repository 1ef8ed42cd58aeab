#pragma once
/// Rigid transforms (SE(3)) as an aggregate: x_world = rotation · x_local + translation.
#include "swept/geometry/types.h"

#include <algorithm>
#include <cmath>

namespace swept {

/// A rigid pose: rotation (orthonormal, det +1) then translation. Units: the model's length
/// unit. The default is the identity.
struct Pose {
  Mat3 rotation = Mat3::Identity();
  Vec3 translation = Vec3::Zero();

  Vec3 apply(const Vec3& v) const { return rotation * v + translation; }
  Vec3 apply_inverse(const Vec3& v) const { return rotation.transpose() * (v - translation); }

  static Pose identity() { return {}; }
  static Pose from_translation(const Vec3& t) { return {Mat3::Identity(), t}; }
  /// From a (not necessarily normalised) quaternion and a translation. The components are
  /// scaled by the largest first, so huge or tiny ones neither overflow nor underflow the norm;
  /// an all-zero or non-finite quaternion gives the identity (callers that read files reject
  /// those with a message first).
  static Pose from_quaternion(const Quat& q, const Vec3& t) {
    const double big = q.coeffs().cwiseAbs().maxCoeff();
    if (!(big > 0.0) || !std::isfinite(big)) return {Mat3::Identity(), t};
    const Quat u(q.coeffs() / big);
    return {u.normalized().toRotationMatrix(), t};
  }
  /// From an axis (any length > 0, scaled like the quaternion) and an angle in radians, and a
  /// translation. A zero or non-finite axis gives the identity rotation.
  static Pose from_axis_angle(const Vec3& axis, double angle, const Vec3& t) {
    const double big = axis.cwiseAbs().maxCoeff();
    if (!(big > 0.0) || !std::isfinite(big)) return {Mat3::Identity(), t};
    return {Eigen::AngleAxisd(angle, (axis / big).normalized()).toRotationMatrix(), t};
  }
  Quat quaternion() const { return Quat(rotation).normalized(); }
};

/// a ∘ b: first b, then a.
inline Pose compose(const Pose& a, const Pose& b) {
  return {a.rotation * b.rotation, a.rotation * b.translation + a.translation};
}

/// The inverse transform.
inline Pose inverse(const Pose& a) {
  Mat3 rt = a.rotation.transpose();
  return {rt, -(rt * a.translation)};
}

/// The pose of frame B expressed in frame A: inverse(a) ∘ b.
inline Pose relative(const Pose& a, const Pose& b) { return compose(inverse(a), b); }

}  // namespace swept

namespace swept {

/// The straight SE(3) motion of SPEC §3/§4 at parameter t ∈ [0, 1]: the body-frame point
/// `reference` moves linearly from a.apply(reference) to b.apply(reference); the rotation is
/// the slerp from a.rotation to b.rotation (shortest arc).
inline Pose interpolate(const Pose& a, const Pose& b, double t, const Vec3& reference) {
  const Quat qa = a.quaternion();
  Quat qb = b.quaternion();
  const Quat q = qa.slerp(t, qb);
  const Vec3 ca = a.apply(reference), cb = b.apply(reference);
  const Vec3 c = (1.0 - t) * ca + t * cb;
  const Mat3 rot = q.toRotationMatrix();
  return {rot, c - rot * reference};
}

/// Angle in radians of the rotation between two orientations, in [0, π].
inline double rotation_angle(const Mat3& a, const Mat3& b) {
  const Quat q(a.transpose() * b);
  const double w = std::min(1.0, std::abs(q.normalized().w()));
  return 2.0 * std::acos(w);
}

/// Appends `from`'s triangles to `to`, placed by `pose` (copied as they are for the identity),
/// with its CAD cylinders placed the same way and `cylinder_of` renumbered; once either soup has
/// cylinders, the triangles without one are marked −1.
void append_placed(TriangleSoup& to, const TriangleSoup& from, const Pose& pose = {});

}  // namespace swept
