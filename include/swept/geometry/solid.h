#pragma once
/// Closed surfaces in a triangle soup, and whether a point is inside one. The distance queries
/// measure between surfaces, so a body wholly inside a closed part (or a part wholly inside a
/// closed body) is at a positive distance although the solids overlap; the planner and
/// `check_path` use these to call that a collision.
#include "swept/geometry/types.h"

#include <cstdint>
#include <span>
#include <vector>

namespace swept {

/// A connected part of a triangle soup: triangles connected through shared edges (vertices
/// matched by exact coordinates), closed when every edge of the part is shared by exactly two of
/// its triangles (a closed 2-manifold surface; orientation is not needed).
struct SurfacePart {
  std::vector<std::uint32_t> triangles;  ///< ascending
  bool closed = false;
  Aabb box;
};

/// The connected parts of a triangle soup, ordered by their first triangle. Degenerate triangles
/// (two equal vertices) belong to no part.
std::vector<SurfacePart> surface_parts(std::span<const Triangle> triangles);

/// Is `p` inside the solid bounded by the closed surface `triangles[component[i]]`? The solid is
/// the side the triangles' normals ((q − p) × (r − p)) point away from: for each of three rays
/// from p in fixed, non-axis directions the crossings are counted +1 where the ray leaves through
/// a triangle's front and −1 where it enters, and p is inside when at least two rays count a
/// positive total (a ray through an edge or vertex can miscount). A surface oriented inward, like
/// a room modelled from the inside, has its solid outside: points in the room are not inside. A
/// surface with inconsistent orientation may go unreported. Points on the surface give either
/// answer.
bool inside_closed(std::span<const Triangle> triangles, std::span<const std::uint32_t> component, const Vec3& p);

}  // namespace swept
