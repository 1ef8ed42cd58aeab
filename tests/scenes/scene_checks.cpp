#include "scene_checks.h"

#include "swept/geometry/distance.h"

#include <algorithm>
#include <cmath>

namespace swept::test {

namespace {

Aabb triangle_box(const Triangle& t) {
  Aabb b;
  b.extend(t.p);
  b.extend(t.q);
  b.extend(t.r);
  return b;
}

double box_gap(const Aabb& a, const Aabb& b) {
  const Vec3 d = (a.min - b.max).cwiseMax(b.min - a.max).cwiseMax(Vec3::Zero());
  return d.norm();
}

Aabb grown(const Aabb& b, double g) { return {b.min - Vec3::Constant(g), b.max + Vec3::Constant(g)}; }

bool segment_free(const TriangleGrid& obstacles, const MovingBody& body, const Pose& a, const Pose& b, double da,
                  double db, double clearance, int depth) {
  const double motion = (b.apply(body.reference) - a.apply(body.reference)).norm() +
                        body.radius * rotation_angle(a.rotation, b.rotation);
  if (motion < (da - clearance) + (db - clearance)) return true;
  if (depth > 40) return false;
  const Pose m = interpolate(a, b, 0.5, body.reference);
  const double dm = capped_distance(obstacles, placed(body.triangles, m), 50.0);
  if (dm <= clearance) return false;
  return segment_free(obstacles, body, a, m, da, dm, clearance, depth + 1) &&
         segment_free(obstacles, body, m, b, dm, db, clearance, depth + 1);
}

}  // namespace

std::size_t TriangleGrid::KeyHash::operator()(const std::array<std::int64_t, 3>& k) const {
  std::uint64_t h = 1469598103934665603ull;
  for (std::int64_t v : k) h = (h ^ static_cast<std::uint64_t>(v)) * 1099511628211ull;
  return static_cast<std::size_t>(h);
}

std::array<std::int64_t, 3> TriangleGrid::key(const Vec3& p) const {
  return {static_cast<std::int64_t>(std::floor(p.x() / cell_)), static_cast<std::int64_t>(std::floor(p.y() / cell_)),
          static_cast<std::int64_t>(std::floor(p.z() / cell_))};
}

TriangleGrid::TriangleGrid(std::vector<Triangle> triangles, double cell) : triangles_(std::move(triangles)), cell_(cell) {
  boxes_.reserve(triangles_.size());
  for (std::uint32_t i = 0; i < triangles_.size(); ++i) {
    const Aabb b = triangle_box(triangles_[i]);
    boxes_.push_back(b);
    bounds_.extend(b);
    const auto lo = key(b.min), hi = key(b.max);
    for (auto x = lo[0]; x <= hi[0]; ++x)
      for (auto y = lo[1]; y <= hi[1]; ++y)
        for (auto z = lo[2]; z <= hi[2]; ++z) cells_[{x, y, z}].push_back(i);
  }
}

std::vector<std::uint32_t> TriangleGrid::near(const Aabb& query) const {
  std::vector<std::uint32_t> out;
  const Aabb q{query.min.cwiseMax(bounds_.min), query.max.cwiseMin(bounds_.max)};
  if (q.empty()) return out;
  const auto lo = key(q.min), hi = key(q.max);
  for (auto x = lo[0]; x <= hi[0]; ++x)
    for (auto y = lo[1]; y <= hi[1]; ++y)
      for (auto z = lo[2]; z <= hi[2]; ++z) {
        const auto it = cells_.find({x, y, z});
        if (it != cells_.end()) out.insert(out.end(), it->second.begin(), it->second.end());
      }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<Triangle> placed(const std::vector<Triangle>& body, const Pose& pose) {
  std::vector<Triangle> out;
  out.reserve(body.size());
  for (const Triangle& t : body) out.push_back({pose.apply(t.p), pose.apply(t.q), pose.apply(t.r)});
  return out;
}

double capped_distance(const TriangleGrid& obstacles, const std::vector<Triangle>& body_world, double cap) {
  double best = cap;
  if (box_gap(bounds(body_world), obstacles.bounds()) >= cap) return cap;
  for (const Triangle& t : body_world) {
    const Aabb tb = triangle_box(t);
    if (box_gap(tb, obstacles.bounds()) >= best) continue;
    for (std::uint32_t j : obstacles.near(grown(tb, best))) {
      if (box_gap(tb, obstacles.box(j)) >= best) continue;
      best = std::min(best, triangle_distance(t, obstacles.triangles()[j]).distance);
    }
  }
  return best;
}

bool collides(const TriangleGrid& obstacles, const std::vector<Triangle>& body_world) {
  for (const Triangle& t : body_world) {
    const Aabb tb = triangle_box(t);
    for (std::uint32_t j : obstacles.near(tb)) {
      if (box_gap(tb, obstacles.box(j)) > 0.0) continue;
      if (triangles_intersect(t, obstacles.triangles()[j])) return true;
    }
  }
  return false;
}

MovingBody moving_body(std::vector<Triangle> triangles) {
  MovingBody b;
  b.reference = bounds(triangles).center();
  for (const Triangle& t : triangles)
    for (int k = 0; k < 3; ++k) b.radius = std::max(b.radius, (t[k] - b.reference).norm());
  b.triangles = std::move(triangles);
  return b;
}

bool motion_free(const TriangleGrid& obstacles, const MovingBody& body, const Pose& a, const Pose& b,
                 double clearance) {
  const double da = capped_distance(obstacles, placed(body.triangles, a), 50.0);
  const double db = capped_distance(obstacles, placed(body.triangles, b), 50.0);
  if (da <= clearance || db <= clearance) return false;
  return segment_free(obstacles, body, a, b, da, db, clearance, 0);
}

}  // namespace swept::test
