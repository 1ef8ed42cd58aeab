#pragma once
// The way out of contact (internal to src/plan; docs/planner.md, "The contact model"): from a
// pose in contact — the start, or the goal of an insertion, whose approach is an escape played
// backwards — one or two straight pulls, each certified by the contact layer under the mate rule
// taken where it starts, to the nearest pose with the full clearance.
#include "contact_moves.h"
#include "plan_context.h"

#include <optional>
#include <vector>

namespace swept::detail {

/// The poses after `from` of the way out: one pull (along a contact direction, a world axis,
/// the body's axes or toward the goal) to the first pose with the full clearance at distances
/// 10^-3·size·1.5^k inside the bounds, the nearest such pose over all directions; where no
/// single pull is certified, a slide (along a direction of the same list, as far as it is
/// certified, at the same distances) then such a pull from where the slide ends, the first found
/// in that order. Every pose but the last may be in contact; the last has the full clearance.
/// Nullopt when none (or the time is up).
std::optional<std::vector<Pose>> escape_from_contact(PlanContext& context, const ContactMoves& contact, const Pose& from);

}  // namespace swept::detail
