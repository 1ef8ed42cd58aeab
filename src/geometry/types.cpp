#include "swept/geometry/types.h"

#include "swept/geometry/pose.h"

#include <algorithm>
#include <cmath>

namespace swept {

double area(const Triangle& t) { return 0.5 * (t.p - t.q).cross(t.p - t.r).norm(); }

Vec3 centroid(const Triangle& t) { return (t.p + t.q + t.r) / 3.0; }

double shape_quality(const Triangle& t) {
  const double l2 = std::max({(t.q - t.p).squaredNorm(), (t.r - t.q).squaredNorm(),
                              (t.p - t.r).squaredNorm()});
  if (l2 == 0.0) return 0.0;
  return 2.0 * area(t) / l2;
}

double aspect_ratio(const Triangle& t) {
  const double l = std::sqrt(std::max({(t.q - t.p).squaredNorm(), (t.r - t.q).squaredNorm(),
                                       (t.p - t.r).squaredNorm()}));
  const double a = area(t);
  if (a <= 0.0) return std::numeric_limits<double>::infinity();
  const double h = 2.0 * a / l;  // smallest height is the one onto the longest edge
  return l / h;
}

Aabb bounds(const std::vector<Triangle>& triangles) {
  Aabb box;
  for (const Triangle& t : triangles) {
    box.extend(t.p);
    box.extend(t.q);
    box.extend(t.r);
  }
  return box;
}

bool cylinders_usable(const TriangleSoup& m) {
  if (m.cylinders.empty() && m.cylinder_of.empty()) return true;
  bool usable = m.cylinder_of.size() == m.triangles.size();
  for (const CadCylinder& c : m.cylinders)
    usable = usable && c.origin.allFinite() && c.axis.allFinite() && std::abs(c.axis.norm() - 1.0) < 1e-9 &&
             std::isfinite(c.radius) && c.radius > 0.0 && std::isfinite(c.deviation) && c.deviation >= 0.0;
  for (std::int32_t k : m.cylinder_of) usable = usable && k >= -1 && k < static_cast<std::int32_t>(m.cylinders.size());
  return usable;
}

void append_placed(TriangleSoup& to, const TriangleSoup& from, const Pose& pose) {
  const bool identity = pose.rotation == Mat3::Identity() && pose.translation == Vec3::Zero();
  if (!from.cylinders.empty() || !to.cylinder_of.empty()) {
    to.cylinder_of.resize(to.triangles.size(), -1);
    const auto base = static_cast<std::int32_t>(to.cylinders.size());
    if (from.cylinder_of.empty()) to.cylinder_of.insert(to.cylinder_of.end(), from.triangles.size(), -1);
    for (std::int32_t f : from.cylinder_of) to.cylinder_of.push_back(f < 0 ? -1 : base + f);
    for (CadCylinder c : from.cylinders) {
      if (!identity) c.origin = pose.apply(c.origin), c.axis = pose.rotation * c.axis;
      to.cylinders.push_back(c);
    }
  }
  if (identity) {
    to.triangles.insert(to.triangles.end(), from.triangles.begin(), from.triangles.end());
  } else {
    for (const Triangle& t : from.triangles) to.triangles.push_back({pose.apply(t.p), pose.apply(t.q), pose.apply(t.r)});
  }
}

}  // namespace swept
