#pragma once
/// Disassembly sequences of whole assemblies (SPEC §6; docs/assembly.md).
///
/// Round by round, every part still in place is tried: first straight pulls along its local
/// freedom directions (±x, ±y, ±z, then the normals and axes of its contacts) to outside the
/// box of the parts still in place, certified against all of them with the contact model of
/// contact.h; when no part leaves straight, the planner (swept::plan) with the others as
/// obstacles; when no single part leaves, connected groups of touching parts as one body. One
/// part (or group) is removed per round by a fixed rule, and the rounds go on until every
/// movable part is out or none can leave; the parts that stay are reported with their blockers
/// per direction. Deterministic: the same assembly and options give the same result at any
/// number of jobs (parallel work is consumed in part order).
#include "swept/assembly/assembly.h"
#include "swept/geometry/pose.h"
#include "swept/plan/planner.h"
#include "swept/plan/problem.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace swept {

/// Two parts overlapping by more than the mating tolerance at their mounted poses.
struct Interference {
  std::size_t part_a = 0, part_b = 0;   ///< indices into the assembly's parts, a < b
  double depth = 0.0;                   ///< the deepest intersecting triangle pair's pair_overlap
  double extent = 0.0;                  ///< diagonal of the box of the intersecting triangles' crossing points
  std::size_t triangle_pairs = 0;       ///< intersecting triangle pairs deeper than the tolerance
};

/// Reported while disassembling (DisassemblyOptions::progress), for a progress line.
struct DisassemblyProgress {
  /// "trees" (one per part), "interferences" (pairs whose boxes meet), "contacts" (pairs),
  /// "removals" (parts out of the movable ones), "blockings" (--target: the parts looked at)
  const char* phase = "";
  std::size_t done = 0, total = 0;
  double elapsed_s = 0.0;  ///< since disassemble() began
};

struct DisassemblyOptions {
  double clearance = 0.01;  ///< every non-mated pair keeps more than this (assembly unit)
  /// Mated pairs may overlap across their plane by up to this much (tessellation sag of both
  /// meshes); also the interference threshold. ≤ 0: 0.2, twice the default linear deflection
  /// (`swept disassemble` passes twice its --deflection).
  double tolerance = 0.0;
  int jobs = 0;                     ///< threads for the candidates of a round (0: all cores)
  /// Distance queries per planner attempt: the limit that ends an attempt without a path, the
  /// same on every machine and at any `jobs` (PlanOptions::max_queries); 0: none.
  std::uint64_t plan_max_queries = 20000;
  /// Seconds per planner attempt (0: no planner fallback): a safety net behind the query budget;
  /// an attempt it ends could end otherwise on another machine.
  double plan_time_limit = 60.0;
  bool subassemblies = true;        ///< try groups of touching parts when no single part leaves
  /// The parts never moved, by index; empty: the parts marked `fixed`, or when none is, the
  /// part with the largest bounding box (the base).
  std::optional<std::vector<std::size_t>> fixed;
  /// Selective disassembly: take out only these parts (indices, not fixed) and the fewest others
  /// that must come off first, by straight pulls with every blocking taken with all parts in
  /// place (docs/assembly.md, "What must come off first"); empty: the whole assembly.
  std::vector<std::size_t> targets;
  /// The selective search's limit on the sets of removals it keeps; past it the answer is a
  /// greedy one, not proved the fewest (DisassemblyResult::fewest false).
  std::size_t target_states = 200000;
  /// Called as the work advances (about ten times a second at most, and at the end of each
  /// phase), one call at a time, from whichever thread did the work. Not called when empty.
  std::function<void(const DisassemblyProgress&)> progress;
};

/// How a part (or group) left.
enum class RemovalMethod { pull, plan };

/// One entry of the sequence.
struct SequenceStep {
  std::vector<std::size_t> parts;  ///< one part, or a subassembly (ascending indices)
  bool removed = false;            ///< false: blocked (the remaining parts at the end)
  RemovalMethod method = RemovalMethod::pull;
  Vec3 direction = Vec3::Zero();   ///< pull: the unit direction
  double distance = 0.0;           ///< pull: how far (to outside the remaining parts' box)
  Path path;                       ///< the motion (poses of the part's frame = world at the mounted pose)
  Vec3 reference = Vec3::Zero();   ///< the point the path's rotations interpolate about
  int round = 0;                   ///< 1-based; blocked steps: the last round
  double time_ms = 0.0;            ///< time of the round's attempts on this part (not deterministic)
  /// Blocked: for each direction tried, the parts that block a pull along it on their own.
  struct Blocking {
    Vec3 direction = Vec3::Zero();
    std::vector<std::size_t> blockers;
  };
  std::vector<Blocking> blocking;
};

struct DisassemblyResult {
  bool complete = false;  ///< every movable part removed
  std::vector<std::size_t> fixed;           ///< the parts never moved
  std::vector<Interference> interferences;  ///< checked first, at the mounted poses
  std::vector<SequenceStep> sequence;       ///< removals in order, then the blocked parts
  double tolerance = 0.0;                   ///< the mating tolerance used
  struct {
    double build = 0, interference = 0, sequence = 0;
  } time_ms;
  /// Queries made: one exact sweep (sweep_translation) per obstacle a pull comes near, and the
  /// planner's distance queries when it was asked.
  std::uint64_t distance_queries = 0;
  /// Selective disassembly (DisassemblyOptions::targets): `sequence` is the removals that free
  /// the targets, the targets among them (`complete`: they all come out); `fewest`: no smaller
  /// set of removals does (the search ran to the end); `lower_bound`: no set of fewer removals
  /// does (the size of the answer when `fewest`); `why`: for each target and each part removed
  /// for it, the directions tried and the parts blocking each with every part in place.
  std::vector<std::size_t> targets;
  bool fewest = false;
  std::size_t lower_bound = 0;
  std::vector<SequenceStep> why;
};

/// Parts overlapping by more than `tolerance` at their mounted poses, pair by pair (i < j), with
/// the deepest triangle pair by the mate rule's overlap. Deterministic; runs in the caller's arena.
std::vector<Interference> find_interferences(const Assembly& assembly, double tolerance);

/// The problem of taking `group` (indices) out of the parts `present` (the others stay as
/// obstacles): the group is the body, its frame the world's (start: its mounted pose, the
/// identity), the goal outside the obstacles' box, any rotation, the clearance and contact
/// tolerance of `options` (tolerance ≤ 0: the default of DisassemblyOptions), the CAD's cylinders
/// kept for the contact model. What `swept plan ASSEMBLY --part NAME` and the planner fallback of
/// `disassemble` plan. An error when no part stays as an obstacle.
struct PartProblem {
  Problem problem;
  PlanScene scene;
};
Result<PartProblem> part_problem(const Assembly& assembly, const std::vector<std::size_t>& group,
                                 const std::vector<std::size_t>& present, const DisassemblyOptions& options);
/// The part named `name` (as `swept disassemble` prints it), or an error listing the names.
Result<std::size_t> find_part(const Assembly& assembly, const std::string& name);

/// The disassembly sequence (or with `targets`, the fewest removals that free them). Parts in an
/// interference are not exempted: they simply block each other (the interference is reported first).
DisassemblyResult disassemble(const Assembly& assembly, const DisassemblyOptions& options = {});

}  // namespace swept
