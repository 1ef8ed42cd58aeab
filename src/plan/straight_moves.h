#pragma once
// Phase 1 of the search (internal to src/plan): straight moves. Most parts come out along a
// line or two, so before any grid the planner tries a few paths of one or two straight moves.
#include "plan_context.h"

#include <optional>
#include <vector>

namespace swept::detail {

/// The first certified path of straight moves from `start` (lower bound `start_distance` on its
/// distance): the start–goal segment; then along each candidate direction one move to the goal
/// region (the shortest that reaches it) or, with a goal pose, a move of 1/4, 1/2 or all of the
/// room inside the bounds followed by a move to the goal pose; then for a goal region two
/// moves, a slide along u1 (1/8, 1/4, 1/2, 3/4 of the room) and a move out along a direction u2
/// not within 60° of ±u1. Nullopt when none is certified (or the time is up).
std::optional<std::vector<Pose>> straight_moves(PlanContext& context, const Pose& start, double start_distance);

}  // namespace swept::detail
