#pragma once
/// OMPL's side of the planner-vs-OMPL benchmark, set up as an OMPL user would, with nothing tuned:
/// - state: the pose of the body about swept's reference point c (translation of c, rotation
///   about c) in SE3StateSpace, or RealVectorStateSpace(3) when the problem fixes the rotation.
///   OMPL's SE(3) interpolation (linear translation, slerp) is then exactly swept's local path,
///   and the translation bounds are exactly swept's bounds on the reference point
///   (swept::search_space(), include/swept/plan/search_space.h).
/// - validity: fcl::collide of BVHModel<OBBRSSd> body against the obstacles, then
///   fcl::distance ≥ the problem's clearance (swept certifies the same margin); rotation limits
///   (mode "limits") checked on the rotation vector relative to the start orientation, as swept's
///   grid does.
/// - motions: OMPL's default DiscreteMotionValidator (longest valid segment 1 % of the space's
///   extent); planner: RRTConnect with its default range; goal: GoalState, or for `goal outside`
///   problems a GoalSampleableRegion "the sphere of radius r_max about c is outside the
///   obstacles' box grown by the margin" (swept's goal test).
/// - seeds: ompl::RNG::setSeed(seed) before each run; time: the solve call only (OMPL's raw
///   solve time). Each solution is then re-checked, outside the timing, by swept's certified
///   motion query (margin 0) to count the paths that collide between the discrete samples;
///   then simplified by SimpleSetup::simplifySolution() (OMPL's defaults), timed on its own
///   (OmplRun::simplify_ms), and the simplified path re-checked the same way.
#include "swept/bench/plan_compare.h"
#include "swept/bench/search_space.h"

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/math/bv/OBBRSS.h>

namespace swept::bench {

/// One OMPL RRTConnect run on the problem, FCL models of the scene's meshes prebuilt.
OmplRun run_ompl(const Problem& problem, const SearchSpace& space, const PlanScene& scene,
                 const fcl::BVHModel<fcl::OBBRSSd>& body, const fcl::BVHModel<fcl::OBBRSSd>& obstacles,
                 std::uint32_t seed, const CompareOptions& o);

}  // namespace swept::bench
