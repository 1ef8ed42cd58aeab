// Selective disassembly (DisassemblyOptions::targets, `swept disassemble --target`) on the
// built-in gearbox, whose answers follow from how it is built (scenes/gearbox.cpp): four screws
// hold the cover down; under the cover the upper bearing sits on the shaft above the gear, the
// lower bearing below it, all in the fixed housing, which leaves only the way up. So the cover
// needs the four screws off, the upper bearing the screws and the cover, the gear those and the
// upper bearing, the lower bearing everything. Every pull is re-checked by the independent
// sampled check against the parts still in place.
#include "assembly/assembly_support.h"
#include "swept/scenes/gearbox.h"

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
// not in the answer never move.
void expect_pulls_hold(const DisassemblyResult& r) {
  const Assembly& a = gearbox();
  std::vector<bool> gone(a.parts.size(), false);
  for (const SequenceStep& s : r.sequence) {
    ASSERT_TRUE(s.removed);
    ASSERT_EQ(s.parts.size(), 1u);
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

}  // namespace
}  // namespace swept
