#pragma once
// Rotation vectors (axis × angle, radians) and back (internal to src/plan): the grid's and the
// trees' rotation coordinates, the rotation limits' too.
#include "swept/geometry/types.h"

#include <Eigen/Geometry>

namespace swept::detail {

/// The rotation by |w| about w (the identity for w = 0).
inline Mat3 exp_rotation(const Vec3& w) {
  const double angle = w.norm();
  if (angle == 0.0) return Mat3::Identity();
  return Eigen::AngleAxisd(angle, w / angle).toRotationMatrix();
}

/// The rotation vector of `r`: angle in [0, π] times the unit axis.
inline Vec3 rotation_vector(const Mat3& r) {
  const Eigen::AngleAxisd turn(r);
  return turn.angle() * turn.axis();
}

}  // namespace swept::detail
