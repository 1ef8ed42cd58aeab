// Disassembly sequences with known answers (disassemble.h): a bolted ring comes apart bolt first;
// riveted plates do not, and the blockers are named; every straight pull is re-checked by the
// independent sampled check of assembly_support.h; the result is the same at any job count; the
// shared as1 STEP comes apart completely.
#include "assembly/assembly_support.h"
#include "support/test_support.h"

#include <chrono>
#include <iostream>
#include <optional>
#include <set>

namespace swept {
namespace {

using namespace swept::test;

std::vector<std::string> names(const Assembly& a, const std::vector<std::size_t>& parts) {
  std::vector<std::string> out;
  for (std::size_t i : parts) out.push_back(a.parts[i].name);
  return out;
}

// Every removal by a straight pull, checked against the parts still in place at its round (with
// the mate rule's cases 1–3 at `tolerance`, by default the one the sequence used).
void check_pulls_independently(const Assembly& a, const DisassemblyResult& r, double clearance, int samples,
                               std::optional<double> tolerance = std::nullopt) {
  std::set<std::size_t> gone;
  for (const SequenceStep& s : r.sequence) {
    if (!s.removed) break;
    std::vector<std::size_t> staying;
    for (std::size_t i = 0; i < a.parts.size(); ++i)
      if (!gone.count(i) && std::find(s.parts.begin(), s.parts.end(), i) == s.parts.end()) staying.push_back(i);
    if (s.method == RemovalMethod::pull) {
      EXPECT_EQ(pull_violations(a, s.parts, staying, s.direction, s.distance, clearance, tolerance.value_or(r.tolerance),
                                samples),
                0)
          << "the pull of " << names(a, s.parts)[0] << " passes through material";
    }
    gone.insert(s.parts.begin(), s.parts.end());
  }
}

TEST(Sequence, BoltedRingComesApartBoltFirst) {
  const Assembly a = bolted_ring();
  const DisassemblyOptions options{.clearance = 0.01, .tolerance = 0.2, .plan_time_limit = 0};
  const DisassemblyResult r = disassemble(a, options);
  EXPECT_TRUE(r.interferences.empty());
  ASSERT_TRUE(r.complete);
  EXPECT_EQ(r.fixed, std::vector<std::size_t>{0});  // the base: the largest box
  ASSERT_EQ(r.sequence.size(), 2u);
  EXPECT_EQ(r.sequence[0].parts, std::vector<std::size_t>{2});  // the bolt ...
  EXPECT_EQ(r.sequence[0].method, RemovalMethod::pull);
  EXPECT_TRUE(r.sequence[0].direction.isApprox(Vec3::UnitZ()));  // ... along its axis, up
  EXPECT_EQ(r.sequence[1].parts, std::vector<std::size_t>{1});  // then the ring
  EXPECT_TRUE(r.sequence[1].direction.isApprox(Vec3::UnitZ()));
  // The bolt leaves the ring's box: it travels at least the ring's height plus its own.
  EXPECT_GT(r.sequence[0].distance, 10.0);
  check_pulls_independently(a, r, options.clearance, 40);
}

TEST(Sequence, TheOldRuleWouldPullTheRingThroughTheBoltHead) {
  // The ring is not free while the bolt is in: pulling it up (+z) presses its top into the bolt's
  // head, which the independent check sees as pairs through material; the sequence never does it.
  const Assembly a = bolted_ring();
  EXPECT_GT(pull_violations(a, {1}, {0, 2}, Vec3::UnitZ(), 25.0, 0.01, 0.2, 40), 0);
}

// A box whose faces are each meshed as an n × n grid (2n² triangles, outward), vertices shared
// exactly along the box's edges: a large planar contact of many coplanar facets.
std::vector<Triangle> fine_box(const Vec3& lo, const Vec3& hi, int n) {
  std::vector<Triangle> out;
  auto at = [&](int axis, int i) { return lo[axis] + (hi[axis] - lo[axis]) * i / n; };
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      Vec3 outward = Vec3::Zero();
      outward[axis] = side ? 1.0 : -1.0;
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          auto corner = [&](int di, int dj) {
            Vec3 x;
            x[axis] = side ? hi[axis] : lo[axis];
            x[u] = at(u, i + di);
            x[v] = at(v, j + dj);
            return x;
          };
          for (Triangle t : {Triangle{corner(0, 0), corner(1, 0), corner(1, 1)}, Triangle{corner(0, 0), corner(1, 1), corner(0, 1)}}) {
            if ((t.q - t.p).cross(t.r - t.p).dot(outward) < 0) std::swap(t.q, t.r);
            out.push_back(t);
          }
        }
    }
  return out;
}

TEST(Sequence, APlateSlidesOutAlongItsFinelyMeshedBase) {
  // A plate lies face to face on a base (both faces meshed fine), under a roof 0.5 above it, with
  // a fence 5 in front of it (+x): up is the roof, down the base, +x the fence; it can only slide
  // out along −x, over the whole length of the base's top, every facet pair of the two faces at 0.
  Assembly a;
  a.source = "sliding_plate";
  a.parts = {part("base", fine_box(Vec3(0, 0, 0), Vec3(100, 100, 10), 6), true),
             part("plate", fine_box(Vec3(30, 30, 10), Vec3(50, 50, 15), 6)),
             part("roof", fine_box(Vec3(20, 20, 15.5), Vec3(60, 60, 20), 2), true),
             part("fence", fine_box(Vec3(55, 20, 10), Vec3(60, 60, 15), 2), true)};
  const DisassemblyOptions options{.clearance = 0.01, .tolerance = 0.2, .plan_time_limit = 0};
  const DisassemblyResult r = disassemble(a, options);
  EXPECT_TRUE(r.interferences.empty());
  ASSERT_TRUE(r.complete);
  ASSERT_EQ(r.sequence.size(), 1u);
  EXPECT_EQ(r.sequence[0].parts, std::vector<std::size_t>{1});
  EXPECT_EQ(r.sequence[0].method, RemovalMethod::pull);
  EXPECT_TRUE(r.sequence[0].direction.isApprox(-Vec3::UnitX())) << r.sequence[0].direction.transpose();
  EXPECT_GT(r.sequence[0].distance, 50.0);  // past the base's far edge
  check_pulls_independently(a, r, options.clearance, 20);
  // And the pulls it rejected do pass through material (the independent check says so).
  EXPECT_GT(pull_violations(a, {1}, {0, 2, 3}, Vec3::UnitZ(), 10.0, 0.01, 0.2, 20), 0);
  EXPECT_GT(pull_violations(a, {1}, {0, 2, 3}, -Vec3::UnitZ(), 10.0, 0.01, 0.2, 20), 0);
  EXPECT_GT(pull_violations(a, {1}, {0, 2, 3}, Vec3::UnitX(), 60.0, 0.01, 0.2, 20), 0);
}

TEST(Sequence, APlateOnAnOpenSheetDoesNotPressThroughIt) {
  // The same with the base reduced to its top face, an open sheet: nothing behind it would stop
  // a plate pressed down through it, so only the mate rule on the facing facets does (a face may
  // slide along or leave another, never press into it).
  std::vector<Triangle> sheet;
  for (const Triangle& t : fine_box(Vec3(0, 0, 0), Vec3(100, 100, 10), 6))
    if (t.p.z() == 10 && t.q.z() == 10 && t.r.z() == 10) sheet.push_back(t);
  ASSERT_EQ(sheet.size(), 72u);
  Assembly a;
  a.source = "plate_on_a_sheet";
  a.parts = {part("sheet", sheet, true), part("plate", fine_box(Vec3(30, 30, 10), Vec3(50, 50, 15), 6)),
             part("roof", fine_box(Vec3(20, 20, 15.5), Vec3(60, 60, 20), 2), true),
             part("fence", fine_box(Vec3(55, 20, 10), Vec3(60, 60, 15), 2), true)};
  const DisassemblyOptions options{.clearance = 0.01, .tolerance = 0.2, .plan_time_limit = 0};
  const DisassemblyResult r = disassemble(a, options);
  ASSERT_TRUE(r.complete);
  ASSERT_EQ(r.sequence.size(), 1u);
  EXPECT_TRUE(r.sequence[0].direction.isApprox(-Vec3::UnitX())) << r.sequence[0].direction.transpose();
  check_pulls_independently(a, r, options.clearance, 20);
  EXPECT_GT(pull_violations(a, {1}, {0, 2, 3}, -Vec3::UnitZ(), 10.0, 0.01, 0.2, 20), 0);
}

TEST(Sequence, RivetedPlatesAreReportedWithTheirBlockers) {
  const Assembly a = riveted_plates();
  const DisassemblyOptions options{.clearance = 0.01, .tolerance = 0.2, .plan_time_limit = 0.5};
  const DisassemblyResult r = disassemble(a, options);
  EXPECT_TRUE(r.interferences.empty());
  EXPECT_FALSE(r.complete);
  EXPECT_EQ(r.fixed, std::vector<std::size_t>{0});  // plate A is the largest
  ASSERT_EQ(r.sequence.size(), 2u);
  for (const SequenceStep& s : r.sequence) EXPECT_FALSE(s.removed);
  // Plate B: up, the rivet's head; down, plate A (and the rivet's shank sideways).
  const SequenceStep& b = r.sequence[0];
  ASSERT_EQ(b.parts, std::vector<std::size_t>{1});
  ASSERT_GE(b.blocking.size(), 6u);
  EXPECT_EQ(b.blocking[0].direction, Vec3::UnitZ());
  EXPECT_EQ(b.blocking[0].blockers, std::vector<std::size_t>{2});
  EXPECT_EQ(b.blocking[1].direction, -Vec3::UnitZ());
  EXPECT_EQ(b.blocking[1].blockers, (std::vector<std::size_t>{0, 2}));
  for (std::size_t k = 2; k < 6; ++k) EXPECT_EQ(b.blocking[k].blockers, std::vector<std::size_t>{2}) << k;
  // The rivet: held by both plates along every axis (up, its lower head meets A, and B above it;
  // down, its upper head meets B, and A below it; sideways, both bores).
  const SequenceStep& rivet = r.sequence[1];
  ASSERT_EQ(rivet.parts, std::vector<std::size_t>{2});
  ASSERT_GE(rivet.blocking.size(), 6u);
  for (std::size_t k = 0; k < 6; ++k) EXPECT_EQ(rivet.blocking[k].blockers, (std::vector<std::size_t>{0, 1})) << k;
}

// A closed room (floor, ceiling, four walls) with a window in the +x wall at z ∈ [8, 19], and
// a block resting on the floor: every straight pull hits a wall, the floor or the ceiling; the
// planner lifts it to the window and out.
Assembly block_in_a_room() {
  Assembly a;
  std::vector<Triangle> room, block;
  scenes::add_box(room, Vec3(-22, -22, -2), Vec3(22, 22, 0));   // floor
  scenes::add_box(room, Vec3(-22, -22, 20), Vec3(22, 22, 22));  // ceiling
  scenes::add_box(room, Vec3(-22, -22, 0), Vec3(-20, 22, 20));  // -x wall
  scenes::add_box(room, Vec3(-20, -22, 0), Vec3(20, -20, 20));  // -y wall
  scenes::add_box(room, Vec3(-20, 20, 0), Vec3(20, 22, 20));    // +y wall
  scenes::add_box(room, Vec3(20, -22, 0), Vec3(22, 22, 8));     // +x wall under the window
  scenes::add_box(room, Vec3(20, -22, 19), Vec3(22, 22, 20));   // above it
  scenes::add_box(room, Vec3(20, -22, 8), Vec3(22, -10, 19));   // beside it
  scenes::add_box(room, Vec3(20, 10, 8), Vec3(22, 22, 19));
  scenes::add_box(block, Vec3(-4, -4, 0), Vec3(4, 4, 6));
  a.parts = {part("room", room, true), part("block", block)};
  return a;
}

TEST(Sequence, ABlockInARoomLeavesByThePlannerThroughTheWindow) {
  const Assembly a = block_in_a_room();
  const DisassemblyResult r = disassemble(a, {.clearance = 0.01, .tolerance = 0.2, .plan_time_limit = 20});
  ASSERT_TRUE(r.complete);
  ASSERT_EQ(r.sequence.size(), 1u);
  EXPECT_EQ(r.sequence[0].method, RemovalMethod::plan);
  ASSERT_GE(r.sequence[0].path.poses.size(), 3u);
  // It goes out through the window: some pose has the block beyond the +x wall.
  bool outside = false;
  for (const Pose& q : r.sequence[0].path.poses) outside = outside || q.translation.x() > 26;
  EXPECT_TRUE(outside);
}

TEST(Sequence, SameResultAtAnyJobCount) {
  for (const Assembly& a : {bolted_ring(), riveted_plates()}) {
    std::vector<DisassemblyResult> runs;
    for (int jobs : {1, 2, 4})
      runs.push_back(disassemble(a, {.clearance = 0.01, .tolerance = 0.2, .jobs = jobs, .plan_time_limit = 0}));
    for (const DisassemblyResult& r : runs) {
      EXPECT_EQ(r.complete, runs[0].complete);
      ASSERT_EQ(r.sequence.size(), runs[0].sequence.size());
      for (std::size_t i = 0; i < r.sequence.size(); ++i) {
        const SequenceStep& s = r.sequence[i];
        const SequenceStep& t = runs[0].sequence[i];
        EXPECT_EQ(s.parts, t.parts);
        EXPECT_EQ(s.removed, t.removed);
        EXPECT_EQ(s.direction, t.direction);
        EXPECT_EQ(s.distance, t.distance);
        EXPECT_EQ(s.path.poses.size(), t.path.poses.size());
        ASSERT_EQ(s.blocking.size(), t.blocking.size());
        for (std::size_t k = 0; k < s.blocking.size(); ++k) EXPECT_EQ(s.blocking[k].blockers, t.blocking[k].blockers);
      }
    }
  }
}

// A planner attempt that finds no path ends at its query budget, not at a time: the same result,
// the same query count, at any job count, with the time limit far away. The room's block needs
// the planner; 40 queries are too few for it (the default budget is enough, above; ~100 are).
TEST(Sequence, PlannerAttemptsEndAtTheirQueryBudgetAtAnyJobCount) {
  const Assembly a = block_in_a_room();
  std::vector<DisassemblyResult> runs;
  for (int jobs : {1, 2, 4})
    runs.push_back(disassemble(a, {.clearance = 0.01, .tolerance = 0.2, .jobs = jobs, .plan_max_queries = 40,
                                   .plan_time_limit = 600}));
  for (const DisassemblyResult& r : runs) {
    EXPECT_FALSE(r.complete);
    ASSERT_EQ(r.sequence.size(), 1u);
    EXPECT_FALSE(r.sequence[0].removed);
    EXPECT_EQ(r.distance_queries, runs[0].distance_queries);
    EXPECT_GE(r.distance_queries, 20u);
  }
}

TEST(Sequence, As1ComesApartCompletely) {
  std::string why;
  const auto a = read_as1(why);
  ASSERT_TRUE(a || why.find("does not read") == std::string::npos) << why;
  if (!a) GTEST_SKIP() << why;
  ASSERT_GE(a->parts.size(), 10u);
  const auto t0 = std::chrono::steady_clock::now();
  const DisassemblyResult r = disassemble(*a, {.clearance = 0.01, .tolerance = 0.2, .jobs = 2});
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_TRUE(r.interferences.empty());
  std::string blocked;
  for (const SequenceStep& step : r.sequence)
    if (!step.removed) blocked += a->parts[step.parts[0]].name + " ";
  EXPECT_TRUE(r.complete) << "still in place: " << blocked;
  std::size_t removed = 0;
  for (const SequenceStep& step : r.sequence) removed += step.removed ? step.parts.size() : 0;
  EXPECT_EQ(removed + r.fixed.size(), a->parts.size());
  // Its time is a benchmark figure (docs/assembly.md: ≤ 30 s on 2 cores in a release build), not
  // asserted here: under the sanitizers the same sequence takes minutes.
  RecordProperty("as1_sequence_s", std::to_string(s));
  std::cout << "as1's sequence took " << s << " s\n";
  check_pulls_independently(*a, r, 0.01, 8);
}

// as1's bolts, nuts and rod fit their holes at zero clearance, and its STEP file writes every
// curved face as a B-spline: at a mating tolerance of 0.01 mm (a twentieth of the facets' sag at
// the default deflection) the triangles alone see 22 clashes and nothing comes out; with the
// cylinders the reader recognizes in those B-splines it comes apart as at 0.2 mm, and no pull goes
// deeper into material than the triangle rules allow at 0.2 mm (the independent check).
TEST(Sequence, As1ComesApartAtATightToleranceByItsCylinders) {
  std::string why;
  const auto a = read_as1(why);
  ASSERT_TRUE(a || why.find("does not read") == std::string::npos) << why;
  if (!a) GTEST_SKIP() << why;
  std::size_t cylinders = 0;
  for (const AssemblyPart& p : a->parts) cylinders += p.mesh.cylinders.size();
  EXPECT_GE(cylinders, 40u);
  EXPECT_GE(find_interferences(without_cylinders(*a), 0.01).size(), 10u);

  const DisassemblyResult r = disassemble(*a, {.clearance = 0.01, .tolerance = 0.01, .jobs = 2});
  EXPECT_TRUE(r.interferences.empty());
  EXPECT_TRUE(r.complete);
  std::vector<std::string> order;
  for (const SequenceStep& step : r.sequence) {
    ASSERT_EQ(step.parts.size(), 1u);
    EXPECT_EQ(step.method, RemovalMethod::pull);
    order.push_back(a->parts[step.parts[0]].name);
  }
  ASSERT_GE(order.size(), 3u);
  // The rod's nuts first, then the rod (it holds the brackets), as at 0.2 mm.
  EXPECT_EQ(std::vector<std::string>(order.begin(), order.begin() + 3), (std::vector<std::string>{"nut", "nut#2", "rod"}));
  check_pulls_independently(*a, r, 0.01, 8, 0.2);
}

}  // namespace
}  // namespace swept
