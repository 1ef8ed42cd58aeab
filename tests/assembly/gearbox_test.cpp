// The built-in gearbox (swept scene gearbox, scenes/gearbox.cpp) comes apart in the order its
// construction dictates: every screw before the cover, the cover before the upper bearing, the
// gear and the shaft, the upper bearing before the gear, the gear before the shaft, the shaft
// before the lower bearing; every pull re-checked by the independent sampled check.
#include "assembly/assembly_support.h"
#include "swept/scenes/gearbox.h"

#include <map>

namespace swept {
namespace {

using namespace swept::test;

TEST(Gearbox, ComesApartInItsKnownOrder) {
  const auto dir = std::filesystem::path(SWEPT_BINARY_DIR) / "tests_assembly_scratch" / "gearbox";
  std::filesystem::remove_all(dir);
  const auto report = scenes::generate_gearbox({.name = "gearbox", .scale = scenes::Scale::test, .output_dir = dir});
  ASSERT_TRUE(report.ok()) << report.error().message;
  EXPECT_LT(report->obstacle_triangles, 30000u);
  const auto a = read_assembly(report->problem_file);
  ASSERT_TRUE(a.ok()) << a.error().message;
  ASSERT_EQ(a->parts.size(), 10u);
  EXPECT_TRUE(a->parts[0].fixed);  // the housing, from assembly.toml
  const DisassemblyResult r = disassemble(*a, {.clearance = 0.01, .tolerance = 0.2, .jobs = 2, .plan_time_limit = 0});
  EXPECT_TRUE(r.interferences.empty());
  ASSERT_TRUE(r.complete);
  std::map<std::string, std::size_t> when;
  for (std::size_t k = 0; k < r.sequence.size(); ++k) {
    ASSERT_EQ(r.sequence[k].parts.size(), 1u);
    when[a->parts[r.sequence[k].parts[0]].name] = k;
  }
  ASSERT_EQ(when.size(), 9u);
  for (const char* screw : {"screw-1", "screw-2", "screw-3", "screw-4"}) EXPECT_LT(when[screw], when["cover"]) << screw;
  EXPECT_LT(when["cover"], when["bearing-upper"]);
  EXPECT_LT(when["bearing-upper"], when["gear"]);
  EXPECT_LT(when["gear"], when["shaft"]);
  EXPECT_LT(when["shaft"], when["bearing-lower"]);
  // Every removal is a straight pull along the shaft's axis, up.
  for (const SequenceStep& s : r.sequence) EXPECT_TRUE(s.direction.isApprox(Vec3::UnitZ())) << s.direction.transpose();
  // The independent check, pull by pull, against what was still in place (in the release suite
  // only: its brute force takes minutes under ASan, which still runs the disassembly).
#if !defined(__SANITIZE_ADDRESS__)
  std::vector<bool> gone(a->parts.size(), false);
  for (const SequenceStep& s : r.sequence) {
    std::vector<std::size_t> staying;
    for (std::size_t i = 0; i < a->parts.size(); ++i)
      if (!gone[i] && i != s.parts[0]) staying.push_back(i);
    EXPECT_EQ(pull_violations(*a, s.parts, staying, s.direction, s.distance, 0.01, r.tolerance, 4), 0)
        << a->parts[s.parts[0]].name;
    gone[s.parts[0]] = true;
  }
#endif
}

}  // namespace
}  // namespace swept
