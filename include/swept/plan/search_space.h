#pragma once
/// The planner's search space and goal test, exported so that other planners given the same
/// problem (the OMPL comparison in bench/) search exactly the same space for the same goal.
#include "swept/plan/planner.h"

#include <array>

namespace swept {

/// Where the planner searches. Configurations are poses of the body frame; what is bounded is
/// the body's reference point (world) and, with `RotationMode::limits`, the rotation vector of
/// the orientation relative to the start's (radians, world axes, per axis).
struct SearchSpace {
  Vec3 reference = Vec3::Zero();  ///< body frame: the point motions interpolate about (PlanScene::reference)
  double radius = 0.0;            ///< r_max: largest distance from `reference` to a body vertex (≥ 1e-12)
  /// Bounds of the reference point (world): the problem's `[bounds]`, else the obstacles' box
  /// grown by the goal margin and then by 2.2·r_max + 0.05·size on every side (size: the larger
  /// of the obstacles' box diagonal and 2·r_max), extended to hold the start and the goal.
  Aabb bounds;
  Aabb goal_box;  ///< the obstacles' box (world) grown by the problem's goal margin
  RotationMode rotation = RotationMode::free;
  std::array<std::array<double, 2>, 3> rotation_limits{};  ///< with RotationMode::limits, radians
};

/// The planner's search space for a problem and its loaded scene.
SearchSpace search_space(const Problem& problem, const PlanScene& scene);

/// Is the reference point `point` (world) inside the bounds (boundary included)?
bool in_bounds(const SearchSpace& space, const Vec3& point);

/// Is the body's bounding sphere (radius r_max about the reference point `point`, world)
/// entirely outside the goal box, on some axis?
bool outside_goal_box(const SearchSpace& space, const Vec3& point);

/// The planner's goal test. `goal outside` problems: the body's bounding sphere at `pose` is
/// outside the goal box (`outside_goal_box`). Problems with a goal pose: `pose` is the goal pose
/// itself (the planner ends its paths on it exactly; a sampling planner compares with its own
/// tolerance instead).
bool goal_reached(const SearchSpace& space, const Problem& problem, const Pose& pose);

}  // namespace swept
