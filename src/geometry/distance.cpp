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
constexpr double kRectSlack = 1e-12;

inline double clamp01(double x) { return x < 0.0 ? 0.0 : (x > 1.0 ? 1.0 : x); }

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

/// The squared distance of the triangles, or any value ≥ limit² when it is at least `limit`
/// (then `out` is untouched). Returns true when the exact distance was computed.
bool triangle_distance_sq(const Triangle& ta, const Triangle& tb, double limit,
                          TriangleDistance& out, double& dist_sq) {
  const double limit_sq = limit * limit;
  if (limit < kInf) {
    // The gap along the line between the centroids bounds the distance from below; it
    // settles most pairs a search tests against its best answer so far.
    const Vec3 n = (tb.p + tb.q + tb.r) - (ta.p + ta.q + ta.r);
    const double lo_b = std::min({n.dot(tb.p), n.dot(tb.q), n.dot(tb.r)});
    const double hi_a = std::max({n.dot(ta.p), n.dot(ta.q), n.dot(ta.r)});
    const double gap = lo_b - hi_a;
    if (gap > 0.0 && gap * gap >= limit_sq * n.squaredNorm()) return false;
  }
  Prepared a, b;
  prepare(ta, a);
  prepare(tb, b);

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

/// Squared distance between segments p1 + s·d1 and p2 + t·d2, s, t ∈ [0, 1] (clamped
/// stationary point; used for rectangles where a tiny overestimate is absorbed by the slack).
inline double seg_seg_sq(const Vec3& p1, const Vec3& d1, const Vec3& p2, const Vec3& d2) {
  const Vec3 r = p1 - p2;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  double s = 0.0, t = 0.0;
  if (a <= 0.0 && e <= 0.0) return r.squaredNorm();
  if (a <= 0.0) {
    t = clamp01(f / e);
  } else {
    const double c = d1.dot(r);
    if (e <= 0.0) {
      s = clamp01(-c / a);
    } else {
      const double b = d1.dot(d2);
      const double denom = a * e - b * b;
      s = denom > 0.0 ? clamp01((b * f - c * e) / denom) : 0.0;
      t = (b * s + f) / e;
      if (t < 0.0) {
        t = 0.0;
        s = clamp01(-c / a);
      } else if (t > 1.0) {
        t = 1.0;
        s = clamp01((b - c) / a);
      }
    }
  }
  return (r + s * d1 - t * d2).squaredNorm();
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

double touch_tolerance(const Triangle& a, const Triangle& b) {
  double m = 0.0;
  for (int i = 0; i < 3; ++i) {
    m = std::max(m, a[i].cwiseAbs().maxCoeff());
    m = std::max(m, b[i].cwiseAbs().maxCoeff());
  }
  return kTouch * m;
}

bool triangles_intersect(const Triangle& a, const Triangle& b) {
  const double tol = touch_tolerance(a, b);
  // Cheap rejection: all of one triangle strictly beyond the other's plane (by more than tol).
  auto separated_by_plane = [tol](const Triangle& s, const Triangle& t) {
    // Only a well-defined plane separates: a degenerate triangle's normal is rounding noise.
    Prepared f;
    prepare(s, f);
    if (f.degenerate) return false;
    const Vec3& n = f.n;
    const double len = n.norm();
    const double lim = tol * len;
    const double d0 = n.dot(t.p - s.p), d1 = n.dot(t.q - s.p), d2 = n.dot(t.r - s.p);
    return (d0 > lim && d1 > lim && d2 > lim) || (d0 < -lim && d1 < -lim && d2 < -lim);
  };
  if (separated_by_plane(a, b) || separated_by_plane(b, a)) return false;
  TriangleDistance d;
  return triangle_distance_below(a, b, std::nextafter(tol, kInf), d);
}

RectanglePair rectangle_pair(const Rss& a, const Rss& b) {
  RectanglePair p;
  p.rotation = a.axes.transpose() * b.axes;
  p.translation = a.axes.transpose() * (b.center - a.center);
  p.a[0] = a.half_length[0];
  p.a[1] = a.half_length[1];
  p.b[0] = b.half_length[0];
  p.b[1] = b.half_length[1];
  return p;
}

namespace {

/// The projection-gap bound; with `projected`, the alternating-projection direction is tried
/// after the face axes.
double gap_bound(const RectanglePair& pr, double stop_at, bool projected) {
  const Mat3& R = pr.rotation;
  const Vec3& t = pr.translation;
  const double a0 = pr.a[0], a1 = pr.a[1], b0 = pr.b[0], b1 = pr.b[1];
  // Rounding allowance, so that the bound never exceeds the exact distance.
  const double slack =
      kRectSlack * (std::abs(t.x()) + std::abs(t.y()) + std::abs(t.z()) + a0 + a1 + b0 + b1);
  stop_at += slack;
  double gap = -kInf;
  if (projected) {
    // Two rounds of alternating projection from B's center: P on A, Q on B. The direction
    // Q − P converges to the closest-pair direction, and the gap along it is a valid bound
    // anyway. |Q − P| is an upper bound on the distance: when it is below `stop_at`, no axis
    // can reach `stop_at` and the remaining axes are skipped.
    const Vec3 u = R.col(0), v = R.col(1);
    auto onto_a = [&](const Vec3& x) {
      return Vec3(std::clamp(x.x(), -a0, a0), std::clamp(x.y(), -a1, a1), 0.0);
    };
    auto onto_b = [&](const Vec3& x) {
      const Vec3 d = x - t;
      return Vec3(t + std::clamp(d.dot(u), -b0, b0) * u + std::clamp(d.dot(v), -b1, b1) * v);
    };
    Vec3 p = onto_a(t);
    Vec3 q = onto_b(p);
    p = onto_a(q);
    q = onto_b(p);
    const Vec3 n = q - p;
    const double nn = n.squaredNorm();
    if (nn > 0.0) {
      const double len = std::sqrt(nn);
      const double ext = a0 * std::abs(n.x()) + a1 * std::abs(n.y()) + b0 * std::abs(n.dot(u)) +
                         b1 * std::abs(n.dot(v));
      gap = (std::abs(t.dot(n)) - ext) / len;
      if (gap >= stop_at || len + slack < stop_at) return gap - slack;
    } else if (stop_at > slack) {
      return -slack;  // the rectangles touch: no positive bound exists
    }
  }
  // Projection half-widths: A on n is a0|n.x| + a1|n.y|; B on n is b0|n·u| + b1|n·v|, with u, v
  // the first two columns of R. The face normals are unit vectors: no square roots.
  const double r00 = std::abs(R(0, 0)), r01 = std::abs(R(0, 1)), r10 = std::abs(R(1, 0)),
               r11 = std::abs(R(1, 1)), r20 = std::abs(R(2, 0)), r21 = std::abs(R(2, 1));
  gap = std::max(gap, std::abs(t.z()) - b0 * r20 - b1 * r21);  // A's normal
  if (gap >= stop_at) return gap - slack;
  const double tw = t.dot(R.col(2));  // B's normal
  gap = std::max(gap, std::abs(tw) - a0 * std::abs(R(0, 2)) - a1 * std::abs(R(1, 2)));
  gap = std::max(gap, std::abs(t.x()) - a0 - b0 * r00 - b1 * r01);
  gap = std::max(gap, std::abs(t.y()) - a1 - b0 * r10 - b1 * r11);
  if (gap >= stop_at) return gap - slack;
  const double tu = t.dot(R.col(0)), tv = t.dot(R.col(1));
  gap = std::max(gap, std::abs(tu) - b0 - a0 * r00 - a1 * r10);
  gap = std::max(gap, std::abs(tv) - b1 - a0 * r01 - a1 * r11);
  if (gap >= stop_at) return gap - slack;
  // The center line: n = t / |t|; n·u = tu / |t|, n·v = tv / |t|.
  const double tt = t.squaredNorm();
  if (tt > 0.0) {
    const double len = std::sqrt(tt);
    gap = std::max(gap, len - (a0 * std::abs(t.x()) + a1 * std::abs(t.y()) + b0 * std::abs(tu) +
                               b1 * std::abs(tv)) / len);
    if (gap >= stop_at) return gap - slack;
  }
  // Edge × edge: n = x × u = (0, −u.z, u.y) etc. With n = e × f for unit e (of A) and f (of
  // B): n·u and n·v follow from R, and |n| = sin of the angle between the edges.
  auto axis = [&](double nx, double ny, double nz, double nu, double nv) {
    const double len2 = nx * nx + ny * ny + nz * nz;
    if (!(len2 > 1e-18)) return;
    const double tn = t.x() * nx + t.y() * ny + t.z() * nz;
    const double ext = a0 * std::abs(nx) + a1 * std::abs(ny) + b0 * std::abs(nu) + b1 * std::abs(nv);
    gap = std::max(gap, (std::abs(tn) - ext) / std::sqrt(len2));
  };
  // x × u: n = (0, −R20, R10); n·u = 0; n·v = −R20·R11 + R10·R21 = (u × v)·x... computed directly.
  axis(0.0, -R(2, 0), R(1, 0), 0.0, -R(2, 0) * R(1, 1) + R(1, 0) * R(2, 1));
  // x × v: n = (0, −R21, R11); n·u = −R21·R10 + R11·R20; n·v = 0.
  axis(0.0, -R(2, 1), R(1, 1), -R(2, 1) * R(1, 0) + R(1, 1) * R(2, 0), 0.0);
  // y × u: n = (R20, 0, −R00); n·u = 0; n·v = R20·R01 − R00·R21.
  axis(R(2, 0), 0.0, -R(0, 0), 0.0, R(2, 0) * R(0, 1) - R(0, 0) * R(2, 1));
  // y × v: n = (R21, 0, −R01); n·u = R21·R00 − R01·R20; n·v = 0.
  axis(R(2, 1), 0.0, -R(0, 1), R(2, 1) * R(0, 0) - R(0, 1) * R(2, 0), 0.0);
  return gap - slack;
}

}  // namespace

double rectangle_gap(const RectanglePair& pr, double stop_at) { return gap_bound(pr, stop_at, false); }

double rectangle_lower_bound(const RectanglePair& pr, double stop_at) {
  return gap_bound(pr, stop_at, true);
}

double rectangle_distance(const RectanglePair& pr) {
  const Mat3& R = pr.rotation;
  const Vec3& t = pr.translation;
  const double a0 = pr.a[0], a1 = pr.a[1], b0 = pr.b[0], b1 = pr.b[1];
  const double scale = std::abs(t.x()) + std::abs(t.y()) + std::abs(t.z()) + a0 + a1 + b0 + b1;
  const double slack = kRectSlack * scale;

  // Corners in A's frame, counter-clockwise; edges from corner k to k + 1.
  const Vec3 u = R.col(0) * b0, v = R.col(1) * b1;
  const Vec3 ca[4] = {{-a0, -a1, 0.0}, {a0, -a1, 0.0}, {a0, a1, 0.0}, {-a0, a1, 0.0}};
  const Vec3 cb[4] = {t - u - v, t + u - v, t + u + v, t - u + v};
  Vec3 da[4], db[4];
  for (int k = 0; k < 4; ++k) {
    da[k] = ca[(k + 1) % 4] - ca[k];
    db[k] = cb[(k + 1) % 4] - cb[k];
  }

  // Crossings: an edge of one passing through the other rectangle means they intersect.
  for (int k = 0; k < 4; ++k) {
    const double z0 = cb[k].z(), z1 = cb[(k + 1) % 4].z();
    if ((z0 > 0.0 && z1 < 0.0) || (z0 < 0.0 && z1 > 0.0)) {
      const Vec3 x = cb[k] + (z0 / (z0 - z1)) * db[k];
      if (std::abs(x.x()) <= a0 && std::abs(x.y()) <= a1) return 0.0;
    }
  }
  // A's corners in B's frame.
  Vec3 ab[4];
  for (int k = 0; k < 4; ++k) ab[k] = R.transpose() * (ca[k] - t);
  for (int k = 0; k < 4; ++k) {
    const double z0 = ab[k].z(), z1 = ab[(k + 1) % 4].z();
    if ((z0 > 0.0 && z1 < 0.0) || (z0 < 0.0 && z1 > 0.0)) {
      const Vec3 x = ab[k] + (z0 / (z0 - z1)) * (ab[(k + 1) % 4] - ab[k]);
      if (std::abs(x.x()) <= b0 && std::abs(x.y()) <= b1) return 0.0;
    }
  }

  double best = kInf;
  // Vertex–face.
  for (int k = 0; k < 4; ++k) {
    if (std::abs(cb[k].x()) <= a0 && std::abs(cb[k].y()) <= a1)
      best = std::min(best, cb[k].z() * cb[k].z());
    if (std::abs(ab[k].x()) <= b0 && std::abs(ab[k].y()) <= b1)
      best = std::min(best, ab[k].z() * ab[k].z());
  }
  // Edge–edge.
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) best = std::min(best, seg_seg_sq(ca[i], da[i], cb[j], db[j]));
  return std::max(0.0, std::sqrt(best) - slack);
}

double rss_distance(const Rss& a, const Rss& b) {
  const RectanglePair p = rectangle_pair(a, b);
  const double d = std::max(rectangle_gap(p), rectangle_distance(p));
  return std::max(0.0, d - a.radius - b.radius);
}

}  // namespace swept
