#pragma once
// What the phases of one plan() call share (internal to src/plan): the problem, its scene and
// search space, the certificate, the clock and the work counters. Each phase is a function of
// this context (docs/planner.md, "Search").
#include "checker.h"
#include "swept/plan/planner.h"
#include "swept/plan/search_space.h"

#include <atomic>
#include <chrono>
#include <cstddef>
#include <mutex>

namespace swept::detail {

struct PlanContext {
  const Problem& problem;
  const PlanScene& scene;
  const SearchSpace& space;
  Checker& check;
  const PlanOptions& options;
  Clock::time_point started;
  double time_limit_s = 60.0;
  /// Motions certified by the search (not the final pass); the grid and the trees add to it at
  /// the same time.
  std::atomic<std::size_t> edges_checked = 0;
  std::mutex progress_mutex;  ///< the grid and the trees report progress from their own threads

  /// Calls PlanOptions::progress, if any, one report at a time.
  void report(const PlanProgress& progress) {
    if (!options.progress) return;
    const std::lock_guard lock(progress_mutex);
    options.progress(progress);
  }

  double elapsed_s() const { return std::chrono::duration<double>(Clock::now() - started).count(); }
  bool out_of_time() const { return elapsed_s() > time_limit_s; }
  /// PlanOptions::max_queries reached? Ask only where the count is the same at any thread count
  /// (between rounds of parallel work, never inside one).
  bool over_budget() const { return options.max_queries && check.distance_queries() >= *options.max_queries; }
  /// The reference point of the body at `pose` (world).
  Vec3 reference_at(const Pose& pose) const { return pose.apply(space.reference); }
  /// The pose with rotation `rotation` whose reference point is at `point` (world).
  Pose pose_with_reference_at(const Mat3& rotation, const Vec3& point) const {
    return {rotation, point - rotation * space.reference};
  }
  /// The larger of the obstacles' box diagonal and the body's diameter: the scene's scale.
  double scene_size() const { return std::max(scene.obstacle_box.extent(), 2 * space.radius); }
  /// Is the pose free with a margin to spare? A lower bound on its distance, exact below
  /// margin + `reach`, and whether it exceeds the margin.
  bool free_at(const Pose& pose, double reach, double* distance = nullptr) const {
    const double d = check.clearance(pose, check.margin() + reach);
    if (distance) *distance = d;
    return d > check.margin();
  }
  /// Certifies the motion a → b (ends' bounds da, db; negative: unknown), counting it; with
  /// `max_queries`, a motion that needs more bisection queries is not clear (Checker::certify).
  /// Two midpoints at a time (the phases that call it are serial), the two earliest unless
  /// `pieces` says otherwise. `cancel`: once either is set, the certificate gives up (not clear).
  bool certify(const Pose& a, double da, const Pose& b, double db, int max_queries = kMaxCertificateQueries,
               std::array<const std::atomic<bool>*, 2> cancel = {}, Pieces pieces = Pieces::two_earliest) {
    ++edges_checked;
    return check.certify(a, da, b, db, max_queries, pieces, cancel).clear();
  }
};

}  // namespace swept::detail
