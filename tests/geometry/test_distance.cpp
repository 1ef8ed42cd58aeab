// Exact primitives against independent oracles: an enumeration of the face pairs of the two
// simplices (least squares on each pair of affine hulls, kept when feasible) and golden-section
// searches. Inputs include slivers, zero-area triangles, repeated vertices, touching and
// parallel configurations and coordinates far from the origin.
#include "swept/geometry/distance.h"

#include "support/test_support.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace swept {
namespace {

using test::Rng;

/// Exact distance between the convex hulls of two small point sets (≤ 4 points each) by
/// enumerating every pair of faces (non-empty vertex subsets) and solving the least-squares
/// problem on their affine hulls; feasible solutions only.
double hull_distance_oracle(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  double best = std::numeric_limits<double>::infinity();
  const int na = static_cast<int>(a.size()), nb = static_cast<int>(b.size());
  for (int ma = 1; ma < (1 << na); ++ma) {
    for (int mb = 1; mb < (1 << nb); ++mb) {
      std::vector<Vec3> fa, fb;
      for (int i = 0; i < na; ++i)
        if (ma & (1 << i)) fa.push_back(a[i]);
      for (int i = 0; i < nb; ++i)
        if (mb & (1 << i)) fb.push_back(b[i]);
      const int ka = static_cast<int>(fa.size()) - 1, kb = static_cast<int>(fb.size()) - 1;
      Eigen::MatrixXd m(3, ka + kb);
      for (int i = 0; i < ka; ++i) m.col(i) = fa[i + 1] - fa[0];
      for (int i = 0; i < kb; ++i) m.col(ka + i) = -(fb[i + 1] - fb[0]);
      Eigen::VectorXd x = Eigen::VectorXd::Zero(ka + kb);
      if (ka + kb > 0) x = m.completeOrthogonalDecomposition().solve(Vec3(fb[0] - fa[0]));
      auto feasible = [&](int off, int k) {
        double sum = 0;
        for (int i = 0; i < k; ++i) {
          if (x[off + i] < 0) return false;
          sum += x[off + i];
        }
        return sum <= 1.0;
      };
      if (!feasible(0, ka) || !feasible(ka, kb)) continue;
      Vec3 pa = fa[0], pb = fb[0];
      for (int i = 0; i < ka; ++i) pa += x[i] * (fa[i + 1] - fa[0]);
      for (int i = 0; i < kb; ++i) pb += x[ka + i] * (fb[i + 1] - fb[0]);
      best = std::min(best, (pa - pb).norm());
    }
  }
  return best;
}

double oracle(const Triangle& a, const Triangle& b) {
  return hull_distance_oracle({a.p, a.q, a.r}, {b.p, b.q, b.r});
}

double scale_of(const Triangle& a, const Triangle& b) {
  double m = 0;
  for (int i = 0; i < 3; ++i) m = std::max({m, a[i].cwiseAbs().maxCoeff(), b[i].cwiseAbs().maxCoeff()});
  return std::max(m, 1.0);
}

/// A random triangle of one of the nasty kinds around `c`, size ~ len.
Triangle nasty(Rng& rng, const Vec3& c, double len) {
  const Vec3 d = rng.vec(-1, 1).normalized();
  const Vec3 e = d.unitOrthogonal();
  switch (rng.next() % 6) {
    case 0: return {c, c + len * d, c + 0.5 * len * d + 1e-4 * len * e};  // sliver 1e4
    case 1: return {c, c + len * d, c + 0.3 * len * d};                    // collinear
    case 2: return {c, c, c + len * d};                                     // repeated
    case 3: return {c, c, c};                                               // a point
    default: return {c + rng.vec(-len, len), c + rng.vec(-len, len), c + rng.vec(-len, len)};
  }
}

void check_witnesses(const Triangle& a, const Triangle& b, const TriangleDistance& r, double tol) {
  EXPECT_LE(point_triangle_closest(r.point_a, a).distance, tol);
  EXPECT_LE(point_triangle_closest(r.point_b, b).distance, tol);
  EXPECT_NEAR((r.point_a - r.point_b).norm(), r.distance, tol);
}

TEST(TriangleDistance, MatchesFacePairOracleOnRandomAndNastyTriangles) {
  Rng rng(1234);
  for (const Vec3& origin : {Vec3(0, 0, 0), Vec3(1e6, -1e6, 1e6)}) {
    for (int it = 0; it < 4000; ++it) {
      const double len = rng.uniform(0.1, 2.0);
      Triangle a = nasty(rng, origin + rng.vec(-1, 1), len);
      Triangle b = nasty(rng, origin + rng.vec(-1, 1), len);
      const TriangleDistance r = triangle_distance(a, b);
      const double o = oracle(a, b);
      const double tol = 1e-14 * scale_of(a, b) * 16;
      ASSERT_NEAR(r.distance, o, tol) << "iteration " << it;
      // Witnesses of slivers far from the origin: the edge vectors carry rounding of the
      // coordinates (~1e-16·1e6), which tilts a 1e-4-thin sliver's plane by ~1e-6 rad.
      check_witnesses(a, b, r, 1e-11 * scale_of(a, b));
      // Symmetry.
      EXPECT_NEAR(triangle_distance(b, a).distance, r.distance, tol);
    }
  }
}

TEST(TriangleDistance, PiercingTrianglesHaveZeroDistanceAndACommonPoint) {
  const Triangle a{{-1, -1, 0}, {2, -1, 0}, {-1, 2, 0}};
  const Triangle b{{0.2, 0.2, -1}, {0.3, 0.2, 1}, {0.25, 0.4, 1}};
  const TriangleDistance r = triangle_distance(a, b);
  EXPECT_EQ(r.distance, 0.0);
  check_witnesses(a, b, r, 1e-14);
  EXPECT_TRUE(triangles_intersect(a, b));
}

TEST(TriangleDistance, ParallelFacesAtKnownGap) {
  Rng rng(7);
  for (int it = 0; it < 200; ++it) {
    const Mat3 rot = rng.rotation();
    const Vec3 off = rng.vec(-1e3, 1e3);
    const double gap = rng.uniform(1e-6, 1.0);
    const Triangle a0{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    const Triangle b0{{0.1, 0.1, gap}, {0.6, 0.1, gap}, {0.1, 0.6, gap}};
    const Triangle a{rot * a0.p + off, rot * a0.q + off, rot * a0.r + off};
    const Triangle b{rot * b0.p + off, rot * b0.q + off, rot * b0.r + off};
    EXPECT_NEAR(triangle_distance(a, b).distance, gap, 1e-12 * 2e3);
    EXPECT_FALSE(triangles_intersect(a, b));
  }
}

// Cheap rejections run before the full evaluation of a triangle pair; a rejected pair must be at
// least the limit away, up to rounding, and a limit above the distance by more than rounding must
// give the full evaluation's answer bit for bit. The bounding-box gap is tight for faces parallel
// to a coordinate plane (their distance is the boxes' gap along that axis when they overlap
// across it), so here the box test meets its own limit: pairs far from the origin (coordinates
// ~1e4), gaps from 1e-9 to 1, limits within 1e-12 of the distance. (A box test whose rounding
// allowance pointed the wrong way, or one that read a gap where there is none, fails it.)
TEST(TriangleDistance, CheapRejectionsAreRightNearTheirLimit) {
  Rng rng(8);
  int accepted = 0, rejected = 0;
  for (int it = 0; it < 20000; ++it) {
    const int axis = it % 3;
    const Vec3 off = rng.vec(-1e4, 1e4);
    const double gap = std::pow(10.0, rng.uniform(-9, 0));
    auto on_plane = [&](double h, double spread) {
      Vec3 p[3];
      for (Vec3& v : p) {
        v = off + rng.vec(-spread, spread);
        v[axis] = off[axis] + h;
      }
      return Triangle{p[0], p[1], p[2]};
    };
    const Triangle a = on_plane(0.0, 1.0), b = on_plane(gap, it % 2 ? 1.0 : 0.1);
    const double d = triangle_distance(a, b).distance;
    for (const double limit : {d * (1 - 1e-12), d, d * (1 + 1e-15), d * (1 + 1e-12), d * (1 + 1e-9)}) {
      TriangleDistance r;
      if (triangle_distance_below(a, b, limit, r)) {
        ++accepted;
        EXPECT_EQ(r.distance, d) << it;
        EXPECT_LE(r.distance, limit) << it;
      } else {
        ++rejected;
        EXPECT_GE(d, limit * (1 - 1e-15)) << it << " gap " << gap;
        EXPECT_LT(limit, d * (1 + 1e-13)) << it << " gap " << gap << ": rejected above the distance";
      }
    }
  }
  EXPECT_GT(accepted, 30000);
  EXPECT_GT(rejected, 20000);
}

// The gap along a caller's axis (triangle_distance_below with an axis and a scale) rejects no
// pair the plain call accepts, and returns what it accepts to the bit. Triangles far from the
// origin, apart by 1e-9 to 1 along a random direction, the axis that direction (where the gap
// is the distance itself when the closest features are a vertex and a face) or tilted from it;
// limits from well below the distance to just within the allowance above it. It fails with the
// allowance dropped or its sign reversed (tried).
TEST(TriangleDistance, GapAlongAnAxisRejectsOnlyWhatTheFullEvaluationWould) {
  Rng rng(9);
  int accepted = 0, rejected = 0;
  for (int it = 0; it < 20000; ++it) {
    const Mat3 r = rng.rotation();
    const Vec3 off = rng.vec(-1e4, 1e4);
    const double gap = std::pow(10.0, rng.uniform(-9, 0));
    auto on_plane = [&](double h, double spread) {
      Vec3 p[3];
      for (Vec3& v : p) v = off + r * Vec3(rng.uniform(-spread, spread), rng.uniform(-spread, spread), h);
      return Triangle{p[0], p[1], p[2]};
    };
    Triangle a = on_plane(0.0, 1.0), b = on_plane(gap, it % 2 ? 1.0 : 0.1);
    if (it % 3 == 2) b.q += r * Vec3(0, 0, rng.uniform(0, 1e-3));  // not parallel
    const TriangleDistance exact = triangle_distance(a, b);
    const double d = exact.distance;
    if (!(d > 0.0)) continue;
    Vec3 axis = r.col(2);
    if (it % 4 == 3) axis = (axis + rng.vec(-1e-3, 1e-3)).normalized();
    double scale = 0.0;
    for (int k = 0; k < 3; ++k) scale = std::max({scale, a[k].cwiseAbs().maxCoeff(), b[k].cwiseAbs().maxCoeff()});
    const double allowance = 1e-12 * scale;
    for (const double limit : {d * 0.5, d - 2 * allowance, d * (1 - 1e-12), d, std::nextafter(d, 1e300),
                               d + 0.5 * allowance, d * (1 + 1e-9)}) {
      if (limit < 0.0) continue;  // a search's limit is an answer so far: never negative
      TriangleDistance plain, with_axis;
      const bool plain_below = triangle_distance_below(a, b, limit, plain);
      const bool axis_below = triangle_distance_below(a, b, limit, with_axis, axis, scale);
      EXPECT_EQ(axis_below, plain_below) << it << " gap " << gap << " limit − d " << limit - d;
      if (axis_below && plain_below) {
        ++accepted;
        EXPECT_EQ(with_axis.distance, plain.distance) << it;
        EXPECT_EQ(with_axis.point_a, plain.point_a) << it;
        EXPECT_EQ(with_axis.point_b, plain.point_b) << it;
      } else {
        ++rejected;
      }
    }
  }
  EXPECT_GT(accepted, 20000);
  EXPECT_GT(rejected, 20000);
}

// No distance is below a limit of zero or less: the squares the test compares must not turn −0.5
// into 0.25 (a pair at 0.1 was once accepted there), nor crossing triangles count as below 0, nor
// a NaN limit give an answer.
TEST(TriangleDistance, NothingIsBelowANegativeZeroOrNaNLimit) {
  const Triangle a{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  const Triangle b{Vec3(0, 0, 0.1), Vec3(1, 0, 0.1), Vec3(0, 1, 0.1)};
  const Triangle crossing{Vec3(0.2, 0.2, -1), Vec3(0.2, 0.2, 1), Vec3(0.3, 0.2, 1)};
  for (const Triangle& t : {b, crossing})
    for (const double limit : {-0.5, -1e-300, -0.0, 0.0, std::nan("")}) {
      TriangleDistance d;
      EXPECT_FALSE(triangle_distance_below(a, t, limit, d)) << limit;
      EXPECT_FALSE(triangle_distance_below(a, t, limit, d, Vec3(0, 0, 1), 1.0)) << limit;
    }
  TriangleDistance d;
  EXPECT_TRUE(triangle_distance_below(a, b, 0.5, d));
  EXPECT_DOUBLE_EQ(d.distance, 0.1);
}

TEST(TrianglesIntersect, TouchingCountsAsIntersectingEvenFarFromTheOrigin) {
  for (const Vec3& o : {Vec3(0, 0, 0), Vec3(1e6, 1e6, -1e6)}) {
    // Coplanar overlap.
    EXPECT_TRUE(triangles_intersect({o + Vec3(0, 0, 0), o + Vec3(2, 0, 0), o + Vec3(0, 2, 0)},
                                    {o + Vec3(1, 1, 0), o + Vec3(-1, 0.5, 0), o + Vec3(0.5, -1, 0)}));
    // Edge on edge (crossing edges, otherwise apart).
    EXPECT_TRUE(triangles_intersect({o + Vec3(0, 0, 0), o + Vec3(2, 0, 0), o + Vec3(1, 0, 1)},
                                    {o + Vec3(1, -1, 0), o + Vec3(1, 1, 0), o + Vec3(1, 0, -1)}));
    // Vertex on face.
    EXPECT_TRUE(triangles_intersect({o + Vec3(0, 0, 0), o + Vec3(2, 0, 0), o + Vec3(0, 2, 0)},
                                    {o + Vec3(0.5, 0.5, 0), o + Vec3(1, 1, 1), o + Vec3(0, 1, 1)}));
    // Coplanar, sharing one edge only.
    EXPECT_TRUE(triangles_intersect({o + Vec3(0, 0, 0), o + Vec3(1, 0, 0), o + Vec3(0, 1, 0)},
                                    {o + Vec3(1, 0, 0), o + Vec3(0, 1, 0), o + Vec3(1, 1, 0)}));
    // Clearly apart: a gap of 1e-3.
    EXPECT_FALSE(triangles_intersect({o + Vec3(0, 0, 0), o + Vec3(2, 0, 0), o + Vec3(1, 0, 1)},
                                     {o + Vec3(1, -1, -1e-3), o + Vec3(1, 1, -1e-3), o + Vec3(1, 0, -1)}));
    // Degenerate: a segment through a face, a point on a face, a point off it.
    EXPECT_TRUE(triangles_intersect({o + Vec3(0, 0, 0), o + Vec3(2, 0, 0), o + Vec3(0, 2, 0)},
                                    {o + Vec3(0.5, 0.5, -1), o + Vec3(0.5, 0.5, 1), o + Vec3(0.5, 0.5, 0.2)}));
    EXPECT_TRUE(triangles_intersect({o + Vec3(0, 0, 0), o + Vec3(2, 0, 0), o + Vec3(0, 2, 0)},
                                    {o + Vec3(0.5, 0.5, 0), o + Vec3(0.5, 0.5, 0), o + Vec3(0.5, 0.5, 0)}));
    EXPECT_FALSE(triangles_intersect({o + Vec3(0, 0, 0), o + Vec3(2, 0, 0), o + Vec3(0, 2, 0)},
                                     {o + Vec3(0.5, 0.5, 1e-3), o + Vec3(0.5, 0.5, 1e-3), o + Vec3(0.5, 0.5, 1e-3)}));
  }
}

TEST(TrianglesIntersect, AgreesWithOracleDistance) {
  Rng rng(99);
  int hits = 0;
  for (int it = 0; it < 5000; ++it) {
    const Triangle a = nasty(rng, rng.vec(-0.3, 0.3), 1.0);
    const Triangle b = nasty(rng, rng.vec(-0.3, 0.3), 1.0);
    const double o = oracle(a, b);
    const double tol = touch_tolerance(a, b);
    // Away from the threshold the answer is unambiguous.
    if (o > 2 * tol + 1e-12) {
      EXPECT_FALSE(triangles_intersect(a, b)) << it;
    }
    if (o <= 0.5 * tol) {
      EXPECT_TRUE(triangles_intersect(a, b)) << it << " oracle " << o << " ours " << triangle_distance(a, b).distance << " tol " << tol;
      ++hits;
    }
  }
  EXPECT_GT(hits, 40);
}

// triangles_intersect rejects most disjoint pairs by a gap along the cross product of two edges
// before the full evaluation. Pairs moved to within a few tolerances of touching, along the
// direction between their closest points (which sets their distance to the chosen gap), must get
// the verdict of the plain distance test with the tolerance as its limit: a rejection that
// trusted gaps below twice the tolerance would call some of the pairs at 0.5-0.9 tolerances apart
// disjoint. The pairs far from the origin have a tolerance far above a unit's rounding.
TEST(TrianglesIntersect, NearTouchingPairsGetThePlainDistanceVerdict) {
  Rng rng(4242);
  int touching = 0, apart = 0;
  for (const Vec3& o : {Vec3(0, 0, 0), Vec3(3e4, -2e4, 1e4)}) {
    for (int it = 0; it < 3000; ++it) {
      const Triangle a{o + rng.vec(-1, 1), o + rng.vec(-1, 1), o + rng.vec(-1, 1)};
      const Triangle b0{o + rng.vec(-1, 1), o + rng.vec(-1, 1), o + rng.vec(-1, 1)};
      const TriangleDistance d0 = triangle_distance(a, b0);
      if (!(d0.distance > 1e-3)) continue;
      const Vec3 dir = (d0.point_b - d0.point_a) / d0.distance;
      for (const double g : {0.25, 0.5, 0.9, 1.5, 1.9, 2.1, 2.5, 4.0, 100.0}) {
        // The tolerance depends on the coordinates: taken where the pair ends up.
        auto moved = [&](double gap) {
          const Vec3 shift = (gap - d0.distance) * dir;
          return Triangle{b0.p + shift, b0.q + shift, b0.r + shift};
        };
        const Triangle b = moved(g * touch_tolerance(a, moved(0.0)));
        const double tol = touch_tolerance(a, b);
        TriangleDistance d;
        const bool plain = triangle_distance_below(a, b, std::nextafter(tol, 1e300), d);
        ASSERT_EQ(triangles_intersect(a, b), plain) << "pair " << it << " at " << g << " tolerances, origin " << o.x();
        if (g <= 0.9) {
          EXPECT_TRUE(plain) << it << " " << g;
          touching += plain;
        }
        if (g >= 1.5) {
          EXPECT_FALSE(plain) << it << " " << g;
          apart += !plain;
        }
      }
    }
  }
  EXPECT_GT(touching, 12000);
  EXPECT_GT(apart, 20000);
}

/// Golden-section search of a unimodal function on [0, 1].
template <class F>
double golden_min(F f) {
  double lo = 0, hi = 1;
  const double g = (std::sqrt(5.0) - 1) / 2;
  double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo), f1 = f(x1), f2 = f(x2);
  for (int i = 0; i < 200; ++i) {
    if (f1 < f2) {
      hi = x2; x2 = x1; f2 = f1; x1 = hi - g * (hi - lo); f1 = f(x1);
    } else {
      lo = x1; x1 = x2; f1 = f2; x2 = lo + g * (hi - lo); f2 = f(x2);
    }
  }
  return std::min({f(0.0), f(1.0), f1, f2});
}

TEST(SegmentClosestPoints, MatchesConvexSearchIncludingParallelAndDegenerate) {
  Rng rng(5);
  for (int it = 0; it < 3000; ++it) {
    Vec3 p0 = rng.vec(-1, 1), p1 = rng.vec(-1, 1), q0 = rng.vec(-1, 1), q1 = rng.vec(-1, 1);
    switch (it % 5) {
      case 1: q1 = q0 + 0.7 * (p1 - p0); break;                           // parallel
      case 2: q1 = q0 + 0.7 * (p1 - p0) + 1e-9 * rng.vec(-1, 1); break;   // nearly parallel
      case 3: p1 = p0; break;                                             // a point
      case 4: q0 = p0 + 0.3 * (p1 - p0); q1 = p0 + 1.4 * (p1 - p0); break;  // collinear overlap
      default: break;
    }
    const SegmentClosest r = segment_closest_points(p0, p1, q0, q1);
    const double o = golden_min([&](double s) {
      return point_segment_closest(p0 + s * (p1 - p0), q0, q1).distance;
    });
    ASSERT_NEAR(r.distance, o, 1e-12) << it;
    EXPECT_NEAR((r.point_a - r.point_b).norm(), r.distance, 1e-14);
    EXPECT_LE(point_segment_closest(r.point_a, p0, p1).distance, 1e-14);
    EXPECT_LE(point_segment_closest(r.point_b, q0, q1).distance, 1e-14);
  }
}

TEST(PointTriangleClosest, MatchesOracleOnSlivers) {
  Rng rng(11);
  for (int it = 0; it < 3000; ++it) {
    const Triangle t = nasty(rng, rng.vec(-1, 1), 1.0);
    const Vec3 x = rng.vec(-2, 2);
    const PointClosest r = point_triangle_closest(x, t);
    EXPECT_NEAR(r.distance, hull_distance_oracle({x}, {t.p, t.q, t.r}), 1e-12) << it;
    EXPECT_NEAR((r.point - x).norm(), r.distance, 1e-14);
  }
}

TEST(RssDistance, IsALowerBoundAndRectangleDistanceIsExact) {
  Rng rng(21);
  int touching = 0, separated = 0, tight = 0;
  for (int it = 0; it < 3000; ++it) {
    auto random_rss = [&](const Vec3& c) {
      Rss v;
      v.axes = rng.rotation();
      v.center = c;
      v.half_length = {rng.uniform(0, 1), rng.uniform(0, 0.5)};
      if (it % 7 == 0) v.half_length[1] = 0;  // a segment
      if (it % 11 == 0) v.half_length = {0, 0};  // a sphere
      v.radius = rng.uniform(0, 0.2);
      return v;
    };
    const Vec3 far = (it % 2) ? Vec3(1e6, 0, -1e6) : Vec3::Zero();
    Rss a = random_rss(far + rng.vec(-1, 1)), b = random_rss(far + rng.vec(-1, 1));
    if (it % 5 == 0) b.axes = a.axes;  // parallel rectangles
    auto corners = [](const Rss& v) {
      std::vector<Vec3> c;
      for (int sx : {-1, 1})
        for (int sy : {-1, 1})
          c.push_back(v.center + sx * v.half_length[0] * v.axes.col(0) + sy * v.half_length[1] * v.axes.col(1));
      return c;
    };
    const double exact_rect = hull_distance_oracle(corners(a), corners(b));
    const RectanglePair pair = rectangle_pair(a, b);
    const double scale = far.norm() + 4;
    const double rd = rectangle_distance(pair);
    EXPECT_LE(rd, exact_rect + 1e-14 * scale) << it;
    EXPECT_NEAR(rd, exact_rect, 1e-11 * scale) << it;
    EXPECT_LE(rectangle_gap(pair), exact_rect + 1e-14 * scale) << it;
    const double lb = rectangle_lower_bound(pair);
    EXPECT_LE(lb, exact_rect + 1e-14 * scale) << it;
    // Early exit: the returned value still bounds from below, and reaches stop_at when the
    // full bound does.
    const double stop = 0.5 * exact_rect;
    const double early = rectangle_lower_bound(pair, stop);
    EXPECT_LE(early, exact_rect + 1e-14 * scale) << it;
    if (lb >= stop + 1e-12 * scale) {
      EXPECT_GE(early, stop - 1e-12 * scale) << it;
    }
    if (exact_rect > 1e-3) {
      ++separated;
      if (lb >= exact_rect * (1 - 1e-9)) ++tight;
    }
    EXPECT_LE(rss_distance(a, b), std::max(0.0, exact_rect - a.radius - b.radius) + 1e-14 * scale) << it;
    if (exact_rect == 0) ++touching;
  }
  EXPECT_GT(touching, 10);
  // The projection-direction bound is exact in most separated configurations.
  std::printf("rectangle_lower_bound exact (1e-9) in %d of %d separated pairs\n", tight, separated);
  EXPECT_GT(tight, separated / 2);
}

// The distance search runs rectangle_lower_bound in its two steps from B's first two axes and
// center alone (src/query/query.cpp, DistanceSearch::bound): the same bound, to the bit, for
// any stop level, whether the first step decides or not.
TEST(RssDistance, TwoStepBoundIsTheLowerBoundToTheBit) {
  Rng rng(22);
  int decided = 0, second = 0, past_stop = 0;
  for (int it = 0; it < 4000; ++it) {
    Rss a, b;
    a.axes = rng.rotation();
    b.axes = (it % 5 == 0) ? a.axes : rng.rotation();
    const double spread = (it % 3 == 0) ? 10.0 : 1.0;
    a.center = rng.vec(-spread, spread);
    b.center = rng.vec(-spread, spread);
    a.half_length = {rng.uniform(0, 1), rng.uniform(0, 0.5)};
    b.half_length = {rng.uniform(0, 1), (it % 7 == 0) ? 0.0 : rng.uniform(0, 0.5)};
    const RectanglePair pair = rectangle_pair(a, b);
    const double exact = rectangle_distance(pair);
    for (const double stop : {std::numeric_limits<double>::infinity(), 0.0, 0.5 * exact, exact, 2.0 * exact + 0.1}) {
      const double slack = detail::rectangle_slack(pair.translation, pair.a[0], pair.a[1], pair.b[0], pair.b[1]);
      const detail::ProjectionGap first =
          detail::projection_gap(pair.rotation.col(0), pair.rotation.col(1), pair.translation, pair.a[0], pair.a[1],
                                 pair.b[0], pair.b[1], stop + slack, slack);
      double two_step;
      if (first.decided) {
        ++decided;
        two_step = first.gap > -std::numeric_limits<double>::infinity() ? first.gap - slack : -slack;
      } else {
        ++second;
        two_step = detail::rectangle_axes_gap(pair, stop + slack, first.gap, slack);
      }
      EXPECT_EQ(two_step, rectangle_lower_bound(pair, stop)) << it << " stop " << stop;
      EXPECT_LE(two_step, exact + 1e-14 * (2 * spread + 4)) << it;
      // For callers that only compare with the level: +∞ stands for a bound that reaches it;
      // every other answer is the same to the bit.
      const detail::ProjectionGap quick =
          detail::projection_gap(pair.rotation.col(0), pair.rotation.col(1), pair.translation, pair.a[0], pair.a[1],
                                 pair.b[0], pair.b[1], stop + slack, slack, /*value_past_stop=*/false);
      if (quick.gap == std::numeric_limits<double>::infinity()) {
        ++past_stop;
        EXPECT_TRUE(first.decided) << it;
        EXPECT_GE(first.gap, stop + slack) << it << " stop " << stop;
      } else {
        EXPECT_EQ(quick.decided, first.decided) << it;
        EXPECT_EQ(quick.gap, first.gap) << it;
      }
    }
  }
  EXPECT_GT(decided, 1000);
  EXPECT_GT(second, 1000);
  EXPECT_GT(past_stop, 1000);
}

// The quick reach test (`value_past_stop` false) where it is tight: the projection gap equals the
// level up to a few units in the last place. It may answer +∞ only when the gap, computed with
// the square root and the division, is at or past the level.
TEST(RssDistance, QuickReachTestNeverClaimsAGapBelowTheLevel) {
  Rng rng(23);
  int quick = 0, slow = 0;
  for (int it = 0; it < 20000; ++it) {
    Rss a, b;
    a.axes = rng.rotation();
    b.axes = rng.rotation();
    a.center = rng.vec(-1, 1);
    b.center = a.center + rng.vec(-1, 1).normalized() * rng.uniform(3, 30);
    a.half_length = {rng.uniform(0, 1), rng.uniform(0, 0.5)};
    b.half_length = {rng.uniform(0, 1), rng.uniform(0, 0.5)};
    const RectanglePair pair = rectangle_pair(a, b);
    const Vec3 u = pair.rotation.col(0), v = pair.rotation.col(1), t = pair.translation;
    const double slack = detail::rectangle_slack(t, pair.a[0], pair.a[1], pair.b[0], pair.b[1]);
    const detail::ProjectionGap exact = detail::projection_gap(u, v, t, pair.a[0], pair.a[1], pair.b[0], pair.b[1],
                                                               std::numeric_limits<double>::infinity(), slack);
    // Levels within ±8 ulp and ±1e-13 of the gap itself.
    for (const double level : {exact.gap, std::nextafter(exact.gap, 0.0), std::nextafter(exact.gap, 1e300),
                               exact.gap * (1 - 8e-16), exact.gap * (1 + 8e-16), exact.gap * (1 - 1e-13),
                               exact.gap * (1 - 2e-13)}) {
      const detail::ProjectionGap q =
          detail::projection_gap(u, v, t, pair.a[0], pair.a[1], pair.b[0], pair.b[1], level, slack, false);
      if (q.gap == std::numeric_limits<double>::infinity()) {
        ++quick;
        EXPECT_GE(exact.gap, level) << it;
      } else {
        ++slow;
      }
    }
  }
  EXPECT_GT(quick, 1000);  // it does answer, below the gap by more than its margin
  EXPECT_GT(slow, 1000);   // and leaves the last ulps to the division
}

}  // namespace
}  // namespace swept
