// The mate rule (contact.h) on contacts whose freedom is known by hand, and the interference
// report at the mounted poses.
#include "assembly/assembly_support.h"

#include <bit>

namespace swept {
namespace {

using namespace swept::test;

bool allows(const Triangle& o, const Triangle& p, const Vec3& d, double length, double tol) {
  return mate_allows(o, plane_of(o), p, plane_of(p), d, length, tol);
}

TEST(Mate, PlanarFacesSeparateAndSlideButNeverPress) {
  // A floor triangle (normal +z) and the bottom of a part resting on it (normal −z).
  const Triangle floor{Vec3(-10, -10, 0), Vec3(10, -10, 0), Vec3(0, 10, 0)};
  const Triangle bottom{Vec3(-1, -1, 0), Vec3(0, 1, 0), Vec3(1, -1, 0)};
  ASSERT_GT(plane_of(floor).normal.z(), 0.99);
  ASSERT_LT(plane_of(bottom).normal.z(), -0.99);
  EXPECT_TRUE(allows(floor, bottom, Vec3::UnitZ(), 50, 0.01));   // lifted off
  EXPECT_TRUE(allows(floor, bottom, Vec3::UnitX(), 50, 0.01));   // slid along
  EXPECT_TRUE(allows(floor, bottom, Vec3(1, 0, 1).normalized(), 50, 0.01));
  EXPECT_FALSE(allows(floor, bottom, -Vec3::UnitZ(), 50, 0.01)); // pressed into it
  // Pressed by less than the tolerance over the whole pull: still within the mate.
  EXPECT_TRUE(allows(floor, bottom, Vec3(1, 0, -1e-4).normalized(), 50, 0.01));
  EXPECT_FALSE(allows(floor, bottom, Vec3(1, 0, -1e-3).normalized(), 50, 0.01));
}

TEST(Mate, AFaceFarBehindIsNoMate) {
  // The flange's top (z = 7, normal +z) and a cover's bottom (z = 0): 7 apart through material.
  const Triangle flange_top{Vec3(-8, -8, 7), Vec3(8, -8, 7), Vec3(0, 8, 7)};
  const Triangle cover_bottom{Vec3(-1, -1, 0), Vec3(0, 1, 0), Vec3(1, -1, 0)};
  EXPECT_FALSE(allows(flange_top, cover_bottom, Vec3::UnitZ(), 56, 0.2));
  EXPECT_FALSE(allows(flange_top, cover_bottom, Vec3::UnitX(), 56, 0.2));
}

TEST(Mate, ShaftInABoreSlidesAlongTheAxisOnly) {
  // A 24-gon shaft and a bore of 16 segments on the same circle (radius 3): their chords cross
  // by up to the sag 3·(1 − cos(π/16)) ≈ 0.058. Every pair that touches may slide along the axis
  // (the rim of the bore past the shaft's facets too), none may move sideways.
  std::vector<Triangle> shaft, ring;
  add_prism(shaft, 3, 24, 0, 10);
  add_ring(ring, 3, 10, 16, 0, 10);
  const auto ps = part_planes(shaft), pr = part_planes(ring);
  const double tol = 0.2, threshold = 0.21;
  int touching = 0, sideways_allowed_all = 0;
  for (std::size_t i = 0; i < ring.size(); ++i)
    for (std::size_t j = 0; j < shaft.size(); ++j) {
      if (triangle_distance(ring[i], shaft[j]).distance >= threshold) continue;
      ++touching;
      EXPECT_TRUE(mate_allows(ring[i], pr[i], shaft[j], ps[j], Vec3::UnitZ(), 30, tol)) << i << " " << j;
      EXPECT_TRUE(mate_allows(ring[i], pr[i], shaft[j], ps[j], -Vec3::UnitZ(), 30, tol)) << i << " " << j;
    }
  EXPECT_GT(touching, 0);
  // Sideways: for any direction across the axis, some touching pair refuses.
  for (int k = 0; k < 8; ++k) {
    const Vec3 d = on_circle(1, k, 8, 0);
    bool refused = false;
    for (std::size_t i = 0; i < ring.size(); ++i)
      for (std::size_t j = 0; j < shaft.size(); ++j)
        if (triangle_distance(ring[i], shaft[j]).distance < threshold &&
            !mate_allows(ring[i], pr[i], shaft[j], ps[j], d, 30, tol))
          refused = true;
    EXPECT_TRUE(refused) << "direction " << k;
    sideways_allowed_all += !refused;
  }
  EXPECT_EQ(sideways_allowed_all, 0);
}

TEST(Mate, CreasesAreFaceBoundariesNotDiagonals) {
  // A box: 12 triangles, 18 edges of which 12 are the box's (convex creases) and 6 the faces'
  // diagonals. Each triangle has two crease edges and one diagonal.
  std::vector<Triangle> box;
  scenes::add_box(box, Vec3(0, 0, 0), Vec3(1, 2, 3));
  for (const TrianglePlane& p : part_planes(box)) EXPECT_EQ(std::popcount(static_cast<unsigned>(p.creases)), 2);
  // A ring's bore: the first bore triangle of each segment is (i0, j1, j0). Its edge i0 → j1 is
  // the facet's diagonal, j1 → j0 the concave edge between two bore facets, j0 → i0 the convex
  // rim with the bottom face: one crease.
  std::vector<Triangle> ring;
  add_ring(ring, 3, 10, 16, 0, 10);
  const auto planes = part_planes(ring);
  for (std::size_t i = 2; i < ring.size(); i += 8) EXPECT_EQ(planes[i].creases, 0b100) << i;
}

TEST(Interference, ATessellatedShaftInItsBoreIsNone) {
  Assembly a;
  std::vector<Triangle> shaft, ring;
  add_prism(shaft, 3, 24, -2, 12);
  add_ring(ring, 3, 10, 16, 0, 10);
  a.parts = {part("ring", ring), part("shaft", shaft)};
  EXPECT_TRUE(find_interferences(a, 0.2).empty());
  // With a tolerance below the sag, the crossing facets are reported.
  const auto tight = find_interferences(a, 0.01);
  ASSERT_EQ(tight.size(), 1u);
  EXPECT_GT(tight[0].depth, 0.01);
  EXPECT_LT(tight[0].depth, 0.06);
}

TEST(Interference, APinPushedIntoAWallIsReportedWithItsDepth) {
  // A pin (radius 1) whose end is 2 deep inside a wall [-10, 10]² × [0, 5] (top at z = 5).
  Assembly a;
  std::vector<Triangle> wall, pin;
  scenes::add_box(wall, Vec3(-10, -10, 0), Vec3(10, 10, 5));
  add_prism(pin, 1, 12, 3, 20);
  a.parts = {part("wall", wall), part("pin", pin)};
  const auto f = find_interferences(a, 0.2);
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f[0].part_a, 0u);
  EXPECT_EQ(f[0].part_b, 1u);
  EXPECT_GT(f[0].depth, 1.9);  // 2, or the far side of the pin seen from a facet's plane
  EXPECT_LE(f[0].depth, 2.0 + 1e-9);
  EXPECT_GT(f[0].extent, 1.5);   // the pin's circle where it crosses the top face
  EXPECT_LT(f[0].extent, 3.0);
}

}  // namespace
}  // namespace swept
