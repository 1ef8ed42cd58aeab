// OMPL RRTConnect + FCL on a swept problem: see swept/bench/ompl_peer.h.
#include "swept/bench/ompl_peer.h"

#include "swept/bench/fcl_model.h"
#include "swept/bench/timing.h"
#include "swept/query/query.h"

#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/distance.h>
#include <ompl/base/goals/GoalSampleableRegion.h>
#include <ompl/base/goals/GoalState.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/SE3StateSpace.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <atomic>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace swept::bench {
namespace {

namespace ob = ompl::base;
namespace og = ompl::geometric;

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
  OutsideBoxGoal(const ob::SpaceInformationPtr& si, StateMap map, const SearchSpace& space)
      : ob::GoalSampleableRegion(si), map_(map), space_(space), box_(space.goal_box), r_(space.radius),
        bounds_(space.bounds) {}

  double distanceGoal(const ob::State* st) const override { return distance_to_goal_region(space_, map_.point(st)); }

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
  SearchSpace space_;
  Aabb box_;
  double r_;
  Aabb bounds_;
  mutable ob::StateSamplerPtr sampler_;
  mutable ompl::RNG rng_;
};

/// The path's length in swept's motion metric (PlanResult::path_length's).
double metric_length(const PlanScene& scene, const std::vector<Pose>& poses) {
  double length = 0.0;
  for (std::size_t i = 1; i < poses.size(); ++i) length += motion_length(poses[i - 1], poses[i], scene.reference, scene.radius);
  return length;
}

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

}  // namespace

OmplRun run_ompl(const Problem& pb, const SearchSpace& g, const PlanScene& scene,
                 const fcl::BVHModel<fcl::OBBRSSd>& body, const fcl::BVHModel<fcl::OBBRSSd>& obstacles,
                 std::uint32_t seed, const CompareOptions& o) {
  const bool collide_only = o.collide_only;
  const double limit = o.time_limit;
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
    const fcl::Transform3d tf = to_fcl(q);
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
    ss.setGoal(std::make_shared<OutsideBoxGoal>(ss.getSpaceInformation(), map, g));
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
    run.length = metric_length(scene, poses);
    // OMPL's own smoothing, timed apart from the solve: swept's plan times include its
    // smoothing, so solve + simplify is the like-for-like figure.
    const auto t1 = Clock::now();
    ss.simplifySolution();
    run.simplify_ms = ms_since(t1);
    std::vector<Pose> simplified;
    for (const ob::State* s : ss.getSolutionPath().getStates()) simplified.push_back(map.pose(s));
    run.simplified_verified = verify_path(scene, simplified);
    run.simplified_length = metric_length(scene, simplified);
  }
  return run;
}

}  // namespace swept::bench
