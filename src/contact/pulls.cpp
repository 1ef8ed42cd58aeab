// Straight pulls of a body out of its contacts (contact.h): the directions of local freedom, the
// length to leave the box, and the certificate with the mate rule.
#include "swept/contact/contact.h"

#include "swept/geometry/assert.h"
#include "swept/query/motion.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>

namespace swept::contact {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();


void add_unique(std::vector<Vec3>& out, const Vec3& v) {
  const double n = v.norm();
  if (!(n > 1e-12)) return;
  const Vec3 u = v / n;
  for (const Vec3& e : out)
    if (e.dot(u) > 1.0 - 1e-9) return;
  out.push_back(u);
}

// How far apart two normals of one flat node may be: a tessellated plane's facets agree to
// rounding; a curved face's facets do not (and its nodes are left to the triangles).
constexpr double kFlatSpread = 1e-6;

// Over the world-frame triangles and planes of the tree's input ids.
std::vector<FlatNode> flat_nodes(const Bvh& tree, const std::vector<Triangle>& triangles,
                                 const std::vector<TrianglePlane>& planes) {
  const std::size_t n = tree.nodes.size();
  std::vector<FlatNode> out(n);
  std::vector<std::pair<std::int32_t, std::int32_t>> range(n);  // triangles of the subtree
  // Children come after their parent in `nodes` (level order, then depth-first blocks).
  for (std::size_t k = n; k-- > 0;) {
    const Node& node = tree.nodes[k];
    bool children_flat = true;
    if (node.is_leaf()) {
      range[k] = {node.first, node.first + node.count};
    } else {
      const auto c = static_cast<std::size_t>(node.first);
      SWEPT_ASSERT(c > k, "children after their parent");
      range[k] = {std::min(range[c].first, range[c + 1].first), std::max(range[c].second, range[c + 1].second)};
      children_flat = out[c].flat && out[c + 1].flat;
    }
    if (!children_flat) continue;
    const auto [b, e] = range[k];
    FlatNode f;
    f.normal = planes[tree.triangle_ids[b]].normal;
    if (f.normal.isZero()) continue;
    f.lo = kInf;
    f.hi = -kInf;
    f.two_sided = true;
    bool flat = true;
    for (std::int32_t i = b; i < e && flat; ++i) {
      const std::uint32_t id = tree.triangle_ids[i];
      const Vec3& m = planes[id].normal;
      f.two_sided = f.two_sided && planes[id].two_sided;
      f.spread = std::max(f.spread, (m - f.normal).norm());
      flat = !m.isZero() && f.spread <= kFlatSpread;
      for (int v = 0; v < 3; ++v) {
        const double x = f.normal.dot(triangles[id][v]);
        f.lo = std::min(f.lo, x);
        f.hi = std::max(f.hi, x);
      }
    }
    f.flat = flat;
    if (flat) out[k] = f;
  }
  return out;
}

// The smallest n·x over an RSS's volume, for a unit n.
double rss_min_along(const Rss& r, const Vec3& n) {
  return n.dot(r.center) - r.half_length[0] * std::abs(n.dot(r.axes.col(0))) -
         r.half_length[1] * std::abs(n.dot(r.axes.col(1))) - r.radius;
}

// An RSS of a tree placed at `pose` (tree frame → world).
Rss placed(Rss r, const Pose& pose) {
  r.center = pose.apply(r.center);
  r.axes = pose.rotation * r.axes;
  return r;
}

// planes, box and flat nodes of a body whose triangles (world frame) and tree are set; creases
// soup by soup over `sizes` consecutive runs of triangles.
void finish_body(Body& b, const std::vector<std::size_t>& sizes) {
  std::size_t at = 0;
  for (std::size_t n : sizes) {
    const std::vector<Triangle> part(b.triangles.begin() + static_cast<std::ptrdiff_t>(at),
                                     b.triangles.begin() + static_cast<std::ptrdiff_t>(at + n));
    const auto planes = part_planes(part);
    b.planes.insert(b.planes.end(), planes.begin(), planes.end());
    at += n;
  }
  for (const Triangle& t : b.triangles)
    for (int v = 0; v < 3; ++v) b.box.extend(t[v]);
  b.flat = flat_nodes(*b.tree, b.triangles, b.planes);
}

}  // namespace

std::vector<ContactFacet> touching_facets(const Body& obstacle, const Body& moving, double threshold) {
  const ProximityTrianglesResult near =
      proximity_triangles(*obstacle.tree, obstacle.pose, *moving.tree, moving.pose, {.threshold = threshold});
  std::vector<ContactFacet> out;
  out.reserve(near.a.size() + near.b.size());
  for (std::uint32_t t : near.a) out.push_back({t, false});
  for (std::uint32_t t : near.b) out.push_back({t, true});
  return out;
}

double box_gap(const Aabb& a, const Aabb& b) {
  const Vec3 lo = (b.min - a.max).cwiseMax(a.min - b.max).cwiseMax(Vec3::Zero());
  return lo.norm();
}

bool nodes_mate(const Body& obstacle, std::int32_t ia, const Body& moving, std::int32_t ib, const Vec3& d,
                double length, double tolerance) {
  const Rss ra = placed(obstacle.tree->bv(static_cast<std::size_t>(ia)), obstacle.pose);
  const Rss rb = placed(moving.tree->bv(static_cast<std::size_t>(ib)), moving.pose);
  auto reach = [](const Rss& r) { return r.half_length[0] + r.half_length[1] + r.radius; };
  // Any two points of the pair are at most this far apart; the same bound, 1e-9 of it, covers rounding.
  const double span = (ra.center - rb.center).norm() + reach(ra) + reach(rb);
  const double slack = 1e-9 * (span + ra.center.cwiseAbs().maxCoeff() + rb.center.cwiseAbs().maxCoeff());
  // Case 1 of the mate rule with m = o's normal n, for every o under ia: with |n − N| ≤ ε,
  // min_p n·v − max_o n·w ≥ (min over rb of N·x) − hi − ε·span, and n·d ≥ N·d − ε.
  const FlatNode& fa = obstacle.flat[static_cast<std::size_t>(ia)];
  if (fa.flat) {
    const double gap = rss_min_along(rb, fa.normal) - fa.hi - fa.spread * span;
    if (gap + length * std::min(0.0, fa.normal.dot(d) - fa.spread) >= -tolerance + slack) return true;
    // A sheet: the other side, m = −n.
    const double back = rss_min_along(rb, -fa.normal) + fa.lo - fa.spread * span;
    if (fa.two_sided && back + length * std::min(0.0, -fa.normal.dot(d) - fa.spread) >= -tolerance + slack) return true;
  }
  // ... and with m = −(p's normal) n, for every p under ib: min_o n·w − max_p n·v, and −n·d.
  const FlatNode& fb = moving.flat[static_cast<std::size_t>(ib)];
  if (fb.flat) {
    const double gap = rss_min_along(ra, fb.normal) - fb.hi - fb.spread * span;
    if (gap + length * std::min(0.0, -fb.normal.dot(d) - fb.spread) >= -tolerance + slack) return true;
    const double back = rss_min_along(ra, -fb.normal) + fb.lo - fb.spread * span;
    if (fb.two_sided && back + length * std::min(0.0, fb.normal.dot(d) - fb.spread) >= -tolerance + slack) return true;
  }
  return false;
}

Body make_body(const std::vector<const TriangleSoup*>& parts, const BuildConfig& config) {
  Body b;
  std::vector<std::size_t> sizes;
  for (const TriangleSoup* p : parts) {
    b.triangles.insert(b.triangles.end(), p->triangles.begin(), p->triangles.end());
    sizes.push_back(p->triangles.size());
  }
  auto tree = build_bvh(b.triangles, config);
  SWEPT_ASSERT(tree.ok(), "bodies are made of checked, non-empty parts");
  b.tree = std::make_shared<const Bvh>(std::move(*tree));
  finish_body(b, sizes);
  add_cylinders(b, parts);
  return b;
}

Body place_body(const TriangleSoup& soup, std::shared_ptr<const Bvh> tree, const Pose& pose) {
  Body b;
  b.tree = std::move(tree);
  b.pose = pose;
  b.triangles.reserve(soup.triangles.size());
  for (const Triangle& t : soup.triangles) b.triangles.push_back({pose.apply(t.p), pose.apply(t.q), pose.apply(t.r)});
  finish_body(b, {soup.triangles.size()});
  TriangleSoup placed_soup;
  placed_soup.cylinder_of = soup.cylinder_of;
  placed_soup.triangles = b.triangles;
  for (CadCylinder c : soup.cylinders) {
    c.origin = pose.apply(c.origin);
    c.axis = pose.rotation * c.axis;
    placed_soup.cylinders.push_back(c);
  }
  add_cylinders(b, {&placed_soup});
  return b;
}

Body translated(const Body& body, const Vec3& t) {
  Body b = body;
  b.pose.translation += t;
  for (Triangle& x : b.triangles) x.p += t, x.q += t, x.r += t;
  for (TrianglePlane& p : b.planes) p.offset += p.normal.dot(t);
  for (FlatNode& f : b.flat)
    if (f.flat) f.lo += f.normal.dot(t), f.hi += f.normal.dot(t);
  if (!b.box.empty()) b.box.min += t, b.box.max += t;
  for (BodyCylinder& c : b.cylinders) {
    c.surface.origin += t;
    // The same additions as the triangles' vertices: the rim's keys still match them exactly.
    for (auto& e : c.boundary) {
      for (int k = 0; k < 3; ++k) e[k] += t[k], e[k + 3] += t[k];
      if (std::lexicographical_compare(e.begin() + 3, e.end(), e.begin(), e.begin() + 3))
        std::swap_ranges(e.begin(), e.begin() + 3, e.begin() + 3);
    }
    std::sort(c.boundary.begin(), c.boundary.end());
  }
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

std::vector<Vec3> pull_directions(const Body& moving, const std::vector<const Body*>& obstacles, double threshold,
                                  const std::function<const std::vector<ContactFacet>*(const Body& obstacle)>& contacts) {
  std::vector<Vec3> out{Vec3::UnitZ(), -Vec3::UnitZ(), Vec3::UnitX(), -Vec3::UnitX(), Vec3::UnitY(), -Vec3::UnitY()};
  // Contact normals by contact area (each touching triangle's area once per obstacle it touches),
  // ties by first appearance (obstacle order, then touching_facets' order). A normal joins the first-made
  // group whose normal is within 1e-9 of its direction (e·n > 1 − 1e-9, so |e − n| < 4.5e-5);
  // the groups are found through a grid of that cell size, so that a large contact (every facet
  // of a fine cylinder its own normal) costs n log n, not n².
  std::vector<std::pair<Vec3, double>> normals;
  constexpr double kCell = 4.5e-5;
  std::map<std::array<std::int64_t, 3>, std::vector<std::size_t>> grid;
  auto cell = [](const Vec3& n) {
    return std::array<std::int64_t, 3>{static_cast<std::int64_t>(std::floor(n.x() / kCell)),
                                       static_cast<std::int64_t>(std::floor(n.y() / kCell)),
                                       static_cast<std::int64_t>(std::floor(n.z() / kCell))};
  };
  auto add = [&](const Vec3& n, const Triangle& t) {
    if (n.isZero()) return;
    const auto c = cell(n);
    std::size_t first = normals.size();
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
          const auto it = grid.find({c[0] + dx, c[1] + dy, c[2] + dz});
          if (it == grid.end()) continue;
          for (std::size_t g : it->second)
            if (g < first && normals[g].first.dot(n) > 1.0 - 1e-9) first = g;
        }
    if (first == normals.size()) {
      grid[c].push_back(normals.size());
      normals.push_back({n, 0.0});
    }
    normals[first].second += 0.5 * (t.q - t.p).cross(t.r - t.p).norm();
  };
  for (const Body* o : obstacles) {
    if (box_gap(o->box, moving.box) > threshold) continue;
    const std::vector<ContactFacet>* known = contacts ? contacts(*o) : nullptr;
    std::vector<ContactFacet> found;
    if (!known)
      found = touching_facets(*o, moving, threshold);
    for (const ContactFacet& f : known ? *known : found) {
      if (f.moving) add(-moving.planes[f.triangle].normal, moving.triangles[f.triangle]);
      else add(o->planes[f.triangle].normal, o->triangles[f.triangle]);
    }
  }
  std::stable_sort(normals.begin(), normals.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
  if (normals.size() > 8) normals.resize(8);
  for (const auto& [n, a] : normals) add_unique(out, n);
  // The axes of the CAD's cylinder mates with the obstacles it touches (exact, where the cross
  // products below only approximate a tessellated cylinder's axis), both signs, at most 8.
  std::size_t mate_axes = 0;
  for (const Body* o : obstacles) {
    if (box_gap(o->box, moving.box) > threshold) continue;
    for (const CylinderMate& m : cylinder_mates(*o, moving, Vec3::UnitZ(), 0.0, threshold)) {
      if (mate_axes == 8) break;
      const std::size_t before = out.size();
      add_unique(out, m.axis);
      add_unique(out, -m.axis);
      if (out.size() > before) ++mate_axes;
    }
  }
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
  // One exact sweep of the translation per obstacle the swept box comes near (sweep_translation):
  // the mates along the pull are visited once, not at every pose a certificate would ask.
  const double tol = settings.tolerance;
  for (const Body* o : obstacles) {
    if (box_gap(o->box, swept) > reach) continue;
    const std::vector<CylinderMate> cylinders = cylinder_mates(*o, moving, d, length, tol);
    const std::function<bool(std::uint32_t, std::uint32_t)> mates = [&](std::uint32_t a, std::uint32_t b) {
      return mate_allows(o->triangles[a], o->planes[a], moving.triangles[b], moving.planes[b], d, length, tol) ||
             (!cylinders.empty() && cylinder_mate_allows(cylinders, *o, a, moving, b, tol));
    };
    const std::function<bool(std::int32_t, std::int32_t)> node_mates = [&](std::int32_t a, std::int32_t b) {
      return nodes_mate(*o, a, moving, b, d, length, tol);
    };
    ++queries;
    const SweepResult r = sweep_translation(*o->tree, o->pose, *moving.tree, moving.pose,
                                            {.translation = length * d, .margin = settings.clearance,
                                             .exclude_if = &mates, .exclude_nodes_if = &node_mates});
    if (!r.clear) {
      if (blocker) *blocker = o;
      return false;
    }
  }
  return true;
}

}  // namespace swept::contact
