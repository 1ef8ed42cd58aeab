// The way out of contact (escape.h).
#include "escape.h"

#include "directions.h"

#include <algorithm>
#include <limits>

namespace swept::detail {
namespace {

// Slides tried before a lift, along each direction: 10^-3·size·1.5^k for k < kSlides.
constexpr int kSlides = 18;

struct Pull {
  Vec3 direction = Vec3::Zero();
  double length = std::numeric_limits<double>::infinity();
};

// The directions to try from where `moving` is: the contact layer's, then the planner's
// candidates (toward the goal, the body's axes), each once.
std::vector<Vec3> directions_from(const PlanContext& context, const ContactMoves& contact, const contact::Body& moving,
                                  const Pose& at) {
  std::vector<Vec3> out = contact.directions(moving);
  for (const Vec3& d : candidate_directions(context, at)) add_direction(out, d);
  return out;
}

// The nearest single pull from `at` (the body there: `moving`) to a pose with the full
// clearance, over `directions`; length +∞ when none.
Pull nearest_pull(PlanContext& context, const ContactMoves& contact, const contact::Body& moving, const Pose& at,
                  const std::vector<Vec3>& directions) {
  const double size = context.scene_size();
  const Vec3 from = context.reference_at(at);
  // Along each direction the first free pose; then the pulls certified nearest first.
  std::vector<Pull> free_ends;
  for (const Vec3& u : directions) {
    const double room = room_along(context.space.bounds, from, u);
    for (double s = 1e-3 * size; s <= room; s *= 1.5) {
      if (context.out_of_time()) return {};
      if (context.free_at(context.pose_with_reference_at(at.rotation, from + s * u), s)) {
        free_ends.push_back({u, s});
        break;  // the first free pose along u decides this direction
      }
    }
  }
  std::stable_sort(free_ends.begin(), free_ends.end(), [](const Pull& a, const Pull& b) { return a.length < b.length; });
  for (const Pull& p : free_ends) {
    if (context.out_of_time()) return {};
    if (contact.pull_clear(moving, p.direction, p.length)) return p;
  }
  return {};
}

}  // namespace

std::optional<std::vector<Pose>> escape_from_contact(PlanContext& context, const ContactMoves& contact, const Pose& from) {
  const contact::Body moving = contact.body_at(from);
  const std::vector<Vec3> directions = directions_from(context, contact, moving, from);
  const Vec3 start = context.reference_at(from);
  auto pose_at = [&](const Vec3& point) { return context.pose_with_reference_at(from.rotation, point); };
  if (const Pull one = nearest_pull(context, contact, moving, from, directions); one.length < 1e300)
    return std::vector<Pose>{pose_at(start + one.length * one.direction)};
  // A slide along a face, then a lift from where it ends.
  const double size = context.scene_size();
  for (const Vec3& u : directions) {
    const double room = room_along(context.space.bounds, start, u);
    double s = 1e-3 * size;
    for (int k = 0; k < kSlides && s <= room; ++k, s *= 1.5) {
      if (context.out_of_time()) return std::nullopt;
      // A longer slide sweeps what a shorter one does: the first blocked length ends this direction.
      if (!contact.pull_clear(moving, u, s)) break;
      const Pose mid = pose_at(start + s * u);
      const contact::Body there = contact::translated(moving, s * u);
      const Pull lift = nearest_pull(context, contact, there, mid, directions_from(context, contact, there, mid));
      if (lift.length < 1e300)
        return std::vector<Pose>{mid, context.pose_with_reference_at(from.rotation, context.reference_at(mid) + lift.length * lift.direction)};
    }
  }
  return std::nullopt;
}

}  // namespace swept::detail
