// Exact distances between points, segments and triangles, and the triangle–triangle
// intersection test.
#include "swept/geometry/distance.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace swept {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
/// Area (relative to the squared longest edge) below which a triangle is treated as its edges.
constexpr double kDegenerateArea = 1e-13;
constexpr double kTouch = 1e-12;

/// A triangle's edges and plane, computed once per triangle pair.
struct Prepared {
  const Triangle* t = nullptr;
  Vec3 e[3];          ///< e[i] = v[i+1] − v[i]
  double ee[3] = {};  ///< |e[i]|²
  Vec3 n;             ///< unnormalised normal, oriented like (q − p) × (r − p)
  double nn = 0.0;    ///< |n|²
  Vec3 m[3];          ///< n × e[i]: (x − v[i])·m[i] ≥ 0 on the inner side of edge i
  bool degenerate = true;
  bool edges_ready = false;  ///< m[] computed

  const Vec3& v(int i) const { return (*t)[i]; }
};

void prepare(const Triangle& t, Prepared& f) {
  f.t = &t;
  f.e[0] = t.q - t.p;
  f.e[1] = t.r - t.q;
  f.e[2] = t.p - t.r;
  for (int i = 0; i < 3; ++i) f.ee[i] = f.e[i].squaredNorm();
  const double l = std::max({f.ee[0], f.ee[1], f.ee[2]});
  // The cross product of the two edges meeting at the vertex opposite the longest edge is
  // the best conditioned one (all three have the orientation of (q − p) × (r − p)).
  if (f.ee[0] == l)
    f.n = f.e[1].cross(f.e[2]);
  else if (f.ee[1] == l)
    f.n = f.e[2].cross(f.e[0]);
  else
    f.n = f.e[0].cross(f.e[1]);
  f.nn = f.n.squaredNorm();
  f.degenerate = !(f.nn > kDegenerateArea * kDegenerateArea * l * l);
}

/// The in-plane edge normals, needed only once the cheap plane tests did not settle a pair.
void prepare_edges(Prepared& f) {
  if (f.edges_ready) return;
  f.edges_ready = true;
  if (!f.degenerate)
    for (int i = 0; i < 3; ++i) f.m[i] = f.n.cross(f.e[i]);
}

/// Squared distance from x to edge i of f, and the closest point.
inline double point_edge_sq(const Vec3& x, const Prepared& f, int i, Vec3& y) {
  const Vec3 w = x - f.v(i);
  const double ee = f.ee[i];
  if (!(ee > 0.0)) {
    y = f.v(i);
    return w.squaredNorm();
  }
  const double s = w.dot(f.e[i]);
  if (s <= 0.0) {
    y = f.v(i);
  } else if (s >= ee) {
    y = f.v((i + 1) % 3);
  } else {
    y = f.v(i) + (s / ee) * f.e[i];
  }
  return (x - y).squaredNorm();
}

/// Squared distance from x to the triangle and the closest point. Non-degenerate: inside the
/// prism over the triangle, the foot of the perpendicular; outside, the closest point lies
/// on an edge whose outer side holds x. Degenerate: the closest of the three edges.
inline double point_triangle_sq(const Vec3& x, const Prepared& f, Vec3& y) {
  bool check[3] = {true, true, true};
  if (!f.degenerate) {
    const Vec3 w0 = x - f.v(0);
    const double s0 = w0.dot(f.m[0]);
    const double s1 = (x - f.v(1)).dot(f.m[1]);
    const double s2 = (x - f.v(2)).dot(f.m[2]);
    if (s0 >= 0.0 && s1 >= 0.0 && s2 >= 0.0) {
      const double h = w0.dot(f.n);
      y = x - (h / f.nn) * f.n;
      return (x - y).squaredNorm();
    }
    check[0] = s0 <= 0.0;
    check[1] = s1 <= 0.0;
    check[2] = s2 <= 0.0;
  }
  double best = kInf;
  Vec3 c;
  for (int i = 0; i < 3; ++i) {
    if (!check[i]) continue;
    const double d = point_edge_sq(x, f, i, c);
    if (d < best) {
      best = d;
      y = c;
    }
  }
  return best;
}

/// Is x (on or near the plane of non-degenerate f) inside the triangle? Boundary counts.
inline bool inside(const Vec3& x, const Prepared& f) {
  return (x - f.v(0)).dot(f.m[0]) >= 0.0 && (x - f.v(1)).dot(f.m[1]) >= 0.0 &&
         (x - f.v(2)).dot(f.m[2]) >= 0.0;
}

/// Whether the triangles' bounding boxes are at least √limit_sq apart along one of the three
/// axes: a lower bound on the distance, which settles most of the pairs that the centroid line
/// leaves and the full evaluation would reject (counted on the planner's scenes: 55 % in the
/// house, 74 % in the tunnel console). A gap is trusted only beyond a rounding allowance far above
/// the full evaluation's (1e-12 of the largest coordinate), so it rejects no pair that the full
/// evaluation would accept.
inline bool boxes_apart(const Triangle& a, const Triangle& b, double limit_sq) {
  double gap = 0.0, big = 0.0;
  for (int k = 0; k < 3; ++k) {
    const double a_lo = std::min({a.p[k], a.q[k], a.r[k]}), a_hi = std::max({a.p[k], a.q[k], a.r[k]});
    const double b_lo = std::min({b.p[k], b.q[k], b.r[k]}), b_hi = std::max({b.p[k], b.q[k], b.r[k]});
    gap = std::max({gap, b_lo - a_hi, a_lo - b_hi});
    big = std::max({big, std::abs(a_lo), std::abs(a_hi), std::abs(b_lo), std::abs(b_hi)});
  }
  gap -= kTouch * big;
  return gap > 0.0 && gap * gap >= limit_sq;
}

/// Whether a cheap lower bound settles the pair: the gap along the line between the centroids,
/// then the bounding boxes' gaps (for a finite `limit` only).
bool centroid_line_or_boxes_apart(const Triangle& ta, const Triangle& tb, double limit, double limit_sq) {
  if (!(limit < kInf)) return false;
  // The gap along the line between the centroids bounds the distance from below; it
  // settles most pairs a search tests against its best answer so far.
  const Vec3 n = (tb.p + tb.q + tb.r) - (ta.p + ta.q + ta.r);
  const double lo_b = std::min({n.dot(tb.p), n.dot(tb.q), n.dot(tb.r)});
  const double hi_a = std::max({n.dot(ta.p), n.dot(ta.q), n.dot(ta.r)});
  const double gap = lo_b - hi_a;
  if (gap > 0.0 && gap * gap >= limit_sq * n.squaredNorm()) return true;
  return boxes_apart(ta, tb, limit_sq);
}

bool prepared_distance_sq(Prepared& a, Prepared& b, double limit_sq, TriangleDistance& out, double& dist_sq);

/// The squared distance of the triangles, or any value ≥ limit² when it is at least `limit`
/// (then `out` is untouched). Returns true when the exact distance was computed.
bool triangle_distance_sq(const Triangle& ta, const Triangle& tb, double limit,
                          TriangleDistance& out, double& dist_sq, const Vec3* axis = nullptr,
                          double scale = 0.0) {
  if (!(limit > 0.0)) return false;  // no distance is below zero (nor below a NaN limit)
  const double limit_sq = limit * limit;
  if (axis && limit < kInf) {
    // The gap along the caller's axis (triangle_distance_below's second overload), first:
    // far apart it settles more pairs than the centroid line (2-3 % less distance time).
    const Vec3& u = *axis;
    const double lo = std::min({u.dot(tb.p), u.dot(tb.q), u.dot(tb.r)});
    const double hi = std::max({u.dot(ta.p), u.dot(ta.q), u.dot(ta.r)});
    if (lo - hi - kTouch * scale >= limit) return false;
  }
  if (centroid_line_or_boxes_apart(ta, tb, limit, limit_sq)) return false;
  Prepared a, b;
  prepare(ta, a);
  prepare(tb, b);
  return prepared_distance_sq(a, b, limit_sq, out, dist_sq);
}

/// triangle_distance_sq from the point where both triangles are prepared: the planes, the
/// crossings, then every vertex–face and edge–edge pair.
bool prepared_distance_sq(Prepared& a, Prepared& b, double limit_sq, TriangleDistance& out, double& dist_sq) {
  // Signed (unnormalised) distances of each triangle's vertices to the other's plane: a
  // separating plane bounds the distance from below, and sign changes locate crossings.
  double sa[3] = {0, 0, 0}, sb[3] = {0, 0, 0};
  if (!b.degenerate) {
    for (int i = 0; i < 3; ++i) sa[i] = b.n.dot(a.v(i) - b.v(0));
    const bool above = sa[0] > 0.0 && sa[1] > 0.0 && sa[2] > 0.0;
    const bool below = sa[0] < 0.0 && sa[1] < 0.0 && sa[2] < 0.0;
    if (above || below) {
      const double m = std::min({std::abs(sa[0]), std::abs(sa[1]), std::abs(sa[2])});
      if (m * m >= limit_sq * b.nn) return false;
    } else {
      prepare_edges(b);
      for (int i = 0; i < 3; ++i) {
        const double u = sa[i], w = sa[(i + 1) % 3];
        if ((u > 0.0 && w < 0.0) || (u < 0.0 && w > 0.0)) {
          const Vec3 x = a.v(i) + (u / (u - w)) * a.e[i];
          if (inside(x, b)) {
            out = {0.0, x, x};
            dist_sq = 0.0;
            return true;
          }
        }
      }
    }
  }
  if (!a.degenerate) {
    for (int i = 0; i < 3; ++i) sb[i] = a.n.dot(b.v(i) - a.v(0));
    const bool above = sb[0] > 0.0 && sb[1] > 0.0 && sb[2] > 0.0;
    const bool below = sb[0] < 0.0 && sb[1] < 0.0 && sb[2] < 0.0;
    if (above || below) {
      const double m = std::min({std::abs(sb[0]), std::abs(sb[1]), std::abs(sb[2])});
      if (m * m >= limit_sq * a.nn) return false;
    } else {
      prepare_edges(a);
      for (int i = 0; i < 3; ++i) {
        const double u = sb[i], w = sb[(i + 1) % 3];
        if ((u > 0.0 && w < 0.0) || (u < 0.0 && w > 0.0)) {
          const Vec3 x = b.v(i) + (u / (u - w)) * b.e[i];
          if (inside(x, a)) {
            out = {0.0, x, x};
            dist_sq = 0.0;
            return true;
          }
        }
      }
    }
  }

  prepare_edges(a);
  prepare_edges(b);
  double best = kInf;
  Vec3 pa = a.v(0), pb = b.v(0), y;
  // Vertex–triangle (this also covers every endpoint case of the edge–edge pairs).
  for (int i = 0; i < 3; ++i) {
    const double d = point_triangle_sq(a.v(i), b, y);
    if (d < best) {
      best = d;
      pa = a.v(i);
      pb = y;
    }
  }
  for (int i = 0; i < 3; ++i) {
    const double d = point_triangle_sq(b.v(i), a, y);
    if (d < best) {
      best = d;
      pa = y;
      pb = b.v(i);
    }
  }
  // Edge–edge: only stationary pairs strictly inside both edges.
  for (int i = 0; i < 3; ++i) {
    const double A = a.ee[i];
    if (!(A > 0.0)) continue;
    for (int j = 0; j < 3; ++j) {
      const double E = b.ee[j];
      if (!(E > 0.0)) continue;
      const Vec3 r = a.v(i) - b.v(j);
      const double B = a.e[i].dot(b.e[j]), C = a.e[i].dot(r), F = b.e[j].dot(r);
      const double denom = A * E - B * B;
      if (!(denom > 0.0)) continue;
      const double sn = B * F - C * E, tn = A * F - B * C;
      if (!(sn > 0.0 && sn < denom && tn > 0.0 && tn < denom)) continue;
      const Vec3 qa = a.v(i) + (sn / denom) * a.e[i];
      const Vec3 qb = b.v(j) + (tn / denom) * b.e[j];
      const double d = (qa - qb).squaredNorm();
      if (d < best) {
        best = d;
        pa = qa;
        pb = qb;
      }
    }
  }
  dist_sq = best;
  if (!(best < limit_sq)) return false;
  out = {std::sqrt(best), pa, pb};
  return true;
}

/// The interior stationary pair of two segments when it lies strictly inside both; endpoint
/// cases are left to the caller.
inline bool segment_interior(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1,
                             Vec3& pa, Vec3& pb) {
  const Vec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = d1.squaredNorm(), e = d2.squaredNorm();
  if (!(a > 0.0) || !(e > 0.0)) return false;
  const double b = d1.dot(d2), c = d1.dot(r), f = d2.dot(r);
  const double denom = a * e - b * b;
  if (!(denom > 0.0)) return false;
  const double sn = b * f - c * e, tn = a * f - b * c;
  if (!(sn > 0.0 && sn < denom && tn > 0.0 && tn < denom)) return false;
  pa = p0 + (sn / denom) * d1;
  pb = q0 + (tn / denom) * d2;
  return true;
}

}  // namespace

PointClosest point_segment_closest(const Vec3& x, const Vec3& a, const Vec3& b) {
  const Vec3 d = b - a;
  const double dd = d.squaredNorm();
  if (!(dd > 0.0)) return {(x - a).norm(), a};
  const double t = (x - a).dot(d) / dd;
  if (t <= 0.0) return {(x - a).norm(), a};
  if (t >= 1.0) return {(x - b).norm(), b};
  const Vec3 p = a + t * d;
  return {(x - p).norm(), p};
}

SegmentClosest segment_closest_points(const Vec3& p0, const Vec3& p1, const Vec3& q0,
                                      const Vec3& q1) {
  SegmentClosest best{kInf, p0, q0};
  auto consider = [&](double d, const Vec3& a, const Vec3& b) {
    if (d < best.distance) best = {d, a, b};
  };
  Vec3 pa, pb;
  if (segment_interior(p0, p1, q0, q1, pa, pb)) consider((pa - pb).norm(), pa, pb);
  PointClosest c = point_segment_closest(p0, q0, q1);
  consider(c.distance, p0, c.point);
  c = point_segment_closest(p1, q0, q1);
  consider(c.distance, p1, c.point);
  c = point_segment_closest(q0, p0, p1);
  consider(c.distance, c.point, q0);
  c = point_segment_closest(q1, p0, p1);
  consider(c.distance, c.point, q1);
  return best;
}

PointClosest point_triangle_closest(const Vec3& x, const Triangle& t) {
  Prepared f;
  prepare(t, f);
  prepare_edges(f);
  Vec3 y;
  const double d = point_triangle_sq(x, f, y);
  return {std::sqrt(d), y};
}

TriangleDistance triangle_distance(const Triangle& a, const Triangle& b) {
  TriangleDistance out;
  double d2 = 0.0;
  triangle_distance_sq(a, b, kInf, out, d2);
  return out;
}

bool triangle_distance_below(const Triangle& a, const Triangle& b, double limit,
                             TriangleDistance& out) {
  double d2 = 0.0;
  return triangle_distance_sq(a, b, limit, out, d2);
}

bool triangle_distance_below(const Triangle& a, const Triangle& b, double limit, TriangleDistance& out,
                             const Vec3& axis, double scale) {
  double d2 = 0.0;
  return triangle_distance_sq(a, b, limit, out, d2, &axis, scale);
}

double touch_tolerance(const Triangle& a, const Triangle& b) {
  double m = 0.0;
  for (int i = 0; i < 3; ++i) {
    m = std::max(m, a[i].cwiseAbs().maxCoeff());
    m = std::max(m, b[i].cwiseAbs().maxCoeff());
  }
  return kTouch * m;
}

bool triangles_intersect(const Triangle& ta, const Triangle& tb) {
  const double tol = touch_tolerance(ta, tb);
  const double limit = std::nextafter(tol, kInf);
  const double limit_sq = limit * limit;
  // The cheapest rejections first, before either triangle is prepared: near contact most of the
  // pairs a collide query tests have bounding boxes apart (510 of 598 a query on the tunnel
  // console's scene, 15 of 35 on a coarse engine pair).
  if (centroid_line_or_boxes_apart(ta, tb, limit, limit_sq)) return false;
  // Each triangle is prepared once, for the plane tests and for the distance below.
  Prepared a, b;
  prepare(ta, a);
  prepare(tb, b);
  // Cheap rejection: all of one triangle strictly beyond the other's plane (by more than tol).
  auto separated_by_plane = [tol](const Prepared& f, const Triangle& t) {
    // Only a well-defined plane separates: a degenerate triangle's normal is rounding noise.
    if (f.degenerate) return false;
    const Vec3& n = f.n;
    const double len = n.norm();
    const double lim = tol * len;
    const Vec3& s = f.v(0);
    const double d0 = n.dot(t.p - s), d1 = n.dot(t.q - s), d2 = n.dot(t.r - s);
    return (d0 > lim && d1 > lim && d2 > lim) || (d0 < -lim && d1 < -lim && d2 < -lim);
  };
  if (separated_by_plane(a, tb) || separated_by_plane(b, ta)) return false;
  // Two disjoint triangles that neither plane separates are separated along the cross product
  // of an edge of each (the separating axis theorem). A gap of more than twice the tolerance
  // along one is a lower bound on the distance far above the projections' rounding (1e-16 of
  // the coordinates against the tolerance's 1e-12), so this rejects only pairs the full
  // evaluation below would reject too, and spares it (15 point and segment distances) for nearly
  // every pair that gets this far near contact (counted on the tunnel console's scene and the
  // engine pair: none of them reached it).
  if (!a.degenerate && !b.degenerate) {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const Vec3 u = a.e[i].cross(b.e[j]);
        const double uu = u.squaredNorm();
        if (!(uu > 0.0)) continue;
        const double pa0 = u.dot(ta.p), pa1 = u.dot(ta.q), pa2 = u.dot(ta.r);
        const double pb0 = u.dot(tb.p), pb1 = u.dot(tb.q), pb2 = u.dot(tb.r);
        const double gap = std::max(std::min({pb0, pb1, pb2}) - std::max({pa0, pa1, pa2}),
                                    std::min({pa0, pa1, pa2}) - std::max({pb0, pb1, pb2}));
        if (gap > 0.0 && gap * gap > 4.0 * limit_sq * uu) return false;
      }
  }
  TriangleDistance d;
  double d2 = 0.0;
  return prepared_distance_sq(a, b, limit_sq, d, d2);
}

bool triangle_sweep_within(const Triangle& a, const Triangle& b, const Vec3& sweep, double limit) {
  const double below = std::nextafter(limit, kInf);
  TriangleDistance d;
  auto within = [&](const Triangle& f) { return triangle_distance_below(a, f, below, d) && d.distance <= limit; };
  if (within(b)) return true;
  if (sweep.isZero()) return false;
  if (within(Triangle{b.p + sweep, b.q + sweep, b.r + sweep})) return true;
  for (int k = 0; k < 3; ++k) {
    const Vec3& x = b[k];
    const Vec3& y = b[(k + 1) % 3];
    if (within(Triangle{x, y, y + sweep}) || within(Triangle{x, y + sweep, x + sweep})) return true;
  }
  // Not near the prism's boundary: near it only from inside, where every vertex of `a` then is.
  // a.p = b.p + α·(b.q − b.p) + β·(b.r − b.p) + τ·sweep, inside for α, β ≥ 0, α + β ≤ 1, τ ∈ [0, 1].
  Mat3 m;
  m.col(0) = b.q - b.p;
  m.col(1) = b.r - b.p;
  m.col(2) = sweep;
  const double det = m.determinant();
  if (!(std::abs(det) > 1e-12 * m.col(0).norm() * m.col(1).norm() * sweep.norm())) return false;  // a flat prism: no inside
  const Vec3 c = m.inverse() * (a.p - b.p);
  return c[0] >= 0.0 && c[1] >= 0.0 && c[0] + c[1] <= 1.0 && c[2] >= 0.0 && c[2] <= 1.0;
}

}  // namespace swept
