// Selective disassembly (DisassemblyOptions::targets, `swept disassemble --target`) on the
// built-in gearbox, whose answers follow from how it is built (scenes/gearbox.cpp): four screws
// hold the cover down; under the cover the upper bearing sits on the shaft above the gear, the
// lower bearing below it, all in the fixed housing, which leaves only the way up. So the cover
// needs the four screws off, the upper bearing the screws and the cover, the gear those and the
// upper bearing, the lower bearing everything. Every pull is re-checked by the independent
// sampled check against the parts still in place.
#include "assembly/assembly_support.h"
#include "support/test_support.h"
#include "swept/scenes/gearbox.h"

#include <limits>
#include <set>

namespace swept {
namespace {

using namespace swept::test;

const Assembly& gearbox() {
  static const Assembly a = [] {
    const auto dir = std::filesystem::path(SWEPT_BINARY_DIR) / "tests_assembly_scratch" / "gearbox_target";
    std::filesystem::remove_all(dir);
    const auto report = scenes::generate_gearbox({.name = "gearbox", .scale = scenes::Scale::test, .output_dir = dir});
    EXPECT_TRUE(report.ok());
    auto read = read_assembly(report->problem_file);
    EXPECT_TRUE(read.ok());
    return std::move(*read);
  }();
  return a;
}

std::size_t index_of(const Assembly& a, const std::string& name) {
  const auto i = find_part(a, name);
  EXPECT_TRUE(i.ok()) << name;
  return *i;
}

std::set<std::string> removed_names(const Assembly& a, const DisassemblyResult& r) {
  std::set<std::string> out;
  for (const SequenceStep& s : r.sequence) out.insert(a.parts[s.parts[0]].name);
  return out;
}

DisassemblyResult take_out(const std::vector<std::string>& targets) {
  const Assembly& a = gearbox();
  DisassemblyOptions o{.clearance = 0.01, .tolerance = 0.2, .jobs = 2, .plan_time_limit = 0};
  for (const std::string& t : targets) o.targets.push_back(index_of(a, t));
  return disassemble(a, o);
}

// Every pull certified independently against what is still in place when it runs; the parts
// not in the answer never move. The sampled check in the release suite only (its brute force over
// the triangle pairs: about 6 s per answer here, 2 to 3 min under ASan); the sanitizers still run
// the disassembly and the checks of its steps.
void expect_pulls_hold(const DisassemblyResult& r, const Assembly& a = gearbox()) {
  std::vector<bool> gone(a.parts.size(), false);
  for (const SequenceStep& s : r.sequence) {
    ASSERT_TRUE(s.removed);
    ASSERT_EQ(s.parts.size(), 1u);
#if defined(__SANITIZE_ADDRESS__)
    continue;
#endif
    std::vector<std::size_t> staying;
    for (std::size_t i = 0; i < a.parts.size(); ++i)
      if (!gone[i] && i != s.parts[0]) staying.push_back(i);
    EXPECT_EQ(pull_violations(a, s.parts, staying, s.direction, s.distance, 0.01, r.tolerance, 4), 0)
        << a.parts[s.parts[0]].name;
    gone[s.parts[0]] = true;
  }
}

const std::set<std::string> kScrews{"screw-1", "screw-2", "screw-3", "screw-4"};

std::set<std::string> with(std::set<std::string> s, std::initializer_list<const char*> more) {
  for (const char* m : more) s.insert(m);
  return s;
}

TEST(Target, TheCoverNeedsItsFourScrewsOff) {
  const DisassemblyResult r = take_out({"cover"});
  ASSERT_TRUE(r.complete);
  EXPECT_TRUE(r.fewest);
  EXPECT_EQ(r.lower_bound, 5u);
  EXPECT_EQ(removed_names(gearbox(), r), with(kScrews, {"cover"}));
  EXPECT_EQ(gearbox().parts[r.sequence.back().parts[0]].name, "cover");  // the target last
  expect_pulls_hold(r);
}

TEST(Target, TheGearNeedsTheScrewsTheCoverAndTheUpperBearingOff) {
  const DisassemblyResult r = take_out({"gear"});
  ASSERT_TRUE(r.complete);
  EXPECT_TRUE(r.fewest);
  EXPECT_EQ(removed_names(gearbox(), r), with(kScrews, {"cover", "bearing-upper", "gear"}));
  expect_pulls_hold(r);
  // Why: the gear first, then each part taken off for it, with its directions and blockers; up
  // (a pull out of the whole assembly's box), by the upper bearing and the cover above it.
  ASSERT_EQ(r.why.size(), r.sequence.size());
  EXPECT_EQ(gearbox().parts[r.why[0].parts[0]].name, "gear");
  bool up = false;
  for (const auto& b : r.why[0].blocking)
    if (b.direction.isApprox(Vec3::UnitZ())) {
      up = true;
      std::set<std::string> names;
      for (std::size_t q : b.blockers) names.insert(gearbox().parts[q].name);
      EXPECT_EQ(names, (std::set<std::string>{"bearing-upper", "cover"}));
    }
  EXPECT_TRUE(up);
}

TEST(Target, TheLowerBearingNeedsEverything) {
  const DisassemblyResult r = take_out({"bearing-lower"});
  ASSERT_TRUE(r.complete);
  EXPECT_TRUE(r.fewest);
  EXPECT_EQ(r.sequence.size(), 9u);  // every part but the housing
  expect_pulls_hold(r);
}

TEST(Target, SeveralTargetsShareTheirRemovals) {
  const DisassemblyResult r = take_out({"cover", "screw-2"});
  ASSERT_TRUE(r.complete);
  EXPECT_TRUE(r.fewest);
  EXPECT_EQ(removed_names(gearbox(), r), with(kScrews, {"cover"}));
  expect_pulls_hold(r);
}

TEST(Target, AScrewNeedsNothingOff) {
  const DisassemblyResult r = take_out({"screw-3"});
  ASSERT_TRUE(r.complete);
  ASSERT_EQ(r.sequence.size(), 1u);
  EXPECT_TRUE(r.sequence[0].direction.isApprox(Vec3::UnitZ()));
}

TEST(Target, PastTheSearchLimitAGreedyAnswerNotProvedTheFewest) {
  const Assembly& a = gearbox();
  DisassemblyOptions o{.clearance = 0.01, .tolerance = 0.2, .jobs = 2, .plan_time_limit = 0};
  o.targets = {index_of(a, "gear")};
  o.target_states = 3;
  const DisassemblyResult r = disassemble(a, o);
  ASSERT_TRUE(r.complete);
  EXPECT_FALSE(r.fewest);
  EXPECT_LE(r.lower_bound, r.sequence.size());
  EXPECT_EQ(removed_names(a, r), with(kScrews, {"cover", "bearing-upper", "gear"}));
  expect_pulls_hold(r);
}

TEST(Target, AShutInTargetStaysWithItsBlockers) {
  // The housing and the cover fixed: the gear cannot come out at all.
  const Assembly& a = gearbox();
  DisassemblyOptions o{.clearance = 0.01, .tolerance = 0.2, .jobs = 2, .plan_time_limit = 0};
  o.fixed = std::vector<std::size_t>{index_of(a, "housing"), index_of(a, "cover")};
  o.targets = {index_of(a, "gear")};
  const DisassemblyResult r = disassemble(a, o);
  EXPECT_FALSE(r.complete);
  EXPECT_TRUE(r.sequence.empty());
  ASSERT_FALSE(r.why.empty());
  std::set<std::string> blockers;
  for (const auto& b : r.why[0].blocking)
    for (std::size_t q : b.blockers) blockers.insert(a.parts[q].name);
  EXPECT_TRUE(blockers.count("bearing-upper") || blockers.count("cover")) << "the way up is named";
}

// The shared as1 STEP (AP214's test assembly): a plate (the base), two L-brackets each held down
// by three bolts through bracket and plate with a nut under the plate, and a rod through both
// brackets with a nut on each end. Without threads in the geometry a shaft slides out of its nut:
// a bolt leaves upwards and the rod along its axis with the nuts in place. So, from the parts'
// boxes alone (not from swept's blocking): a bracket needs off the bolts whose shafts go through
// it (their boxes cross the bracket's) and one of what holds it on the rod's axis (the rod, or
// the nut at that end): five removals with itself; a bolt under the rod (its box, swept upwards,
// crosses the rod's) needs the rod off; the other bolts and the rod need nothing.
Aabb box_of(const AssemblyPart& p) {
  Aabb b;
  for (const Triangle& t : p.mesh.triangles)
    for (int k = 0; k < 3; ++k) b.extend(t[k]);
  return b;
}

bool boxes_cross(const Aabb& a, const Aabb& b) {
  return (a.min.array() < b.max.array()).all() && (b.min.array() < a.max.array()).all();
}

std::vector<std::string> named(const Assembly& a, const std::string& prefix) {
  std::vector<std::string> out;
  for (const AssemblyPart& p : a.parts)
    if (p.name == prefix || p.name.starts_with(prefix + "#")) out.push_back(p.name);
  return out;
}

DisassemblyResult take_out_of(const Assembly& a, const std::string& target) {
  DisassemblyOptions o{.clearance = 0.01, .tolerance = 0.2, .jobs = 2, .plan_time_limit = 0};
  o.targets = {index_of(a, target)};
  return disassemble(a, o);
}

TEST(Target, As1BracketsNeedTheirBoltsAndTheRodsWayOff) {
  std::string why;
  const auto a = read_as1(why);
  if (!a) GTEST_SKIP() << why;
  ASSERT_EQ(named(*a, "l-bracket").size(), 2u);
  ASSERT_EQ(named(*a, "bolt").size(), 6u);
  ASSERT_EQ(named(*a, "nut").size(), 8u);
  const Aabb rod = box_of(a->parts[index_of(*a, "rod")]);
  for (const std::string& bracket : named(*a, "l-bracket")) {
    const Aabb b = box_of(a->parts[index_of(*a, bracket)]);
    std::set<std::string> bolts;
    for (const std::string& bolt : named(*a, "bolt"))
      if (boxes_cross(b, box_of(a->parts[index_of(*a, bolt)]))) bolts.insert(bolt);
    ASSERT_EQ(bolts.size(), 3u) << bracket;
    ASSERT_TRUE(boxes_cross(b, rod)) << "the rod goes through " << bracket;
    const DisassemblyResult r = take_out_of(*a, bracket);
    ASSERT_TRUE(r.complete) << bracket;
    EXPECT_TRUE(r.fewest);
    ASSERT_EQ(r.sequence.size(), 5u) << bracket;
    std::set<std::string> removed = removed_names(*a, r);
    for (const std::string& bolt : bolts) EXPECT_EQ(removed.count(bolt), 1u) << bolt << " for " << bracket;
    EXPECT_EQ(a->parts[r.sequence.back().parts[0]].name, bracket);  // the target last
    // The fifth: the rod, or a nut on the rod's axis (its box crosses the rod's).
    for (const std::string& bolt : bolts) removed.erase(bolt);
    removed.erase(bracket);
    ASSERT_EQ(removed.size(), 1u);
    const std::string fifth = *removed.begin();
    EXPECT_TRUE(fifth == "rod" || (fifth.starts_with("nut") && boxes_cross(rod, box_of(a->parts[index_of(*a, fifth)]))))
        << fifth;
    expect_pulls_hold(r, *a);
  }
}

TEST(Target, As1BoltsAndTheRodNeedOnlyWhatIsAboveThem) {
  std::string why;
  const auto a = read_as1(why);
  if (!a) GTEST_SKIP() << why;
  const Aabb rod = box_of(a->parts[index_of(*a, "rod")]);
  const DisassemblyResult r = take_out_of(*a, "rod");
  ASSERT_TRUE(r.complete);
  EXPECT_EQ(removed_names(*a, r), std::set<std::string>{"rod"});
  expect_pulls_hold(r, *a);
  std::size_t under = 0;
  for (const std::string& bolt : named(*a, "bolt")) {
    Aabb above = box_of(a->parts[index_of(*a, bolt)]);  // what the bolt sweeps going up
    above.max.z() = std::numeric_limits<double>::max();
    const bool under_rod = boxes_cross(rod, above);
    under += under_rod ? 1 : 0;
    const DisassemblyResult b = take_out_of(*a, bolt);
    ASSERT_TRUE(b.complete) << bolt;
    EXPECT_TRUE(b.fewest);
    const std::set<std::string> expected = under_rod ? std::set<std::string>{"rod", bolt} : std::set<std::string>{bolt};
    EXPECT_EQ(removed_names(*a, b), expected) << bolt;
    EXPECT_TRUE(b.sequence.back().direction.isApprox(Vec3::UnitZ())) << bolt << ": a bolt leaves upwards";
    expect_pulls_hold(b, *a);
  }
  EXPECT_GE(under, 1u);
}

}  // namespace
}  // namespace swept
