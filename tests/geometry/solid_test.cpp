// Closed parts of a triangle soup and the point-in-solid test, on boxes whose answers are known.
#include "swept/geometry/solid.h"
#include "swept/scenes/box_problems.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace swept {
namespace {

using scenes::add_box;

std::vector<Triangle> flipped(std::vector<Triangle> t) {
  for (Triangle& x : t) std::swap(x.q, x.r);
  return t;
}

TEST(SurfaceParts, BoxesAreClosedALooseTriangleIsNot) {
  std::vector<Triangle> t;
  add_box(t, Vec3(0, 0, 0), Vec3(1, 1, 1));
  add_box(t, Vec3(5, 0, 0), Vec3(6, 2, 1));
  t.push_back({Vec3(10, 0, 0), Vec3(11, 0, 0), Vec3(10, 1, 0)});
  t.push_back({Vec3(20, 0, 0), Vec3(20, 0, 0), Vec3(20, 1, 0)});  // degenerate: no part
  const auto parts = surface_parts(t);
  ASSERT_EQ(parts.size(), 3u);
  EXPECT_TRUE(parts[0].closed);
  EXPECT_TRUE(parts[1].closed);
  EXPECT_FALSE(parts[2].closed);
  EXPECT_EQ(parts[0].triangles.size(), 12u);
  EXPECT_EQ(parts[1].triangles.front(), 12u);
  EXPECT_EQ(parts[2].triangles, std::vector<std::uint32_t>{24});
  EXPECT_EQ(parts[1].box.min, Vec3(5, 0, 0));
  EXPECT_EQ(parts[1].box.max, Vec3(6, 2, 1));
}

TEST(SurfaceParts, AMissingTriangleOpensTheBox) {
  std::vector<Triangle> t;
  add_box(t, Vec3(0, 0, 0), Vec3(1, 1, 1));
  t.erase(t.begin() + 5);
  const auto parts = surface_parts(t);
  ASSERT_EQ(parts.size(), 1u);
  EXPECT_FALSE(parts[0].closed);
}

TEST(SurfaceParts, TwoBoxesSharingAnEdgeAreOnePartThatIsNotAManifold) {
  // Boxes touching along an edge: that edge has four triangles, so the part is not closed.
  std::vector<Triangle> t;
  add_box(t, Vec3(0, 0, 0), Vec3(1, 1, 1));
  add_box(t, Vec3(1, 1, 0), Vec3(2, 2, 1));
  const auto parts = surface_parts(t);
  ASSERT_EQ(parts.size(), 1u);
  EXPECT_FALSE(parts[0].closed);
}

TEST(InsideClosed, PointsInAndOutOfABox) {
  std::vector<Triangle> t;
  add_box(t, Vec3(0, 0, 0), Vec3(2, 2, 2));
  const auto part = surface_parts(t)[0].triangles;
  EXPECT_TRUE(inside_closed(t, part, Vec3(1, 1, 1)));
  EXPECT_TRUE(inside_closed(t, part, Vec3(0.001, 1.999, 0.5)));
  EXPECT_FALSE(inside_closed(t, part, Vec3(3, 1, 1)));
  EXPECT_FALSE(inside_closed(t, part, Vec3(-1e-3, 1, 1)));
  EXPECT_FALSE(inside_closed(t, part, Vec3(1, 1, 100)));
  // Rays through the box's edges and corners from a point on a diagonal still decide.
  EXPECT_TRUE(inside_closed(t, part, Vec3(1, 1, 1) + 1e-9 * Vec3(1, 1, 1)));
}

TEST(InsideClosed, AnInwardSurfaceHasItsSolidOutside) {
  // A room modelled from the inside: the normals point into it, so the solid is around it.
  const std::vector<Triangle> room = flipped([] {
    std::vector<Triangle> t;
    add_box(t, Vec3(-10, -10, -10), Vec3(10, 10, 10));
    return t;
  }());
  const auto part = surface_parts(room)[0].triangles;
  EXPECT_FALSE(inside_closed(room, part, Vec3(0, 0, 0)));
  EXPECT_FALSE(inside_closed(room, part, Vec3(9, -9, 3)));
}

}  // namespace
}  // namespace swept
