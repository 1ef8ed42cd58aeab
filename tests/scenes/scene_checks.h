#pragma once
/// Brute-force geometric checks for the scene tests: a uniform grid over triangle boxes, exact
/// triangle distances (swept/geometry/distance.h) and a certified straight-motion check
/// (Schwarzer, Saha, Latombe 2005) that does not depend on the BVH or query layers.
#include "swept/geometry/pose.h"
#include "swept/geometry/types.h"

#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace swept::test {

/// Triangles bucketed by the grid cells their bounding boxes touch.
class TriangleGrid {
 public:
  TriangleGrid(std::vector<Triangle> triangles, double cell);
  const std::vector<Triangle>& triangles() const { return triangles_; }
  const Aabb& box(std::uint32_t i) const { return boxes_[i]; }
  const Aabb& bounds() const { return bounds_; }
  /// Indices of the triangles whose boxes may overlap `query` (each once, ascending).
  std::vector<std::uint32_t> near(const Aabb& query) const;

 private:
  struct KeyHash {
    std::size_t operator()(const std::array<std::int64_t, 3>& k) const;
  };
  std::array<std::int64_t, 3> key(const Vec3& p) const;
  std::vector<Triangle> triangles_;
  std::vector<Aabb> boxes_;
  Aabb bounds_;
  double cell_;
  std::unordered_map<std::array<std::int64_t, 3>, std::vector<std::uint32_t>, KeyHash> cells_;
};

/// The body's triangles (given in the body frame) placed at `pose`.
std::vector<Triangle> placed(const std::vector<Triangle>& body, const Pose& pose);

/// min(cap, exact minimum distance between the placed body and the obstacles).
double capped_distance(const TriangleGrid& obstacles, const std::vector<Triangle>& body_world, double cap);

/// Do the placed body and the obstacles intersect (or touch)?
bool collides(const TriangleGrid& obstacles, const std::vector<Triangle>& body_world);

/// A body for motion checks: its triangles, the reference point (centre of its box) and the
/// largest distance from it to a vertex.
struct MovingBody {
  std::vector<Triangle> triangles;
  Vec3 reference = Vec3::Zero();
  double radius = 0.0;
};
MovingBody moving_body(std::vector<Triangle> triangles);

/// Certifies that the straight motion a → b (reference point linear, rotation slerp) keeps at
/// least `clearance` from the obstacles everywhere: a segment is free when the motion bound
/// ‖Δc‖ + radius·θ is below (D(a) − clearance) + (D(b) − clearance), else it is bisected.
bool motion_free(const TriangleGrid& obstacles, const MovingBody& body, const Pose& a, const Pose& b,
                 double clearance);

}  // namespace swept::test
