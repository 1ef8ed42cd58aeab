// Exact triangle–triangle distance, written for the oracle alone.
//
// The closest points of two triangles are either a vertex of one and a point of the other, or
// two edge points; when the triangles intersect, an edge of one crosses the other (or, when they
// lie in one plane, edges cross or a vertex lies inside). Every candidate below is the distance
// between two points that lie on the triangles (convex combinations of their corners), so
// rounding can make a candidate slightly too large but never invents a short distance; the
// crossing tests return an exact 0 only when every orientation sign agrees strictly.
#include "oracle/path_oracle.h"

#include <algorithm>
#include <cmath>

namespace oracle {
namespace {

using V = Eigen::Vector3d;

double point_segment_sq(const V& p, const V& a, const V& b) {
  const V ab = b - a;
  const double len2 = ab.squaredNorm();
  double s = 0.0;
  if (len2 > 0.0) s = std::clamp((p - a).dot(ab) / len2, 0.0, 1.0);
  return (p - (a + s * ab)).squaredNorm();
}

// The foot of p in the triangle's plane, when it lies inside the triangle; +∞ otherwise (the
// edges then hold the closest point, which the callers take separately).
double point_face_sq(const V& p, const Tri& t) {
  const V& a = t.v[0];
  const V& b = t.v[1];
  const V& c = t.v[2];
  const V n = (b - a).cross(c - a);
  const double nn = n.squaredNorm();
  if (!(nn > 0.0) || !std::isfinite(nn)) return std::numeric_limits<double>::infinity();
  // Barycentric weights of the foot: signed sub-areas along n (p's offset along n drops out).
  const double wa = (b - p).cross(c - p).dot(n) / nn;
  const double wb = (c - p).cross(a - p).dot(n) / nn;
  const double wc = 1.0 - wa - wb;
  if (!(wa >= 0.0 && wb >= 0.0 && wc >= 0.0)) return std::numeric_limits<double>::infinity();
  return (p - (wa * a + wb * b + wc * c)).squaredNorm();
}

// Both segments' interior points, when the closest points of the two lines fall strictly inside
// both; +∞ otherwise (then an endpoint is closest, covered by the point–segment candidates).
double edge_interior_sq(const V& p0, const V& p1, const V& q0, const V& q1) {
  const V d1 = p1 - p0;
  const V d2 = q1 - q0;
  const V r = p0 - q0;
  const double den = d1.cross(d2).squaredNorm();  // a·e − b², without the cancellation
  if (!(den > 0.0) || !std::isfinite(den)) return std::numeric_limits<double>::infinity();
  const double a = d1.squaredNorm(), b = d1.dot(d2), e = d2.squaredNorm();
  const double c = d1.dot(r), f = d2.dot(r);
  // Zero gradient of |r + s·d1 − u·d2|²:  a·s − b·u = −c,  b·s − e·u = −f.
  const double s = (b * f - c * e) / den;
  const double u = (a * f - b * c) / den;
  if (!(s > 0.0 && s < 1.0 && u > 0.0 && u < 1.0)) return std::numeric_limits<double>::infinity();
  return ((p0 + s * d1) - (q0 + u * d2)).squaredNorm();
}

double orient(const V& a, const V& b, const V& c, const V& d) { return (b - a).cross(c - a).dot(d - a); }

// Which coordinate to drop to see the plane with normal n without collapsing it.
int dominant_axis(const V& n) {
  const V m = n.cwiseAbs();
  return m.x() >= m.y() ? (m.x() >= m.z() ? 0 : 2) : (m.y() >= m.z() ? 1 : 2);
}

double cross2(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

Eigen::Vector2d drop(const V& p, int axis) {
  return axis == 0 ? Eigen::Vector2d(p.y(), p.z()) : axis == 1 ? Eigen::Vector2d(p.z(), p.x()) : Eigen::Vector2d(p.x(), p.y());
}

// Does the segment pq (lying in t's plane) touch the non-degenerate triangle t? Seen in 2D:
// an endpoint inside or on t, or a proper crossing of an edge.
bool coplanar_touch(const V& p, const V& q, const Tri& t, const V& n) {
  const int axis = dominant_axis(n);
  const Eigen::Vector2d P = drop(p, axis), Q = drop(q, axis);
  const Eigen::Vector2d A = drop(t.v[0], axis), B = drop(t.v[1], axis), C = drop(t.v[2], axis);
  auto inside = [&](const Eigen::Vector2d& x) {
    const double s1 = cross2(A, B, x), s2 = cross2(B, C, x), s3 = cross2(C, A, x);
    return (s1 >= 0 && s2 >= 0 && s3 >= 0) || (s1 <= 0 && s2 <= 0 && s3 <= 0);
  };
  if (inside(P) || inside(Q)) return true;
  const Eigen::Vector2d* corner[3] = {&A, &B, &C};
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector2d& E0 = *corner[i];
    const Eigen::Vector2d& E1 = *corner[(i + 1) % 3];
    const double o1 = cross2(P, Q, E0), o2 = cross2(P, Q, E1);
    const double o3 = cross2(E0, E1, P), o4 = cross2(E0, E1, Q);
    if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0))) return true;
  }
  return false;
}

// Does the edge pq meet the triangle t? Exact zero only on unambiguous signs: a proper crossing
// of t's interior, or (in t's plane exactly) a 2D overlap. Anything borderline is left to the
// distance candidates, which are then tiny anyway.
bool edge_meets_triangle(const V& p, const V& q, const Tri& t) {
  const V& a = t.v[0];
  const V& b = t.v[1];
  const V& c = t.v[2];
  const V n = (b - a).cross(c - a);
  if (!(n.squaredNorm() > 0.0)) return false;  // degenerate: its edges are all there is
  const double dp = orient(a, b, c, p);
  const double dq = orient(a, b, c, q);
  if (dp == 0.0 && dq == 0.0) return coplanar_touch(p, q, t, n);
  if (!((dp > 0 && dq < 0) || (dp < 0 && dq > 0))) return false;
  // The line pq passes inside t when it turns the same way around all three edges.
  const double s1 = orient(p, q, a, b), s2 = orient(p, q, b, c), s3 = orient(p, q, c, a);
  return (s1 > 0 && s2 > 0 && s3 > 0) || (s1 < 0 && s2 < 0 && s3 < 0);
}

}  // namespace

double triangle_distance(const Tri& a, const Tri& b) {
  for (int i = 0; i < 3; ++i) {
    if (edge_meets_triangle(a.v[i], a.v[(i + 1) % 3], b)) return 0.0;
    if (edge_meets_triangle(b.v[i], b.v[(i + 1) % 3], a)) return 0.0;
  }
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    const V& a0 = a.v[i];
    const V& a1 = a.v[(i + 1) % 3];
    for (int j = 0; j < 3; ++j) {
      const V& b0 = b.v[j];
      const V& b1 = b.v[(j + 1) % 3];
      // Vertex–edge pairs both ways (every endpoint case of the 9 edge–edge distances) and the
      // edge–edge interior case.
      best = std::min(best, point_segment_sq(a.v[i], b0, b1));
      best = std::min(best, point_segment_sq(b.v[j], a0, a1));
      best = std::min(best, edge_interior_sq(a0, a1, b0, b1));
    }
    best = std::min(best, point_face_sq(a.v[i], b));
    best = std::min(best, point_face_sq(b.v[i], a));
  }
  return std::sqrt(best);
}

double translation_minimum(const Tri& a, const Tri& b, const Eigen::Vector3d& sweep) {
  auto f = [&](double t) {
    Tri m = b;
    for (auto& v : m.v) v += t * sweep;
    return triangle_distance(a, m);
  };
  const double g = (std::sqrt(5.0) - 1.0) / 2.0;
  double lo = 0.0, hi = 1.0;
  double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo), f1 = f(x1), f2 = f(x2);
  for (int i = 0; i < 120; ++i) {
    if (f1 <= f2) {
      hi = x2, x2 = x1, f2 = f1, x1 = hi - g * (hi - lo), f1 = f(x1);
    } else {
      lo = x1, x1 = x2, f1 = f2, x2 = lo + g * (hi - lo), f2 = f(x2);
    }
  }
  return std::min({f1, f2, f(0.0), f(1.0)});
}

}  // namespace oracle
