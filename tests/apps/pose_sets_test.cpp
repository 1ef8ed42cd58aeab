// The benchmarks' one pose-set generator (bench/lib: swept/bench/pose_sets.h): every pose is of
// the kind its set promises, checked with the brute-force oracle's queries, and a seed gives the
// same poses every time.
#include "support/test_support.h"

#include "swept/bench/pose_sets.h"
#include "swept/query/query.h"

#include <gtest/gtest.h>

namespace swept::bench {
namespace {

Bvh tree(const std::vector<Triangle>& tris) { return build_bvh(tris).value(); }

TEST(PoseSets, EveryPoseIsOfItsKind) {
  // A plate (obstacles) and a bar longer than the plate is thick (body): most poses with the bar's
  // centre inside the plate's box cut the plate's surface.
  const Bvh a = tree(test::box_triangles(Vec3(-10, -10, -1), Vec3(10, 10, 1)));
  const Bvh b = tree(test::box_triangles(Vec3(-1, -1, -6), Vec3(1, 1, 6)));
  const PoseSetRequest request{.count = 6, .seed = 7, .near_fraction = 0.01};
  const std::vector<PoseSet> sets = make_pose_sets(a, b, request);
  ASSERT_EQ(sets.size(), 3u);
  EXPECT_EQ(sets[0].name, "overlapping");
  EXPECT_EQ(sets[1].name, "near");
  EXPECT_EQ(sets[2].name, "far");
  for (const PoseSet& s : sets) EXPECT_EQ(s.poses.size(), 6u) << s.name;
  const Pose id;
  for (const Pose& p : sets[0].poses) EXPECT_TRUE(collide(a, id, b, p).colliding);
  const double limit = request.near_fraction * b.extent;
  for (const Pose& p : sets[1].poses) {
    const double d = distance(a, id, b, p).distance;
    EXPECT_GT(d, 0.0);
    EXPECT_LE(d, limit);
  }
  // Far: the bounding spheres (about the box centres, radius half the diagonal) are apart.
  const Vec3 ca = bounds(a.triangles).center(), cb = bounds(b.triangles).center();
  for (const Pose& p : sets[2].poses)
    EXPECT_GT((p.apply(cb) - ca).norm(), 0.5 * (a.extent + b.extent));
}

TEST(PoseSets, SameSeedSamePoses) {
  const Bvh a = tree(test::box_triangles(Vec3(-5, -5, -5), Vec3(5, 5, 5)));
  const Bvh b = tree(test::box_triangles(Vec3(-1, -1, -1), Vec3(1, 1, 1)));
  const auto first = make_pose_sets(a, b, {.count = 4, .seed = 3});
  const auto again = make_pose_sets(a, b, {.count = 4, .seed = 3});
  const auto other = make_pose_sets(a, b, {.count = 4, .seed = 4});
  for (std::size_t s = 0; s < first.size(); ++s) {
    ASSERT_EQ(first[s].poses.size(), again[s].poses.size());
    for (std::size_t i = 0; i < first[s].poses.size(); ++i) {
      EXPECT_TRUE(first[s].poses[i].translation == again[s].poses[i].translation) << first[s].name << " " << i;
      EXPECT_TRUE(first[s].poses[i].rotation == again[s].poses[i].rotation) << first[s].name << " " << i;
    }
  }
  EXPECT_TRUE(first[2].poses[0].translation != other[2].poses[0].translation);
}

TEST(PoseSets, NoPosesWantedGivesEmptySets) {
  const Bvh a = tree(test::box_triangles(Vec3(0, 0, 0), Vec3(1, 1, 1)));
  const Bvh b = tree(test::box_triangles(Vec3(0, 0, 0), Vec3(1, 1, 1)));
  for (const PoseSet& s : make_pose_sets(a, b, {.count = 0})) EXPECT_TRUE(s.poses.empty()) << s.name;
}

}  // namespace
}  // namespace swept::bench
