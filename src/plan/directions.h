#pragma once
// Candidate directions of straight moves (internal to src/plan): shared by the straight-move
// phase and the escape from contact.
#include "plan_context.h"

#include <vector>

namespace swept::detail {

/// Unit directions for straight moves of the body from `start`, without near-repeats
/// (cosine > 1 − 1e-9): toward the goal pose's reference point, then +z, −z, +x, −x, +y, −y
/// (most parts come out upwards), then ± each of the body's axes at `start`'s orientation, as
/// the problem's fitter (`problem.build.fitter`; inertia by default) fits them to all of the
/// body's triangles.
std::vector<Vec3> candidate_directions(const PlanContext& context, const Pose& start);

/// Adds the unit vector of `d` to `list` unless it is (near) zero or (near) repeats one there.
void add_direction(std::vector<Vec3>& list, const Vec3& d);

/// How far the point `p` can travel along the unit direction `u` inside `box` (0 if outside).
double room_along(const Aabb& box, const Vec3& p, const Vec3& u);

/// The shortest move of the reference point from `p` along `u` (at most `room`) that brings the
/// body's bounding sphere outside the goal box, by bisection (40 halvings), or a negative value
/// when the move of length `room` does not.
double shortest_move_out(const PlanContext& context, const Mat3& rotation, const Vec3& p, const Vec3& u,
                         double room);

}  // namespace swept::detail
