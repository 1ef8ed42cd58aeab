// Fitters (SPEC §2.1) against hand-computed values and the paper's formulas evaluated literally.
#include "support/tables.h"
#include "support/test_support.h"
#include "swept/bvh/fitter.h"

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace swept {
namespace {

using test::Rng;

// The paper's formulas, literally (eq. 1–2, 5–9, 10), relative to a local origin.
Mat3 literal_matrix(const std::vector<Triangle>& tris, Fitter f, Vec3& split) {
  const double n = static_cast<double>(tris.size());
  const Vec3 o = tris[0].p;
  if (f == Fitter::pqp) {
    Vec3 mu = Vec3::Zero();
    for (auto& t : tris) mu += (t.p - o) + (t.q - o) + (t.r - o);
    mu /= 3 * n;
    Mat3 c = Mat3::Zero();
    for (auto& t : tris)
      for (int v = 0; v < 3; ++v) {
        Vec3 d = t[v] - o - mu;
        c += d * d.transpose();
      }
    split = mu + o;
    return c / (3 * n);
  }
  double ah = 0;
  Vec3 mh = Vec3::Zero();
  for (auto& t : tris) {
    ah += area(t);
    mh += area(t) * (centroid(t) - o);
  }
  mh /= ah;
  split = mh + o;
  Mat3 c = Mat3::Zero();
  if (f == Fitter::rapid2) {
    for (auto& t : tris) {
      Vec3 m = centroid(t) - o, p = t.p - o, q = t.q - o, r = t.r - o;
      c += area(t) / 12 * (9 * m * m.transpose() + p * p.transpose() + q * q.transpose() + r * r.transpose());
    }
    return c - ah * mh * mh.transpose();
  }
  double amin = 1e300;
  for (auto& t : tris) amin = std::min(amin, area(t));
  for (auto& t : tris)
    for (int v = 0; v < 3; ++v) {
      Vec3 d = t[v] - o - mh;
      c += area(t) / amin * d * d.transpose();
    }
  return c / (3 * n);
}

void expect_same_axis(const Vec3& a, const Vec3& b, double tol) {
  EXPECT_NEAR(std::abs(a.dot(b)), 1.0, tol) << a.transpose() << " vs " << b.transpose();
}

TEST(Fitter, OneTriangleHandComputed) {
  // Right triangle (0,0,0) (2,0,0) (0,1,0): µ = (2/3, 1/3, 0),
  // C = [[8/9, −2/9, 0], [−2/9, 2/9, 0], [0, 0, 0]], λ = (10 ± √52)/18, 0.
  const std::vector<Triangle> tri{{Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 1, 0)}};
  const double l1 = (10 + std::sqrt(52.0)) / 18, l2 = (10 - std::sqrt(52.0)) / 18;
  Fit p = fit(tri, Fitter::pqp);
  EXPECT_NEAR((p.split_point - Vec3(2.0 / 3, 1.0 / 3, 0)).norm(), 0, 1e-15);
  EXPECT_NEAR(p.eigenvalues[0], l1, 1e-14);
  EXPECT_NEAR(p.eigenvalues[1], l2, 1e-14);
  EXPECT_NEAR(p.eigenvalues[2], 0, 1e-14);
  expect_same_axis(p.axes.col(2), Vec3::UnitZ(), 1e-14);
  // e1 solves (C − λ1)v = 0: v ∝ (2/9, 8/9 − λ1, 0) rotated: v = (−2/9, λ1 − 8/9)ᵀ⊥ → (λ1 − 2/9, −2/9).
  expect_same_axis(p.axes.col(0), Vec3(l1 - 2.0 / 9, -2.0 / 9, 0).normalized(), 1e-14);
  // INERTIA_FIT on one triangle: A/A_min = 1, so the same matrix and the centroid.
  Fit i = fit(tri, Fitter::inertia);
  EXPECT_NEAR((i.split_point - Vec3(2.0 / 3, 1.0 / 3, 0)).norm(), 0, 1e-15);
  EXPECT_NEAR(i.eigenvalues[0], l1, 1e-14);
  // RAPID2_FIT: C' = (A/12)·S with A = 1 and S = 3C, so C' = C/4.
  Fit r = fit(tri, Fitter::rapid2);
  EXPECT_NEAR(r.eigenvalues[0], l1 / 4, 1e-14);
  EXPECT_NEAR(r.eigenvalues[1], l2 / 4, 1e-14);
  EXPECT_FALSE(p.fell_back || i.fell_back || r.fell_back);
  // Right-handed, orthonormal.
  for (const Fit* f : {&p, &i, &r}) {
    EXPECT_NEAR((f->axes.transpose() * f->axes - Mat3::Identity()).norm(), 0, 1e-14);
    EXPECT_NEAR(f->axes.determinant(), 1.0, 1e-14);
  }
}

TEST(Fitter, CubeHandComputed) {
  // Unit cube surface: the shell centroid is the centre; the area-weighted covariance of a
  // uniform distribution on the surface is (2·¼ + 4·(1/12))·I = (5/6)·I.
  const auto cube = test::box_triangles(Vec3(0, 0, 0), Vec3(1, 1, 1));
  Fit r = fit(cube, Fitter::rapid2);
  EXPECT_NEAR((r.split_point - Vec3(0.5, 0.5, 0.5)).norm(), 0, 1e-15);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(r.eigenvalues[k], 5.0 / 6.0, 1e-14);
  Fit i = fit(cube, Fitter::inertia);
  EXPECT_NEAR((i.split_point - Vec3(0.5, 0.5, 0.5)).norm(), 0, 1e-15);
  // All 12 triangles have area ½ = A_min; every vertex is at squared distance ¾ from the centre:
  // trace(I) = (1/36)·36·¾ = ¾.
  EXPECT_NEAR(i.eigenvalues.sum(), 0.75, 1e-14);
  Fit p = fit(cube, Fitter::pqp);
  EXPECT_NEAR(p.eigenvalues.sum(), 0.75 - (p.split_point - Vec3(0.5, 0.5, 0.5)).squaredNorm(), 1e-14);
}

TEST(Fitter, MatchesLiteralFormulas) {
  Rng rng(7);
  for (Fitter f : swept::test::every_fitter()) {
    for (int trial = 0; trial < 20; ++trial) {
      auto tris = test::random_triangles(rng, 1 + trial * 7, 10.0, 3.0, rng.vec(-5, 5));
      Vec3 split;
      const Mat3 m = literal_matrix(tris, f, split);
      Eigen::SelfAdjointEigenSolver<Mat3> es(m);
      const Fit got = fit(tris, f);
      EXPECT_NEAR((got.split_point - split).norm(), 0, 1e-12) << to_string(f);
      const double scale = es.eigenvalues()[2];
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(got.eigenvalues[k], es.eigenvalues()[2 - k], 1e-11 * scale);
      if (es.eigenvalues()[2] - es.eigenvalues()[1] > 1e-6 * scale)
        expect_same_axis(got.axes.col(0), es.eigenvectors().col(2), 1e-9);
    }
  }
}

TEST(Fitter, InvariantUnderFarTranslationAndRotation) {
  Rng rng(11);
  const auto tris = test::random_triangles(rng, 200, 10.0, 4.0);
  const Pose moved{rng.rotation(), Vec3(1e6, -1e6, 1e6)};
  const auto far = test::transformed(tris, moved);
  for (Fitter f : swept::test::every_fitter()) {
    const Fit a = fit(tris, f), b = fit(far, f);
    for (int k = 0; k < 3; ++k) expect_same_axis(moved.rotation * a.axes.col(k), b.axes.col(k), 1e-9);
    EXPECT_NEAR((moved.apply(a.split_point) - b.split_point).norm(), 0, 1e-9 * 10.0);
    const Rss ra = fit_rss(tris, a.axes), rb = fit_rss(far, b.axes);
    EXPECT_NEAR(surface_area(rb) / surface_area(ra), 1.0, 1e-9) << to_string(f);
    EXPECT_NEAR(volume(rb) / volume(ra), 1.0, 1e-9) << to_string(f);
  }
}

TEST(Fitter, ZeroAreaNodeFallsBackToPqp) {
  // Collinear vertices: every triangle has zero area.
  std::vector<Triangle> line;
  for (int i = 0; i < 10; ++i)
    line.push_back({Vec3(i, 2.0 * i, 0), Vec3(i + 1, 2.0 * i + 2, 0), Vec3(i + 0.5, 2.0 * i + 1, 0)});
  const Fit pqp = fit(line, Fitter::pqp);
  for (Fitter f : {Fitter::rapid2, Fitter::inertia}) {
    const Fit g = fit(line, f);
    EXPECT_TRUE(g.fell_back) << to_string(f);
    EXPECT_NEAR((g.split_point - pqp.split_point).norm(), 0, 1e-14);
    expect_same_axis(g.axes.col(0), Vec3(1, 2, 0).normalized(), 1e-12);
    EXPECT_TRUE(g.axes.allFinite());
  }
  EXPECT_FALSE(pqp.fell_back);
}

TEST(Fitter, EpsilonIsScaleAware) {
  // The same shapes at 1e-6 and 1e6 scale make the same decisions.
  std::vector<Triangle> mixed{{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)},
                              {Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(2, 0, 1)}};  // second: zero area
  for (double s : {1e-6, 1.0, 1e6}) {
    std::vector<Triangle> scaled;
    for (auto& t : mixed) scaled.push_back({t.p * s, t.q * s, t.r * s});
    EXPECT_NEAR(degeneracy_epsilon(scaled), 1e-12 * 6.0 * s * s, 1e-24 * s * s);  // box (2,1,1): L² = 6
    const Fit f = fit(scaled, Fitter::inertia);
    EXPECT_FALSE(f.fell_back) << s;
    // Tiny triangles relative to the node, below ε, do not lower A_min, so the weights and thus
    // the axes are those of the non-degenerate triangle.
    std::vector<Triangle> with_dust = scaled;
    with_dust.push_back({Vec3(0, 0, 0.5) * s, Vec3(1e-9, 0, 0.5) * s, Vec3(0, 1e-9, 0.5) * s});
    const Fit g = fit(with_dust, Fitter::inertia);
    EXPECT_FALSE(g.fell_back);
    EXPECT_TRUE(g.axes.allFinite());
  }
  // Only dust: falls back.
  std::vector<Triangle> dust{{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1e-14, 0)},
                             {Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(0, 1e-14, 1)}};
  EXPECT_TRUE(fit(dust, Fitter::inertia).fell_back);
  EXPECT_TRUE(fit(dust, Fitter::rapid2).fell_back);
}

TEST(Rss, SurfaceAreaAndVolumeFormulas) {
  Rss v;
  v.half_length = {1.0, 0.5};  // a = 2, b = 1
  v.radius = 0.5;
  EXPECT_NEAR(surface_area(v), 4.0 + 4.0 * std::numbers::pi, 1e-14);
  EXPECT_NEAR(volume(v), 2.0 + 0.75 * std::numbers::pi + std::numbers::pi / 6.0, 1e-14);
  // A sphere (a = b = 0) and a flat rectangle (r = 0).
  Rss s;
  s.radius = 2.0;
  EXPECT_NEAR(surface_area(s), 4 * std::numbers::pi * 4, 1e-12);
  EXPECT_NEAR(volume(s), 4.0 / 3.0 * std::numbers::pi * 8, 1e-12);
  Rss f;
  f.half_length = {1.5, 1.0};
  EXPECT_NEAR(surface_area(f), 2 * 3.0 * 2.0, 1e-14);
  EXPECT_EQ(volume(f), 0.0);
}

TEST(Rss, FitOfOneTriangleIsFlatAndTight) {
  const std::vector<Triangle> tri{{Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(0, 2, 0)}};
  const Fit f = fit(tri, Fitter::pqp);
  const Rss r = fit_rss(tri, f.axes);
  EXPECT_NEAR(r.radius, 0.0, 1e-14);
  for (int v = 0; v < 3; ++v) EXPECT_LE(signed_distance(r, tri[0][v]), 1e-14);
  // The rectangle is the triangle's bounding rectangle in the fitted frame.
  double w[2];
  for (int k = 0; k < 2; ++k) {
    const Vec3 e = f.axes.col(k);
    const double a = e.dot(tri[0].p), b = e.dot(tri[0].q), c = e.dot(tri[0].r);
    w[k] = std::max({a, b, c}) - std::min({a, b, c});
  }
  EXPECT_NEAR(4 * r.half_length[0] * r.half_length[1], w[0] * w[1], 1e-12);
}

TEST(Rss, RoundedCornersContainEveryVertex) {
  Rng rng(3);
  for (int trial = 0; trial < 200; ++trial) {
    auto tris = test::random_triangles(rng, 1 + trial % 17, 5.0, 5.0);
    const Mat3 axes = rng.rotation();
    const Rss r = fit_rss(tris, axes);
    for (auto& t : tris)
      for (int v = 0; v < 3; ++v) EXPECT_LE(signed_distance(r, t[v]), 1e-12) << trial;
    EXPECT_GE(r.half_length[0], r.half_length[1]);
    EXPECT_NEAR(r.axes.determinant(), 1.0, 1e-12);
  }
}

}  // namespace
}  // namespace swept

namespace swept {
namespace {

TEST(Fitter, OneTriangleLeafAxesMatchTheFitters) {
  // The builder's closed form for one-triangle leaves gives the fitters' own axes.
  test::Rng rng(17);
  for (int trial = 0; trial < 200; ++trial) {
    const auto tri = test::random_triangles(rng, 1, 10.0, 5.0, rng.vec(-100, 100));
    auto bvh = build_bvh(tri);
    ASSERT_TRUE(bvh);
    const Fit f = fit(tri, Fitter::inertia);
    if (f.eigenvalues[0] - f.eigenvalues[1] < 1e-6 * f.eigenvalues[0]) continue;  // axes not unique
    const Rss leaf = bvh->bv(0);
    EXPECT_NEAR(std::abs(leaf.axes.col(2).dot(f.axes.col(2))), 1.0, 1e-9);
    const Rss direct = fit_rss(tri, f.axes);
    // Eigen solver rounding, and the tree's single-precision storage rounded outward (Node:
    // axes, center and lengths each within a few float units in the last place of the size;
    // a length, not the area, for the area of a sliver's RSS is steep in its radius).
    const double size = direct.half_length[0] + direct.half_length[1] + direct.radius;
    for (int k = 0; k < 2; ++k) EXPECT_NEAR(leaf.half_length[k], direct.half_length[k], 1e-6 * size);
    EXPECT_NEAR(leaf.radius, direct.radius, 1e-6 * size);
    EXPECT_GE(surface_area(leaf), surface_area(direct) * (1.0 - 1e-12));
  }
}

// The fitter table is the one place a fitter is named: every row parses back to itself, names
// are unique, and the paper's three are there in the paper's order (PQP_FIT, the baseline, first).
TEST(FitterTable, NamesRoundTripAndAreUnique) {
  const auto fitters = all_fitters();
  ASSERT_EQ(fitters.size(), 3u);
  EXPECT_EQ(fitters[0].paper_name, "PQP_FIT");
  EXPECT_EQ(fitters[1].paper_name, "RAPID2_FIT");
  EXPECT_EQ(fitters[2].paper_name, "INERTIA_FIT");
  for (std::size_t i = 0; i < fitters.size(); ++i) {
    Fitter parsed = fitters[(i + 1) % fitters.size()].fitter;
    ASSERT_TRUE(parse_fitter(fitters[i].name, parsed)) << fitters[i].name;
    EXPECT_EQ(parsed, fitters[i].fitter);
    EXPECT_EQ(to_string(fitters[i].fitter), fitters[i].name);
    EXPECT_EQ(&info(fitters[i].fitter), &fitters[i]);
    for (std::size_t j = 0; j < i; ++j) {
      EXPECT_NE(fitters[i].name, fitters[j].name);
      EXPECT_NE(fitters[i].fitter, fitters[j].fitter);
    }
  }
  EXPECT_EQ(fitter_names(), "pqp, rapid2, inertia");
  EXPECT_EQ(split_rule_names(" | "), "min-sa | largest | min-sa-box");
  Fitter f = Fitter::inertia;
  EXPECT_FALSE(parse_fitter("PQP_FIT", f));
  EXPECT_FALSE(parse_fitter("", f));
  EXPECT_EQ(f, Fitter::inertia);
  for (const SplitRuleInfo& row : all_split_rules()) {
    SplitRule s = row.rule == SplitRule::min_sa ? SplitRule::largest : SplitRule::min_sa;
    ASSERT_TRUE(parse_split_rule(row.name, s));
    EXPECT_EQ(s, row.rule);
  }
}

}  // namespace
}  // namespace swept
