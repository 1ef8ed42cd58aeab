// collide / distance / tolerance against the all-pairs oracle on seeded meshes and poses,
// for every fitter: random soups, slivers and degenerate triangles, touching and parallel
// boxes, and a model far from the origin.
#include "support/tables.h"
#include "swept/query/query.h"

#include "query_oracle.h"
#include "support/test_support.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <thread>
#include <set>
#include <vector>

namespace swept {
namespace {

using test::Rng;

Bvh build(const std::vector<Triangle>& tris, Fitter fitter) {
  Result<Bvh> r = build_bvh(tris, {.fitter = fitter});
  EXPECT_TRUE(r.ok()) << (r.ok() ? "" : r.error().message);
  return std::move(r).value();
}

struct Scene {
  std::string name;
  std::vector<Triangle> a, b;
  std::vector<Pose> poses_a, poses_b;
};

/// The B pose t% of the way between "overlapping" and "far", around A.
Pose random_pose(Rng& rng, const Vec3& center, double spread) {
  return {rng.rotation(), center + rng.vec(-spread, spread)};
}

std::vector<Scene> scenes() {
  std::vector<Scene> out;
  Rng rng(2024);
  {
    Scene s{"random", test::random_triangles(rng, 300, 10, 2), test::random_triangles(rng, 200, 6, 2), {}, {}};
    for (int i = 0; i < 24; ++i) {
      s.poses_a.push_back(random_pose(rng, Vec3::Zero(), 1));
      s.poses_b.push_back(random_pose(rng, Vec3::Zero(), 2 + i));
    }
    out.push_back(std::move(s));
  }
  {
    Scene s{"nasty", test::nasty_triangles(rng, 300, 10), test::nasty_triangles(rng, 250, 8), {}, {}};
    for (int i = 0; i < 24; ++i) {
      s.poses_a.push_back(random_pose(rng, Vec3::Zero(), 1));
      s.poses_b.push_back(random_pose(rng, Vec3::Zero(), 1 + 0.5 * i));
    }
    out.push_back(std::move(s));
  }
  {
    // Far from the origin: the models' own coordinates are ~1e6.
    const Vec3 far(1e6, -1e6, 1e6);
    Scene s{"far", test::random_triangles(rng, 200, 10, 2, far), test::nasty_triangles(rng, 150, 6), {}, {}};
    for (int i = 0; i < 16; ++i) {
      s.poses_a.push_back({Mat3::Identity(), Vec3::Zero()});
      s.poses_b.push_back(random_pose(rng, far, 1 + i));
    }
    out.push_back(std::move(s));
  }
  {
    // Boxes: face-to-face touching (coplanar faces), edge on edge, parallel faces at a gap,
    // overlapping.
    Scene s{"boxes", test::box_triangles({0, 0, 0}, {2, 2, 2}), test::box_triangles({0, 0, 0}, {1, 1, 1}), {}, {}};
    const Mat3 rz = Eigen::AngleAxisd(0.25 * std::numbers::pi, Vec3::UnitZ()).toRotationMatrix();
    const Mat3 rx = Eigen::AngleAxisd(0.25 * std::numbers::pi, Vec3::UnitX()).toRotationMatrix();
    const std::vector<Pose> pb = {
        Pose::from_translation({2, 0.5, 0.5}),           // face on face
        Pose::from_translation({2, 2, 0.5}),             // edge on edge, coplanar faces
        Pose::from_translation({2, 2, 2}),               // corner on corner
        Pose::from_translation({2 + 1e-3, 0.5, 0.5}),    // parallel faces, gap 1e-3
        Pose::from_translation({2 + 1e-9, 0.2, 0.3}),    // parallel faces, gap 1e-9
        Pose::from_translation({1.5, 0.5, 0.5}),         // overlapping
        Pose::from_translation({0.5, 0.5, 0.5}),         // inside, no surface contact
        {rz * rx, Vec3(2.0 + std::sqrt(0.5), 1, 1)},     // tilted edge touching a face
        {rz, Vec3(2.0, 1, 0.5)},                         // vertical edge on a face
    };
    for (const Pose& p : pb) {
      s.poses_a.push_back(Pose::identity());
      s.poses_b.push_back(p);
    }
    // The same configurations far from the origin, with A moved there by its pose.
    Rng r2(3);
    const Mat3 rot = r2.rotation();
    const Pose shift{rot, Vec3(1e6, 2e6, -1e6)};
    for (const Pose& p : pb) {
      s.poses_a.push_back(shift);
      s.poses_b.push_back(compose(shift, p));
    }
    out.push_back(std::move(s));
  }
  return out;
}

class QueryOracle : public ::testing::TestWithParam<Fitter> {};

TEST_P(QueryOracle, CollideDistanceToleranceMatchBruteForce) {
  int colliding = 0, separated = 0;
  for (const Scene& s : scenes()) {
    const Bvh a = build(s.a, GetParam());
    const Bvh b = build(s.b, GetParam());
    for (std::size_t k = 0; k < s.poses_b.size(); ++k) {
      SCOPED_TRACE(s.name + " pose " + std::to_string(k));
      const Pose& pa = s.poses_a[k];
      const Pose& pb = s.poses_b[k];
      // Collide: flag and the full contact set.
      const auto expected = test::brute_contacts(s.a, s.b, pa, pb);
      const CollideResult all = collide(a, pa, b, pb, {.all_contacts = true});
      ASSERT_EQ(all.colliding, !expected.empty());
      ASSERT_EQ(all.contacts.size(), expected.size());
      for (std::size_t i = 0; i < expected.size(); ++i) {
        EXPECT_EQ(all.contacts[i].triangle_a, expected[i].first);
        EXPECT_EQ(all.contacts[i].triangle_b, expected[i].second);
      }
      const CollideResult first = collide(a, pa, b, pb);
      EXPECT_EQ(first.colliding, all.colliding);
      if (first.colliding) {
        ASSERT_EQ(first.contacts.size(), 1u);
        EXPECT_TRUE(std::find(expected.begin(), expected.end(),
                              std::make_pair(first.contacts[0].triangle_a, first.contacts[0].triangle_b)) !=
                    expected.end());
        ++colliding;
      } else {
        ++separated;
      }
      EXPECT_GT(all.stats.bv_tests, 0u);

      // Distance: value, witnesses on the reported triangles at the reported distance.
      const test::BruteDistance bd = test::brute_distance(s.a, s.b, pa, pb);
      const DistanceResult d = distance(a, pa, b, pb);
      EXPECT_TRUE(d.exact);
      ASSERT_NEAR(d.distance, bd.distance, 1e-12 * bd.distance + 1e-300);
      double scale = 1.0;
      for (const Triangle& t : s.a) scale = std::max(scale, pa.apply(t.p).cwiseAbs().maxCoeff());
      const double wtol = 1e-11 * scale;
      EXPECT_NEAR((d.point_a - d.point_b).norm(), d.distance, wtol);
      const Triangle ta = s.a[d.triangle_a];
      const Triangle tb = s.b[d.triangle_b];
      EXPECT_LE(point_triangle_closest(pa.apply_inverse(d.point_a), ta).distance, wtol);
      EXPECT_LE(point_triangle_closest(pb.apply_inverse(d.point_b), tb).distance, wtol);
      EXPECT_GT(d.stats.triangle_tests, 0u);
      EXPECT_LE(d.stats.triangle_tests, s.a.size() * s.b.size());

      // Error bounds (PQP semantics): within the bound, never below the true distance.
      const DistanceResult dr = distance(a, pa, b, pb, {.rel_err = 0.1});
      EXPECT_GE(dr.distance, bd.distance * (1 - 1e-12));
      EXPECT_LE(dr.distance, 1.1 * bd.distance * (1 + 1e-12) + 1e-300);
      const double abs_err = 0.05;
      const DistanceResult da = distance(a, pa, b, pb, {.abs_err = abs_err});
      EXPECT_GE(da.distance, bd.distance * (1 - 1e-12));
      EXPECT_LE(da.distance, bd.distance + abs_err * (1 + 1e-9));

      // Warm start: a valid upper bound changes nothing but the work.
      const DistanceResult dw = distance(a, pa, b, pb, {.upper_bound = bd.distance * 1.5 + 1e-3});
      EXPECT_EQ(dw.distance, d.distance);
      const DistanceResult dx = distance(a, pa, b, pb, {.upper_bound = bd.distance});
      EXPECT_EQ(dx.distance, d.distance);
      EXPECT_LE(point_triangle_closest(pa.apply_inverse(dx.point_a), s.a[dx.triangle_a]).distance, wtol);

      // Early exit: a lower bound ≥ enough when the distance is at least that, else exact.
      for (const double enough : {0.5 * bd.distance, 2.0 * bd.distance + 1e-6}) {
        const DistanceResult de = distance(a, pa, b, pb, {.enough = enough});
        if (bd.distance >= enough) {
          EXPECT_GE(de.distance, enough);
          EXPECT_LE(de.distance, bd.distance * (1 + 1e-12));
        } else {
          EXPECT_TRUE(de.exact);
          EXPECT_NEAR(de.distance, bd.distance, 1e-12 * bd.distance);
        }
      }

      // Stop below: a pair under the threshold ends the search (an upper bound under it, never
      // below the true distance, with its witnesses); a distance at or above it is exact. With
      // `enough` beside it, as the planner asks.
      for (const double below : {0.5 * bd.distance, 1.5 * bd.distance + 1e-6, 1e-3}) {
        const DistanceResult ds = distance(a, pa, b, pb, {.enough = 4.0 * below + 1.0, .stop_below = below});
        if (bd.distance < below) {
          EXPECT_FALSE(ds.exact);
          EXPECT_LT(ds.distance, below);
          EXPECT_GE(ds.distance, bd.distance * (1 - 1e-12));
          EXPECT_NEAR((ds.point_a - ds.point_b).norm(), ds.distance, wtol);
          EXPECT_LE(point_triangle_closest(pa.apply_inverse(ds.point_a), s.a[ds.triangle_a]).distance, wtol);
        } else if (bd.distance < 4.0 * below + 1.0) {
          EXPECT_TRUE(ds.exact);
          EXPECT_NEAR(ds.distance, bd.distance, 1e-12 * bd.distance);
        } else {
          EXPECT_GE(ds.distance, 4.0 * below + 1.0);
          EXPECT_LE(ds.distance, bd.distance * (1 + 1e-12));
        }
      }

      // A stop_below of 0 or less, which no distance is below (the planner at a clearance of 0):
      // the exact distance, as without it, with a witness at that distance. A touching pose ends
      // the distance search at its first touching pair: still exactly 0.
      for (const DistanceRequest& request : {DistanceRequest{.stop_below = 0.0}, DistanceRequest{.stop_below = -1.0}}) {
        const DistanceResult w = distance(a, pa, b, pb, request);
        EXPECT_TRUE(w.exact);
        EXPECT_NEAR(w.distance, bd.distance, 1e-12 * bd.distance);
        if (bd.distance == 0.0) {
          EXPECT_EQ(w.distance, 0.0);
        }
        EXPECT_NEAR((w.point_a - w.point_b).norm(), w.distance, wtol);
        EXPECT_LE(point_triangle_closest(pa.apply_inverse(w.point_a), s.a[w.triangle_a]).distance, wtol);
        EXPECT_LE(point_triangle_closest(pb.apply_inverse(w.point_b), s.b[w.triangle_b]).distance, wtol);
      }

      // Tolerance: either side of the true distance.
      if (bd.distance > 0) {
        const ToleranceResult in = tolerance(a, pa, b, pb, {.tolerance = bd.distance * 1.01});
        EXPECT_TRUE(in.within);
        EXPECT_LT(in.distance, bd.distance * 1.01);
        EXPECT_NEAR((in.point_a - in.point_b).norm(), in.distance, wtol);
        const ToleranceResult out = tolerance(a, pa, b, pb, {.tolerance = bd.distance * 0.99});
        EXPECT_FALSE(out.within);
      } else {
        // Overlapping: within any tolerance, with a witness pair (any pair closer than it, the
        // search stops at the first) whose points lie on their triangles.
        for (const double t : {1e-9, 0.1}) {
          const ToleranceResult in = tolerance(a, pa, b, pb, {.tolerance = t});
          EXPECT_TRUE(in.within);
          EXPECT_LT(in.distance, t);
          EXPECT_NEAR((in.point_a - in.point_b).norm(), in.distance, wtol);
          EXPECT_LE(point_triangle_closest(pa.apply_inverse(in.point_a), s.a[in.triangle_a]).distance, wtol);
          EXPECT_LE(point_triangle_closest(pb.apply_inverse(in.point_b), s.b[in.triangle_b]).distance, wtol);
        }
      }

      // Proximity pairs: exactly the pairs closer than the threshold; then the distance with
      // those pairs left out is the smallest distance of all the other pairs.
      {
        const double threshold = 2.0 * bd.distance + 0.05;
        const std::vector<Triangle> bb = test::b_in_a(s.b, pa, pb);
        std::vector<ContactPair> near;
        double rest = std::numeric_limits<double>::infinity();
        for (std::uint32_t i = 0; i < s.a.size(); ++i)
          for (std::uint32_t j = 0; j < bb.size(); ++j) {
            const double dij = triangle_distance(s.a[i], bb[j]).distance;
            if (dij < threshold) near.push_back({i, j});
            else rest = std::min(rest, dij);
          }
        const ProximityResult pr = proximity_pairs(a, pa, b, pb, {.threshold = threshold});
        ASSERT_EQ(pr.pairs.size(), near.size());
        for (std::size_t i = 0; i < near.size(); ++i) {
          EXPECT_EQ(pr.pairs.pairs[i].triangle_a, near[i].triangle_a);
          EXPECT_EQ(pr.pairs.pairs[i].triangle_b, near[i].triangle_b);
        }
        // The near triangles of each side: exactly the ones the brute-force pairs name.
        {
          std::set<std::uint32_t> want_a, want_b;
          for (const ContactPair& p : near) want_a.insert(p.triangle_a), want_b.insert(p.triangle_b);
          const ProximityTrianglesResult pt = proximity_triangles(a, pa, b, pb, {.threshold = threshold});
          EXPECT_EQ(pt.a, std::vector<std::uint32_t>(want_a.begin(), want_a.end()));
          EXPECT_EQ(pt.b, std::vector<std::uint32_t>(want_b.begin(), want_b.end()));
        }
        const DistanceResult dx = distance(a, pa, b, pb, {.exclude = &pr.pairs});
        if (std::isfinite(rest)) {
          EXPECT_NEAR(dx.distance, rest, 1e-12 * rest);
          EXPECT_FALSE(pr.pairs.contains(dx.triangle_a, dx.triangle_b));
        } else {
          EXPECT_EQ(dx.distance, rest);
        }
        // The same pairs left out by a rule (exclude_if) give the same answer, and any rule
        // leaves out exactly the pairs it names: brute force over the pairs it keeps.
        const std::function<bool(std::uint32_t, std::uint32_t)> near_rule = [&](std::uint32_t i, std::uint32_t j) {
          return pr.pairs.contains(i, j);
        };
        EXPECT_EQ(distance(a, pa, b, pb, {.exclude_if = &near_rule}).distance, dx.distance);
        const std::function<bool(std::uint32_t, std::uint32_t)> thirds = [](std::uint32_t i, std::uint32_t j) {
          return (7 * i + j) % 3 == 0;
        };
        double kept = std::numeric_limits<double>::infinity();
        for (std::uint32_t i = 0; i < s.a.size(); ++i)
          for (std::uint32_t j = 0; j < bb.size(); ++j)
            if (!thirds(i, j)) kept = std::min(kept, triangle_distance(s.a[i], bb[j]).distance);
        const DistanceResult dt = distance(a, pa, b, pb, {.exclude_if = &thirds});
        EXPECT_NEAR(dt.distance, kept, 1e-12 * kept + 1e-15);
        EXPECT_FALSE(thirds(dt.triangle_a, dt.triangle_b));
      }
    }
  }
  EXPECT_GT(colliding, 10);
  EXPECT_GT(separated, 10);
}

INSTANTIATE_TEST_SUITE_P(Fitters, QueryOracle,
                         ::testing::ValuesIn(swept::test::every_fitter()),
                         [](const auto& info) { return std::string(to_string(info.param)); });

TEST_P(QueryOracle, HintedQueriesAlongMotionsMatchBruteForce) {
  // Coherence (DistanceRequest::hint): along straight motions through every scene's poses, each
  // query hinted with the previous one's pair gives the brute-force distance; a hint out of
  // range, or naming a pair left out, is ignored; on a tie the hinted pair stays the witness;
  // a batch along the path equals the independent one and does not depend on the threads.
  for (const Scene& s : scenes()) {
    SCOPED_TRACE(s.name);
    const Bvh a = build(s.a, GetParam());
    const Bvh b = build(s.b, GetParam());
    std::vector<Pose> path;
    for (std::size_t k = 0; k + 1 < s.poses_b.size(); ++k) {
      const Pose p0 = relative(s.poses_a[k], s.poses_b[k]), p1 = relative(s.poses_a[k + 1], s.poses_b[k + 1]);
      const Quat q0 = p0.quaternion(), q1 = p1.quaternion();
      for (int i = 0; i < 3; ++i) {
        const double t = i / 3.0;
        path.push_back({q0.slerp(t, q1).toRotationMatrix(), (1 - t) * p0.translation + t * p1.translation});
      }
    }
    DistanceRequest request;
    std::uint64_t bv_hinted = 0, bv_cold = 0;
    for (std::size_t k = 0; k < path.size(); ++k) {
      SCOPED_TRACE("path pose " + std::to_string(k));
      const test::BruteDistance bd = test::brute_distance(s.a, s.b, Pose::identity(), path[k]);
      const DistanceResult hinted = distance(a, {}, b, path[k], request);
      const DistanceResult cold = distance(a, {}, b, path[k]);
      ASSERT_NEAR(hinted.distance, bd.distance, 1e-12 * bd.distance + 1e-300);
      EXPECT_NEAR(hinted.distance, cold.distance, 1e-12 * cold.distance + 1e-300);
      EXPECT_NEAR((hinted.point_a - hinted.point_b).norm(), hinted.distance, 1e-9 * (1 + path[k].translation.norm()));
      if (request.hint.valid() && hinted.distance > 0.0) {
        // The hinted pair at this pose is an upper bound the answer reached: when it is the
        // answer, the hinted pair is reported (ties keep the witness).
        const Triangle& t = b.triangles[request.hint.b];
        const TriangleDistance h = triangle_distance(a.triangles[request.hint.a],
                                                     {path[k].apply(t.p), path[k].apply(t.q), path[k].apply(t.r)});
        if (h.distance == hinted.distance) {
          EXPECT_EQ(hinted.triangle_a, a.triangle_ids[request.hint.a]);
          EXPECT_EQ(hinted.triangle_b, b.triangle_ids[request.hint.b]);
        }
      }
      bv_hinted += hinted.stats.bv_tests;
      bv_cold += cold.stats.bv_tests;
      ASSERT_TRUE(hinted.hint.valid());
      EXPECT_EQ(a.triangle_ids[hinted.hint.a], hinted.triangle_a);
      EXPECT_EQ(b.triangle_ids[hinted.hint.b], hinted.triangle_b);
      request.hint = hinted.hint;
    }
    EXPECT_LE(bv_hinted, bv_cold);  // the hint only prunes
    // Ignored hints: out of range, and a pair left out.
    const DistanceResult cold = distance(a, {}, b, path[0]);
    EXPECT_EQ(distance(a, {}, b, path[0], {.hint = {UINT32_MAX - 1, 0}}).distance, cold.distance);
    EXPECT_EQ(distance(a, {}, b, path[0], {.hint = {0, static_cast<std::uint32_t>(b.triangles.size())}}).distance, cold.distance);
    TrianglePairs leave_out;
    leave_out.pairs.push_back({cold.triangle_a, cold.triangle_b});
    const DistanceResult left = distance(a, {}, b, path[0], {.exclude = &leave_out, .hint = cold.hint});
    const DistanceResult left_cold = distance(a, {}, b, path[0], {.exclude = &leave_out});
    EXPECT_NEAR(left.distance, left_cold.distance, 1e-12 * left_cold.distance + 1e-300);
    EXPECT_FALSE(left.triangle_a == cold.triangle_a && left.triangle_b == cold.triangle_b);
    // Batches: along the path, the same distances as independent queries, at any thread count.
    const auto independent = distance_batch(a, {}, b, path);
    std::vector<std::vector<DistanceResult>> along;
    for (int threads : {1, 2}) {
      tbb::task_arena arena(threads);
      along.push_back(arena.execute([&] { return distance_batch(a, {}, b, path, {}, true); }));
    }
    for (std::size_t k = 0; k < path.size(); ++k) {
      EXPECT_NEAR(along[0][k].distance, independent[k].distance, 1e-12 * independent[k].distance + 1e-300);
      EXPECT_EQ(along[0][k].distance, along[1][k].distance);
      EXPECT_EQ(along[0][k].triangle_a, along[1][k].triangle_a);
      EXPECT_EQ(along[0][k].triangle_b, along[1][k].triangle_b);
      EXPECT_EQ(along[0][k].point_a, along[1][k].point_a);
    }
  }
}

TEST(QueryConcurrency, ManyThreadsGiveTheSerialResults) {
  Rng rng(77);
  const auto ta = test::random_triangles(rng, 400, 10, 2);
  const auto tb = test::nasty_triangles(rng, 300, 8);
  const Bvh a = build(ta, Fitter::inertia);
  const Bvh b = build(tb, Fitter::pqp);
  std::vector<Pose> poses;
  for (int i = 0; i < 200; ++i) poses.push_back(random_pose(rng, Vec3::Zero(), 1 + 0.1 * i));
  std::vector<DistanceResult> serial_d;
  std::vector<CollideResult> serial_c;
  for (const Pose& p : poses) {
    serial_d.push_back(distance(a, Pose::identity(), b, p));
    serial_c.push_back(collide(a, Pose::identity(), b, p, {.all_contacts = true}));
  }
  auto same_d = [](const DistanceResult& x, const DistanceResult& y) {
    return x.distance == y.distance && x.point_a == y.point_a && x.point_b == y.point_b &&
           x.triangle_a == y.triangle_a && x.triangle_b == y.triangle_b &&
           x.stats.bv_tests == y.stats.bv_tests;
  };
  auto same_c = [](const CollideResult& x, const CollideResult& y) {
    if (x.colliding != y.colliding || x.contacts.size() != y.contacts.size()) return false;
    for (std::size_t i = 0; i < x.contacts.size(); ++i)
      if (x.contacts[i].triangle_a != y.contacts[i].triangle_a || x.contacts[i].triangle_b != y.contacts[i].triangle_b)
        return false;
    return true;
  };
  // Batches (oneTBB) keep input order.
  const auto bd = distance_batch(a, Pose::identity(), b, poses);
  const auto bc = collide_batch(a, Pose::identity(), b, poses, {.all_contacts = true});
  ASSERT_EQ(bd.size(), poses.size());
  for (std::size_t i = 0; i < poses.size(); ++i) {
    EXPECT_TRUE(same_d(bd[i], serial_d[i])) << i;
    EXPECT_TRUE(same_c(bc[i], serial_c[i])) << i;
  }
  // Plain threads hammering the same trees.
  std::vector<int> mismatches(8, 0);
  std::vector<std::thread> threads;
  for (int t = 0; t < 8; ++t) {
    threads.emplace_back([&, t] {
      for (std::size_t k = 0; k < poses.size(); ++k) {
        const std::size_t i = (k * 7 + static_cast<std::size_t>(t) * 13) % poses.size();
        if (!same_d(distance(a, Pose::identity(), b, poses[i]), serial_d[i])) ++mismatches[t];
        if (!same_c(collide(a, Pose::identity(), b, poses[i], {.all_contacts = true}), serial_c[i]))
          ++mismatches[t];
      }
    });
  }
  for (auto& th : threads) th.join();
  for (int t = 0; t < 8; ++t) EXPECT_EQ(mismatches[t], 0) << "thread " << t;
}

/// A bumpy plate over [0, 10]²: an n × n grid of heights `noise`·uniform, two triangles a cell.
std::vector<Triangle> bumpy_plate(Rng& rng, int n, double noise) {
  std::vector<Vec3> v;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) v.emplace_back(10.0 * i / (n - 1), 10.0 * j / (n - 1), noise * rng.uniform());
  std::vector<Triangle> out;
  for (int i = 0; i + 1 < n; ++i)
    for (int j = 0; j + 1 < n; ++j) {
      const Vec3 &p = v[i * n + j], &q = v[(i + 1) * n + j], &r = v[(i + 1) * n + j + 1], &s = v[i * n + j + 1];
      out.push_back({p, q, r});
      out.push_back({p, r, s});
    }
  return out;
}

// Long searches: two bumpy plates facing each other, where thousands of node pairs have bounds
// near the answer. The distance search takes its first dives best first and then goes on depth
// first; both phases must find the all-pairs answer, ties included, for every fitter.
TEST_P(QueryOracle, LongSearchesMatchBruteForce) {
  Rng rng(91);
  const auto ta = bumpy_plate(rng, 22, 0.3);
  const auto tb = bumpy_plate(rng, 20, 0.3);
  const Bvh a = build(ta, GetParam());
  const Bvh b = build(tb, GetParam());
  // A dive tests at most two pairs per level of the two trees: past this many tests the search
  // has made more dives than it takes best first (kBestFirstDives = 64 in query.cpp).
  const std::uint64_t past_best_first = 2u * 64u * static_cast<std::uint64_t>(a.depth + b.depth);
  std::uint64_t longest = 0;
  for (int k = 0; k < 6; ++k) {
    SCOPED_TRACE("pose " + std::to_string(k));
    // B upside down above A, a little tilted, at gaps from contact to a plate's size.
    const Mat3 flip = Eigen::AngleAxisd(std::numbers::pi, Vec3::UnitX()).toRotationMatrix();
    const Mat3 tilt = Eigen::AngleAxisd(0.05 * rng.uniform(-1, 1), Vec3::UnitY()).toRotationMatrix();
    const double gap = k < 2 ? 0.3 * rng.uniform() : (k < 4 ? 0.6 + rng.uniform() : 3.0 + 8.0 * rng.uniform());
    const Pose pb{tilt * flip, Vec3(rng.uniform(-2, 2), 10.0 + rng.uniform(-2, 2), 0.3 + gap)};
    const test::BruteDistance bd = test::brute_distance(ta, tb, Pose::identity(), pb);
    const DistanceResult d = distance(a, Pose::identity(), b, pb);
    ASSERT_TRUE(d.exact);
    ASSERT_NEAR(d.distance, bd.distance, 1e-12 * bd.distance + 1e-300);
    const double wtol = 1e-11 * 20.0;
    EXPECT_NEAR((d.point_a - d.point_b).norm(), d.distance, wtol);
    EXPECT_LE(point_triangle_closest(d.point_a, ta[d.triangle_a]).distance, wtol);
    EXPECT_LE(point_triangle_closest(pb.apply_inverse(d.point_b), tb[d.triangle_b]).distance, wtol);
    longest = std::max<std::uint64_t>(longest, d.stats.bv_tests);
    // Warm starts and early exits on the same long searches.
    EXPECT_EQ(distance(a, Pose::identity(), b, pb, {.upper_bound = bd.distance}).distance, d.distance);
    EXPECT_EQ(distance(a, Pose::identity(), b, pb, {.hint = d.hint}).distance, d.distance);
    const DistanceResult de = distance(a, Pose::identity(), b, pb, {.enough = 0.5 * bd.distance});
    EXPECT_GE(de.distance, 0.5 * bd.distance);
    EXPECT_LE(de.distance, bd.distance * (1 + 1e-12));
  }
  EXPECT_GT(longest, past_best_first) << "no pose reached the depth-first phase";
}

// The distance search reuses per-thread buffers for its waiting pairs and its decoded nodes: a
// search started from inside another on the same thread (here from a pair rule) must not disturb
// the outer one, which must test the very node pairs it tests with a rule that starts nothing.
TEST(QueryEdgeCases, NestedDistanceSearchesOnOneThread) {
  Rng rng(5);
  const auto ta = bumpy_plate(rng, 20, 0.3);
  const auto tb = bumpy_plate(rng, 18, 0.3);
  const Bvh a = build(ta, Fitter::inertia);
  const Bvh b = build(tb, Fitter::inertia);
  const Mat3 flip = Eigen::AngleAxisd(std::numbers::pi, Vec3::UnitX()).toRotationMatrix();
  const Pose pb{flip, Vec3(0.5, 10.5, 1.0)};
  const Pose inner_pose{flip, Vec3(-0.5, 9.5, 2.0)};
  const DistanceResult inner_alone = distance(a, Pose::identity(), b, inner_pose);
  int nested = 0;
  bool inner_same = true;
  const std::function<bool(std::uint32_t, std::uint32_t)> rule = [&](std::uint32_t i, std::uint32_t j) {
    if ((i + j) % 97 == 0) {
      ++nested;
      inner_same = inner_same && distance(a, Pose::identity(), b, inner_pose).distance == inner_alone.distance;
    }
    return false;  // leaves every pair in
  };
  const std::function<bool(std::uint32_t, std::uint32_t)> quiet = [](std::uint32_t, std::uint32_t) { return false; };
  const DistanceResult plain = distance(a, Pose::identity(), b, pb);
  const DistanceResult with_quiet_rule = distance(a, Pose::identity(), b, pb, {.exclude_if = &quiet});
  const DistanceResult with_rule = distance(a, Pose::identity(), b, pb, {.exclude_if = &rule});
  EXPECT_GT(nested, 0);
  EXPECT_EQ(with_rule.stats.bv_tests, with_quiet_rule.stats.bv_tests);
  EXPECT_EQ(with_rule.stats.triangle_tests, with_quiet_rule.stats.triangle_tests);
  EXPECT_TRUE(inner_same);
  EXPECT_EQ(with_rule.distance, plain.distance);
  EXPECT_EQ(with_rule.triangle_a, plain.triangle_a);
  EXPECT_EQ(with_rule.triangle_b, plain.triangle_b);
  const double brute = test::brute_distance(ta, tb, Pose::identity(), pb).distance;
  EXPECT_NEAR(plain.distance, brute, 1e-12 * brute);
}

TEST(QueryEdgeCases, SingleTriangleModelsAndIdenticalPoses) {
  const std::vector<Triangle> one = {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}};
  const Bvh a = build(one, Fitter::inertia);
  // The same model at the same pose: coplanar overlap.
  EXPECT_TRUE(collide(a, Pose::identity(), a, Pose::identity()).colliding);
  EXPECT_EQ(distance(a, Pose::identity(), a, Pose::identity()).distance, 0.0);
  const DistanceResult d = distance(a, Pose::identity(), a, Pose::from_translation({0, 0, 2.5}));
  EXPECT_NEAR(d.distance, 2.5, 1e-15);
  EXPECT_FALSE(tolerance(a, Pose::identity(), a, Pose::from_translation({0, 0, 2.5}), {.tolerance = 2.5}).within);
  EXPECT_TRUE(tolerance(a, Pose::identity(), a, Pose::from_translation({0, 0, 2.5}), {.tolerance = 2.50001}).within);
}

// Collide settles far-apart models from the balls around the roots (each rectangle's
// circumscribed disc grown by its radius). Two flat 4 × 2 rectangles (two triangles each) lying in
// one plane, corner to corner along their common diagonal, touch at one point, where their
// circumscribed discs touch too: the ball test is tight there and must not call them apart. Moved
// apart along the diagonal by a little more than the rounding, they are apart (by hand: the
// corners (2, 1) and (2, 1) + δ·(2, 1)/√5).
TEST(QueryEdgeCases, RectanglesTouchingCornerToCornerWhereTheirBallsTouch) {
  auto rectangle = [](const Vec3& c) {
    const Vec3 p = c + Vec3(-2, -1, 0), q = c + Vec3(2, -1, 0), r = c + Vec3(2, 1, 0), s = c + Vec3(-2, 1, 0);
    return std::vector<Triangle>{{p, q, r}, {p, r, s}};
  };
  const Vec3 diagonal = Vec3(2, 1, 0) / std::sqrt(5.0);
  Rng rng(5);
  for (const Fitter f : test::every_fitter()) {
    const Bvh a = build(rectangle(Vec3::Zero()), f);
    const Bvh b_touching = build(rectangle(Vec3(4, 2, 0)), f);
    const Bvh b_apart = build(rectangle(Vec3(4, 2, 0) + 1e-6 * diagonal), f);
    // At the identity, and both moved by one rigid motion far from the origin.
    for (int k = 0; k < 4; ++k) {
      const Pose both = k == 0 ? Pose::identity() : Pose{rng.rotation(), rng.vec(-1e3, 1e3)};
      const std::string what = std::string(to_string(f)) + " pose " + std::to_string(k);
      EXPECT_TRUE(collide(a, both, b_touching, both).colliding) << what;
      EXPECT_FALSE(collide(a, both, b_apart, both).colliding) << what;
      EXPECT_NEAR(distance(a, both, b_apart, both).distance, 1e-6, 1e-9) << what;
    }
  }
}

}  // namespace
}  // namespace swept
