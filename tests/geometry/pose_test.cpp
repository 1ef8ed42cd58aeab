// Poses from quaternions and axes of any magnitude.
#include "swept/geometry/pose.h"

#include <gtest/gtest.h>

#include <numbers>

namespace swept {
namespace {

TEST(Pose, HugeAndTinyQuaternionsGiveTheirRotation) {
  // 90° about z: (x, y, z, w) = (0, 0, s, s) for any s > 0; s = 1e300 overflowed the norm to
  // infinity and read as the identity, s = 1e-300 underflowed it.
  for (double s : {1e300, 1.0, 1e-300}) {
    const Pose p = Pose::from_quaternion(Quat(s, 0, 0, s), Vec3::Zero());  // Eigen: (w, x, y, z)
    const Vec3 x = p.apply(Vec3::UnitX());
    EXPECT_NEAR(x.x(), 0.0, 1e-15) << s;
    EXPECT_NEAR(x.y(), 1.0, 1e-15) << s;
  }
  const Pose a = Pose::from_axis_angle(Vec3(0, 0, 1e300), std::numbers::pi / 2, Vec3::Zero());
  EXPECT_NEAR(a.apply(Vec3::UnitX()).y(), 1.0, 1e-15);
  const Pose b = Pose::from_axis_angle(Vec3(0, 0, 1e-300), std::numbers::pi / 2, Vec3::Zero());
  EXPECT_NEAR(b.apply(Vec3::UnitX()).y(), 1.0, 1e-15);
  // Nothing to normalise: the identity, never NaN.
  EXPECT_EQ(Pose::from_quaternion(Quat(0, 0, 0, 0), Vec3::Zero()).rotation, Mat3::Identity());
  EXPECT_TRUE(Pose::from_quaternion(Quat(1, std::nan(""), 0, 0), Vec3::Zero()).rotation.allFinite());
}

}  // namespace
}  // namespace swept
