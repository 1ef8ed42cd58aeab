// Straight pulls of a part (or subassembly) out of the parts still in place (parts.h): the
// directions of local freedom, the length to leave the box, and the certificate with the mate rule.
#include "parts.h"

#include "swept/geometry/assert.h"
#include "swept/query/motion.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>

namespace swept::assembly_detail {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Gap between two boxes (0 when they overlap).
double box_gap(const Aabb& a, const Aabb& b) {
  const Vec3 lo = (b.min - a.max).cwiseMax(a.min - b.max).cwiseMax(Vec3::Zero());
  return lo.norm();
}

void add_unique(std::vector<Vec3>& out, const Vec3& v) {
  const double n = v.norm();
  if (!(n > 1e-12)) return;
  const Vec3 u = v / n;
  for (const Vec3& e : out)
    if (e.dot(u) > 1.0 - 1e-9) return;
  out.push_back(u);
}

}  // namespace

Body make_body(const Assembly& assembly, const std::vector<std::size_t>& parts, const BuildConfig& config) {
  Body b;
  for (std::size_t i : parts) {
    const auto& t = assembly.parts[i].mesh.triangles;
    b.triangles.insert(b.triangles.end(), t.begin(), t.end());
  }
  // Creases are found part by part (parts of a group do not share edges).
  for (std::size_t i : parts) {
    const auto planes = part_planes(assembly.parts[i].mesh.triangles);
    b.planes.insert(b.planes.end(), planes.begin(), planes.end());
  }
  for (const Triangle& t : b.triangles)
    for (int v = 0; v < 3; ++v) b.box.extend(t[v]);
  auto tree = build_bvh(b.triangles, config);
  SWEPT_ASSERT(tree.ok(), "read_assembly refuses empty parts and non-finite coordinates");
  b.tree = std::move(*tree);
  return b;
}

double exit_length(const Body& moving, const std::vector<const Body*>& obstacles, const Vec3& d, double margin) {
  Aabb others;
  for (const Body* o : obstacles) others.extend(o->box);
  if (others.empty()) return 0.0;
  // The smallest s ≥ 0 at which the moved box is apart from the others' box along some axis.
  double best = kInf;
  for (int k = 0; k < 3; ++k) {
    double s = kInf;
    if (d[k] > 1e-12) s = (others.max[k] + margin - moving.box.min[k]) / d[k];
    else if (d[k] < -1e-12) s = (others.min[k] - margin - moving.box.max[k]) / d[k];
    best = std::min(best, std::max(s, 0.0));
  }
  return best;
}

std::vector<Vec3> pull_directions(const Body& moving, const std::vector<const Body*>& obstacles, double threshold) {
  std::vector<Vec3> out{Vec3::UnitZ(), -Vec3::UnitZ(), Vec3::UnitX(), -Vec3::UnitX(), Vec3::UnitY(), -Vec3::UnitY()};
  // Contact normals by area, ties by first appearance (obstacle order, then pair order).
  std::vector<std::pair<Vec3, double>> normals;
  auto add_normal = [&](const Vec3& n, double area) {
    if (n.isZero()) return;
    for (auto& [e, a] : normals)
      if (e.dot(n) > 1.0 - 1e-9) {
        a += area;
        return;
      }
    normals.push_back({n, area});
  };
  for (const Body* o : obstacles) {
    if (box_gap(o->box, moving.box) > threshold) continue;
    const ProximityResult near = proximity_pairs(o->tree, Pose{}, moving.tree, Pose{}, {.threshold = threshold});
    for (const ContactPair& p : near.pairs.pairs) {
      const Triangle& to = o->triangles[p.triangle_a];
      const Triangle& tp = moving.triangles[p.triangle_b];
      add_normal(o->planes[p.triangle_a].normal, 0.5 * (to.q - to.p).cross(to.r - to.p).norm());
      add_normal(-moving.planes[p.triangle_b].normal, 0.5 * (tp.q - tp.p).cross(tp.r - tp.p).norm());
    }
  }
  std::stable_sort(normals.begin(), normals.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
  if (normals.size() > 8) normals.resize(8);
  for (const auto& [n, a] : normals) add_unique(out, n);
  std::size_t axes = 0;
  for (std::size_t i = 0; i < normals.size() && axes < 8; ++i)
    for (std::size_t j = i + 1; j < normals.size() && axes < 8; ++j) {
      const Vec3 c = normals[i].first.cross(normals[j].first);
      if (!(c.norm() > 1e-6)) continue;
      const std::size_t before = out.size();
      add_unique(out, c);
      add_unique(out, -c);
      if (out.size() > before) ++axes;
    }
  return out;
}

bool pull_is_clear(const Body& moving, const std::vector<const Body*>& obstacles, const Vec3& d, double length,
                   const PullSettings& settings, std::atomic<std::uint64_t>& queries, const Body** blocker) {
  // Only the obstacles the swept box can come near.
  Aabb swept = moving.box;
  swept.extend(Aabb{moving.box.min + length * d, moving.box.max + length * d});
  const double reach = settings.clearance + settings.tolerance;
  std::vector<const Body*> near;
  for (const Body* o : obstacles)
    if (box_gap(o->box, swept) <= reach) near.push_back(o);
  if (near.empty()) return true;
  std::vector<std::function<bool(std::uint32_t, std::uint32_t)>> mates;
  mates.reserve(near.size());
  for (const Body* o : near)
    mates.emplace_back([o, &moving, d, length, tol = settings.tolerance](std::uint32_t a, std::uint32_t b) {
      return mate_allows(o->triangles[a], o->planes[a], moving.triangles[b], moving.planes[b], d, length, tol);
    });
  std::size_t nearest = 0;  // the obstacle of the smallest bound at the last pose asked
  auto bound = [&](const Pose& pose, double enough) {
    double best = kInf;
    for (std::size_t k = 0; k < near.size(); ++k) {
      ++queries;
      const double e = std::min(enough, best);
      const DistanceResult r =
          distance(near[k]->tree, Pose{}, moving.tree, pose, {.enough = e, .exclude_if = &mates[k]});
      if (r.distance < best) best = r.distance, nearest = k;
    }
    return best;
  };
  const Vec3 reference = moving.box.center();
  const Motion motion{Pose{}, Pose::from_translation(length * d), reference, motion_radius(moving.tree, reference)};
  const Certificate c = certify_motion(motion, bound, {.margin = settings.clearance});
  if (blocker && c.status == MotionStatus::blocked) {
    // Which part it was: asked again at the pose found (the certificate asks both ends first).
    bound(Pose::from_translation(c.t_blocked * length * d), kInf);
    *blocker = near[nearest];
  }
  return c.clear();
}

}  // namespace swept::assembly_detail
