#include "swept/geometry/rss.h"

#include <algorithm>
#include <cmath>

namespace swept {

double signed_distance(const Rss& v, const Vec3& point) {
  const Vec3 d = v.axes.transpose() * (point - v.center);
  const double dx = std::max(std::abs(d.x()) - v.half_length[0], 0.0);
  const double dy = std::max(std::abs(d.y()) - v.half_length[1], 0.0);
  return std::sqrt(dx * dx + dy * dy + d.z() * d.z()) - v.radius;
}

}  // namespace swept
