// Shortcut smoothing (src/plan/smoothing.cpp) on paths whose shortcuts can be seen by hand.
#include "plan/phase_support.h"
#include "plan/smoothing.h"

namespace swept {
namespace {

using namespace swept::test;
using scenes::add_box;
using scenes::GeneratedProblem;

GeneratedProblem cube_near(const Vec3& wall_lo, const Vec3& wall_hi) {
  GeneratedProblem g;
  g.name = "cube_near";
  add_box(g.obstacles.triangles, wall_lo, wall_hi);
  add_box(g.body.triangles, Vec3(-0.5, -0.5, -0.5), Vec3(0.5, 0.5, 0.5));
  g.problem.start = Pose::from_translation(Vec3(-3, 0, 0));
  g.problem.goal = Pose::from_translation(Vec3(3, 0, 0));
  g.problem.clearance = 0.05;
  g.problem.rotation = RotationMode::none;
  return g;
}

std::vector<Pose> at(std::initializer_list<Vec3> points) {
  std::vector<Pose> out;
  for (const Vec3& p : points) out.push_back(Pose::from_translation(p));
  return out;
}

TEST(Smoothing, ZigZagInOpenSpaceBecomesOneSegment) {
  // The only obstacle is far away: every shortcut is certified.
  PhaseRig rig(cube_near(Vec3(100, 100, 100), Vec3(101, 101, 101)));
  std::vector<Pose> path = at({{0, 0, 0}, {1, 1, 0}, {2, 0, 0}, {3, 1, 0}, {4, 0, 0}});
  detail::smooth(rig.context, path, 0);
  ASSERT_EQ(path.size(), 2u);
  EXPECT_EQ(path[1].translation, Vec3(4, 0, 0));
  EXPECT_EQ(rig.context.edges_checked, 2u);  // 0→3, then 0→4; no second round for 2 poses
  // A fixed prefix (an escape) stays as it is.
  std::vector<Pose> kept = at({{0, 0, 0}, {1, 1, 0}, {2, 0, 0}, {3, 1, 0}, {4, 0, 0}});
  detail::smooth(rig.context, kept, 1);
  ASSERT_EQ(kept.size(), 3u);
  EXPECT_EQ(kept[1].translation, Vec3(1, 1, 0));
  EXPECT_EQ(kept[2].translation, Vec3(4, 0, 0));
}

TEST(Smoothing, KeepsTheCornersAWallNeedsAndStaysCertified) {
  // A wall [−0.5, 0.5] × [−5, 5]² between (−3, 0, 0) and (3, 0, 0); a detour over y = 7 with an
  // extra waypoint on top. Every shortcut across the wall hits it (the line from (−3, 0) to
  // (3, 7) is at y = 3.5 at x = 0; from (−3, 0) to (0, 7) the cube touches the wall's edge
  // region at y < 5), so only the top's middle waypoint goes.
  PhaseRig rig(cube_near(Vec3(-0.5, -5, -5), Vec3(0.5, 5, 5)));
  std::vector<Pose> path = at({{-3, 0, 0}, {-3, 7, 0}, {0, 7, 0}, {3, 7, 0}, {3, 0, 0}});
  detail::smooth(rig.context, path, 0);
  const std::vector<Pose> expected = at({{-3, 0, 0}, {-3, 7, 0}, {3, 7, 0}, {3, 0, 0}});
  ASSERT_EQ(path.size(), expected.size());
  for (std::size_t i = 0; i < path.size(); ++i) EXPECT_EQ(path[i].translation, expected[i].translation) << i;
  check_path_independently(rig.scene, rig.problem(), Path{path});
}

}  // namespace
}  // namespace swept
