#pragma once
// Internal to swept_io: the triangles of a file's polygon face (OFF), for the readers that
// are ours.
#include "swept/geometry/types.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace swept::io_detail {

/// Appends the k − 2 triangles of the polygon whose corners are `points[corners[0]]`,
/// `points[corners[1]]`, … in the file's order, each wound as the polygon is, so that they cover
/// the polygon exactly, convex or not: ear clipping in the plane across the polygon's Newell
/// normal (a polygon that is not quite planar is triangulated as its shadow on that plane). A
/// polygon whose corners are all on one line (no normal) is fanned from its first corner: its
/// triangles have no area, as the face has none. Returns false when the polygon is not simple in that plane (its edges cross)
/// or the clipping ran past its work budget: the corners left are then fanned from one of them,
/// still k − 2 triangles, which a caller should report.
bool triangulate_polygon(std::span<const Vec3> points, std::span<const std::uint32_t> corners,
                         std::vector<std::array<std::uint32_t, 3>>& out);

}  // namespace swept::io_detail
