#pragma once
/// The deterministic, certified 6-DOF disassembly planner (SPEC §4; paper §II).
///
/// Configurations are poses of the body frame. The motion between two configurations moves the
/// body's reference point c linearly and slerps the rotation about it; the metric
/// d(q0, q1) = ‖Δc‖ + r_max·θ bounds how far any body point moves (r_max: the body's radius
/// about c). Every edge of a returned path is certified by the motion certificate
/// (`certify_motion`, Schwarzer, Saha, Latombe 2005): the distance stays above the clearance
/// margin along the whole continuous motion. The search follows Bohlin & Kavraki 2000 (lazy
/// checking) and Bohlin 2001 (a multi-resolution grid), then grows trees from both ends on a
/// Halton sequence (RRT-Connect's manner, with free-ball steps, slides and quarter-turn lattice
/// moves); docs/planner.md walks through it.
#include "swept/bvh/bvh.h"
#include "swept/geometry/solid.h"
#include "swept/plan/problem.h"

#include <tbb/task_arena.h>

#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>

namespace swept {

/// The problem's meshes loaded and merged (obstacles in the world, body in the body frame),
/// with their RSS trees.
struct PlanScene {
  TriangleSoup obstacles;  ///< world frame
  TriangleSoup body;       ///< body frame
  Bvh obstacle_tree;
  Bvh body_tree;
  Vec3 reference = Vec3::Zero();  ///< body-frame point the motions interpolate about
  double radius = 0.0;            ///< max distance from `reference` to a body vertex
  Aabb obstacle_box;              ///< world bounding box of the obstacles
  std::vector<SurfacePart> obstacle_parts;  ///< connected parts of the obstacles, closed or not
  std::vector<SurfacePart> body_parts;      ///< connected parts of the body (body frame)
  /// What reading the meshes left out or noticed (ImportedModel::warnings: CAD faces that did not
  /// tessellate, parts without triangles, ...), each naming its file: the certificate covers the
  /// triangles read, so a user must see them.
  std::vector<std::string> warnings;
  double load_ms = 0.0;           ///< reading and tessellating the meshes
  double build_ms = 0.0;          ///< building both trees
};

/// Imports every mesh of the problem (units, deflection, poses applied) and builds the trees
/// with `config` (usually `problem.build`). Errors name the mesh file.
Result<PlanScene> load_scene(const Problem& problem, const BuildConfig& config);

/// A scene from meshes already in memory (obstacles in the world, body in the body frame).
Result<PlanScene> make_scene(TriangleSoup obstacles, TriangleSoup body, const BuildConfig& config,
                             std::optional<Vec3> reference_point = std::nullopt);

/// At `pose`, is a part of the body inside a closed part of the obstacles, or an obstacle part
/// inside a closed part of the body? Then the solids overlap although their surfaces may be far
/// apart (the distance queries measure between surfaces). Returns what is inside what, or
/// nullopt. Meaningful when the surfaces do not touch at `pose`.
std::optional<std::string> enclosure_at(const PlanScene& scene, const Pose& pose);

/// `PlanResult::level` and `PlanProgress::level` of the phase that grows trees from both ends.
inline constexpr int kTreeLevel = -2;

/// Reported while planning (about once a second) for the progress line.
struct PlanProgress {
  int level = 0;                ///< grid resolution level (kTreeLevel: the trees from both ends)
  std::size_t nodes_checked = 0;
  std::uint64_t queries = 0;    ///< distance queries so far
  double elapsed_s = 0.0;
};

/// Overrides of the problem's settings, and the progress callback.
struct PlanOptions {
  std::optional<double> time_limit;  ///< seconds
  /// A limit on the work that does not depend on the machine: the search stops once it has made
  /// this many distance queries (status no_path_budget). The count is checked only where it is
  /// the same at any thread count — before each straight move, each expansion of the grid, each round of the
  /// trees, before each probe of the smoothing (which then keeps the path it has) — so an outcome
  /// decided by the budget is the same everywhere, unlike one decided by the time limit. The
  /// search may pass the budget by what one round of the trees costs. Under a budget nothing
  /// runs ahead of the phases in turn (the trees beside the grid, the bridges' tries on every
  /// core), so the count is the one-thread count. None: no limit.
  std::optional<std::uint64_t> max_queries;
  /// Threads for the parallel work (the final certification): plan() runs in a oneTBB task
  /// arena of this many (0: all cores; default: the problem's `threads`). Nothing process-wide
  /// is changed. The path is the same at any count.
  std::optional<int> threads;
  /// An arena owned by the caller to run in instead (then `threads` is not used): one arena
  /// shared by many plan() calls, or the caller's own executor.
  tbb::task_arena* arena = nullptr;
  std::function<void(const PlanProgress&)> progress;
};

enum class PlanStatus {
  solved,
  no_path_time,        ///< time limit reached
  no_path_budget,      ///< PlanOptions::max_queries reached (the same at any thread count and on any machine)
  no_path_bounds,      ///< the search exhausted the bounds/rotation limits at every resolution
  no_path_resolution,  ///< the finest resolution was searched without a path
  invalid_start,       ///< start outside bounds or closer than the clearance (bad input)
  invalid_goal,        ///< goal outside bounds or closer than the clearance (bad input)
  invalid_bounds,      ///< bounds (or start, goal, goal margin) too far from the scene for its precision (bad input)
};

struct PlanResult {
  PlanStatus status = PlanStatus::no_path_resolution;
  std::string message;  ///< what happened, in a sentence (which limit, for failures)
  Path path;            ///< start … goal, every segment certified
  double path_length = 0.0;         ///< Σ metric length ‖Δc‖ + r_max·θ
  double translation_length = 0.0;  ///< Σ ‖Δc‖
  double rotation_length = 0.0;     ///< Σ θ, radians
  /// Smallest exact distance found along the whole path, every segment and every triangle pair
  /// included: ≥ the margin, except for a start or goal in contact (then it is at most that
  /// pose's distance).
  double min_clearance = 0.0;
  /// A start in contact: the leading segments that take the body out of contact (1 or 2 pure
  /// translations: a pull, or a slide then a pull); a goal in contact: the trailing segments of
  /// its approach (the same, played backwards). Each is certified by the contact model
  /// (docs/planner.md, "The contact model"); 0 for an end with the full clearance.
  std::size_t escape_segments = 0;
  std::size_t approach_segments = 0;
  struct {
    double build = 0, search = 0, smooth = 0, total = 0;
  } time_ms;
  /// Queries the planner issued, the final certification included: distance queries,
  /// proximity-pair queries, and exact sweeps of pure translations: those that graze the margin
  /// and the pulls in contact (docs/planner.md, "Certificates"). It issues no collide or
  /// tolerance queries.
  struct {
    std::uint64_t distance = 0, proximity = 0, sweep = 0;
  } queries;
  std::uint64_t path_hash = 0;  ///< `path_hash(path)`: equal paths, equal hashes
  int level = 0;                ///< the grid level the path was found at (-1: straight-line phase; kTreeLevel: the trees)
  std::size_t tree_nodes = 0;   ///< nodes of the trees from both ends (when that phase ran)
  std::size_t nodes_checked = 0;
  std::size_t edges_checked = 0;

  bool solved() const { return status == PlanStatus::solved; }
};

/// Plans a certified path for the problem. Deterministic: the same problem and scene give the
/// same path, bit for bit, at any thread count while the time limit is not reached
/// (tested at 1, 2, 4 and 8 threads); PlanOptions::max_queries bounds the work without a clock.
PlanResult plan(const Problem& problem, const PlanScene& scene, const PlanOptions& options = {});

/// FNV-1a 64 (offset basis 14695981039346656037, prime 1099511628211) over the bytes of the
/// poses: for each pose the rotation row by row, then the translation, as little-endian IEEE
/// doubles, −0.0 taken as +0.0.
std::uint64_t path_hash(const Path& path);

}  // namespace swept
