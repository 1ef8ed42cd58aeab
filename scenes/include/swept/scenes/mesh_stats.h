#pragma once
/// Triangle-quality statistics of a mesh (`swept mesh-stats`): how widely triangle sizes and
/// shapes spread, the property of CAD-exported meshes that the paper's INERTIA_FIT addresses.
#include "swept/geometry/types.h"

#include <cstddef>
#include <vector>

namespace swept::scenes {

/// A triangle counts as degenerate when shape_quality() (2·area / longest edge²) is ≤ this:
/// the criterion swept's importer uses for ImportedModel::degenerate_triangles.
inline constexpr double kDegenerateShapeQuality = 1e-12;

/// Statistics over one triangle soup. Areas in the soup's unit squared. Everything but
/// `triangles` and `degenerate` is taken over the non-degenerate triangles only; when there
/// are none, the ratios and the median are 0.
struct MeshStats {
  std::size_t triangles = 0;
  std::size_t degenerate = 0;        ///< shape_quality() ≤ kDegenerateShapeQuality
  double area_min = 0.0;             ///< smallest non-degenerate triangle area
  double area_max = 0.0;             ///< largest triangle area
  double area_ratio = 0.0;           ///< area_max / area_min
  double aspect_median = 0.0;        ///< median aspect_ratio() (longest edge / smallest height)
  double aspect_max = 0.0;
  double aspect_over_10 = 0.0;       ///< fraction (0…1) with aspect ratio > 10
};

/// Computes the statistics (deterministic: sorts a copy of the aspect ratios; O(n log n)).
MeshStats mesh_stats(const std::vector<Triangle>& triangles);

}  // namespace swept::scenes
