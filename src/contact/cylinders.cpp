// Case 4 of the mate rule (mate_rule.h): a shaft slides along its bore by the CAD's cylinders, not
// by their facets. Under a pull along a cylinder's axis every point keeps its distance from the
// axis (up to the pull's drift), so two triangles whose distances from it do not overlap by more
// than the tolerance never reach further into each other, wherever they are along the axis.
#include "swept/contact/contact.h"

#include "swept/geometry/distance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace swept::contact {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// How parallel two axes must be to be taken for one (|a × b|): a B-spline face's fitted axis is
// off by more than rounding. What the angle moves a point off the line is measured, not assumed
// (axis_offset, and the pull's drift).
constexpr double kParallel = 1e-6;

std::array<double, 6> edge_key(const Vec3& u, const Vec3& v) {
  std::array<double, 3> a{u.x(), u.y(), u.z()}, b{v.x(), v.y(), v.z()};
  if (b < a) std::swap(a, b);
  return {a[0], a[1], a[2], b[0], b[1], b[2]};
}

// The part of w perpendicular to the unit a.
Vec3 across(const Vec3& w, const Vec3& a) { return w - a * w.dot(a); }

bool parallel(const Vec3& a, const Vec3& b) { return a.cross(b).norm() <= kParallel; }

// Distance from x to the line through o along the unit a.
double line_distance(const Vec3& x, const Vec3& o, const Vec3& a) { return across(x - o, a).norm(); }

// How far the points of triangle t, at their positions along g's axis, may be off by measuring
// their distance from the line (o, a) instead of from g's own axis.
double axis_offset(const CadCylinder& g, const Triangle& t, const Vec3& o, const Vec3& a) {
  double off = 0.0;
  for (int v = 0; v < 3; ++v) {
    const Vec3 foot = g.origin + g.axis * (t[v] - g.origin).dot(g.axis);
    off = std::max(off, line_distance(foot, o, a));
  }
  return off;
}

// A bore face of `body` on the line (o, a): parallel, its axis within `tolerance` of the line.
bool coaxial_bore(const BodyCylinder& g, const Vec3& o, const Vec3& a, double tolerance) {
  return g.known && !g.material_inside && parallel(g.surface.axis, a) &&
         line_distance(g.surface.origin, o, a) <= tolerance;
}

// The largest distance of triangle t's points from the line (o, a): at a vertex (the distance
// from a line is convex).
double radial_ceiling(const Triangle& t, const Vec3& o, const Vec3& a) {
  return std::max({line_distance(t.p, o, a), line_distance(t.q, o, a), line_distance(t.r, o, a)});
}

// The smallest distance from the line (o, a) of what triangle t of `outer` stands for:
// - on a coaxial bore: the bore's surface (its radius, less its deviation and the axes' offset),
//   not the facet, whose middle lies inside the circle by the tessellation's sag;
// - at a coaxial bore's rim (an edge of t is a boundary edge of the bore's triangles, so it lies
//   on the cylinder, and t comes nearest the axis on such an edge): the smaller of the radius and
//   t's other edges' distance — the distance from the line is convex over t, so t's points
//   nearer than that form one region against the chord: the rim's sag between the chord and the
//   cylinder, which the part's surface does not hold;
// - otherwise the triangle itself (the exact minimum, in the plane across the axis).
double radial_floor(const Body& outer, std::uint32_t k, const Vec3& o, const Vec3& a, double tolerance) {
  const Triangle& t = outer.triangles[k];
  if (!outer.cylinder_of.empty()) {
    if (const std::int32_t f = outer.cylinder_of[k]; f >= 0) {
      const BodyCylinder& g = outer.cylinders[static_cast<std::size_t>(f)];
      if (coaxial_bore(g, o, a, tolerance))
        return g.surface.radius - g.surface.deviation - axis_offset(g.surface, t, o, a);
    }
  }
  const Vec3 u[3] = {across(t.p - o, a), across(t.q - o, a), across(t.r - o, a)};
  const double own = point_triangle_closest(Vec3::Zero(), Triangle{u[0], u[1], u[2]}).distance;
  double edge[3];
  for (int e = 0; e < 3; ++e) edge[e] = point_segment_closest(Vec3::Zero(), u[e], u[(e + 1) % 3]).distance;
  double best = own;
  for (const BodyCylinder& g : outer.cylinders) {
    if (!coaxial_bore(g, o, a, tolerance)) continue;
    const double r = g.surface.radius - g.surface.deviation - axis_offset(g.surface, t, o, a);
    double chord = kInf, others = kInf;
    for (int e = 0; e < 3; ++e) {
      const bool on_rim = std::binary_search(g.boundary.begin(), g.boundary.end(), edge_key(t[e], t[(e + 1) % 3]));
      (on_rim ? chord : others) = std::min(on_rim ? chord : others, edge[e]);
    }
    // The minimum over t on a rim chord (to rounding): t's nearest points lie against it.
    if (chord < kInf && chord <= own * (1.0 + 1e-12) + 1e-300) best = std::max(best, std::min(r, others));
  }
  return best;
}

}  // namespace

void add_cylinders(Body& body, const std::vector<const TriangleSoup*>& parts) {
  bool any = false;
  for (const TriangleSoup* m : parts) any = any || !m->cylinders.empty();
  if (!any) return;
  for (const TriangleSoup* part : parts) {
    const TriangleSoup& m = *part;
    const auto base = static_cast<std::int32_t>(body.cylinders.size());
    if (m.cylinder_of.empty()) {
      body.cylinder_of.insert(body.cylinder_of.end(), m.triangles.size(), -1);
      continue;
    }
    for (std::int32_t f : m.cylinder_of) body.cylinder_of.push_back(f < 0 ? -1 : base + f);
    std::vector<double> outward(m.cylinders.size(), 0.0), area(m.cylinders.size(), 0.0);
    std::vector<std::vector<std::array<double, 6>>> edges(m.cylinders.size());
    for (std::size_t k = 0; k < m.triangles.size(); ++k) {
      const std::int32_t f = m.cylinder_of[k];
      if (f < 0) continue;
      const auto fi = static_cast<std::size_t>(f);
      const Triangle& t = m.triangles[k];
      const CadCylinder& c = m.cylinders[fi];
      const Vec3 n = (t.q - t.p).cross(t.r - t.p);  // twice the area, outward
      const Vec3 radial = across(centroid(t) - c.origin, c.axis);
      if (radial.norm() > 0.0) outward[fi] += n.dot(radial.normalized());
      area[fi] += n.norm();
      for (int e = 0; e < 3; ++e) edges[fi].push_back(edge_key(t[e], t[(e + 1) % 3]));
    }
    for (std::size_t f = 0; f < m.cylinders.size(); ++f) {
      BodyCylinder g;
      g.surface = m.cylinders[f];
      // Facets of a cylinder face its axis within their half-angle; a face whose normals do not
      // agree on a side by half its area is not trusted.
      g.known = area[f] > 0.0 && std::abs(outward[f]) >= 0.5 * area[f];
      g.material_inside = outward[f] > 0.0;
      auto& e = edges[f];
      std::sort(e.begin(), e.end());
      for (std::size_t j = 0; j < e.size();) {
        std::size_t k = j;
        while (k < e.size() && e[k] == e[j]) ++k;
        if (k - j == 1) g.boundary.push_back(e[j]);
        j = k;
      }
      body.cylinders.push_back(std::move(g));
    }
  }
}

std::vector<CylinderMate> cylinder_mates(const Body& obstacle, const Body& moving, const Vec3& d, double length,
                                         double tolerance) {
  std::vector<CylinderMate> out;
  if (obstacle.cylinders.empty() || moving.cylinders.empty()) return out;
  auto add = [&](const Body& outer, const Body& inner, bool moving_is_outer) {
    for (const BodyCylinder& bore : outer.cylinders) {
      if (!bore.known || bore.material_inside) continue;
      const CadCylinder& b = bore.surface;
      const double drift = length * d.cross(b.axis).norm();
      if (!(drift <= tolerance)) continue;
      const bool mated = std::any_of(inner.cylinders.begin(), inner.cylinders.end(), [&](const BodyCylinder& shaft) {
        const CadCylinder& s = shaft.surface;
        return shaft.known && shaft.material_inside && parallel(s.axis, b.axis) &&
               line_distance(s.origin, b.origin, b.axis) <= tolerance && s.radius <= b.radius + tolerance;
      });
      if (mated) out.push_back({b.origin, b.axis, moving_is_outer, drift});
    }
  };
  add(obstacle, moving, false);
  add(moving, obstacle, true);
  return out;
}

bool cylinder_mate_allows(const std::vector<CylinderMate>& mates, const Body& obstacle, std::uint32_t a,
                          const Body& moving, std::uint32_t b, double tolerance) {
  for (const CylinderMate& m : mates) {
    const Body& outer = m.moving_is_outer ? moving : obstacle;
    const std::uint32_t out_k = m.moving_is_outer ? b : a;
    const Triangle& inner_t = m.moving_is_outer ? obstacle.triangles[a] : moving.triangles[b];
    const double ceiling = radial_ceiling(inner_t, m.origin, m.axis);
    if (ceiling - radial_floor(outer, out_k, m.origin, m.axis, tolerance) + m.drift <= tolerance) return true;
  }
  return false;
}

}  // namespace swept::contact
