// The trees from both ends (src/plan/tree_search.cpp), run on their own.
#include "plan/phase_support.h"
#include "plan/tree_search.h"
#include "swept/io/mesh_io.h"
#include "swept/scenes/planning_suite.h"

#include <tbb/task_arena.h>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <optional>

namespace swept {
namespace {

using namespace swept::test;
using scenes::add_box;
using scenes::GeneratedProblem;

// A closed cage [−10, 10]³ with walls 1 thick and one way out: a square hole of side `hole`
// in the +x wall, continued inward by a tube `tube` long. The body is a rod 5 × 1 × 1 that
// starts off the hole's axis, turned 1.2 rad about z; the goal is outside, beyond the hole.
// The only way out is through the tube with the rod turned along x (tilted by at most
// atan((hole − 1) / (tube + 1)) from it), so straight moves are blocked and the grid's
// coarse levels are too coarse to thread the tube.
GeneratedProblem rod_in_cage(double hole, double tube) {
  GeneratedProblem g;
  g.name = "rod_in_cage";
  auto& o = g.obstacles.triangles;
  const double a = 10, t = 1, s = hole / 2;
  add_box(o, Vec3(-a, -a, -a), Vec3(a, a, -a + t));
  add_box(o, Vec3(-a, -a, a - t), Vec3(a, a, a));
  add_box(o, Vec3(-a, -a, -a + t), Vec3(-a + t, a, a - t));
  add_box(o, Vec3(-a + t, -a, -a + t), Vec3(a - t, -a + t, a - t));
  add_box(o, Vec3(-a + t, a - t, -a + t), Vec3(a - t, a, a - t));
  const double x0 = a - t, x1 = a;
  add_box(o, Vec3(x0, -a, -a + t), Vec3(x1, -s, a - t));
  add_box(o, Vec3(x0, s, -a + t), Vec3(x1, a, a - t));
  add_box(o, Vec3(x0, -s, -a + t), Vec3(x1, s, -s));
  add_box(o, Vec3(x0, -s, s), Vec3(x1, s, a - t));
  if (tube > 0) {
    add_box(o, Vec3(x0 - tube, -s - t, -s - t), Vec3(x0, -s, s + t));
    add_box(o, Vec3(x0 - tube, s, -s - t), Vec3(x0, s + t, s + t));
    add_box(o, Vec3(x0 - tube, -s, -s - t), Vec3(x0, s, -s));
    add_box(o, Vec3(x0 - tube, -s, s), Vec3(x0, s, s + t));
  }
  add_box(g.body.triangles, Vec3(-2.5, -0.5, -0.5), Vec3(2.5, 0.5, 0.5));
  g.problem.start = {Eigen::AngleAxisd(1.2, Vec3::UnitZ()).toRotationMatrix(), Vec3(-5, 6, 6)};
  g.problem.goal = Pose::from_translation(Vec3(15, 0, 0));
  g.problem.clearance = 0.01;
  g.problem.rotation = RotationMode::free;
  return g;
}

TEST(TreeSearch, HaltonIsTheRadicalInverse) {
  // Base 2: 1/2, 1/4, 3/4, 1/8; base 3: 1/3, 2/3, 1/9, 4/9; base 13 at 14 = 1·13 + 1: 1/13 + 1/169.
  const double b2[] = {0.5, 0.25, 0.75, 0.125};
  const double b3[] = {1.0 / 3, 2.0 / 3, 1.0 / 9, 4.0 / 9};
  for (int i = 1; i <= 4; ++i) {
    const auto p = detail::Halton::point(static_cast<std::uint64_t>(i));
    EXPECT_DOUBLE_EQ(p[0], b2[i - 1]);
    EXPECT_DOUBLE_EQ(p[1], b3[i - 1]);
  }
  EXPECT_DOUBLE_EQ(detail::Halton::point(14)[5], 1.0 / 13 + 1.0 / 169);
  EXPECT_DOUBLE_EQ(detail::Halton::point(5)[2], 1.0 / 25);
}

TEST(TreeSearch, SamplesStayInTheSpace) {
  auto g = rod_in_cage(2.3, 6.0);
  g.problem.rotation = RotationMode::limits;
  g.problem.rotation_limits = {{{-0.1, 0.2}, {-0.3, 0.0}, {0.5, 0.6}}};
  PhaseRig rig(std::move(g));
  const Pose start = rig.problem().start;
  detail::TreeSearch search(rig.context, start, rig.start_distance(start), 1.0);
  for (std::uint64_t i = 1; i <= 500; ++i) {
    const Pose q = search.sample(i);
    ASSERT_TRUE(in_bounds(rig.space, q.apply(rig.space.reference))) << i;
    ASSERT_NEAR((q.rotation.transpose() * q.rotation - Mat3::Identity()).norm(), 0.0, 1e-12);
    // The rotation vector relative to the start's rotation, within the limits.
    const Eigen::AngleAxisd turn(q.rotation * start.rotation.transpose());
    const Vec3 w = turn.angle() * turn.axis();
    for (int k = 0; k < 3; ++k) {
      EXPECT_GE(w[k], rig.problem().rotation_limits[k][0] - 1e-9) << i;
      EXPECT_LE(w[k], rig.problem().rotation_limits[k][1] + 1e-9) << i;
    }
  }
}

TEST(TreeSearch, FreeRotationsCoverSO3) {
  // Shoemake's map of a low-dispersion sequence: the rotation angles follow the Haar measure,
  // whose share of angles below π/2 is (π/2 − sin(π/2)) / π ≈ 0.182. Every fourth sample is a
  // lattice orientation of the start's or the goal's rotation instead.
  PhaseRig rig(rod_in_cage(2.3, 6.0));
  const Pose start = rig.problem().start;
  detail::TreeSearch search(rig.context, start, rig.start_distance(start), 1.0);
  int small = 0, n = 0;
  for (int i = 1; i <= 4000; ++i) {
    const Mat3 r = search.sample(i).rotation;
    if (i % 4 == 3) {
      // R·R₀ᵀ maps the axes onto the axes (R₀ the start's rotation; this problem's goal is unturned).
      const Mat3 lattice = r * (i / 8 / 24 % 2 == 0 ? start.rotation : rig.problem().goal->rotation).transpose();
      EXPECT_NEAR((lattice.cwiseAbs() - lattice.cwiseAbs().array().round().matrix()).norm(), 0.0, 1e-12) << i;
      continue;
    }
    ++n;
    small += rotation_angle(r, Mat3::Identity()) < std::numbers::pi / 2;
  }
  EXPECT_NEAR(static_cast<double>(small) / n, (std::numbers::pi / 2 - 1.0) / std::numbers::pi, 0.01);
}

TEST(TreeSearch, ASeedShiftsEverySampleByOneOffsetModuloOne) {
  // Problem::seed: the reference point of sample i with seed s is that of seed 0 moved by the
  // same fraction of the bounds for every i, modulo the bounds (a Cranley–Patterson rotation);
  // the same seed gives the same samples, another seed another offset.
  auto offsets = [](std::uint64_t seed) {
    auto g = rod_in_cage(2.3, 6.0);
    g.problem.seed = seed;
    PhaseRig rig(std::move(g));
    const Pose start = rig.problem().start;
    detail::TreeSearch search(rig.context, start, rig.start_distance(start), 1.0);
    const Vec3 lo = rig.space.bounds.min, size = rig.space.bounds.max - rig.space.bounds.min;
    std::vector<Vec3> out;
    for (std::uint64_t i = 1; i <= 200; ++i) out.push_back((search.sample(i).apply(rig.space.reference) - lo).cwiseQuotient(size));
    return out;
  };
  const std::vector<Vec3> plain = offsets(0), seven = offsets(7), again = offsets(7), eight = offsets(8);
  auto shift = [&](const std::vector<Vec3>& u, std::size_t i) {
    Vec3 d = u[i] - plain[i];
    for (int k = 0; k < 3; ++k) d[k] -= std::floor(d[k]);
    return d;
  };
  const Vec3 s7 = shift(seven, 0);
  for (std::size_t i = 0; i < plain.size(); ++i) {
    EXPECT_EQ(seven[i], again[i]) << i;
    const Vec3 d = shift(seven, i);
    for (int k = 0; k < 3; ++k) {
      // The same offset (a wrap near 0 or 1 is the same point of the circle).
      const double gap = std::abs(d[k] - s7[k]);
      EXPECT_LT(std::min(gap, 1.0 - gap), 1e-9) << i << " " << k;
      EXPECT_GE(seven[i][k], -1e-12);
      EXPECT_LT(seven[i][k], 1.0 + 1e-12);
    }
  }
  EXPECT_GT(s7.minCoeff(), 1e-6);  // the seed moves every coordinate (this seed's offsets)
  EXPECT_GT((shift(eight, 0) - s7).norm(), 1e-3);
}

TEST(TreeSearch, ASeedIsAnotherPathTheSameAtAnyThreadCountAndValid) {
  // The suite's house, solved by the trees: seeds 0, 1 and 2 give three paths, each the same at
  // 1 and 2 threads, each valid by the oracle that shares no code with swept.
  std::vector<std::uint64_t> seen;
  for (std::uint64_t seed : {0u, 1u, 2u}) {
    std::vector<std::uint64_t> hashes;
    for (int threads : {1, 2}) {
      GeneratedProblem g = scenes::suite::house().problem;
      g.problem.seed = seed;
      PhaseRig rig(std::move(g), 120.0);
      const Pose start = rig.problem().start;
      detail::TreeSearch search(rig.context, start, rig.start_distance(start), rig.start_distance(*rig.problem().goal));
      detail::TreeOutcome outcome = detail::TreeOutcome::time_limit;
      tbb::task_arena arena(threads);
      const auto path = arena.execute([&] { return search.run(outcome); });
      ASSERT_TRUE(path) << "seed " << seed << ", " << search.nodes() << " nodes";
      if (threads == 1) check_path_independently(rig.scene, rig.problem(), Path{*path});
      hashes.push_back(path_hash(Path{*path}));
    }
    EXPECT_EQ(hashes[0], hashes[1]) << "seed " << seed;
    for (std::uint64_t h : seen) EXPECT_NE(hashes[0], h) << "seed " << seed;
    seen.push_back(hashes[0]);
  }
}

TEST(TreeSearch, LatticeRotationsAreTheCubeGroup) {
  std::vector<Mat3> seen;
  for (std::uint64_t k = 0; k < 24; ++k) {
    const Mat3 m = detail::lattice_rotation(k);
    EXPECT_NEAR((m * m.transpose() - Mat3::Identity()).norm(), 0.0, 1e-15);
    EXPECT_DOUBLE_EQ(m.determinant(), 1.0);
    for (const Mat3& other : seen) EXPECT_GT((m - other).norm(), 0.5) << k;
    seen.push_back(m);
  }
  EXPECT_EQ((detail::lattice_rotation(24) - detail::lattice_rotation(0)).norm(), 0.0);
}

TEST(TreeSearch, NearestIsTheClosestInTheMetricLowestIndexFirst) {
  PhaseRig rig(rod_in_cage(2.3, 6.0));
  const Pose start = rig.problem().start;
  const detail::TreeSearch search(rig.context, start, rig.start_distance(start), 1.0);
  // The rotation's part of the metric is the angle times r·w (w = kNearestTurnWeight).
  const double r = rig.space.radius * detail::TreeSearch::kNearestTurnWeight;
  // Poses by their reference point (world) and rotation.
  auto at = [&](const Mat3& rotation, double x) { return rig.context.pose_with_reference_at(rotation, Vec3(x, 0, 0)); };
  auto node = [&](const Pose& p) { return detail::TreeNode{p, p.apply(rig.space.reference), p.quaternion(), 1.0, -1}; };
  const Mat3 turn = Eigen::AngleAxisd(0.5, Vec3::UnitX()).toRotationMatrix();
  const Pose query = at(Mat3::Identity(), 1.0);
  // From the query the turned node is 0.5·r away (an angle of 0.5), the others 0.5·r − 0.1 and 0.5·r.
  std::vector<detail::TreeNode> tree{node(at(Mat3::Identity(), 0.9 + 0.5 * r)), node(at(turn, 1.0)),
                                     node(at(Mat3::Identity(), 1.0 - 0.5 * r))};
  EXPECT_EQ(search.nearest(tree, query), 0);
  tree[0] = node(at(Mat3::Identity(), 1.0 + 0.75 * r));
  tree[2] = node(at(Mat3::Identity(), 1.0 - 0.25 * r));
  EXPECT_EQ(search.nearest(tree, query), 2);
  tree[2] = node(at(Mat3::Identity(), 1.0 - 0.6 * r));
  EXPECT_EQ(search.nearest(tree, query), 1);  // the turn (0.5·r) before a move of 0.6·r
  tree[1] = tree[2];
  EXPECT_EQ(search.nearest(tree, query), 1);  // equal nodes: the lower index
}

TEST(TreeSearch, ThreadsTheTubeOutOfTheCage) {
  PhaseRig rig(rod_in_cage(2.3, 2.0), 120.0);
  const Pose start = rig.problem().start;
  rig.check.set_deadline(rig.context.started + std::chrono::seconds(120));
  const double goal_distance = rig.start_distance(*rig.problem().goal);
  detail::TreeSearch search(rig.context, start, rig.start_distance(start), goal_distance);
  detail::TreeOutcome outcome = detail::TreeOutcome::time_limit;
  const auto path = search.run(outcome);
  ASSERT_TRUE(path) << "no path: " << search.nodes() << " nodes";
  EXPECT_EQ(outcome, detail::TreeOutcome::found);
  EXPECT_TRUE(path->front().translation == start.translation && path->front().rotation == start.rotation);
  EXPECT_TRUE(path->back().translation == rig.problem().goal->translation);
  // Somewhere in the tube (x in [3, 10]) the rod lies along x, within the tilt the tube allows:
  // at a waypoint, or along a motion between two (a long step may pass the tube whole).
  bool threaded = false;
  for (std::size_t i = 0; i + 1 < path->size() && !threaded; ++i)
    for (int k = 0; k <= 400 && !threaded; ++k) {
      const Pose q = interpolate((*path)[i], (*path)[i + 1], k / 400.0, rig.scene.reference);
      const double along = std::abs((q.rotation * Vec3::UnitX()).x());
      threaded = q.translation.x() > 3 && q.translation.x() < 10 && along > std::cos(0.5);
    }
  EXPECT_TRUE(threaded);
  check_path_independently(rig.scene, rig.problem(), Path{*path});
}

// Cancelled (the grid beside them has decided the plan), the trees stop before their next
// round, or within a round without adding it. Raised before run(), no node grows; raised after
// a few rounds, no round after it adds any.
TEST(TreeSearch, StopsWhenCancelled) {
  PhaseRig rig(scenes::suite::house().problem, 120.0);
  const Pose start = rig.problem().start;
  const double goal_distance = rig.start_distance(*rig.problem().goal);
  std::atomic<bool> cancel{true};
  detail::TreeSearch search(rig.context, start, rig.start_distance(start), goal_distance);
  search.set_cancel(&cancel);
  const std::size_t roots = search.nodes();
  detail::TreeOutcome outcome = detail::TreeOutcome::found;
  EXPECT_FALSE(search.run(outcome));
  EXPECT_EQ(outcome, detail::TreeOutcome::cancelled);
  EXPECT_EQ(search.nodes(), roots);
  EXPECT_EQ(search.samples(), 0u);
  // Not raised: three rounds grow the trees; raised then, the next run adds nothing.
  cancel = false;
  EXPECT_FALSE(search.run(outcome, 3));
  EXPECT_EQ(outcome, detail::TreeOutcome::round_limit);
  const std::size_t grown = search.nodes();
  EXPECT_GT(grown, roots);
  cancel = true;
  EXPECT_FALSE(search.run(outcome));
  EXPECT_EQ(outcome, detail::TreeOutcome::cancelled);
  EXPECT_EQ(search.nodes(), grown);
}

// Raised while the trees join (the grid or a straight move has found the plan meanwhile), the
// cancel flag stops the join's certificates before their next query: the lazy edges and the
// bridges of a joined path cost seconds on a large scene (the air cleaner's joins ran 40 ms past
// the grid's path before they looked). Without it the house's first join makes queries.
TEST(TreeSearch, CancelStopsAJoinBeforeItsNextQuery) {
  for (bool raise : {false, true}) {
    PhaseRig rig(scenes::suite::house().problem, 120.0);
    rig.options.max_queries = 10'000'000;  // never reached: the bridges' tries in turn
    const Pose start = rig.problem().start;
    std::atomic<bool> cancel{false};
    detail::TreeSearch search(rig.context, start, rig.start_distance(start), rig.start_distance(*rig.problem().goal));
    search.set_cancel(&cancel);
    std::optional<std::uint64_t> at_join;
    search.set_on_join([&] {
      if (at_join) return;
      at_join = rig.check.distance_queries();
      if (raise) cancel = true;
    });
    tbb::task_arena one(1);  // one join's certificates in turn: none in flight when the flag rises
    detail::TreeOutcome outcome = detail::TreeOutcome::found;
    const auto path = one.execute([&] { return search.run(outcome, 200); });
    ASSERT_TRUE(at_join) << "the house's trees join within 200 rounds";
    if (raise) {
      EXPECT_FALSE(path);
      EXPECT_EQ(outcome, detail::TreeOutcome::cancelled);
      EXPECT_EQ(rig.check.distance_queries(), *at_join) << "no query after the flag";
    } else {
      EXPECT_GT(search.lazy_certified(), 0u);
      EXPECT_GT(rig.check.distance_queries(), *at_join) << "the join certifies its lazy edges";
    }
  }
}

TEST(TreeSearch, SameTreesAtAnyThreadCount) {
  std::vector<std::size_t> nodes;
  std::vector<std::uint64_t> hashes;
  for (int threads : {1, 2, 3}) {
    PhaseRig rig(rod_in_cage(2.3, 2.0), 120.0);
    const Pose start = rig.problem().start;
    detail::TreeSearch search(rig.context, start, rig.start_distance(start), rig.start_distance(*rig.problem().goal));
    detail::TreeOutcome outcome = detail::TreeOutcome::time_limit;
    tbb::task_arena arena(threads);
    // A fixed number of rounds, found or not: the trees must match, not only the path.
    const auto path = arena.execute([&] { return search.run(outcome, 40); });
    nodes.push_back(search.nodes());
    hashes.push_back(path ? path_hash(Path{*path}) : 0);
  }
  EXPECT_EQ(nodes[0], nodes[1]);
  EXPECT_EQ(nodes[0], nodes[2]);
  EXPECT_EQ(hashes[0], hashes[1]);
  EXPECT_EQ(hashes[0], hashes[2]);
  EXPECT_GT(nodes[0], 2u);
}

TEST(TreeSearch, GoalRegionTreeGrowsFromSamplesInTheRegion) {
  // The cage without its tube, with a goal region (outside the obstacles' box): the goal tree's
  // roots are free samples in the region.
  auto g = rod_in_cage(3.0, 0.0);
  g.problem.goal.reset();
  g.problem.goal_outside = true;
  PhaseRig rig(std::move(g), 120.0);
  const Pose start = rig.problem().start;
  detail::TreeSearch search(rig.context, start, rig.start_distance(start), 0.0);
  detail::TreeOutcome outcome = detail::TreeOutcome::time_limit;
  const auto path = search.run(outcome);
  ASSERT_TRUE(path);
  EXPECT_TRUE(goal_reached(rig.space, rig.problem(), path->back()));
  EXPECT_FALSE(goal_reached(rig.space, rig.problem(), path->front()));
  check_path_independently(rig.scene, rig.problem(), Path{*path});
}


TEST(TreeSearch, LazyEdgesAreCertifiedBeforeAPathUsesThem) {
  // The house of the benchmark suite: long steps through rooms cross walls at their ends'
  // blind spots. Steps past a node's free ball are taken unchecked (their ends and midpoint
  // are free) and certified only when a path joining the ends uses them; those whose
  // certificate fails are cut with the subtrees below them. The path that comes out must pass
  // the independent check, at any thread count, and the house must actually cut edges (else
  // this test does not test the cut). An edge that fails is bridged by a certified motion between
  // the waypoints around it when one is free; the house's first joined path is saved so (else
  // this test does not test the bridges).
  // Seed 3 is such a draw; of seeds 0-79, 49 bridge an edge (2026-12-02).
  std::vector<std::uint64_t> hashes, cut, bridges;
  for (int threads : {1, 2}) {
    GeneratedProblem g = scenes::suite::house().problem;
    g.problem.seed = 3;
    PhaseRig rig(std::move(g), 120.0);
    rig.check.set_deadline(rig.context.started + std::chrono::seconds(120));
    const Pose start = rig.problem().start;
    detail::TreeSearch search(rig.context, start, rig.start_distance(start), rig.start_distance(*rig.problem().goal));
    detail::TreeOutcome outcome = detail::TreeOutcome::time_limit;
    tbb::task_arena arena(threads);
    const auto path = arena.execute([&] { return search.run(outcome); });
    ASSERT_TRUE(path) << search.nodes() << " nodes";
    EXPECT_GT(search.lazy_certified(), 0u);
    check_path_independently(rig.scene, rig.problem(), Path{*path});
    hashes.push_back(path_hash(Path{*path}));
    cut.push_back(search.lazy_cut());
    bridges.push_back(search.bridges());
    EXPECT_GE(search.bridges_tried(), search.bridges());
  }
  EXPECT_EQ(hashes[0], hashes[1]);
  EXPECT_EQ(cut[0], cut[1]);
  EXPECT_GT(cut[0], 0u);
  EXPECT_EQ(bridges[0], bridges[1]);
  EXPECT_GT(bridges[0], 0u);
}

TEST(TreeSearch, BridgesStopAfterFourJoinsWithoutOne) {
  // Joined paths fail where lazy steps cross whole walls, which no motion between nearby
  // waypoints avoids: after kBridgeMisses such joins no bridge is tried any more, so the tries
  // stay within kBridgeMisses × kBridges (each miss stops at its first edge without a bridge),
  // however many joins fail after them. The path is the one the later joins find, and passes the
  // independent check. The suite's house at seed 23 is such a draw since the nearest node weighs
  // turns by half (2026-12-02; it cuts 11 edges; a scan of seeds 0-79 found 9 with four misses
  // and no bridge). Before, seeds 0 and 20 were; since a lazy step's quarters are checked, the
  // cubicles' seed 0, this test's first draw, no longer joins through walls.
  GeneratedProblem g = scenes::suite::house().problem;
  g.problem.seed = 23;
  PhaseRig rig(std::move(g), 120.0);
  rig.check.set_deadline(rig.context.started + std::chrono::seconds(120));
  const Pose start = rig.problem().start;
  detail::TreeSearch search(rig.context, start, rig.start_distance(start), rig.start_distance(*rig.problem().goal));
  detail::TreeOutcome outcome = detail::TreeOutcome::time_limit;
  const auto path = search.run(outcome);
  ASSERT_TRUE(path) << search.nodes() << " nodes";
  EXPECT_EQ(search.bridges(), 0u);
  EXPECT_EQ(search.bridge_misses(), detail::TreeSearch::kBridgeMisses);
  EXPECT_GT(search.bridges_tried(), 0u);
  EXPECT_LE(search.bridges_tried(), detail::TreeSearch::kBridgeMisses * detail::TreeSearch::kBridges.size());
  EXPECT_GT(search.lazy_cut(), static_cast<std::uint64_t>(detail::TreeSearch::kBridgeMisses));  // joins failed after the misses too
  check_path_independently(rig.scene, rig.problem(), Path{*path});
}

TEST(TreeSearch, AnExternalBodyThroughTheHouseIsBridgedAndCheckedIndependently) {
  // A body nobody here wrote: the KUKA KR10's third link (ROS-Industrial's visual mesh, in
  // metres), read from the shared data and scaled 10× (4.4 × 3.1 × 1.9 in the house's units,
  // as `file_unit = "cm"` reads it), carried through the suite's house. Its path comes from the
  // trees at seed 5, with failed lazy edges bridged (of seeds 0-11, five bridge, 2026-12-02); it
  // must be the same at 1 and 2 threads and pass the oracle that shares no code with swept
  // (checked once: the two paths are one; in the release suite only, the sanitizers still run the
  // search).
  const auto data = shared_data();
  if (!data) GTEST_SKIP() << "shared CAD data folder is absent";
  const auto file = *data / "ros_industrial" / "kuka_kr10r1420_visual_link_3.stl";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " not found";
  const Result<ImportedModel> model = import_mesh(file);
  ASSERT_TRUE(model) << model.error().message;
  std::vector<Triangle> link = model->merged().triangles;
  const Vec3 center = bounds(link).center();
  for (Triangle& t : link)
    for (int k = 0; k < 3; ++k) t[k] = 10.0 * (t[k] - center);
  std::vector<std::uint64_t> hashes, bridges, tried;
  for (int threads : {1, 2}) {
    GeneratedProblem g = scenes::suite::house().problem;
    g.body.triangles = link;
    g.problem.seed = 5;
    PhaseRig rig(std::move(g), 120.0);
    rig.check.set_deadline(rig.context.started + std::chrono::seconds(120));
    const Pose start = rig.problem().start;
    detail::TreeSearch search(rig.context, start, rig.start_distance(start), rig.start_distance(*rig.problem().goal));
    detail::TreeOutcome outcome = detail::TreeOutcome::time_limit;
    tbb::task_arena arena(threads);
    const auto path = arena.execute([&] { return search.run(outcome); });
    ASSERT_TRUE(path) << search.nodes() << " nodes";
#if !defined(__SANITIZE_ADDRESS__)  // the oracle on 9,689 × 336 triangles: 15 s here, 6 min under ASan
    if (threads == 1) check_path_independently(rig.scene, rig.problem(), Path{*path});
#endif
    hashes.push_back(path_hash(Path{*path}));
    bridges.push_back(search.bridges());
    tried.push_back(search.bridges_tried());
  }
  EXPECT_EQ(hashes[0], hashes[1]);
  EXPECT_EQ(bridges[0], bridges[1]);
  EXPECT_GT(bridges[0], 0u);
  EXPECT_GE(tried[0], bridges[0]);
}

TEST(TreeSearch, BlockedPosesDecidedOrMeasuredGiveTheSameTrees) {
  // The planner's search stops a query at the first pair under the margin (Checker::
  // set_decide_blocked): a blocked pose's distance is then some pair's, not the smallest. Every
  // decision must be the one the exact distances give: the same trees, cuts and path on the
  // house (blocked steps, slides, lazy edges cut) and in the cage, with the queries measured
  // exactly or decided.
  for (int problem = 0; problem < 2; ++problem) {
    std::vector<std::uint64_t> hashes, nodes, cut, queries;
    for (bool decide : {false, true}) {
      PhaseRig rig(problem == 0 ? scenes::suite::house().problem : rod_in_cage(2.3, 2.0), 120.0);
      rig.check.set_deadline(rig.context.started + std::chrono::seconds(120));
      rig.check.set_decide_blocked(decide);
      // A query budget never reached: the bridges' tries run in turn, so the count of queries
      // does not depend on when a try still running is cancelled (on every core it would).
      rig.options.max_queries = 10'000'000;
      const Pose start = rig.problem().start;
      detail::TreeSearch search(rig.context, start, rig.start_distance(start), rig.start_distance(*rig.problem().goal));
      detail::TreeOutcome outcome = detail::TreeOutcome::time_limit;
      const auto path = search.run(outcome, 200);
      ASSERT_TRUE(path) << problem << ": " << search.nodes() << " nodes";
      hashes.push_back(path_hash(Path{*path}));
      nodes.push_back(search.nodes());
      cut.push_back(search.lazy_cut());
      queries.push_back(rig.check.distance_queries());
    }
    EXPECT_EQ(hashes[0], hashes[1]) << problem;
    EXPECT_EQ(nodes[0], nodes[1]) << problem;
    EXPECT_EQ(cut[0], cut[1]) << problem;
    EXPECT_EQ(queries[0], queries[1]) << problem;
  }
}


}  // namespace
}  // namespace swept
