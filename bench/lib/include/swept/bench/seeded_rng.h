#pragma once
/// The seeded generator of the benchmarks' pose sets (SplitMix64): the same poses on every
/// platform, no std::*_distribution. Its one user is make_pose_sets (pose_sets.h).

#include "swept/geometry/types.h"

#include <cmath>
#include <cstdint>
#include <numbers>

namespace swept::bench {

struct SeededRng {
  std::uint64_t state;
  std::uint64_t next() {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  /// Uniform in [0, 1).
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  /// A uniformly distributed unit vector (rejection from the cube).
  Vec3 direction() {
    for (;;) {
      const Vec3 v(2 * uniform() - 1, 2 * uniform() - 1, 2 * uniform() - 1);
      const double n = v.norm();
      if (n > 1e-3 && n <= 1.0) return v / n;
    }
  }
  /// A uniformly distributed rotation (Shoemake's quaternion).
  Mat3 rotation() {
    const double u1 = uniform(), u2 = uniform(), u3 = uniform();
    const double a = std::sqrt(1 - u1), b = std::sqrt(u1);
    const double t2 = 2 * std::numbers::pi * u2, t3 = 2 * std::numbers::pi * u3;
    return Quat(b * std::cos(t3), a * std::sin(t2), a * std::cos(t2), b * std::sin(t3)).normalized().toRotationMatrix();
  }
};

}  // namespace swept::bench
