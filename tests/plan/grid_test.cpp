// The multi-resolution grid (src/plan/grid.cpp): levels, poses of keys and neighbours, on a
// search space made by hand.
#include "plan/grid.h"

#include <gtest/gtest.h>

#include <cmath>

namespace swept {
namespace {

using detail::Grid;
using detail::GridKey;

// Bounds [−4, 4]³ for the reference point (at the body origin), r_max 1: level 0 steps 8/8 = 1;
// with clearance 0.1 and scene size 10 the finest step is the first ≤ max(0.1, 0.02), 1/16.
SearchSpace cube_space(RotationMode rotation) {
  SearchSpace s;
  s.reference = Vec3::Zero();
  s.radius = 1.0;
  s.bounds = Aabb{Vec3(-4, -4, -4), Vec3(4, 4, 4)};
  s.rotation = rotation;
  s.rotation_limits = {{{-0.5, 0.5}, {-0.5, 0.5}, {-0.5, 0.5}}};
  return s;
}

TEST(Grid, LevelsAndSteps) {
  const SearchSpace space = cube_space(RotationMode::none);
  const Grid grid(space, Pose{}, Pose{}, 0.1, 10.0);
  EXPECT_EQ(grid.dimensions(), 3);
  EXPECT_EQ(grid.finest_level(), 4);
  EXPECT_EQ(grid.fine_step(), 1.0 / 16);
  EXPECT_EQ(grid.stride(0), 16);
  EXPECT_EQ(grid.step(0), 1.0);
  EXPECT_EQ(grid.step(4), 1.0 / 16);
  // The finest level is capped at 7.
  EXPECT_EQ(Grid(space, Pose{}, Pose{}, 1e-9, 1e-9).finest_level(), 7);
}

TEST(Grid, NeighboursInOrderInsideTheBounds) {
  const SearchSpace space = cube_space(RotationMode::none);
  const Grid grid(space, Pose{}, Pose::from_translation(Vec3(1, 2, 3)), 0.1, 10.0);
  // At level 0 around the anchor: −x, +x, −y, +y, −z, +z by one step of 16 fine units.
  const detail::GridNeighbours n = grid.neighbours(GridKey{}, 0);
  ASSERT_EQ(n.count, 6);
  const std::array<GridKey, 6> expected = {GridKey{-16, 0, 0, 0, 0, 0}, GridKey{16, 0, 0, 0, 0, 0},
                                           GridKey{0, -16, 0, 0, 0, 0}, GridKey{0, 16, 0, 0, 0, 0},
                                           GridKey{0, 0, -16, 0, 0, 0}, GridKey{0, 0, 16, 0, 0, 0}};
  for (int i = 0; i < 6; ++i) EXPECT_EQ(n.keys[i], expected[i]) << i;
  // The anchor's reference point is at (1, 2, 3): z may rise 1 more (to the boundary, which
  // is inside), not 1 + 1/16.
  EXPECT_TRUE(grid.contains(GridKey{0, 0, 16, 0, 0, 0}));
  EXPECT_FALSE(grid.contains(GridKey{0, 0, 17, 0, 0, 0}));
  const detail::GridNeighbours top = grid.neighbours(GridKey{0, 0, 16, 0, 0, 0}, 4);
  EXPECT_EQ(top.count, 5);  // no +z
  EXPECT_EQ(grid.pose_of(GridKey{16, -32, 8, 0, 0, 0}).translation, Vec3(2, 0, 3.5));
}

TEST(Grid, RotationKeysWithinPiOrTheLimits) {
  const SearchSpace free_space = cube_space(RotationMode::free);
  const Grid grid(free_space, Pose{}, Pose{}, 0.1, 10.0);
  EXPECT_EQ(grid.dimensions(), 6);
  EXPECT_EQ(grid.neighbours(GridKey{}, 0).count, 12);
  // One fine rotation step turns r_max·Δθ = 1/16: 50 steps are 3.125 ≤ π, 51 are not.
  EXPECT_TRUE(grid.contains(GridKey{0, 0, 0, 50, 0, 0}));
  EXPECT_FALSE(grid.contains(GridKey{0, 0, 0, 51, 0, 0}));
  const Pose turned = grid.pose_of(GridKey{0, 0, 0, 0, 0, 8});
  EXPECT_NEAR(rotation_angle(Mat3::Identity(), turned.rotation), 0.5, 1e-12);
  // Limits ±0.5 rad per axis, relative to the problem's start; the anchor is turned 0.2 about x
  // from it, so its keys reach 0.2 + 4/16 = 0.45 (not 0.5125) and 0.2 − 11/16 = −0.4875 (not
  // −0.55) about x.
  const SearchSpace limited = cube_space(RotationMode::limits);
  const Pose anchor{Eigen::AngleAxisd(0.2, Vec3::UnitX()).toRotationMatrix(), Vec3::Zero()};
  const Grid turned_grid(limited, Pose{}, anchor, 0.1, 10.0);
  EXPECT_TRUE(turned_grid.contains(GridKey{0, 0, 0, 4, 0, 0}));
  EXPECT_FALSE(turned_grid.contains(GridKey{0, 0, 0, 5, 0, 0}));
  EXPECT_TRUE(turned_grid.contains(GridKey{0, 0, 0, -11, 0, 0}));
  EXPECT_FALSE(turned_grid.contains(GridKey{0, 0, 0, -12, 0, 0}));
  EXPECT_TRUE(turned_grid.contains(GridKey{0, 0, 0, 0, 7, -7}));
  EXPECT_FALSE(turned_grid.contains(GridKey{0, 0, 0, 0, 9, 0}));
  // The grid turns about the reference point: it stays where the anchor put it.
  SearchSpace offset = cube_space(RotationMode::free);
  offset.reference = Vec3(0.5, 0, 0);
  const Grid about(offset, Pose{}, Pose{}, 0.1, 10.0);
  EXPECT_LT((about.pose_of(GridKey{0, 0, 0, 0, 0, 20}).apply(offset.reference) - offset.reference).norm(), 1e-14);
}

}  // namespace
}  // namespace swept
