// Rectangles and RSSs: the exact rectangle distance and the cheap lower bounds the tree
// traversals use.
#include "swept/geometry/distance.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace swept {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kRectSlack = detail::kRectangleSlack;

inline double clamp01(double x) { return x < 0.0 ? 0.0 : (x > 1.0 ? 1.0 : x); }

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
  const Vec3& t = pr.translation;
  // Rounding allowance, so that the bound never exceeds the exact distance.
  const double slack = detail::rectangle_slack(t, pr.a[0], pr.a[1], pr.b[0], pr.b[1]);
  stop_at += slack;
  double gap = -kInf;
  if (projected) {
    const detail::ProjectionGap first = detail::projection_gap(pr.rotation.col(0), pr.rotation.col(1), t, pr.a[0],
                                                               pr.a[1], pr.b[0], pr.b[1], stop_at, slack);
    if (first.decided) return first.bound(slack);
    gap = first.gap;
  }
  return detail::rectangle_axes_gap(pr, stop_at, gap, slack);
}

}  // namespace

double detail::rectangle_axes_gap(const RectanglePair& pr, double stop_at, double gap, double slack) {
  const Mat3& R = pr.rotation;
  const Vec3& t = pr.translation;
  const double a0 = pr.a[0], a1 = pr.a[1], b0 = pr.b[0], b1 = pr.b[1];
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

double swept_rectangle_lower_bound(const RectanglePair& pr, const Vec3& sweep, double stop_at) {
  const Mat3& R = pr.rotation;
  const double a0 = pr.a[0], a1 = pr.a[1], b0 = pr.b[0], b1 = pr.b[1];
  // B along the sweep is the zonotope {mid + s·u + t·v + τ·half}, |s| ≤ b0, |t| ≤ b1, |τ| ≤ 1.
  const Vec3 half = 0.5 * sweep;
  const Vec3 mid = pr.translation + half;
  const Vec3 u = R.col(0), v = R.col(1), w = R.col(2);
  const double slack = kRectSlack * (mid.cwiseAbs().sum() + half.cwiseAbs().sum() + a0 + a1 + b0 + b1);
  stop_at += slack;
  double gap = -kInf;
  // The gap along n (any length; skipped when n is too short to have a direction).
  auto axis = [&](const Vec3& n) {
    const double len2 = n.squaredNorm();
    if (!(len2 > 1e-18)) return false;
    const double ext = a0 * std::abs(n.x()) + a1 * std::abs(n.y()) + b0 * std::abs(n.dot(u)) +
                       b1 * std::abs(n.dot(v)) + std::abs(n.dot(half));
    gap = std::max(gap, (std::abs(n.dot(mid)) - ext) / std::sqrt(len2));
    return gap >= stop_at;
  };
  const double hh = half.squaredNorm();
  const double mm = mid.squaredNorm();
  if (!(mm > 0.0)) return -slack;
  const Vec3 along = hh > 0.0 ? Vec3(half / std::sqrt(hh)) : Vec3::Zero();
  // The center line across the sweep first: a body passing beside another is told apart by it.
  if (axis((mid - mid.dot(along) * along) / std::sqrt(mm))) return gap - slack;
  if (axis(Vec3::UnitZ()) || axis(w) || axis(mid / std::sqrt(mm))) return gap - slack;
  if (axis(Vec3::UnitX()) || axis(Vec3::UnitY()) || axis(u) || axis(v)) return gap - slack;
  if (hh > 0.0) {
    // Faces of the zonotope and edge × edge with the sweep.
    if (axis(along) || axis(u.cross(along)) || axis(v.cross(along)) || axis(Vec3::UnitX().cross(along)) ||
        axis(Vec3::UnitY().cross(along)) || axis(Vec3::UnitZ().cross(along)))
      return gap - slack;
  }
  const Vec3 x = Vec3::UnitX(), y = Vec3::UnitY();
  axis(x.cross(u));
  axis(x.cross(v));
  axis(y.cross(u));
  axis(y.cross(v));
  return gap - slack;
}

double rss_distance(const Rss& a, const Rss& b) {
  const RectanglePair p = rectangle_pair(a, b);
  const double d = std::max(rectangle_gap(p), rectangle_distance(p));
  return std::max(0.0, d - a.radius - b.radius);
}

}  // namespace swept
