#pragma once
/// Internal to swept_scenes: the B-rep description of one scene before tessellation.
/// Needs the OpenCASCADE include directory (see modeling.h).
#include "swept/geometry/pose.h"

#include <TopoDS_Shape.hxx>

#include <array>
#include <string>
#include <vector>

namespace swept::scenes::detail {

/// One mesh file of a scene: a body part (in the body frame) or an obstacle (in the world).
struct ScenePart {
  std::string file;    ///< output file name, e.g. "frame.stl"
  bool body = false;
  TopoDS_Shape shape;
};

/// A scene: parts, start and goal, bounds, clearance. Lengths in mm.
struct SceneModel {
  std::vector<ScenePart> parts;
  Pose start;                 ///< body frame in the world at the start
  bool goal_outside = false;  ///< goal region "outside the obstacles' box grown by goal_margin"
  double goal_margin = 0.0;
  Pose goal;                  ///< goal pose when !goal_outside
  Vec3 bounds_min = Vec3::Zero();  ///< where the body frame's origin may go
  Vec3 bounds_max = Vec3::Zero();
  double clearance = 0.5;     ///< planner margin, mm
  std::string comment;        ///< written at the top of problem.toml
  /// Starting points of the deflection search, mm, {body, obstacles}: the deflections the
  /// search converged to when measured (docs/scenes.md); any start converges, these save runs.
  std::array<double, 2> test_deflection{1.0, 1.0};
  std::array<double, 2> paper_deflection{1.0, 1.0};
};

SceneModel build_air_cleaner();
SceneModel build_cylinder_head();
SceneModel build_tunnel_console();

}  // namespace swept::scenes::detail
