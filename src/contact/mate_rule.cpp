// The mate rule of the contact model (mate_rule.h): separating axes of two triangles.
#include "swept/contact/mate_rule.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <vector>

namespace swept {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Interval {
  double lo = kInf, hi = -kInf;
};

Interval project(const Triangle& t, const Vec3& m) {
  const double a = m.dot(t.p), b = m.dot(t.q), c = m.dot(t.r);
  return {std::min({a, b, c}), std::max({a, b, c})};
}

// A convex polygon of at most 3 + (number of clipping planes) vertices.
struct Polygon {
  std::array<Vec3, 8> v;
  int n = 0;
};

Polygon polygon_of(const Triangle& t) {
  Polygon p;
  p.v[0] = t.p, p.v[1] = t.q, p.v[2] = t.r;
  p.n = 3;
  return p;
}

// Keeps the part of `in` where m·x ≥ c (Sutherland–Hodgman, one plane).
Polygon clip(const Polygon& in, const Vec3& m, double c) {
  Polygon out;
  for (int i = 0; i < in.n; ++i) {
    const Vec3& a = in.v[i];
    const Vec3& b = in.v[(i + 1) % in.n];
    const double fa = m.dot(a) - c, fb = m.dot(b) - c;
    if (fa >= 0) out.v[out.n++] = a;
    if ((fa < 0) != (fb < 0)) out.v[out.n++] = a + (fa / (fa - fb)) * (b - a);
  }
  return out;
}

// How far the part of `b` inside the prism over `a` along the unit `across` directions' slab
// reaches behind a's plane: b clipped to u·x ∈ [min, max of a] for u = `across` (one slab), or to
// the prism over a along its normal (`across` zero: three edge slabs). −∞ when nothing is left.
double clipped_depth(const Triangle& a, const TrianglePlane& pa, const Triangle& b, const Vec3& across) {
  Polygon part = polygon_of(b);
  if (!across.isZero()) {
    const double lo = std::min({across.dot(a.p), across.dot(a.q), across.dot(a.r)});
    const double hi = std::max({across.dot(a.p), across.dot(a.q), across.dot(a.r)});
    part = clip(clip(part, across, lo), -across, -hi);
  } else {
    for (int i = 0; i < 3 && part.n > 0; ++i) {
      const Vec3 inward = pa.normal.cross(a[(i + 1) % 3] - a[i]);  // a counter-clockwise about its normal
      part = clip(part, inward, inward.dot(a[i]));
    }
  }
  if (part.n == 0) return -kInf;
  double lowest = kInf;
  for (int i = 0; i < part.n; ++i) lowest = std::min(lowest, pa.normal.dot(part.v[i]));
  return pa.offset - lowest;
}

// A triangle the pull slides along (`d`, its motion relative to the other, within 0.05 of its
// plane: a tessellated cylinder's facets are not exactly parallel to the axis): the part of the
// other triangle inside the strip it sweeps (its extent across d, u = n × d, which the motion
// does not change) is in front of its plane up to the tolerance, counting how far the plane
// itself advances over the pull (length · n·d when positive).
bool slides_clear(const Triangle& a, const TrianglePlane& pa, const Triangle& b, const Vec3& d, double length,
                  double tolerance) {
  if (pa.normal.isZero()) return false;
  if (pa.two_sided) {  // a sheet: b may slide along either side
    TrianglePlane back = pa;
    back.normal = -pa.normal, back.offset = -pa.offset, back.two_sided = false;
    back.creases = 0;
    if (slides_clear(a, back, b, d, length, tolerance)) return true;
  }
  const double along = pa.normal.dot(d);
  if (std::abs(along) > 0.05) return false;
  const Vec3 u = pa.normal.cross(d);
  return clipped_depth(a, pa, b, u / u.norm()) + length * std::max(0.0, along) <= tolerance;
}

// The column `a` sweeps along the unit `d` (the prism over it along d, not across its own
// plane: |n_a·d| ≥ 0.05) shrunk by the tolerance on every side: does `b` miss it? Then a's
// motion along d never takes it more than the tolerance into b.
bool column_misses(const Triangle& a, const TrianglePlane& pa, const Triangle& b, const Vec3& d, double tolerance) {
  if (pa.normal.isZero() || std::abs(pa.normal.dot(d)) < 0.05) return false;
  Polygon part = polygon_of(b);
  for (int i = 0; i < 3 && part.n > 0; ++i) {
    Vec3 m = d.cross(a[(i + 1) % 3] - a[i]);
    const double len = m.norm();
    if (!(len > 1e-300)) return false;
    m /= len;
    if (m.dot(a[(i + 2) % 3] - a[i]) < 0) m = -m;  // toward the inside of the column
    part = clip(part, m, m.dot(a[i]) + tolerance);
  }
  return part.n == 0;
}

// The separating axes of contact.h, oriented from o toward p. Returns how many were written.
int axes_of(const Triangle& o, const TrianglePlane& po, const Triangle& p, const TrianglePlane& pp,
            std::array<Vec3, 32>& out) {
  int n = 0;
  const Vec3& no = po.normal;
  const Vec3& np = pp.normal;
  if (!no.isZero()) out[n++] = no;
  if (!np.isZero()) out[n++] = -np;
  // A sheet has no inside: either side of it.
  if (po.two_sided && !no.isZero()) out[n++] = -no;
  if (pp.two_sided && !np.isZero()) out[n++] = np;
  const bool either = po.two_sided || pp.two_sided;
  Vec3 eo[3], ep[3];
  int co = 0, cp = 0;
  for (int i = 0; i < 3; ++i) {
    if (po.creases & (1u << i)) {
      const Vec3 e = o[(i + 1) % 3] - o[i];
      eo[co++] = e;
      // o's outward in-plane normal of the edge (o counter-clockwise about its normal).
      const Vec3 m = e.cross(no);
      if (m.norm() > 1e-300 && !no.isZero()) out[n++] = m.normalized();
    }
    if (pp.creases & (1u << i)) {
      const Vec3 e = p[(i + 1) % 3] - p[i];
      ep[cp++] = e;
      const Vec3 m = e.cross(np);
      if (m.norm() > 1e-300 && !np.isZero()) out[n++] = -m.normalized();
    }
  }
  const Vec3 outward = no - np;
  for (int i = 0; i < co; ++i)
    for (int j = 0; j < cp; ++j) {
      const Vec3 c = eo[i].cross(ep[j]);
      const double len = c.norm();
      // Nearly parallel edges give no axis (their separation is one of the others').
      if (!(len > 1e-9 * eo[i].norm() * ep[j].norm()) || !(len > 1e-300)) continue;
      const Vec3 m = c / len;
      const double side = m.dot(outward);
      if (either || side >= -1e-12) out[n++] = m;
      if (either || side <= 1e-12) out[n++] = -m;
    }
  return n;
}

}  // namespace

TrianglePlane plane_of(const Triangle& t) {
  Vec3 n = (t.q - t.p).cross(t.r - t.p);
  const double len = n.norm();
  // Degenerate triangles have no plane (their pairs still have the edge axes).
  if (!(len > 1e-300) || !std::isfinite(len)) return {};
  n /= len;
  return {n, n.dot(t.p)};
}

std::vector<TrianglePlane> part_planes(const std::vector<Triangle>& triangles) {
  std::vector<TrianglePlane> planes;
  planes.reserve(triangles.size());
  for (const Triangle& t : triangles) planes.push_back(plane_of(t));
  // Edges by their two end points (exact coordinates, ordered), with (triangle, edge) uses.
  using Key = std::array<double, 6>;
  auto key = [](const Vec3& a, const Vec3& b) {
    Key x{a.x(), a.y(), a.z()}, y{b.x(), b.y(), b.z()};
    Key k;
    const bool swap = std::lexicographical_compare(y.begin(), y.begin() + 3, x.begin(), x.begin() + 3);
    for (int i = 0; i < 3; ++i) k[i] = swap ? y[i] : x[i], k[i + 3] = swap ? x[i] : y[i];
    return k;
  };
  std::map<Key, std::vector<std::pair<std::uint32_t, int>>> edges;
  for (std::uint32_t t = 0; t < triangles.size(); ++t)
    for (int i = 0; i < 3; ++i) edges[key(triangles[t][i], triangles[t][(i + 1) % 3])].push_back({t, i});
  // Connected parts (union-find over shared edges) and which of them are open.
  std::vector<std::uint32_t> root(triangles.size());
  for (std::uint32_t t = 0; t < root.size(); ++t) root[t] = t;
  auto find = [&](std::uint32_t t) {
    while (root[t] != t) t = root[t] = root[root[t]];
    return t;
  };
  for (const auto& [k, uses] : edges)
    for (std::size_t u = 1; u < uses.size(); ++u) {
      const std::uint32_t a = find(uses[0].first), b = find(uses[u].first);
      if (a != b) root[std::max(a, b)] = std::min(a, b);
    }
  std::vector<bool> open(triangles.size(), false);
  for (const auto& [k, uses] : edges)
    if (uses.size() == 1) open[find(uses[0].first)] = true;
  for (std::uint32_t t = 0; t < triangles.size(); ++t) planes[t].two_sided = open[find(t)];
  for (const auto& [k, uses] : edges) {
    // Open or non-manifold edges (vertices that do not match exactly) are no creases: fewer axes,
    // so fewer pairs are mates: the conservative side.
    if (uses.size() != 2) continue;
    for (int s = 0; s < 2; ++s) {
      const auto [t, i] = uses[s];
      const auto [u, j] = uses[1 - s];
      const TrianglePlane& other = planes[u];
      if (other.normal.isZero() || planes[t].normal.isZero()) continue;
      // The vertex of t off the edge, behind the neighbour's plane: a convex dihedral.
      const Vec3& apex = triangles[t][(i + 2) % 3];
      const double edge = (triangles[t][(i + 1) % 3] - triangles[t][i]).norm();
      if (other.normal.dot(apex) - other.offset < -1e-9 * edge) planes[t].creases |= static_cast<std::uint8_t>(1u << i);
    }
  }
  return planes;
}

double depth_behind(const TrianglePlane& a, const Triangle& b) {
  if (a.normal.isZero()) return kInf;
  const double lowest = std::min({a.normal.dot(b.p), a.normal.dot(b.q), a.normal.dot(b.r)});
  return a.offset - lowest;
}

bool mate_allows(const Triangle& o, const TrianglePlane& po, const Triangle& p, const TrianglePlane& pp,
                 const Vec3& direction, double length, double tolerance) {
  std::array<Vec3, 32> axes;
  const int n = axes_of(o, po, p, pp, axes);
  for (int k = 0; k < n; ++k) {
    const Vec3& m = axes[k];
    // p on the +m side of o up to the tolerance; the pull changes the gap by L·(m·d).
    const double gap = project(p, m).lo - project(o, m).hi;
    if (gap + length * std::min(0.0, m.dot(direction)) >= -tolerance) return true;
  }
  // A face the pull slides along: only what it sweeps over counts (p moves by +d relative to o,
  // o by −d relative to p).
  if (slides_clear(p, pp, o, direction, length, tolerance) || slides_clear(o, po, p, -direction, length, tolerance))
    return true;
  // The moving triangle's column along the pull misses o (the end of a shaft coming out of its
  // bore past the rim of the face round it).
  return column_misses(p, pp, o, direction, tolerance);
}

double pair_overlap(const Triangle& a, const TrianglePlane& pa, const Triangle& b, const TrianglePlane& pb) {
  std::array<Vec3, 32> axes;
  const int n = axes_of(a, pa, b, pb, axes);
  double best = kInf;
  for (int k = 0; k < n; ++k) best = std::min(best, project(a, axes[k]).hi - project(b, axes[k]).lo);
  // Or how far each reaches behind the other's plane over its footprint.
  if (!pa.normal.isZero()) best = std::min(best, clipped_depth(a, pa, b, Vec3::Zero()));
  if (!pb.normal.isZero()) best = std::min(best, clipped_depth(b, pb, a, Vec3::Zero()));
  return std::max(best, -kInf);
}

}  // namespace swept
