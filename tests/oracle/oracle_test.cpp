// The path oracle against answers derived by hand (every expected number is worked out in the
// comment next to it), so that it can be trusted to check the planner.
#include "oracle/path_oracle.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>

namespace oracle {
namespace {

using V = Eigen::Vector3d;

Tri tri(const V& a, const V& b, const V& c) { return Tri{{a, b, c}}; }

// The 12 triangles of an axis-aligned box; each face is split into two triangles that each hold
// three of its four corners.
std::vector<Tri> box(const V& lo, const V& hi) {
  auto corner = [&](int i) { return V(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(), i & 4 ? hi.z() : lo.z()); };
  const int faces[6][4] = {{0, 1, 3, 2}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 3, 7, 5}};
  std::vector<Tri> out;
  for (const auto& f : faces) {
    out.push_back(tri(corner(f[0]), corner(f[1]), corner(f[2])));
    out.push_back(tri(corner(f[0]), corner(f[2]), corner(f[3])));
  }
  return out;
}

RigidPose at(const V& t) { return {Eigen::Matrix3d::Identity(), t}; }
RigidPose rotated(const V& axis, double angle, const V& t) {
  return {Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix(), t};
}
Tri moved(const Tri& t, const RigidPose& p) {
  return tri(p.R * t.v[0] + p.t, p.R * t.v[1] + p.t, p.R * t.v[2] + p.t);
}

// A small deterministic generator for the consistency checks (no std distributions).
struct Lcg {
  std::uint64_t s;
  double next() {
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(s >> 11) * 0x1.0p-53;
  }
  V vec(double lo, double hi) {
    const double x = next(), y = next(), z = next();
    return V(lo + (hi - lo) * x, lo + (hi - lo) * y, lo + (hi - lo) * z);
  }
};

// ---- triangle–triangle distance -------------------------------------------------------------

TEST(OracleTriangle, ParallelAtKnownGap) {
  const Tri a = tri(V(0, 0, 0), V(1, 0, 0), V(0, 1, 0));
  // Straight above, overlapping in projection: the gap is the plane distance.
  EXPECT_DOUBLE_EQ(triangle_distance(a, tri(V(0.2, 0.2, 0.5), V(1.2, 0.2, 0.5), V(0.2, 1.2, 0.5))), 0.5);
  // Beside and above: A ends at x = 1 (vertex (1,0,0)), B starts at x = 2 one unit up → √2.
  EXPECT_DOUBLE_EQ(triangle_distance(a, tri(V(2, 0, 1), V(3, 0, 1), V(2, 1, 1))), std::sqrt(2.0));
}

TEST(OracleTriangle, SkewEdgesByHand) {
  // A lies in the plane y + z = 0 with y ≥ 0; its edge (0,0,0)–(2,0,0) is the x axis.
  // B lies in x = 1 on the side z ≥ y + 1; its edge runs (1,−1.5,−0.5)–(1,0.5,1.5) along (0,1,1).
  // Every point of A has z − y = −2y ≤ 0, every point of B has z − y ≥ 1, so they are at least
  // 1/√2 apart (the gap between the planes z − y = 0 and z − y = 1), which (1,0,0) ∈ A and
  // (1,−0.5,0.5) ∈ B attain: two edge interiors.
  const Tri a = tri(V(0, 0, 0), V(2, 0, 0), V(1, 1, -1));
  const Tri b = tri(V(1, -1.5, -0.5), V(1, 0.5, 1.5), V(1, -1.5, 1.5));
  EXPECT_NEAR(triangle_distance(a, b), std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(triangle_distance(b, a), std::sqrt(0.5), 1e-15);
  // The same after any rigid motion of both.
  const RigidPose p = rotated(V(0.3, -1, 2), 1.1, V(5, -2, 7));
  EXPECT_NEAR(triangle_distance(moved(a, p), moved(b, p)), std::sqrt(0.5), 1e-13);
}

TEST(OracleTriangle, CrossingIsExactlyZero) {
  const Tri a = tri(V(0, 0, 0), V(2, 0, 0), V(0, 2, 0));
  // B's edge (0.5,0.5,−1)–(0.5,0.5,1) pierces A's interior; no vertex of either touches the other.
  const Tri b = tri(V(0.5, 0.5, -1), V(0.5, 0.5, 1), V(3, 3, 0.2));
  EXPECT_EQ(triangle_distance(a, b), 0.0);
  EXPECT_EQ(triangle_distance(b, a), 0.0);
  // Two interlocking triangles (each pierces the other, like chain links).
  const Tri c = tri(V(-1, 0, 0), V(1, 0, 0), V(0, 0, 2));
  const Tri d = tri(V(0, -1, 1), V(0, 1, 1), V(0, 0, -1));
  EXPECT_EQ(triangle_distance(c, d), 0.0);
}

TEST(OracleTriangle, CoplanarOverlapAndGap) {
  // A star of David: no vertex of either inside the other, the edges cross.
  const Tri a = tri(V(0, 0, 0), V(4, 0, 0), V(2, 3, 0));
  const Tri b = tri(V(0, 2, 0), V(4, 2, 0), V(2, -1, 0));
  EXPECT_EQ(triangle_distance(a, b), 0.0);
  // A vertex inside.
  EXPECT_EQ(triangle_distance(a, tri(V(2, 1, 0), V(9, 1, 0), V(9, 2, 0))), 0.0);
  // One inside the other entirely.
  EXPECT_EQ(triangle_distance(a, tri(V(1.5, 0.5, 0), V(2.5, 0.5, 0), V(2, 1, 0))), 0.0);
  // Side by side in one plane: A's hypotenuse x + y = 2 ends at (2,0); B's edge x = 3 → 1.
  const Tri c = tri(V(0, 0, 0), V(2, 0, 0), V(0, 2, 0));
  EXPECT_DOUBLE_EQ(triangle_distance(c, tri(V(3, 0, 0), V(5, 0, 0), V(3, 2, 0))), 1.0);
}

TEST(OracleTriangle, VertexOnAndAboveAFace) {
  const Tri a = tri(V(0, 0, 0), V(2, 0, 0), V(0, 2, 0));
  EXPECT_NEAR(triangle_distance(a, tri(V(0.5, 0.5, 0), V(1, 0.5, 1), V(0.5, 1, 1))), 0.0, 1e-15);
  EXPECT_NEAR(triangle_distance(a, tri(V(0.5, 0.5, 0.25), V(1, 0.5, 1), V(0.5, 1, 1))), 0.25, 1e-15);
  // Below, pointing up: same.
  EXPECT_NEAR(triangle_distance(tri(V(0.5, 0.5, -0.25), V(1, 0.5, -1), V(0.5, 1, -1)), a), 0.25, 1e-15);
}

TEST(OracleTriangle, DegenerateTriangles) {
  const Tri a = tri(V(0, 0, 0), V(2, 0, 0), V(0, 2, 0));
  // A point (all corners equal) above the face: 3.
  const Tri point = tri(V(0.5, 0.5, 3), V(0.5, 0.5, 3), V(0.5, 0.5, 3));
  EXPECT_DOUBLE_EQ(triangle_distance(a, point), 3.0);
  EXPECT_DOUBLE_EQ(triangle_distance(point, a), 3.0);
  // Two points: their distance (3-4-5).
  EXPECT_DOUBLE_EQ(triangle_distance(point, tri(V(3.5, 4.5, 3), V(3.5, 4.5, 3), V(3.5, 4.5, 3))), 5.0);
  // Collinear corners (a segment) above the face, and piercing it.
  EXPECT_DOUBLE_EQ(triangle_distance(a, tri(V(0.1, 0.1, 1), V(0.6, 0.1, 1), V(1.1, 0.1, 1))), 1.0);
  EXPECT_EQ(triangle_distance(a, tri(V(0.5, 0.5, -1), V(0.5, 0.5, 0.3), V(0.5, 0.5, 1))), 0.0);
  // Two segments crossing at right angles one unit apart: 1.
  EXPECT_NEAR(triangle_distance(tri(V(-1, 0, 0), V(0, 0, 0), V(1, 0, 0)), tri(V(0, -1, 1), V(0, 0, 1), V(0, 1, 1))), 1.0,
              1e-15);
  // A sliver (aspect 1e9) over the face's interior: 1.
  EXPECT_NEAR(triangle_distance(a, tri(V(0.1, 0.1, 1), V(1.1, 0.1, 1), V(0.6, 0.1 + 1e-9, 1))), 1.0, 1e-12);
  // A sliver standing on the face: touching.
  EXPECT_NEAR(triangle_distance(a, tri(V(0.5, 0.5, 0), V(0.5, 0.5, 1), V(0.5, 0.5 + 1e-12, 0.5))), 0.0, 1e-15);
}

TEST(OracleTriangle, NeverNanAndNeverBelowSampledPointsOnRandomNastyPairs) {
  // Consistency, not hand answers: for random (often degenerate) pairs the distance is finite,
  // symmetric, no larger than the distance of any two sampled points of the triangles, and no
  // smaller than the gap between their bounding boxes.
  Lcg rng{42};
  for (int k = 0; k < 3000; ++k) {
    Tri a = tri(rng.vec(-1, 1), rng.vec(-1, 1), rng.vec(-1, 1));
    Tri b = tri(rng.vec(-1, 1), rng.vec(-1, 1), rng.vec(-1, 1));
    if (k % 3 == 1) a.v[2] = a.v[0] + 1e-9 * (a.v[1] - a.v[0]);    // sliver / collinear
    if (k % 5 == 2) b.v[1] = b.v[0];                                // repeated corner
    if (k % 7 == 3) b = tri(b.v[0], b.v[0], b.v[0]);                // a point
    const double d = triangle_distance(a, b);
    ASSERT_TRUE(std::isfinite(d)) << k;
    EXPECT_EQ(d, triangle_distance(b, a)) << k;
    double sampled = INFINITY;
    for (int i = 0; i <= 6; ++i)
      for (int j = 0; i + j <= 6; ++j) {
        const V pa = a.v[0] + (a.v[1] - a.v[0]) * (i / 6.0) + (a.v[2] - a.v[0]) * (j / 6.0);
        for (int u = 0; u <= 6; ++u)
          for (int w = 0; u + w <= 6; ++w) {
            const V pb = b.v[0] + (b.v[1] - b.v[0]) * (u / 6.0) + (b.v[2] - b.v[0]) * (w / 6.0);
            sampled = std::min(sampled, (pa - pb).norm());
          }
      }
    EXPECT_LE(d, sampled + 1e-12) << k;
    V alo = a.v[0].cwiseMin(a.v[1]).cwiseMin(a.v[2]), ahi = a.v[0].cwiseMax(a.v[1]).cwiseMax(a.v[2]);
    V blo = b.v[0].cwiseMin(b.v[1]).cwiseMin(b.v[2]), bhi = b.v[0].cwiseMax(b.v[1]).cwiseMax(b.v[2]);
    const V gap = (alo - bhi).cwiseMax(blo - ahi).cwiseMax(V::Zero());
    EXPECT_GE(d, gap.norm() - 1e-12) << k;
  }
}

// ---- many triangles ----------------------------------------------------------------------------

// A UV sphere with its vertices on the sphere: its faces lie inside the sphere, no deeper than
// the sagitta 1 − cos(largest angular half-diagonal).
std::vector<Tri> sphere(const V& c, double radius, int rings, int sectors) {
  auto p = [&](int i, int j) {
    const double th = std::numbers::pi * i / rings, ph = 2 * std::numbers::pi * j / sectors;
    return V(c.x() + radius * std::sin(th) * std::cos(ph), c.y() + radius * std::sin(th) * std::sin(ph),
             c.z() + radius * std::cos(th));
  };
  std::vector<Tri> out;
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < sectors; ++j) {
      if (i > 0) out.push_back(tri(p(i, j), p(i, j + 1), p(i + 1, j + 1)));
      if (i + 1 < rings) out.push_back(tri(p(i, j), p(i + 1, j + 1), p(i + 1, j)));
    }
  return out;
}

TEST(OracleDistance, TreeAgreesWithAllPairs) {
  Lcg rng{7};
  for (int round = 0; round < 4; ++round) {
    std::vector<Tri> a, b;
    for (int k = 0; k < 300; ++k) {
      const V c = rng.vec(-5, 5);
      a.push_back(tri(c, c + rng.vec(-0.6, 0.6), c + rng.vec(-0.6, 0.6)));
      const V e = rng.vec(-5, 5) + V(round * 2.0, 0, 0);
      b.push_back(tri(e, e + rng.vec(-0.6, 0.6), e + rng.vec(-0.6, 0.6)));
    }
    double brute = INFINITY;
    for (const Tri& x : a)
      for (const Tri& y : b) brute = std::min(brute, triangle_distance(x, y));
    EXPECT_EQ(exact_distance(a, b), brute) << round;
  }
}

TEST(OracleDistance, TwentyThousandTriangleSpheres) {
  // Unit spheres with centres 3 apart. Each tessellation lies inside its ball, so d ≥ 1. A
  // triangle's corners are grid neighbours, at most π/100 + 2π/100 apart in angle, so they all
  // lie in the cap of angular radius 3π/100 around any one of them, and the triangle lies on
  // the cap's side of its base plane: no point deeper than 1 − cos(3π/100) → d ≤ 1 + 2·that.
  const auto a = sphere(V(0, 0, 0), 1.0, 100, 100);
  const auto b = sphere(V(3, 0, 0), 1.0, 100, 100);
  ASSERT_GE(a.size(), 19000u);
  const auto t0 = std::chrono::steady_clock::now();
  const double d = exact_distance(a, b);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  std::printf("exact_distance %zu x %zu triangles: %.1f ms (tree builds included)\n", a.size(), b.size(), ms);
  EXPECT_GE(d, 1.0 - 1e-12);
  EXPECT_LE(d, 1.0 + 2 * (1 - std::cos(3 * std::numbers::pi / 100)));
}

// ---- paths -------------------------------------------------------------------------------------

TEST(OraclePath, CubeSlidingPastACube) {
  // Obstacle [−1,1]³; body [−0.5,0.5]³ about its centre, moving from x = −5 to x = 5 at y = z = 2:
  // the body spans y, z ∈ [1.5, 2.5], so when the x ranges overlap the closest features are the
  // parallel edges (1, 1) and (1.5, 1.5) in (y, z): √(0.5² + 0.5²) = √0.5 ≈ 0.70711.
  PathCheckInput in;
  in.obstacles = box(V(-1, -1, -1), V(1, 1, 1));
  in.body = box(V(-0.5, -0.5, -0.5), V(0.5, 0.5, 0.5));
  in.poses = {at(V(-5, 2, 2)), at(V(5, 2, 2))};
  in.clearance = 0.7;
  PathCheckReport r = check_path(in);
  EXPECT_TRUE(r.valid) << r.why;
  EXPECT_NEAR(r.dense_min, std::sqrt(0.5), 1e-12);  // samples hit the overlap
  // 2000 dense samples over one segment of length 10.
  EXPECT_DOUBLE_EQ(r.dense_spacing, 10.0 / 2000);
  EXPECT_EQ(r.contact_segments, 0u);
  // Just above the true minimum the certificate must refuse, and say where.
  in.clearance = 0.71;
  r = check_path(in);
  EXPECT_FALSE(r.valid);
  EXPECT_EQ(r.bad_segment, 0);
  // The gap is √0.5 < 0.71 only while the x ranges overlap, |x| ≤ 1.5: t ∈ [0.35, 0.65]; the
  // gap beyond (corner to corner) grows as √(0.5 + (|x| − 1.5)²), < 0.71 while |x| < 1.564.
  EXPECT_GE(r.bad_t, 0.34);
  EXPECT_LE(r.bad_t, 0.66);
  EXPECT_NE(r.why.find("segment 0"), std::string::npos) << r.why;
}

TEST(OraclePath, ThroughAWallIsRejectedAtTheRightSegment) {
  // Wall x ∈ [−0.1, 0.1]; body [−0.25,0.25]³. Segment 1 goes from x = −2 to x = 2 straight
  // through it: the gap is below 0.05 for centre x ∈ [−0.4, 0.4], i.e. t ∈ [0.4, 0.6].
  PathCheckInput in;
  in.obstacles = box(V(-0.1, -5, -5), V(0.1, 5, 5));
  in.body = box(V(-0.25, -0.25, -0.25), V(0.25, 0.25, 0.25));
  in.poses = {at(V(-3, 0, 0)), at(V(-2, 0, 0)), at(V(2, 0, 0)), at(V(3, 0, 0))};
  in.clearance = 0.05;
  const PathCheckReport r = check_path(in);
  EXPECT_FALSE(r.valid);
  EXPECT_EQ(r.bad_segment, 1) << r.why;
  EXPECT_GE(r.bad_t, 0.4);
  EXPECT_LE(r.bad_t, 0.6);
  EXPECT_EQ(r.dense_min, 0.0);  // the faces cross while the body is inside the wall
  // Going around the wall instead (over its top at z = 5): certified.
  in.poses = {at(V(-3, 0, 0)), at(V(-3, 0, 6)), at(V(3, 0, 6)), at(V(3, 0, 0))};
  const PathCheckReport around = check_path(in);
  EXPECT_TRUE(around.valid) << around.why;
  // Closest approach: body bottom z = 5.75 over the wall top z = 5 → 0.75; beside the wall at
  // x = ±3 the gap is 3 − 0.25 − 0.1 = 2.65.
  EXPECT_NEAR(around.dense_min, 0.75, 1e-12);
}

TEST(OraclePath, RotatingBarNearAWall) {
  // A bar [−2,2]×[−0.1,0.1]² turns by 90° about z around its centre. Its corner (2, −0.1, ·)
  // sits at radius ρ = √4.01 = 2.0024984 and angle −atan(0.05), so it passes x = ρ when the
  // bar has turned atan(0.05) rad (within [0, π/2]); the bar reaches no farther in x.
  const double rho = std::sqrt(4.01);
  PathCheckInput in;
  in.body = box(V(-2, -0.1, -0.1), V(2, 0.1, 0.1));
  in.poses = {at(V::Zero()), rotated(V::UnitZ(), std::numbers::pi / 2, V::Zero())};
  // A wall at x = 2.01: 0.01 away at both ends, closest 2.01 − ρ = 0.0075016 mid-turn.
  in.obstacles = box(V(2.01, -5, -5), V(3, 5, 5));
  in.clearance = 0.005;
  PathCheckReport r = check_path(in);
  EXPECT_TRUE(r.valid) << r.why;
  EXPECT_GE(r.dense_min, 2.01 - rho - 1e-12);
  EXPECT_LE(r.dense_min, 2.01 - rho + r.dense_spacing / 2 + 1e-12);
  // Margin 0.008: both ends have 0.01, but the swept corner comes to 0.0075: refused.
  in.clearance = 0.008;
  r = check_path(in);
  EXPECT_FALSE(r.valid);
  EXPECT_EQ(r.bad_segment, 0);
  // The corner is within 0.008 of the wall only near atan(0.05) ≈ 0.05 rad of π/2: t ≈ 0.032.
  EXPECT_GT(r.bad_t, 0.0);
  EXPECT_LT(r.bad_t, 0.1);
  // A wall at x = 2.001: the corner (reaching 2.0025) hits it, even with margin 0.
  in.obstacles = box(V(2.001, -5, -5), V(3, 5, 5));
  in.clearance = 0.0;
  r = check_path(in);
  EXPECT_FALSE(r.valid);
  EXPECT_EQ(r.dense_min, 0.0);
}

TEST(OraclePath, StartInContactWithoutToleranceIsInvalid) {
  PathCheckInput in;
  in.obstacles = box(V(-1, -1, -1), V(1, 1, 0));
  in.body = box(V(-0.5, -0.5, -0.5), V(0.5, 0.5, 0.5));
  in.poses = {at(V(0, 0, 0.5)), at(V(0, 0, 3))};  // resting on the top face, lifted off
  in.clearance = 0.01;
  PathCheckReport r = check_path(in);
  EXPECT_FALSE(r.valid);
  EXPECT_EQ(r.contact_segments, 0u);
  EXPECT_EQ(r.bad_segment, 0);
  EXPECT_EQ(r.bad_t, 0.0);
  // With a contact tolerance the lift is a motion in contact: the faces touch (coplanar, no
  // depth) and part.
  in.contact_tolerance = 0.001;
  r = check_path(in);
  EXPECT_TRUE(r.valid) << r.why;
  EXPECT_EQ(r.contact_segments, 1u);
  EXPECT_EQ(r.dense_min, 0.0);
  EXPECT_EQ(r.max_penetration, 0.0);
}

TEST(OraclePath, EscapeFromASealedShellIsInvalid) {
  // A closed shell [−1,1]³ with the body [−0.5,0.5]³ resting on its floor (centre z = −0.5).
  // Lifting it straight up to z = 3 makes the body's sides cross the lid once the top passes
  // it, centre z > 0.5: t > 1/3.5, by up to half the body's height.
  PathCheckInput in;
  in.obstacles = box(V(-1, -1, -1), V(1, 1, 1));
  in.body = box(V(-0.5, -0.5, -0.5), V(0.5, 0.5, 0.5));
  in.poses = {at(V(0, 0, -0.5)), at(V(0, 0, 3))};
  in.clearance = 0.001;
  in.contact_tolerance = 0.01;
  const PathCheckReport r = check_path(in);
  EXPECT_EQ(r.contact_segments, 1u);
  EXPECT_FALSE(r.valid);
  EXPECT_EQ(r.bad_segment, 0);
  EXPECT_GT(r.bad_t, 1.0 / 3.5);
  EXPECT_LT(r.bad_t, 1.0 / 3.5 + 0.01);  // the first sample past the tolerance
  EXPECT_GT(r.max_penetration, 0.4);
}

TEST(OraclePath, TrianglePenetration) {
  // Apart, touching at a point, crossing: 0, 0, and the shorter way out.
  const Tri flat = tri(V(-1, -1, 0), V(1, -1, 0), V(0, 1, 0));
  EXPECT_EQ(triangle_penetration(flat, tri(V(-1, -1, 1), V(1, -1, 1), V(0, 1, 1))), 0.0);
  EXPECT_EQ(triangle_penetration(flat, tri(V(0, 0, 0), V(0, 0, 1), V(0.1, 0, 1))), 0.0);
  // A vertical triangle through the flat one, 0.3 below and 0.7 above: out by 0.3 along z.
  EXPECT_NEAR(triangle_penetration(flat, tri(V(-0.2, -0.5, -0.3), V(0.2, -0.5, -0.3), V(0, -0.5, 0.7))), 0.3, 1e-12);
}

// An open U-channel along x made of three single triangles (floor z = 0, walls y = ±0.5), with
// a block [−0.5,0.5]³ (centre z = 0.5) snug in it: touching floor and both walls.
PathCheckInput u_channel() {
  PathCheckInput in;
  // Floor (−3,−2)–(−3,2)–(3,0): at x = ±0.5 it spans |y| ≤ 0.83 or more, covering the block.
  in.obstacles.push_back(tri(V(-3, -2, 0), V(-3, 2, 0), V(3, 0, 0)));
  // Walls: at x = ±0.5 they span z ∈ [−0.67, 2.67] or more, covering the block's sides.
  for (double y : {0.5, -0.5}) in.obstacles.push_back(tri(V(-3, y, -3), V(-3, y, 5), V(3, y, 1)));
  in.body = box(V(-0.5, -0.5, -0.5), V(0.5, 0.5, 0.5));
  in.clearance = 0.001;
  in.contact_tolerance = 0.01;
  return in;
}

TEST(OraclePath, EscapeAlongAUChannelIsValid) {
  // Sliding out along +x to centre x = 5: the block's faces slide on the floor and the walls
  // (coplanar: no depth). The end is 1.5 from the channel's end at x = 3.
  PathCheckInput in = u_channel();
  in.poses = {at(V(0, 0, 0.5)), at(V(5, 0, 0.5))};
  const PathCheckReport r = check_path(in);
  EXPECT_TRUE(r.valid) << r.why;
  EXPECT_EQ(r.contact_segments, 1u);
  EXPECT_EQ(r.dense_min, 0.0);
  // A second segment after the escape is checked with all pairs and full clearance.
  in.poses.push_back(at(V(5, 0, 3)));
  EXPECT_TRUE(check_path(in).valid);
  in.poses.back() = at(V(0, 3, 3));  // back over the channel, through a wall: refused
  const PathCheckReport back = check_path(in);
  EXPECT_FALSE(back.valid);
  EXPECT_EQ(back.bad_segment, 1) << back.why;
  // Sideways out of the channel, through a wall: the wall cuts the block.
  in.poses = {at(V(0, 0, 0.5)), at(V(0, 3, 0.5))};
  EXPECT_FALSE(check_path(in).valid);
}

TEST(OraclePath, RotatingEscapeIsInvalid) {
  // The same slide with a turn of 0.1 rad about x: not a pure translation, refused outright.
  PathCheckInput in = u_channel();
  in.poses = {at(V(0, 0, 0.5)), rotated(V::UnitX(), 0.1, V(5, 0, 0.5))};
  const PathCheckReport r = check_path(in);
  EXPECT_EQ(r.contact_segments, 1u);
  EXPECT_FALSE(r.valid);
  EXPECT_EQ(r.bad_segment, 0);
  EXPECT_NE(r.why.find("rotates"), std::string::npos) << r.why;
}

TEST(OraclePath, AMotionEndingInContactIsAMotionInContact) {
  // Sliding only to x = 3.5 leaves the block's back face at x = 3 on the floor's tip (3,0,0):
  // in contact at the end too. A rotation from there is a motion in contact: refused.
  PathCheckInput in = u_channel();
  in.poses = {at(V(0, 0, 0.5)), at(V(3.5, 0, 0.5))};
  PathCheckReport r = check_path(in);
  EXPECT_TRUE(r.valid) << r.why;
  in.poses.push_back(rotated(V::UnitZ(), 0.1, V(3.5, 0, 3)));
  r = check_path(in);
  EXPECT_EQ(r.contact_segments, 2u);
  EXPECT_FALSE(r.valid);
  EXPECT_EQ(r.bad_segment, 1) << r.why;
}

TEST(OraclePath, SameReportAtAnyThreadCount) {
  // Results are gathered in path order whatever the scheduling: the same report, bit for bit.
  PathCheckInput in;
  in.obstacles = box(V(-0.1, -5, -5), V(0.1, 5, 5));
  in.body = box(V(-2, -0.1, -0.1), V(2, 0.1, 0.1));
  in.poses = {at(V(-3, 0, 0)), rotated(V::UnitZ(), 1.0, V(-3, 0, 3)), rotated(V(1, 1, 0), 2.0, V(3, 1, 0)),
              at(V(4, 0, 0))};
  in.clearance = 0.01;
  auto run = [&](int threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    return check_path(in);
  };
  const PathCheckReport one = run(1), two = run(2), four = run(4);
  for (const PathCheckReport* r : {&two, &four}) {
    EXPECT_EQ(r->valid, one.valid);
    EXPECT_EQ(r->why, one.why);
    EXPECT_EQ(r->bad_segment, one.bad_segment);
    EXPECT_EQ(r->bad_t, one.bad_t);
    EXPECT_EQ(r->dense_min, one.dense_min);
    EXPECT_EQ(r->certificate_queries, one.certificate_queries);
  }
  EXPECT_FALSE(one.valid);  // the bar's second move sweeps through the wall
  EXPECT_EQ(one.bad_segment, 1) << one.why;
}

TEST(OraclePath, MotionAndAngle) {
  // Half-way through a 90° turn about z with the reference point at (1,0,0): the reference
  // stays put, the body turns 45° about it.
  const V ref(1, 0, 0);
  const RigidPose a = at(V::Zero());
  const RigidPose b = {Eigen::AngleAxisd(std::numbers::pi / 2, V::UnitZ()).toRotationMatrix(), V::Zero()};
  // b moves the reference to (0,1,0); the straight line of the reference passes (0.5,0.5,0).
  const RigidPose m = interpolate_pose(a, b, 0.5, ref);
  EXPECT_NEAR((m.R * ref + m.t - V(0.5, 0.5, 0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR(rotation_angle(a.R, m.R), std::numbers::pi / 4, 1e-15);
  EXPECT_NEAR(rotation_angle(a.R, b.R), std::numbers::pi / 2, 1e-15);
  // The shortest arc: 350° about z is 10° the other way.
  const Eigen::Matrix3d r350 = Eigen::AngleAxisd(350 * std::numbers::pi / 180, V::UnitZ()).toRotationMatrix();
  EXPECT_NEAR(rotation_angle(a.R, r350), 10 * std::numbers::pi / 180, 1e-14);
  const RigidPose h = interpolate_pose(a, {r350, V::Zero()}, 0.5, V::Zero());
  EXPECT_NEAR(rotation_angle(h.R, Eigen::AngleAxisd(-5 * std::numbers::pi / 180, V::UnitZ()).toRotationMatrix()), 0.0,
              1e-7);
}

}  // namespace
}  // namespace oracle
