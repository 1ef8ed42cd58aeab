#pragma once
/// Rectangle Swept Spheres (Larsen, Gottschalk, Lin, Manocha 1999, "Fast proximity queries with
/// swept sphere volumes"): the set of points within `radius` of a rectangle.
#include "swept/geometry/types.h"

#include <array>
#include <numbers>

namespace swept {

/// An RSS: the rectangle { center + s·e1 + t·e2 : |s| ≤ half_length[0], |t| ≤ half_length[1] }
/// swept by a sphere of radius `radius`. `axes` holds e1 (long side), e2 (short side) and
/// e3 = e1 × e2 (the rectangle's normal) as columns. All in the frame of the model.
struct Rss {
  Mat3 axes = Mat3::Identity();
  Vec3 center = Vec3::Zero();
  std::array<double, 2> half_length{0.0, 0.0};
  double radius = 0.0;
};

/// SA(RSS) = 2ab + 2π(a+b)r + 4πr², with side lengths a, b and radius r (SPEC §2.3).
inline double surface_area(const Rss& v) {
  const double a = 2.0 * v.half_length[0], b = 2.0 * v.half_length[1], r = v.radius;
  return 2.0 * a * b + 2.0 * std::numbers::pi * (a + b) * r + 4.0 * std::numbers::pi * r * r;
}

/// V(RSS) = 2abr + π(a+b)r² + (4/3)πr³ (SPEC §2.3).
inline double volume(const Rss& v) {
  const double a = 2.0 * v.half_length[0], b = 2.0 * v.half_length[1], r = v.radius;
  return 2.0 * a * b * r + std::numbers::pi * (a + b) * r * r +
         4.0 / 3.0 * std::numbers::pi * r * r * r;
}

/// Distance from a point (same frame as the RSS) to the RSS's rectangle, minus the radius:
/// ≤ 0 when the point is inside the swept volume.
double signed_distance(const Rss& v, const Vec3& point);

/// True when `point` lies inside the RSS grown by `tolerance`.
inline bool contains(const Rss& v, const Vec3& point, double tolerance = 0.0) {
  return signed_distance(v, point) <= tolerance;
}

}  // namespace swept
