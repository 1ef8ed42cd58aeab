#pragma once
/// The pin-in-bore assembly (`swept scene pin-in-bore`, docs/assembly.md): a headed pin in a
/// through bore of its own radius, both on an axis that is none of x, y, z, written as OpenCASCADE
/// .brep files (so `swept disassemble` reads their cylinders) with an `assembly.toml` that places
/// them and meshes them coarsely: the facets of the pin and of the bore cross by far more than the
/// mating tolerance, their cylinders do not.
///
/// The known answer: the block is the base; the pin leaves along its axis, away from its head,
/// by a straight pull; no other direction is free (the shaft fills the bore, the head sits on
/// the block).
#include "swept/geometry/pose.h"
#include "swept/scenes/scenes.h"

namespace swept::scenes {

/// The pin-in-bore's dimensions and placement (millimetres), for tests that check it against
/// its true geometry.
struct PinInBore {
  static constexpr double kBlockHalf = 20.0;   ///< the block: |x|, |y| ≤ 20, 0 ≤ z ≤ 20 (local frame)
  static constexpr double kBlockHeight = 20.0;
  static constexpr double kRadius = 5.0;       ///< the bore's and the shaft's radius
  static constexpr double kShaftBottom = -10.0;  ///< the shaft: z from −10 to 20
  static constexpr double kHeadRadius = 8.0;   ///< the head: z from 20 to 24
  static constexpr double kHeadTop = 24.0;
  static constexpr double kDeflection = 0.5;   ///< BRepMesh linear deflection of assembly.toml
  /// Both parts are placed with this pose: a rotation of 35° about (1, 2, 0)/√5, then (10, −5, 3).
  static Pose pose();
};

/// Models and writes block.brep, pin.brep (the local frame above) and assembly.toml.
Result<SceneReport> generate_pin_in_bore(const GenerateRequest& request);

}  // namespace swept::scenes
