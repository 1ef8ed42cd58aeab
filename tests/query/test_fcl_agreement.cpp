// Agreement with FCL 0.7 (OBBRSS trees, exact distance) on the shared CAD meshes: the largest
// relative distance difference must stay below 1e-9 at near-contact and far poses.
#include "swept/io/mesh_io.h"
#include "swept/query/query.h"

#include "support/test_support.h"

#include <gtest/gtest.h>

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/math/bv/OBBRSS.h>
#include <fcl/narrowphase/distance.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace swept {
namespace {

using test::Rng;

std::shared_ptr<fcl::BVHModel<fcl::OBBRSSd>> fcl_model(const std::vector<Triangle>& tris) {
  auto m = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
  std::vector<fcl::Vector3d> v;
  std::vector<fcl::Triangle> f;
  for (const Triangle& t : tris) {
    const std::size_t base = v.size();
    v.push_back(t.p);
    v.push_back(t.q);
    v.push_back(t.r);
    f.emplace_back(base, base + 1, base + 2);
  }
  m->beginModel();
  m->addSubModel(v, f);
  m->endModel();
  return m;
}

double fcl_distance(const fcl::CollisionGeometryd* a, const fcl::CollisionGeometryd* b, const Pose& pb) {
  fcl::Transform3d tb = fcl::Transform3d::Identity();
  tb.linear() = pb.rotation;
  tb.translation() = pb.translation;
  fcl::DistanceRequestd req;
  req.enable_nearest_points = true;
  fcl::DistanceResultd res;
  fcl::distance(a, fcl::Transform3d::Identity(), b, tb, req, res);
  return res.min_distance;
}

std::vector<Triangle> load(const std::filesystem::path& p) {
  Result<ImportedModel> m = import_mesh(p);
  EXPECT_TRUE(m.ok()) << p;
  return m ? m->merged().triangles : std::vector<Triangle>{};
}

TEST(FclAgreement, DistanceMatchesFclOnCadMeshes) {
  const auto data = test::shared_data();
  if (!data) GTEST_SKIP() << "shared CAD data folder is absent";
  const std::vector<std::pair<std::string, std::string>> pairs = {
      {"ros_industrial/kuka_kr10r1420_visual_link_2.stl", "ros_industrial/kuka_kr10r1420_visual_link_3.stl"},
      {"ros_industrial/kuka_kr10r1420_visual_base_link.stl", "ros_industrial/kuka_kr10r1420_visual_link_1.stl"},
      {"tessellated/engine_d0.05/engine_p02_Piston_rle_brep.stl", "tessellated/engine_d0.05/engine_p03_CrankArm_rle_brep_s0.stl"},
      {"occt/motor.stl", "occt/motor.stl"},
  };
  Rng rng(31);
  double worst = 0.0;
  int compared = 0;
  for (const auto& [fa, fb] : pairs) {
    if (!std::filesystem::exists(*data / fa) || !std::filesystem::exists(*data / fb)) continue;
    const std::vector<Triangle> ta = load(*data / fa), tb = load(*data / fb);
    ASSERT_FALSE(ta.empty());
    ASSERT_FALSE(tb.empty());
    const Bvh a = build_bvh(ta).value();
    const Bvh b = build_bvh(tb).value();
    const auto ma = fcl_model(ta), mb = fcl_model(tb);
    const Vec3 ca = bounds(ta).center(), cb = bounds(tb).center();
    const double size = std::max(a.extent, b.extent);
    auto place = [&](const Mat3& r, const Vec3& off) { return Pose{r, ca + off - r * cb}; };
    for (int k = 0; k < 12; ++k) {
      const Mat3 r = rng.rotation();
      const Vec3 u = rng.vec(-1, 1).normalized();
      // Near contact: bisect the offset until 0 < distance ≤ 1% of the size; far: 1.5 sizes.
      auto dist = [&](double s) { return distance(a, Pose::identity(), b, place(r, s * u)).distance; };
      double lo = 0, hi = size;
      while (dist(hi) <= 0.01 * size) hi *= 2;
      double s = hi;
      for (int it = 0; it < 60; ++it) {
        const double mid = 0.5 * (lo + hi), d = dist(mid);
        if (d <= 0.0) {
          lo = mid;
        } else {
          hi = mid;
          s = mid;
          if (d <= 0.01 * size) break;
        }
      }
      for (const double off : {s, 1.5 * size}) {
        const Pose pb = place(r, off * u);
        const double ours = distance(a, Pose::identity(), b, pb).distance;
        const double theirs = fcl_distance(ma.get(), mb.get(), pb);
        ASSERT_GT(ours, 0.0);
        const double rel = std::abs(ours - theirs) / std::max(theirs, 1e-300);
        worst = std::max(worst, rel);
        ++compared;
        EXPECT_LE(rel, 1e-9) << fa << " vs " << fb << ": swept " << ours << ", FCL " << theirs;
      }
    }
  }
  std::printf("compared %d distances with FCL OBBRSS: largest relative difference %.3g\n", compared, worst);
  EXPECT_GT(compared, 0);
}

}  // namespace
}  // namespace swept
