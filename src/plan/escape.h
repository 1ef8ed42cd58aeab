#pragma once
// The escape from a start in contact (internal to src/plan; docs/planner.md, "Starting in
// contact"): one pure translation, certified with the start's contact pairs exempt, to the
// nearest pose where the full clearance holds.
#include "plan_context.h"

#include <optional>
#include <vector>

namespace swept::detail {

/// Directions that separate the body at `start` from the obstacle faces of `pairs` (obstacle
/// triangle, body triangle): each touched face's normal, oriented toward the body (toward the
/// touching body triangle, or toward the body's reference point when the two are coplanar),
/// then the normalised sum of every two of them. At most 12 distinct normals, in the order of
/// the pairs.
std::vector<Vec3> separating_directions(const PlanScene& scene, const Pose& start, const TrianglePairs& pairs);

/// The escape's end: along each candidate direction (candidate_directions, then the
/// separating directions of the checker's exempt pairs), the first pose with the full
/// clearance at distances 10^-3·size·1.5^k inside the bounds, kept when the translation to it
/// is certified with the exempt pairs left out; the nearest such pose over all directions.
/// Nullopt when none (or the time is up).
std::optional<Pose> escape_from_contact(PlanContext& context, const Pose& start);

}  // namespace swept::detail
