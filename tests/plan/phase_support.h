#pragma once
// One phase of the planner run on its own: the context a plan() call would give it (the
// problem, its scene and search space, the certificate), for the tests of src/plan's phases.
#include "plan/plan_context.h"
#include "plan/plan_support.h"

#include <memory>

namespace swept::test {

/// Owns everything a PlanContext refers to. Not movable (the context holds references).
struct PhaseRig {
  scenes::GeneratedProblem generated;
  PlanScene scene;
  SearchSpace space;
  detail::Checker check;
  PlanOptions options;
  detail::PlanContext context;

  explicit PhaseRig(scenes::GeneratedProblem g, double time_limit_s = 30.0)
      : generated(std::move(g)),
        scene(scene_of(generated)),
        space(search_space(generated.problem, scene)),
        check(scene, generated.problem.clearance),
        context{generated.problem, scene, space, check, options, detail::Clock::now(), time_limit_s} {}
  PhaseRig(const PhaseRig&) = delete;
  PhaseRig& operator=(const PhaseRig&) = delete;

  const Problem& problem() const { return generated.problem; }
  /// Lower bound on the distance at `pose` as the planner asks for it at its start.
  double start_distance(const Pose& pose) const {
    return check.clearance(pose, check.margin() + 0.05 * context.scene_size());
  }
};

}  // namespace swept::test
