#pragma once
// The planner's view of the contact layer (internal to src/plan; docs/planner.md, "The contact
// model"): the scene's obstacles and body as contact bodies, and the certificate of a straight
// pull from a pose in contact. The escape from a start in contact, the approach to a goal in
// contact and `check_path` use it; no other code of the planner decides a motion in contact.
#include "swept/contact/contact.h"
#include "swept/plan/planner.h"

#include <atomic>
#include <cstdint>
#include <vector>

namespace swept::detail {

class ContactMoves {
 public:
  /// Pulls keep `clearance`, mates reach at most `tolerance` into each other.
  ContactMoves(const PlanScene& scene, double clearance, double tolerance);

  /// The body at `pose` (its tree shared with the scene's).
  contact::Body body_at(const Pose& pose) const;
  /// The directions to try from where `moving` is (contact::pull_directions: the axes, the
  /// contact normals by area, the CAD's cylinder axes, their cross products).
  std::vector<Vec3> directions(const contact::Body& moving) const;
  /// Is the pull of `moving` by `length` along the unit `direction` certified under the mate
  /// rule taken where `moving` is? Exact (one sweep of the translation), counted.
  bool pull_clear(const contact::Body& moving, const Vec3& direction, double length) const;

  double clearance() const { return settings_.clearance; }
  double tolerance() const { return settings_.tolerance; }
  std::uint64_t sweeps() const { return sweeps_.load(); }

 private:
  const PlanScene& scene_;
  contact::Body obstacles_;
  contact::PullSettings settings_;
  mutable std::atomic<std::uint64_t> sweeps_{0};
};

}  // namespace swept::detail
