#pragma once
// Phase 3 (internal to src/plan): deterministic shortcut smoothing of a found path.
#include "plan_context.h"

#include <vector>

namespace swept::detail {

/// Greedy shortcuts, twice over: from each waypoint (after the first `fixed` segments, which
/// stay as they are: the escape from contact), the farthest later waypoint that one certified
/// straight motion reaches, found by binary search (the next waypoint is reachable: the path's
/// own segment); a shortcut whose certificate needs more than a few hundred queries is not
/// taken (it grazes the margin). Every segment of the result is certified. Stops early at the time limit,
/// keeping a path whose segments are all certified.
void smooth(PlanContext& context, std::vector<Pose>& path, std::size_t fixed);

}  // namespace swept::detail
