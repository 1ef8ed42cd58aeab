// The containment invariant on the real CAD of ../shared/data, for every fitter and split rule.
#include "support/tables.h"
#include "support/test_support.h"
#include "swept/bvh/bvh.h"
#include "swept/io/mesh_io.h"

#include <gtest/gtest.h>

#include <functional>

namespace swept {
namespace {

std::size_t count_outside(const Bvh& bvh, double& worst) {
  const double tol = 1e-9 * bvh.extent;
  std::size_t bad = 0;
  worst = -1e300;
  // Walk down with the chain of ancestors: each vertex of a leaf is tested against every RSS on
  // the way from the root.
  std::vector<int> chain;
  std::function<void(int)> walk = [&](int i) {
    chain.push_back(i);
    const Node& n = bvh.nodes[static_cast<std::size_t>(i)];
    if (n.is_leaf()) {
      for (int t = n.first; t < n.first + n.count; ++t)
        for (int v = 0; v < 3; ++v)
          for (int a : chain) {
            const double d = signed_distance(bvh.bv(static_cast<std::size_t>(a)), bvh.triangles[static_cast<std::size_t>(t)][v]);
            worst = std::max(worst, d / bvh.extent);
            bad += d > tol ? 1 : 0;
          }
    } else {
      walk(n.first);
      walk(n.first + 1);
    }
    chain.pop_back();
  };
  walk(0);
  return bad;
}

TEST(CadContainment, EveryVertexInsideLeafAndAncestors) {
  const auto data = test::shared_data();
  if (!data) GTEST_SKIP() << "../shared/data is absent: CAD containment not checked";
  const char* files[] = {"ros_industrial/kuka_kr10r1420_visual_link_2.stl", "occt/motor.stl",
                         "tessellated/as1_d0.01/as1_p10_plate.stl", "tessellated/engine_d0.05/engine_p01_CylinderHead_rle_brep.stl",
                         "nist/nist_ftc_11_asme1_rb.stp"};
  for (const char* f : files) {
    ImportOptions options;
    options.linear_deflection = 0.05;
    auto model = import_mesh(*data / f, options);
    ASSERT_TRUE(model) << model.error().message;
    const auto tris = model->merged().triangles;
    for (Fitter fitter : swept::test::every_fitter())
      for (SplitRule split : swept::test::every_split_rule()) {
        auto bvh = build_bvh(tris, {.fitter = fitter, .split = split});
        ASSERT_TRUE(bvh) << f << ": " << bvh.error().message;
        double worst;
        EXPECT_EQ(count_outside(*bvh, worst), 0u)
            << f << " " << to_string(fitter) << "/" << to_string(split) << ": worst excess " << worst << " × extent";
      }
  }
}

}  // namespace
}  // namespace swept
