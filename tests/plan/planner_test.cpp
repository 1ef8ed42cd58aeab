// The planner on problems generated here: every path checked independently of the planner.
#include "plan/plan_support.h"
#include "swept/scenes/planning_suite.h"

#include <chrono>
#include <cstdio>

namespace swept {
namespace {

using namespace swept::test;
using namespace swept::scenes;

void expect_ends(const GeneratedProblem& g, const PlanScene& s, const PlanResult& r) {
  ASSERT_TRUE(r.solved()) << r.message;
  const Pose& first = r.path.poses.front();
  EXPECT_EQ(first.rotation, g.problem.start.rotation);
  EXPECT_EQ(first.translation, g.problem.start.translation);
  const Pose& last = r.path.poses.back();
  if (g.problem.goal) {
    EXPECT_LT((last.translation - g.problem.goal->translation).norm(), 1e-9);
    EXPECT_LT(rotation_angle(last.rotation, g.problem.goal->rotation), 1e-9);
  } else {
    // Outside the obstacles' box grown by the margin: no body vertex inside it.
    Aabb grown = s.obstacle_box;
    grown.min.array() -= g.problem.goal_margin;
    grown.max.array() += g.problem.goal_margin;
    Aabb body;
    for (const Triangle& t : s.body.triangles)
      for (int v = 0; v < 3; ++v) body.extend(last.apply(t[v]));
    bool separated = false;
    for (int i = 0; i < 3; ++i) separated = separated || body.min[i] > grown.max[i] || body.max[i] < grown.min[i];
    EXPECT_TRUE(separated) << "the path does not end outside the obstacles' box";
  }
  // The whole path keeps the margin, unless an end is in contact (the reported minimum then
  // includes that contact; the oracle checks the motions in contact by their own rule).
  if (r.escape_segments + r.approach_segments == 0) {
    EXPECT_GE(r.min_clearance, g.problem.clearance);
  }
  EXPECT_EQ(r.path_hash, path_hash(r.path));
  check_independently(s, g.problem, r);
}

TEST(Planner, PegOutOfBlindHoleWithTightClearance) {
  const auto g = peg_in_hole();
  const PlanScene s = scene_of(g);
  const PlanResult r = plan(g.problem, s);
  expect_ends(g, s, r);
  std::printf("peg: %zu waypoints, %llu distance queries, %.1f ms\n", r.path.poses.size(),
              static_cast<unsigned long long>(r.queries.distance), r.time_ms.total);
}

TEST(Planner, SliderOutOfTSlotThenLift) {
  const auto g = t_slot();
  const PlanScene s = scene_of(g);
  const PlanResult r = plan(g.problem, s);
  expect_ends(g, s, r);
  // It cannot lift first: the head is under the lips.
  EXPECT_GE(r.path.poses.size(), 3u);
}

TEST(Planner, BoxThroughLShapedTunnel) {
  const auto g = l_tunnel();
  const PlanScene s = scene_of(g);
  const PlanResult r = plan(g.problem, s);
  expect_ends(g, s, r);
  EXPECT_GE(r.path.poses.size(), 3u);
}

TEST(Planner, BarTurnsToPassANarrowSlot) {
  const auto g = bar_through_slot();
  const PlanScene s = scene_of(g);
  const PlanResult r = plan(g.problem, s);
  expect_ends(g, s, r);
  EXPECT_GT(r.rotation_length, 0.5) << "the bar must turn to pass";
}

TEST(Planner, StartTouchingWithContactTolerance) {
  // The peg rests on the bottom of its hole and touches one wall: distance 0 at the start.
  auto g = peg_in_hole(10.0, 1e-2);
  const double c = 1e-2 * 10.0;
  g.problem.start = Pose::from_translation(Vec3(-c, 0, -20 + 12.5));
  g.problem.clearance = 0.01;
  {
    const PlanScene s = scene_of(g);
    const PlanResult r = plan(g.problem, s);
    EXPECT_EQ(r.status, PlanStatus::invalid_start) << r.message;
    EXPECT_NE(r.message.find("contact_tolerance"), std::string::npos) << r.message;
  }
  g.problem.contact_tolerance = 0.02;
  const PlanScene s = scene_of(g);
  const PlanResult r = plan(g.problem, s);
  expect_ends(g, s, r);
  EXPECT_EQ(r.escape_segments, 1u);
  EXPECT_EQ(r.min_clearance, 0.0) << "the peg touches at the start";
  // The escape moves away from the wall and the bottom it touched: after the start, no sample
  // of the escape segment intersects the obstacles.
  for (int k = 1; k <= 1000; ++k) {
    const Pose q = interpolate(r.path.poses[0], r.path.poses[1], k / 1000.0, s.reference);
    ASSERT_FALSE(collide(s.obstacle_tree, Pose{}, s.body_tree, q).colliding) << "escape penetrates at t=" << k / 1000.0;
  }
}

TEST(Planner, NoSolutionIsReportedWithinTheLimit) {
  const auto g = enclosed();
  const PlanScene s = scene_of(g);
  const auto t0 = std::chrono::steady_clock::now();
  const PlanResult r = plan(g.problem, s);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_FALSE(r.solved());
  EXPECT_TRUE(r.status == PlanStatus::no_path_bounds || r.status == PlanStatus::no_path_resolution ||
              r.status == PlanStatus::no_path_time)
      << r.message;
  EXPECT_FALSE(r.message.empty());
  EXPECT_LT(secs, g.problem.time_limit + 5.0);
  EXPECT_TRUE(r.path.poses.empty());
}

TEST(Planner, StartInCollisionAndGoalOutsideBoundsAreErrors) {
  auto g = l_tunnel();
  g.problem.start = Pose::from_translation(Vec3(10, 0, 8));  // inside the roof
  const PlanScene s = scene_of(g);
  PlanResult r = plan(g.problem, s);
  EXPECT_EQ(r.status, PlanStatus::invalid_start);
  EXPECT_NE(r.message.find("collision"), std::string::npos) << r.message;
  g = l_tunnel();
  g.problem.goal = Pose::from_translation(Vec3(100, 0, 0));
  r = plan(g.problem, s);
  EXPECT_EQ(r.status, PlanStatus::invalid_goal);
  EXPECT_NE(r.message.find("bounds"), std::string::npos) << r.message;
}

// The same path, bit for bit, at 1, 2, 4 and 8 threads and across runs: on problems the
// straight-line phase solves, on one the grid or the trees solve (the bar, with rotation), and
// on the bug trap, which only the trees (in parallel rounds) solve.
TEST(Planner, DeterministicAcrossRunsAndThreadCounts) {
  for (const auto& g : {l_tunnel(), t_slot(), bar_through_slot(), scenes::suite::bug_trap().problem}) {
    const PlanScene s = scene_of(g);
    std::vector<std::uint64_t> hashes;
    std::vector<std::size_t> waypoints;
    for (int threads : {1, 2, 4, 8, 1, 2}) {
      PlanOptions options;
      options.threads = threads;
      const PlanResult r = plan(g.problem, s, options);
      ASSERT_TRUE(r.solved()) << g.name << " at " << threads << " threads: " << r.message;
      EXPECT_EQ(r.path_hash, path_hash(r.path));
      hashes.push_back(r.path_hash);
      waypoints.push_back(r.path.poses.size());
      if (g.name == "bar_through_slot") {
        EXPECT_NE(r.level, -1) << "the bar's path must come from a search, not from straight moves";
      } else if (g.name == "bug-trap") {
        EXPECT_EQ(r.level, kTreeLevel) << "the trap's path must come from the trees";
      }
    }
    for (std::size_t i = 1; i < hashes.size(); ++i) {
      EXPECT_EQ(hashes[i], hashes[0]) << g.name << ", run " << i;
      EXPECT_EQ(waypoints[i], waypoints[0]) << g.name << ", run " << i;
    }
  }
}

// The grid and the trees run at the same time on two cores or more (no query budget), in turn
// otherwise; the plan must be the one the phases give in turn: the grid's path when it finds one
// (the hooks at 1.2, solved on the grid at level 0 while the trees grow), else the trees' (the
// twisty slot), with the trees unaffected by the grid beside them (the same nodes).
TEST(Planner, GridAndTreesTogetherGiveThePlanOfThePhasesInTurn) {
  for (const auto& g : {scenes::suite::hooks(1.2).problem, scenes::suite::twisty_slot().problem}) {
    const PlanScene s = scene_of(g);
    PlanOptions in_turn;  // one thread
    in_turn.threads = 1;
    PlanOptions together;
    together.threads = 2;
    PlanOptions budgeted;  // two threads, in turn: a budget never reached
    budgeted.threads = 2;
    budgeted.max_queries = 10'000'000;
    std::vector<PlanResult> runs;
    for (const PlanOptions& options : {in_turn, together, budgeted}) {
      runs.push_back(plan(g.problem, s, options));
      ASSERT_TRUE(runs.back().solved()) << g.name << ": " << runs.back().message;
    }
    if (g.name == "twisty-slot") {
      EXPECT_EQ(runs[0].level, kTreeLevel) << "the slot's path must come from the trees";
      EXPECT_GT(runs[0].tree_nodes, 2u);
    } else {
      EXPECT_EQ(runs[0].level, 0) << "the hooks' path must come from the grid";
      EXPECT_EQ(runs[0].tree_nodes, 0u);
    }
    for (const PlanResult& r : runs) {
      EXPECT_EQ(r.path_hash, runs[0].path_hash) << g.name;
      EXPECT_EQ(r.level, runs[0].level) << g.name;
      EXPECT_EQ(r.tree_nodes, runs[0].tree_nodes) << g.name;
    }
    // In turn, the count of queries is the same at any thread count.
    EXPECT_EQ(runs[2].queries.distance, runs[0].queries.distance) << g.name;
  }
}

// The query budget ends a search at a point that does not depend on threads or on the machine:
// the house needs the trees and a few thousand queries; stopped at 1,500 it must stop in the
// same place at every thread count (same query count, same tree), with a time limit far away.
// A budget it stays within changes nothing.
TEST(Planner, BudgetEndsTheSearchTheSameWayAtAnyThreadCount) {
  GeneratedProblem g = scenes::suite::house().problem;
  g.problem.time_limit = 600;
  const PlanScene s = scene_of(g);
  const PlanResult free_run = plan(g.problem, s);
  ASSERT_TRUE(free_run.solved()) << free_run.message;
  constexpr std::uint64_t kBudget = 1500;
  ASSERT_GT(free_run.queries.distance, kBudget + kBudget / 2) << "the budget below must stop the search";

  std::vector<PlanResult> runs;
  for (int threads : {1, 2, 4}) {
    PlanOptions options;
    options.threads = threads;
    options.max_queries = kBudget;
    runs.push_back(plan(g.problem, s, options));
    const PlanResult& r = runs.back();
    EXPECT_EQ(r.status, PlanStatus::no_path_budget) << threads << " threads: " << r.message;
    EXPECT_NE(r.message.find("budget of " + std::to_string(kBudget) + " distance queries"), std::string::npos) << r.message;
    EXPECT_GE(r.queries.distance, kBudget);
    EXPECT_TRUE(r.path.poses.empty());
  }
  for (const PlanResult& r : runs) {
    EXPECT_EQ(r.queries.distance, runs[0].queries.distance);
    EXPECT_EQ(r.tree_nodes, runs[0].tree_nodes);
    EXPECT_EQ(r.level, runs[0].level);
  }
  EXPECT_GT(runs[0].tree_nodes, 2u) << "stopped in the trees, between rounds";

  // A budget never reached changes nothing: the path, and the count of one thread (under a
  // budget nothing runs ahead, so the count is that of the phases and tries in turn).
  PlanOptions roomy;
  roomy.max_queries = 10 * free_run.queries.distance;
  roomy.threads = 4;
  const PlanResult within = plan(g.problem, s, roomy);
  ASSERT_TRUE(within.solved()) << within.message;
  EXPECT_EQ(within.path_hash, free_run.path_hash);
  PlanOptions one_thread;
  one_thread.threads = 1;
  const PlanResult serial = plan(g.problem, s, one_thread);
  EXPECT_EQ(serial.path_hash, free_run.path_hash);
  EXPECT_EQ(within.queries.distance, serial.queries.distance);
}

}  // namespace
}  // namespace swept
