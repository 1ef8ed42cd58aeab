#pragma once
/// The gearbox assembly (`swept scene gearbox`, docs/assembly.md): a housing (the base) with a
/// blind bearing seat, a shaft with a collar standing in its lower bearing, a gear on the collar,
/// the upper bearing held in the cover's recess, the cover on the housing's walls, and four
/// screws through the cover into the walls. Modelled with OpenCASCADE, written as one binary
/// STL per part and an `assembly.toml` (docs/assembly-format.md) for `swept disassemble`.
///
/// The known answer: every screw before the cover; the cover before the upper bearing, the gear
/// and the shaft; the upper bearing before the gear (it sits above it on the shaft); the gear
/// before the shaft (the collar holds it); the shaft before the lower bearing (the collar again).
#include "swept/scenes/scenes.h"

namespace swept::scenes {

/// Models, tessellates and writes the gearbox: at Scale::test about 20,000 triangles, at
/// Scale::paper over 500,000 (fixed deflections, deterministic bytes). report.problem_file is
/// the assembly.toml; every mesh is listed as an obstacle (nothing is "the body" of an assembly).
Result<SceneReport> generate_gearbox(const GenerateRequest& request);

}  // namespace swept::scenes
