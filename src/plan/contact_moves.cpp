// The planner's view of the contact layer (contact_moves.h).
#include "contact_moves.h"

#include <memory>

namespace swept::detail {
namespace {

// The scene's tree, not owned: the scene outlives every body made of it.
std::shared_ptr<const Bvh> borrowed(const Bvh& tree) { return std::shared_ptr<const Bvh>(std::shared_ptr<const Bvh>{}, &tree); }

}  // namespace

ContactMoves::ContactMoves(const PlanScene& scene, double clearance, double tolerance)
    : scene_(scene),
      obstacles_(contact::place_body(scene.obstacles, borrowed(scene.obstacle_tree), Pose{})),
      settings_{clearance, tolerance} {}

contact::Body ContactMoves::body_at(const Pose& pose) const {
  return contact::place_body(scene_.body, borrowed(scene_.body_tree), pose);
}

std::vector<Vec3> ContactMoves::directions(const contact::Body& moving) const {
  return contact::pull_directions(moving, {&obstacles_}, settings_.clearance + settings_.tolerance);
}

bool ContactMoves::pull_clear(const contact::Body& moving, const Vec3& direction, double length) const {
  return contact::pull_is_clear(moving, {&obstacles_}, direction, length, settings_, sweeps_);
}

}  // namespace swept::detail
