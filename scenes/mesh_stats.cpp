// Triangle-quality statistics (see swept/scenes/mesh_stats.h).
#include "swept/scenes/mesh_stats.h"

#include <algorithm>

namespace swept::scenes {

MeshStats mesh_stats(const std::vector<Triangle>& triangles) {
  MeshStats s;
  s.triangles = triangles.size();
  std::vector<double> aspects;
  aspects.reserve(triangles.size());
  std::size_t over_10 = 0;
  for (const Triangle& t : triangles) {
    if (shape_quality(t) <= kDegenerateShapeQuality) {
      ++s.degenerate;
      continue;
    }
    const double a = area(t);
    s.area_min = aspects.empty() ? a : std::min(s.area_min, a);
    s.area_max = aspects.empty() ? a : std::max(s.area_max, a);
    const double ar = aspect_ratio(t);
    if (ar > 10.0) ++over_10;
    aspects.push_back(ar);
  }
  if (aspects.empty()) return s;
  s.area_ratio = s.area_max / s.area_min;
  std::sort(aspects.begin(), aspects.end());
  const std::size_t n = aspects.size();
  s.aspect_median = n % 2 == 1 ? aspects[n / 2] : 0.5 * (aspects[n / 2 - 1] + aspects[n / 2]);
  s.aspect_max = aspects.back();
  s.aspect_over_10 = static_cast<double>(over_10) / static_cast<double>(n);
  return s;
}

}  // namespace swept::scenes
