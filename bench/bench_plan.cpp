// Side-by-side planner benchmark: swept's certified, deterministic planner against OMPL's
// RRTConnect with FCL collision checking (Debian libompl-dev, libfcl-dev), on the same problems
// in one run. Issue goal: solve every problem OMPL solves at ≤ 1/3 of its median time, and solve
// the narrow-clearance disassembly problems it does not.
//
//   bench_plan [--quick] [--time-limit S] [--seeds N] [--threads N] [--only a,b,...] [--no-cad]
//              [--ompl-collide-only] [--json FILE]
//
// Problems: the box problems of the scenes library (peg_in_hole, t_slot, l_tunnel,
// bar_through_slot, enclosed) and the CAD scenes of `swept scene` at test scale (generated into
// a temporary directory; skipped with a message when generation fails).
//
// OMPL's side, set up as an OMPL user would, with nothing tuned:
// - state: the pose of the body about swept's reference point c (translation of c, rotation
//   about c) in SE3StateSpace, or RealVectorStateSpace(3) when the problem fixes the rotation.
//   OMPL's SE(3) interpolation (linear translation, slerp) is then exactly swept's local path,
//   and the translation bounds are exactly swept's bounds on the reference point (the problem's
//   bounds, else the obstacles' box grown by 2.2·r_max + 0.05·size, see src/plan/planner.cpp).
// - validity: fcl::collide of BVHModel<OBBRSSd> body against the obstacles, then
//   fcl::distance ≥ the problem's clearance (swept certifies the same margin); rotation limits
//   (mode "limits") checked on the rotation vector relative to the start orientation, as swept's
//   grid does.
// - motions: OMPL's default DiscreteMotionValidator (longest valid segment 1 % of the space's
//   extent); planner: RRTConnect with its default range; goal: GoalState, or for `goal outside`
//   problems a GoalSampleableRegion "the sphere of radius r_max about c is outside the
//   obstacles' box grown by the margin" (swept's goal test).
// - seeds: ompl::RNG::setSeed(seed) before each run; time: the solve call only (no
//   simplification; OMPL's raw solve time). Failed runs count as the full time limit in the
//   median. Each solution is then re-checked, outside the timing, by swept's certified motion
//   query (margin 0) to count the paths that collide between the discrete samples.
// swept's side: PlanResult from plan() on a prebuilt scene (tree build reported apart), once
// per fitter (pqp, rapid2, inertia), and the problem's fitter as many times as OMPL has seeds
// (at least twice): its median time is the one compared, and every run must give the same path.
#include "swept/io/file_write.h"
#include "swept/plan/planner.h"
#include "swept/plan/problem.h"
#include "swept/query/query.h"
#include "swept/scenes/box_problems.h"
#include "swept/scenes/scenes.h"

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/math/bv/OBBRSS.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/distance.h>
#include <nlohmann/json.hpp>
#include <ompl/base/goals/GoalSampleableRegion.h>
#include <ompl/base/goals/GoalState.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/SE3StateSpace.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace {

using namespace swept;
namespace ob = ompl::base;
namespace og = ompl::geometric;
using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

// ---- the problems -----------------------------------------------------------------------------

/// One benchmark problem: a generated box problem (meshes in memory) or a CAD scene's problem
/// file (meshes loaded by load_scene).
struct Case {
  std::string name;
  Problem problem;
  std::optional<TriangleSoup> obstacles, body;  ///< set for the box problems
  std::string kind;                             ///< "box" or "cad"
};

/// The problem's tree settings with another fitter.
BuildConfig build_config(const Problem& problem, Fitter fitter) {
  BuildConfig config = problem.build;
  config.fitter = fitter;
  return config;
}

Result<PlanScene> scene_for(const Case& c, Fitter fitter) {
  if (c.obstacles) return make_scene(*c.obstacles, *c.body, build_config(c.problem, fitter), c.problem.reference_point);
  return load_scene(c.problem, build_config(c.problem, fitter));
}

// ---- swept ------------------------------------------------------------------------------------

struct SweptRun {
  Fitter fitter = Fitter::inertia;
  PlanResult result;
  double plan_ms = 0.0;   ///< wall time of plan() on the prebuilt scene (no tree build)
  double build_ms = 0.0;  ///< building both trees
};

std::string status_name(PlanStatus s) {
  switch (s) {
    case PlanStatus::solved: return "solved";
    case PlanStatus::no_path_time: return "no path (time)";
    case PlanStatus::no_path_bounds: return "no path (bounds)";
    case PlanStatus::no_path_resolution: return "no path (resolution)";
    case PlanStatus::invalid_start: return "invalid start";
    case PlanStatus::invalid_goal: return "invalid goal";
    case PlanStatus::invalid_bounds: return "invalid bounds";
  }
  return "?";
}

SweptRun run_swept(const Case& c, const PlanScene& scene, Fitter fitter, double limit, int threads) {
  SweptRun run;
  run.fitter = fitter;
  run.build_ms = scene.build_ms;
  PlanOptions options;
  options.time_limit = limit;
  options.threads = threads;
  const auto t0 = Clock::now();
  run.result = plan(c.problem, scene, options);
  run.plan_ms = ms_since(t0);
  return run;
}

// ---- OMPL + FCL -------------------------------------------------------------------------------

using FclModel = fcl::BVHModel<fcl::OBBRSSd>;

std::shared_ptr<FclModel> fcl_model(const TriangleSoup& soup) {
  std::vector<fcl::Vector3d> vertices;
  std::vector<fcl::Triangle> faces;
  vertices.reserve(3 * soup.triangles.size());
  faces.reserve(soup.triangles.size());
  for (const Triangle& t : soup.triangles) {
    const auto base = vertices.size();
    vertices.push_back(t.p);
    vertices.push_back(t.q);
    vertices.push_back(t.r);
    faces.emplace_back(base, base + 1, base + 2);
  }
  auto model = std::make_shared<FclModel>();
  model->beginModel(static_cast<int>(faces.size()), static_cast<int>(vertices.size()));
  model->addSubModel(vertices, faces);
  model->endModel();
  return model;
}

/// What both planners share about a problem: the reference point, r_max, the bounds of the
/// reference point and the goal box, computed as swept's planner does.
struct Geometry {
  Vec3 reference = Vec3::Zero();
  double radius = 0.0;
  Aabb bounds;    ///< of the reference point
  Aabb goal_box;  ///< the obstacles' box grown by the goal margin
};

Geometry geometry_of(const Problem& pb, const PlanScene& scene) {
  Geometry g;
  g.reference = scene.reference;
  g.radius = std::max(scene.radius, 1e-12);
  const double size = std::max(scene.obstacle_box.extent(), 2 * g.radius);
  g.goal_box = scene.obstacle_box;
  g.goal_box.min.array() -= pb.goal_margin;
  g.goal_box.max.array() += pb.goal_margin;
  if (pb.bounds) {
    g.bounds = *pb.bounds;
  } else {
    g.bounds = g.goal_box;
    g.bounds.min.array() -= 2.2 * g.radius + 0.05 * size;
    g.bounds.max.array() += 2.2 * g.radius + 0.05 * size;
    g.bounds.extend(pb.start.apply(g.reference));
    if (pb.goal) g.bounds.extend(pb.goal->apply(g.reference));
  }
  return g;
}

/// Maps OMPL states (the reference point's position, and the rotation about it) to body poses.
struct StateMap {
  bool rotates = true;
  Vec3 reference = Vec3::Zero();
  Mat3 fixed_rotation = Mat3::Identity();  ///< the start orientation when the rotation is fixed

  Vec3 point(const ob::State* s) const {
    if (!rotates) {
      const double* v = s->as<ob::RealVectorStateSpace::StateType>()->values;
      return Vec3(v[0], v[1], v[2]);
    }
    const auto* se3 = s->as<ob::SE3StateSpace::StateType>();
    return Vec3(se3->getX(), se3->getY(), se3->getZ());
  }
  Mat3 rotation(const ob::State* s) const {
    if (!rotates) return fixed_rotation;
    const auto& r = s->as<ob::SE3StateSpace::StateType>()->rotation();
    return Quat(r.w, r.x, r.y, r.z).normalized().toRotationMatrix();
  }
  Pose pose(const ob::State* s) const {
    const Mat3 rot = rotation(s);
    return {rot, point(s) - rot * reference};
  }
  void set(ob::State* s, const Pose& body_pose) const {
    const Vec3 p = body_pose.apply(reference);
    if (!rotates) {
      double* v = s->as<ob::RealVectorStateSpace::StateType>()->values;
      for (int i = 0; i < 3; ++i) v[i] = p[i];
      return;
    }
    auto* se3 = s->as<ob::SE3StateSpace::StateType>();
    se3->setXYZ(p.x(), p.y(), p.z());
    const Quat q = body_pose.quaternion();
    se3->rotation().x = q.x();
    se3->rotation().y = q.y();
    se3->rotation().z = q.z();
    se3->rotation().w = q.w();
  }
};

/// "The body's bounding sphere (radius r_max about the reference point) is outside the
/// obstacles' box grown by the margin": swept's goal test, sampleable so that RRTConnect can
/// grow its goal tree from it.
class OutsideBoxGoal : public ob::GoalSampleableRegion {
 public:
  OutsideBoxGoal(const ob::SpaceInformationPtr& si, StateMap map, Aabb box, double radius, Aabb bounds)
      : ob::GoalSampleableRegion(si), map_(map), box_(box), r_(radius), bounds_(bounds) {}

  double distanceGoal(const ob::State* st) const override {
    const Vec3 p = map_.point(st);
    double best = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 3; ++i) {
      best = std::min(best, std::max(0.0, box_.max[i] + r_ - p[i]));
      best = std::min(best, std::max(0.0, p[i] - (box_.min[i] - r_)));
    }
    return best;
  }

  void sampleGoal(ob::State* st) const override {
    if (!sampler_) sampler_ = si_->allocStateSampler();
    // Uniform over the bounds, rejecting the inside of the grown box; when that region is thin,
    // move the reference point onto a random side that has room.
    for (int attempt = 0; attempt < 1000; ++attempt) {
      sampler_->sampleUniform(st);
      if (distanceGoal(st) <= 0.0) return;
    }
    Vec3 p = map_.point(st);
    std::vector<std::pair<int, int>> sides;  // (axis, +1/−1)
    for (int i = 0; i < 3; ++i) {
      if (bounds_.max[i] >= box_.max[i] + r_) sides.emplace_back(i, +1);
      if (bounds_.min[i] <= box_.min[i] - r_) sides.emplace_back(i, -1);
    }
    if (sides.empty()) return;  // unreachable region: leave the (invalid) sample to be rejected
    const auto [axis, dir] = sides[static_cast<std::size_t>(rng_.uniformInt(0, static_cast<int>(sides.size()) - 1))];
    p[axis] = dir > 0 ? rng_.uniformReal(box_.max[axis] + r_, bounds_.max[axis])
                      : rng_.uniformReal(bounds_.min[axis], box_.min[axis] - r_);
    Pose q = map_.pose(st);
    const Mat3 rot = q.rotation;
    map_.set(st, Pose{rot, p - rot * map_.reference});
  }

  unsigned int maxSampleCount() const override { return std::numeric_limits<unsigned int>::max(); }

 private:
  StateMap map_;
  Aabb box_;
  double r_;
  Aabb bounds_;
  mutable ob::StateSamplerPtr sampler_;
  mutable ompl::RNG rng_;
};

struct OmplRun {
  std::uint32_t seed = 0;
  bool solved = false;
  double ms = 0.0;
  std::string status;
  std::size_t waypoints = 0;
  std::uint64_t checks = 0;  ///< state validity checks
  /// The solution path re-checked between OMPL's samples by swept's certified motion query
  /// (margin 0): "free", "collides" (a pose in contact was found), or "undecided".
  std::string verified;
};

/// Checks every segment of a path (poses of the body frame, interpolated about `reference` as
/// OMPL's SE(3) interpolation does) for contact along the continuous motion.
std::string verify_path(const PlanScene& scene, const std::vector<Pose>& poses) {
  bool undecided = false;
  for (std::size_t i = 0; i + 1 < poses.size(); ++i) {
    const MotionResult m = motion_clearance(scene.obstacle_tree, Pose{}, scene.body_tree,
                                            {poses[i], poses[i + 1], scene.reference, scene.radius}, {.margin = 0.0});
    if (m.clear()) continue;
    if (m.status == MotionStatus::blocked && m.distance_at_block <= 0.0) return "collides";
    undecided = true;
  }
  return undecided ? "undecided" : "free";
}

OmplRun run_ompl(const Case& c, const Geometry& g, const PlanScene& scene, const FclModel& body,
                 const FclModel& obstacles, std::uint32_t seed, double limit, bool collide_only) {
  const Problem& pb = c.problem;
  // Reseeds OMPL's seed generator before this run's objects draw their seeds. After the first
  // run OMPL 1.5 logs that sampling "will not be deterministic", but it does reseed (see
  // RNGSeedGenerator::setSeed), so each seed gives the same run: silence that one message.
  const auto level = ompl::msg::getLogLevel();
  ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
  ompl::RNG::setSeed(seed);
  ompl::msg::setLogLevel(level);
  OmplRun run;
  run.seed = seed;

  StateMap map;
  map.rotates = pb.rotation != RotationMode::none;
  map.reference = g.reference;
  map.fixed_rotation = pb.start.rotation;
  ob::RealVectorBounds rb(3);
  for (int i = 0; i < 3; ++i) {
    rb.setLow(static_cast<unsigned>(i), g.bounds.min[i]);
    rb.setHigh(static_cast<unsigned>(i), g.bounds.max[i]);
  }
  ob::StateSpacePtr space;
  if (map.rotates) {
    auto se3 = std::make_shared<ob::SE3StateSpace>();
    se3->setBounds(rb);
    space = se3;
  } else {
    auto rv = std::make_shared<ob::RealVectorStateSpace>(3);
    rv->setBounds(rb);
    space = rv;
  }
  og::SimpleSetup ss(space);
  auto checks = std::make_shared<std::atomic<std::uint64_t>>(0);
  const Mat3 start_rotation = pb.start.rotation;
  ss.setStateValidityChecker([&, checks, map, start_rotation](const ob::State* s) {
    checks->fetch_add(1, std::memory_order_relaxed);
    if (!ss.getSpaceInformation()->satisfiesBounds(s)) return false;
    const Pose q = map.pose(s);
    if (pb.rotation == RotationMode::limits) {
      const Eigen::AngleAxisd aa(q.rotation * start_rotation.transpose());
      const Vec3 w = aa.angle() * aa.axis();
      for (int i = 0; i < 3; ++i)
        if (w[i] < pb.rotation_limits[static_cast<std::size_t>(i)][0] ||
            w[i] > pb.rotation_limits[static_cast<std::size_t>(i)][1])
          return false;
    }
    fcl::Transform3d tf = fcl::Transform3d::Identity();
    tf.linear() = q.rotation;
    tf.translation() = q.translation;
    const fcl::Transform3d identity = fcl::Transform3d::Identity();
    fcl::CollisionRequestd creq;
    fcl::CollisionResultd cres;
    if (fcl::collide(&body, tf, &obstacles, identity, creq, cres) > 0) return false;
    if (pb.clearance <= 0.0 || collide_only) return true;
    fcl::DistanceRequestd dreq;
    fcl::DistanceResultd dres;
    fcl::distance(&body, tf, &obstacles, identity, dreq, dres);
    return dres.min_distance >= pb.clearance;
  });

  ob::ScopedState<> start(space);
  map.set(start.get(), pb.start);
  ss.setStartState(start);
  if (pb.goal) {
    ob::ScopedState<> goal(space);
    map.set(goal.get(), *pb.goal);
    ss.setGoalState(goal);
  } else {
    ss.setGoal(std::make_shared<OutsideBoxGoal>(ss.getSpaceInformation(), map, g.goal_box, g.radius, g.bounds));
  }
  ss.setPlanner(std::make_shared<og::RRTConnect>(ss.getSpaceInformation()));
  ss.setup();

  const auto t0 = Clock::now();
  const ob::PlannerStatus status = ss.solve(ob::timedPlannerTerminationCondition(limit));
  run.ms = ms_since(t0);
  run.solved = status == ob::PlannerStatus::EXACT_SOLUTION;
  run.status = status.asString();
  run.checks = checks->load();
  if (run.solved) {
    const auto& states = ss.getSolutionPath().getStates();
    run.waypoints = states.size();
    std::vector<Pose> poses;
    for (const ob::State* s : states) poses.push_back(map.pose(s));
    run.verified = verify_path(scene, poses);
  }
  return run;
}

// ---- one problem ------------------------------------------------------------------------------

/// Median of a sample (the mean of the middle two for an even count); 0 for none.
double median(std::vector<double> t) {
  if (t.empty()) return 0.0;
  std::sort(t.begin(), t.end());
  const std::size_t n = t.size();
  return n % 2 ? t[n / 2] : 0.5 * (t[n / 2 - 1] + t[n / 2]);
}

struct Row {
  std::string name, kind;
  std::size_t body_triangles = 0, obstacle_triangles = 0;
  double clearance = 0.0;
  std::string rotation;
  std::vector<SweptRun> swept;  ///< [0], [1]: the problem's fitter twice; then the other fitters
  bool deterministic = false;
  std::vector<OmplRun> ompl;
  double ompl_fcl_build_ms = 0.0;
  std::string error;  ///< set when the problem could not be loaded

  const SweptRun& main() const { return swept.front(); }
  /// plan() times of every run of the problem's fitter (swept is deterministic: the same path
  /// each time, so repeats measure the timing spread only).
  std::vector<double> main_ms;
  /// Median over the runs of the problem's fitter: compared with OMPL's median over seeds.
  double swept_median() const { return main_ms.empty() ? main().plan_ms : median(main_ms); }
  int ompl_colliding() const {
    return static_cast<int>(std::count_if(ompl.begin(), ompl.end(), [](const OmplRun& r) { return r.verified == "collides"; }));
  }
  int ompl_successes() const {
    return static_cast<int>(std::count_if(ompl.begin(), ompl.end(), [](const OmplRun& r) { return r.solved; }));
  }
  /// Median over all seeds, failures counted at the time they took (the limit).
  double ompl_median() const {
    std::vector<double> t;
    for (const auto& r : ompl) t.push_back(r.ms);
    return median(std::move(t));
  }
  double ompl_min() const {
    double m = std::numeric_limits<double>::infinity();
    for (const auto& r : ompl) m = std::min(m, r.ms);
    return m;
  }
  double ompl_max() const {
    double m = 0.0;
    for (const auto& r : ompl) m = std::max(m, r.ms);
    return m;
  }
  /// The goal for this problem.
  std::string verdict() const {
    if (!error.empty()) return "not run";
    const bool ours = main().result.solved();
    const int theirs = ompl_successes();
    const double ratio = ompl_median() / std::max(swept_median(), 1e-9);
    if (!ours && theirs == 0) {
      const PlanStatus s = main().result.status;
      if (s == PlanStatus::no_path_bounds || s == PlanStatus::no_path_resolution) return "neither (swept: no path)";
      return "neither solved";
    }
    if (!ours) return "MISSED: OMPL solves it";
    if (theirs == 0) return "met: OMPL 0 %";
    return ratio >= 3.0 ? "met: >= 3x" : "MISSED: < 3x";
  }
};

Row run_case(const Case& c, double limit, int seeds, int threads, bool collide_only) {
  Row row;
  row.name = c.name;
  row.kind = c.kind;
  row.clearance = c.problem.clearance;
  row.rotation = c.problem.rotation == RotationMode::none ? "none" : c.problem.rotation == RotationMode::free ? "free" : "limits";
  std::vector<Fitter> fitters{c.problem.build.fitter, c.problem.build.fitter};
  for (Fitter f : {Fitter::pqp, Fitter::rapid2, Fitter::inertia})
    if (f != c.problem.build.fitter) fitters.push_back(f);
  std::optional<PlanScene> main_scene;
  for (std::size_t i = 0; i < fitters.size(); ++i) {
    if (i == 1 && main_scene) {  // the determinism check reuses the scene
      row.swept.push_back(run_swept(c, *main_scene, fitters[i], limit, threads));
    } else {
      auto scene = scene_for(c, fitters[i]);
      if (!scene) {
        row.error = scene.error().message;
        return row;
      }
      row.swept.push_back(run_swept(c, *scene, fitters[i], limit, threads));
      if (i == 0) main_scene = std::move(*scene);
    }
    const SweptRun& s = row.swept.back();
    std::fprintf(stderr, "  swept %-8s %-22s plan %10.1f ms  build %7.1f ms  waypoints %zu\n", std::string(to_string(s.fitter)).c_str(),
                 status_name(s.result.status).c_str(), s.plan_ms, s.build_ms, s.result.path.poses.size());
  }
  // More runs of the problem's fitter, as many in all as OMPL gets seeds (at least two): the
  // median time, and every run must give the same path.
  const PlanResult& first = row.swept[0].result;
  auto same = [&](const PlanResult& r) { return r.status == first.status && r.path_hash == first.path_hash; };
  row.deterministic = same(row.swept[1].result);
  row.main_ms = {row.swept[0].plan_ms, row.swept[1].plan_ms};
  // (A run that ends on the time limit is not repeated: its median is the limit anyway.)
  for (int k = 2; first.status != PlanStatus::no_path_time && k < seeds; ++k) {
    const SweptRun again = run_swept(c, *main_scene, c.problem.build.fitter, limit, threads);
    row.main_ms.push_back(again.plan_ms);
    row.deterministic = row.deterministic && same(again.result);
  }
  row.body_triangles = main_scene->body.triangles.size();
  row.obstacle_triangles = main_scene->obstacles.triangles.size();

  const Geometry g = geometry_of(c.problem, *main_scene);
  const auto t0 = Clock::now();
  const auto body = fcl_model(main_scene->body);
  const auto obstacles = fcl_model(main_scene->obstacles);
  row.ompl_fcl_build_ms = ms_since(t0);
  for (int k = 0; k < seeds; ++k) {
    const auto seed = static_cast<std::uint32_t>(k + 1);
    row.ompl.push_back(run_ompl(c, g, *main_scene, *body, *obstacles, seed, limit, collide_only));
    const OmplRun& r = row.ompl.back();
    std::fprintf(stderr, "  ompl  seed %-3u %-22s %10.1f ms  checks %llu  waypoints %zu%s%s\n", r.seed, r.status.c_str(),
                 r.ms, static_cast<unsigned long long>(r.checks), r.waypoints, r.solved ? "  path " : "",
                 r.verified.c_str());
  }
  return row;
}

// ---- output -----------------------------------------------------------------------------------

std::string fmt(double v, int prec = 1) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", prec, v);
  return buf;
}

void print_tables(const std::vector<Row>& rows, double limit, int seeds, int threads, bool collide_only) {
  std::printf("\nPlanner side by side: swept (fitter of the problem, %s threads) vs OMPL RRTConnect + FCL, "
              "%d seeds, %.0f s limit\n",
              threads > 0 ? std::to_string(threads).c_str() : "all", seeds, limit);
  if (collide_only) std::printf("OMPL's validity check: fcl::collide only (no clearance; swept still certifies it)\n");
  std::printf("%-18s %9s %11s %11s %-20s %5s | %7s %11s %21s %6s | %8s  %s\n", "problem", "clearance", "swept ms",
              "(+build)", "swept status", "wayp", "OMPL ok", "median ms", "min-max ms", "hit", "ratio", "goal");
  for (const Row& r : rows) {
    if (!r.error.empty()) {
      std::printf("%-18s  not run: %s\n", r.name.c_str(), r.error.c_str());
      continue;
    }
    const SweptRun& s = r.main();
    const std::string ok = std::to_string(r.ompl_successes()) + "/" + std::to_string(r.ompl.size());
    const std::string range = fmt(r.ompl_min()) + "-" + fmt(r.ompl_max());
    std::printf("%-18s %9g %11s %11s %-20s %5zu | %7s %11s %21s %6d | %8s  %s\n", r.name.c_str(), r.clearance,
                fmt(r.swept_median()).c_str(), fmt(r.swept_median() + s.build_ms).c_str(), status_name(s.result.status).c_str(),
                s.result.path.poses.size(), ok.c_str(), fmt(r.ompl_median()).c_str(), range.c_str(), r.ompl_colliding(),
                fmt(r.ompl_median() / std::max(r.swept_median(), 1e-9), 2).c_str(), r.verdict().c_str());
  }
  std::printf("swept ms: plan() on the prebuilt trees, median of as many runs as OMPL has seeds (same path each run); "
              "(+build): with the tree build. OMPL ok: exact solutions; "
              "median over all seeds, failures counted at the limit; hit: OMPL solutions that swept's certified "
              "motion check finds in contact between OMPL's discrete motion samples; ratio: OMPL median / swept ms.\n");
  std::printf("\nswept per fitter (plan ms of the first run without the tree build; build ms; status) and determinism\n");
  std::printf("%-18s %28s %28s %28s  %s\n", "problem", "pqp", "rapid2", "inertia", "same hash every run");
  for (const Row& r : rows) {
    if (!r.error.empty()) continue;
    std::printf("%-18s", r.name.c_str());
    for (Fitter f : {Fitter::pqp, Fitter::rapid2, Fitter::inertia}) {
      const auto it = std::find_if(r.swept.begin(), r.swept.end(), [&](const SweptRun& s) { return s.fitter == f; });
      const std::string cell = fmt(it->plan_ms) + " +" + fmt(it->build_ms) + " " +
                               (it->result.solved() ? "ok" : status_name(it->result.status));
      std::printf(" %28s", cell.c_str());
    }
    char hash[32];
    std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(r.main().result.path_hash));
    std::printf("  %s (%s)\n", r.deterministic ? "yes" : "NO", hash);
  }
  std::fflush(stdout);
}

nlohmann::json to_json(const std::vector<Row>& rows, double limit, int seeds, int threads, bool collide_only) {
  nlohmann::json j;
  j["time_limit_s"] = limit;
  j["seeds"] = seeds;
  j["swept_threads"] = threads;
  j["ompl_collide_only"] = collide_only;
  j["hardware_threads"] = std::thread::hardware_concurrency();
  for (const Row& r : rows) {
    nlohmann::json p;
    p["name"] = r.name;
    p["kind"] = r.kind;
    if (!r.error.empty()) {
      p["error"] = r.error;
      j["problems"].push_back(p);
      continue;
    }
    p["clearance"] = r.clearance;
    p["rotation"] = r.rotation;
    p["body_triangles"] = r.body_triangles;
    p["obstacle_triangles"] = r.obstacle_triangles;
    for (const SweptRun& s : r.swept) {
      char hash[32];
      std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(s.result.path_hash));
      p["swept"].push_back({{"fitter", std::string(to_string(s.fitter))},
                            {"status", status_name(s.result.status)},
                            {"message", s.result.message},
                            {"plan_ms", s.plan_ms},
                            {"build_ms", s.build_ms},
                            {"result_total_ms", s.result.time_ms.total},
                            {"result_total_minus_build_ms", s.result.time_ms.total - s.result.time_ms.build},
                            {"search_ms", s.result.time_ms.search},
                            {"smooth_ms", s.result.time_ms.smooth},
                            {"waypoints", s.result.path.poses.size()},
                            {"path_length", s.result.path_length},
                            {"min_clearance", s.result.min_clearance},
                            {"distance_queries", s.result.queries.distance},
                            {"nodes_checked", s.result.nodes_checked},
                            {"level", s.result.level},
                            {"path_hash", hash}});
    }
    p["swept_deterministic"] = r.deterministic;
    p["swept_main_runs_ms"] = r.main_ms;
    p["swept_median_ms"] = r.swept_median();
    p["ompl_fcl_build_ms"] = r.ompl_fcl_build_ms;
    for (const OmplRun& o : r.ompl)
      p["ompl"].push_back({{"seed", o.seed},
                           {"solved", o.solved},
                           {"status", o.status},
                           {"ms", o.ms},
                           {"waypoints", o.waypoints},
                           {"path_verified", o.verified},
                           {"validity_checks", o.checks}});
    p["ompl_successes"] = r.ompl_successes();
    p["ompl_paths_colliding"] = r.ompl_colliding();
    p["ompl_median_ms"] = r.ompl_median();
    p["ratio_ompl_median_over_swept"] = r.ompl_median() / std::max(r.swept_median(), 1e-9);
    p["goal"] = r.verdict();
    j["problems"].push_back(p);
  }
  return j;
}

[[noreturn]] void usage(const std::string& why) {
  std::cerr << "bench_plan: " << why << "\n"
            << "usage: bench_plan [--quick] [--time-limit S] [--seeds N] [--threads N] [--only a,b] [--no-cad] "
               "[--ompl-collide-only] [--json FILE]\n"
            << "  --quick        10 s limit, 5 seeds (defaults: 60 s, 5 seeds)\n"
            << "  --threads N    swept's threads (0: all cores; default 0)\n"
            << "  --only a,b     only these problems (peg_in_hole, t_slot, l_tunnel, bar_through_slot, enclosed, "
               "air-cleaner, cylinder-head, tunnel-console)\n"
            << "  --no-cad       skip the CAD scenes\n"
            << "  --ompl-collide-only  OMPL's validity check without the clearance (fcl::collide only)\n"
            << "  --json FILE    also write the results as JSON\n";
  std::exit(2);
}

}  // namespace

int main(int argc, char** argv) {
  double limit = 60.0;
  int seeds = 5, threads = 0;
  bool cad = true, collide_only = false;
  std::vector<std::string> only;
  std::string json_file;
  auto number = [&](int& i, const std::string& flag) -> double {
    if (i + 1 >= argc) usage(flag + " needs a value");
    char* end = nullptr;
    const double v = std::strtod(argv[++i], &end);
    if (end == argv[i] || *end != '\0' || !std::isfinite(v)) usage(flag + ": not a number: " + argv[i]);
    return v;
  };
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--quick") {
      limit = 10.0;
      seeds = 5;
    } else if (a == "--time-limit") {
      limit = number(i, a);
      if (limit <= 0) usage("--time-limit must be > 0");
    } else if (a == "--seeds") {
      seeds = static_cast<int>(number(i, a));
      if (seeds < 1) usage("--seeds must be >= 1");
    } else if (a == "--threads") {
      threads = static_cast<int>(number(i, a));
      if (threads < 0) usage("--threads must be >= 0");
    } else if (a == "--only") {
      if (i + 1 >= argc) usage("--only needs a value");
      std::stringstream ss(argv[++i]);
      for (std::string n; std::getline(ss, n, ',');)
        if (!n.empty()) only.push_back(n);
    } else if (a == "--no-cad") {
      cad = false;
    } else if (a == "--ompl-collide-only") {
      collide_only = true;
    } else if (a == "--json") {
      if (i + 1 >= argc) usage("--json needs a file");
      json_file = argv[++i];
    } else if (a == "-h" || a == "--help") {
      usage("side-by-side planner benchmark against OMPL RRTConnect + FCL");
    } else {
      usage("unknown argument " + a);
    }
  }
  auto wanted = [&](const std::string& n) { return only.empty() || std::find(only.begin(), only.end(), n) != only.end(); };
  ompl::msg::setLogLevel(ompl::msg::LOG_WARN);

  std::vector<Case> cases;
  for (auto& g : scenes::box_problems()) {
    if (!wanted(g.name)) continue;
    cases.push_back(Case{g.name, g.problem, std::move(g.obstacles), std::move(g.body), "box"});
  }
  std::filesystem::path tmp;
  if (cad) {
    for (const auto& info : scenes::catalog()) {
      if (!wanted(info.name)) continue;
      if (tmp.empty()) {
        tmp = std::filesystem::temp_directory_path() /
              ("swept-bench-plan-" + std::to_string(static_cast<long long>(std::time(nullptr))));
      }
      const auto t0 = Clock::now();
      auto report = scenes::generate_scene({.name = info.name, .scale = scenes::Scale::test, .output_dir = tmp / info.name});
      if (!report) {
        std::fprintf(stderr, "bench_plan: skipping the CAD scene %s: %s\n", info.name.c_str(), report.error().message.c_str());
        continue;
      }
      auto problem = load_problem(report->problem_file);
      if (!problem) {
        std::fprintf(stderr, "bench_plan: skipping the CAD scene %s: %s\n", info.name.c_str(), problem.error().message.c_str());
        continue;
      }
      std::fprintf(stderr, "bench_plan: generated %s (%zu + %zu triangles) in %.1f s\n", info.name.c_str(),
                   report->body_triangles, report->obstacle_triangles, ms_since(t0) / 1e3);
      cases.push_back(Case{info.name, *problem, std::nullopt, std::nullopt, "cad"});
    }
  }
  if (cases.empty()) usage("no problem selected");

  std::vector<Row> rows;
  for (const Case& c : cases) {
    std::fprintf(stderr, "bench_plan: %s\n", c.name.c_str());
    rows.push_back(run_case(c, limit, seeds, threads, collide_only));
    if (!rows.back().error.empty()) std::fprintf(stderr, "  not run: %s\n", rows.back().error.c_str());
    if (!json_file.empty()) {  // rewritten after every problem, so a long run leaves partial results
      // Whole or not at all (a temporary file renamed into place); invalid UTF-8 in names becomes U+FFFD.
      const std::string text =
          to_json(rows, limit, seeds, threads, collide_only).dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
      if (auto written = write_file_atomically(json_file, text); !written)
        std::fprintf(stderr, "bench_plan: %s\n", written.error().message.c_str());
    }
  }
  print_tables(rows, limit, seeds, threads, collide_only);
  if (!tmp.empty()) {
    std::error_code ec;
    std::filesystem::remove_all(tmp, ec);
  }
  return 0;
}
