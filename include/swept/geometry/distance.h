#pragma once
/// Exact closest-point primitives in double precision: point–segment, segment–segment,
/// point–triangle, triangle–triangle (distance and intersection) and rectangle–rectangle /
/// RSS–RSS lower bounds (Larsen, Gottschalk, Lin, Manocha 1999).
///
/// Every function takes its inputs in one common frame and returns points in that frame.
/// Degenerate input is legal everywhere: zero-length segments are points, zero-area triangles
/// (collinear or repeated vertices) are treated as the union of their edges.
#include "swept/geometry/rss.h"
#include "swept/geometry/types.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace swept {

/// A closest point and its distance.
struct PointClosest {
  double distance = 0.0;
  Vec3 point = Vec3::Zero();  ///< the closest point on the primitive
};

/// Closest point on segment [a, b] to `x`. A zero-length segment is the point a.
PointClosest point_segment_closest(const Vec3& x, const Vec3& a, const Vec3& b);

/// Closest points between two segments.
struct SegmentClosest {
  double distance = 0.0;
  Vec3 point_a = Vec3::Zero();  ///< on [p0, p1]
  Vec3 point_b = Vec3::Zero();  ///< on [q0, q1]
};

/// Exact closest points of segments [p0, p1] and [q0, q1]: the minimum of the interior
/// stationary pair (when it exists) and the four endpoint–segment cases, so parallel and
/// nearly parallel segments are exact too. Zero-length segments are points.
SegmentClosest segment_closest_points(const Vec3& p0, const Vec3& p1, const Vec3& q0,
                                      const Vec3& q1);

/// Closest point of triangle `t` to `x`. A triangle whose area is below 1e-13·(longest edge)²
/// is treated as the union of its three edges.
PointClosest point_triangle_closest(const Vec3& x, const Triangle& t);

/// Distance and closest points between two triangles.
struct TriangleDistance {
  double distance = 0.0;
  Vec3 point_a = Vec3::Zero();  ///< on triangle a
  Vec3 point_b = Vec3::Zero();  ///< on triangle b
};

/// Exact triangle–triangle distance: the minimum over the 6 vertex–triangle and 9 edge–edge
/// cases, and 0 (with a common point as both witnesses) when an edge of one triangle crosses
/// the other. Degenerate triangles fall back to their edges.
TriangleDistance triangle_distance(const Triangle& a, const Triangle& b);

/// `triangle_distance` for callers that only want distances below `limit` (a search's best
/// so far): returns false, leaving `out` untouched, as soon as the distance is proven ≥ limit
/// (for instance by a separating plane); otherwise fills `out` and returns true.
bool triangle_distance_below(const Triangle& a, const Triangle& b, double limit,
                             TriangleDistance& out);
/// The same, with one more cheap lower bound tried before the full evaluation: the gap between
/// the triangles' projections on `axis`, a unit vector from A towards B (a search passes the
/// direction of its closest pair so far: far apart, the pairs it must still test lie around
/// that pair, and their gap along it is close to their distance). `scale` bounds the absolute
/// value of every coordinate of both triangles; the gap is trusted only beyond 1e-12 × scale
/// (`touch_tolerance`'s allowance), far above the rounding of the projections and of the full
/// evaluation, so this rejects no pair that the plain call would accept, and what it accepts it
/// returns to the bit as the plain call.
bool triangle_distance_below(const Triangle& a, const Triangle& b, double limit, TriangleDistance& out,
                             const Vec3& axis, double scale);

/// The contact tolerance used by `triangles_intersect`: 1e-12 times the largest absolute
/// coordinate of the six vertices (rounding of coordinates that far from the origin is below
/// it). Depends on the frame the triangles are given in.
double touch_tolerance(const Triangle& a, const Triangle& b);

/// Do the triangles intersect or touch? True when their exact distance is at most
/// `touch_tolerance(a, b)`, so coplanar overlap, edge-on-edge and vertex-on-face contact count
/// as intersecting. Degenerate triangles are tested as segments or points.
bool triangles_intersect(const Triangle& a, const Triangle& b);

/// Does triangle `b`, translated by τ·sweep for some τ ∈ [0, 1], come within `limit` (≥ 0) of
/// triangle `a` (distance ≤ limit)? Exact: the positions of b along the sweep fill the prism
/// conv(b ∪ b + sweep), whose distance to `a` is the smallest over its boundary (b, b + sweep and
/// the three parallelograms its edges sweep, each as two triangles), or 0 when `a` lies inside it.
bool triangle_sweep_within(const Triangle& a, const Triangle& b, const Vec3& sweep, double limit);

/// Rectangle B placed in the frame of rectangle A, where A is [−a0, a0] × [−a1, a1] × {0}:
/// B = { translation + s·rotation.col(0) + t·rotation.col(1) : |s| ≤ b0, |t| ≤ b1 }.
struct RectanglePair {
  Mat3 rotation = Mat3::Identity();  ///< B's axes in A's frame (columns)
  Vec3 translation = Vec3::Zero();   ///< B's center in A's frame
  double a[2] = {0.0, 0.0};          ///< A's half lengths
  double b[2] = {0.0, 0.0};          ///< B's half lengths
};

/// Exact distance between the two rectangles (0 when they intersect), minus a relative slack
/// of 1e-12·(‖translation‖ + sizes) so rounding never makes it exceed the true distance.
/// Clamped at 0.
double rectangle_distance(const RectanglePair& pair);

/// A cheap lower bound on the rectangles' distance: the largest gap of their projections on
/// the axes of both rectangles, the center line and the four edge–edge cross products
/// (separating-axis reasoning). Never larger than `rectangle_distance`; may be 0 or negative
/// when the rectangles' projections overlap on every axis. Returns as soon as a gap ≥
/// `stop_at` is found (callers that only compare against a threshold save the other axes).
double rectangle_gap(const RectanglePair& pair,
                     double stop_at = std::numeric_limits<double>::infinity());

/// A tight, cheap lower bound on the rectangles' distance: the projection gap of
/// `rectangle_gap` and, in addition, the gap along the direction joining the pair found by
/// two rounds of alternating projection between the rectangles (starting from B's center).
/// That direction is the exact closest-pair direction in the vertex–vertex and vertex–edge
/// configurations the fixed axes miss, so the bound is usually within rounding of
/// `rectangle_distance`, at a fraction of its cost. Never larger than the exact distance;
/// returns early once a gap ≥ `stop_at` is found.
double rectangle_lower_bound(const RectanglePair& pair,
                             double stop_at = std::numeric_limits<double>::infinity());

namespace detail {

/// `rectangle_lower_bound` in two steps, so that a traversal can run the first without forming
/// the whole pair: the first needs only B's first two axes in A's frame (`u`, `v`) and B's
/// center (`t`), and decides almost every node pair. `stop_at` here already includes `slack`.
struct ProjectionGap {
  double gap;    ///< the gap along the projection direction (−∞ when there is none)
  bool decided;  ///< `bound(slack)` is the answer; otherwise go on with `rectangle_axes_gap`

  /// The decided bound: the gap with the slack taken off (−slack when the rectangles touch).
  double bound(double slack) const {
    return (gap > -std::numeric_limits<double>::infinity() ? gap : 0.0) - slack;
  }
};

/// Relative rounding allowance of the rectangle bounds, so that a bound never exceeds the exact
/// distance.
inline constexpr double kRectangleSlack = 1e-12;

/// The rounding allowance of both steps, for B's center `t` in A's frame and the half-lengths.
inline double rectangle_slack(const Vec3& t, double a0, double a1, double b0, double b1) {
  return kRectangleSlack * (std::abs(t.x()) + std::abs(t.y()) + std::abs(t.z()) + a0 + a1 + b0 + b1);
}

/// Two rounds (one when far apart) of alternating projection from B's center: P on A, Q on B.
/// The direction Q − P converges to the closest-pair direction, and the gap along it is a valid
/// bound anyway. |Q − P| is an upper bound on the distance: when it is below `stop_at`, no axis
/// can reach `stop_at` and the remaining axes are skipped.
/// `value_past_stop` false: a caller that only needs to know that the gap reaches `stop_at` gets
/// +∞ for such a gap when that is sure without the square root and the division (the squared
/// comparison below, with a margin far above their rounding); every other answer is the same.
[[gnu::always_inline]] inline ProjectionGap projection_gap(const Vec3& u, const Vec3& v, const Vec3& t, double a0,
                                                           double a1, double b0, double b1, double stop_at,
                                                           double slack, bool value_past_stop = true) {
  auto onto_a = [&](const Vec3& x) { return Vec3(std::clamp(x.x(), -a0, a0), std::clamp(x.y(), -a1, a1), 0.0); };
  auto onto_b = [&](const Vec3& x) {
    const Vec3 d = x - t;
    return Vec3(t + std::clamp(d.dot(u), -b0, b0) * u + std::clamp(d.dot(v), -b1, b1) * v);
  };
  Vec3 p = onto_a(t);
  Vec3 q = onto_b(p);
  // Centers more than twice the rectangles' half-lengths apart: the first round's direction is
  // already close to the closest-pair direction, and the second round costs more than the bound
  // gains (far-apart CAD pairs: 5-10 % less distance time with one round there; near contact
  // the second round pays).
  const double span = a0 + a1 + b0 + b1;
  if (!(t.squaredNorm() > 4.0 * span * span)) {
    p = onto_a(q);
    q = onto_b(p);
  }
  const Vec3 n = q - p;
  const double nn = n.squaredNorm();
  if (nn > 0.0) {
    const double ext =
        a0 * std::abs(n.x()) + a1 * std::abs(n.y()) + b0 * std::abs(n.dot(u)) + b1 * std::abs(n.dot(v));
    const double rise = std::abs(t.dot(n)) - ext;
    // rise / √nn ≥ stop_at (1 + 5e-14) in exact arithmetic, from the rounded squares (a few units
    // of 1.1e-16 each), so the rounded gap below is ≥ stop_at too. Away from under- and overflow.
    if (!value_past_stop && stop_at > 1e-50 && stop_at < 1e50 && nn > 1e-100 && nn < 1e100 && rise > 0.0 &&
        rise * rise > (1.0 + 1e-13) * (stop_at * stop_at) * nn)
      return {std::numeric_limits<double>::infinity(), true};
    const double len = std::sqrt(nn);
    const double gap = rise / len;
    return {gap, gap >= stop_at || len + slack < stop_at};
  }
  // The rectangles touch: no positive bound exists.
  return {-std::numeric_limits<double>::infinity(), stop_at > slack};
}

/// The second step: the projection gaps on the rectangles' axes, the center line and the edge ×
/// edge directions, starting from the first step's `gap`; returns the bound (slack taken off).
double rectangle_axes_gap(const RectanglePair& pair, double stop_at, double gap, double slack);

}  // namespace detail

/// A lower bound on the distance between rectangle A and rectangle B *swept* along `sweep` (B at
/// translation + τ·sweep for every τ ∈ [0, 1], all in A's frame): the largest projection gap on
/// the separating axes of A and the zonotope B ⊕ segment (A's and B's normals and edges, the
/// sweep, the cross products of the sweep and of A's edges with B's, the center line and its
/// part across the sweep). Never larger than the smallest distance along the sweep; may be ≤ 0.
/// Returns as soon as a gap ≥ `stop_at` is found. With a zero sweep it is a (weaker)
/// `rectangle_gap`.
double swept_rectangle_lower_bound(const RectanglePair& pair, const Vec3& sweep,
                                   double stop_at = std::numeric_limits<double>::infinity());

/// The pair for two RSSs given in one common frame.
RectanglePair rectangle_pair(const Rss& a, const Rss& b);

/// Lower bound on the distance between the volumes of two RSSs given in one common frame:
/// rectangle distance − radius(a) − radius(b), clamped at 0. Never larger than the true
/// distance between any point set each RSS contains.
double rss_distance(const Rss& a, const Rss& b);

}  // namespace swept
