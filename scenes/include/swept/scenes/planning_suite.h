#pragma once
/// The planner benchmark suite (issue 13): counterparts of OMPL.app's rigid-body benchmark
/// problems, with our own geometry — a slab through two slots at right angles (Twistycool), a
/// body in a cage whose only exit is a narrow inward funnel (BugTrap), two interlocked C-hooks
/// at three gap sizes (alpha-1.5/1.2/1.1), a table carried through a furnished house (Home),
/// an L-shaped robot from a cubicle on one floor to a cubicle on the next (cubicles), and a rod
/// through a capped spiral tube.
///
/// Every problem has a goal pose (like OMPL.app's .cfg files) and a witness path: waypoints
/// known by construction to go through the passage, so that a test can certify the problem
/// solvable without planning. `swept scene NAME` writes a problem as body.stl, obstacles.stl,
/// problem.toml and an OMPL.app-style NAME.cfg that load to the same problem.
///
/// Units: the numbers are unit-less, as in OMPL.app; files say "mm" (a .cfg reads as mm).
#include "swept/scenes/box_problems.h"

#include <filesystem>
#include <string>
#include <vector>

namespace swept::scenes {

/// One catalogue entry of the suite.
struct SuiteInfo {
  std::string name;         ///< e.g. "bug-trap"
  std::string counterpart;  ///< the OMPL.app problem it stands for, e.g. "BugTrap"
  std::string summary;      ///< one line: what moves, through what, to where
  /// One of the hard problems (the trap, the hooks): RRTConnect is expected not to solve
  /// it within 60 s, and swept is allowed 300 s.
  bool hard = false;
};

/// The suite's problems, in a fixed order.
const std::vector<SuiteInfo>& suite_catalog();

/// Is `name` a suite problem?
bool is_suite_problem(const std::string& name);

/// A suite problem in memory. Poses (start, goal, witness) place the body frame in which
/// `problem.body` is modelled (the design frame); `write_suite_problem` re-expresses them for
/// OMPL.app's robot frame.
struct SuiteProblem {
  GeneratedProblem problem;   ///< name, Problem (start, goal pose, bounds, clearance), meshes
  std::vector<Pose> witness;  ///< start … goal, every straight segment free by construction
  double passage_width = 0.0; ///< the narrowest opening on the witness path
  double body_width = 0.0;    ///< the body's extent across that opening
  std::string passage;        ///< what that opening is, in words
};

/// Builds a suite problem. Error: an unknown name (the message lists the known ones), or an
/// OpenCASCADE failure while modelling the spiral tube.
Result<SuiteProblem> suite_problem(const std::string& name);

/// What write_suite_problem() wrote.
struct SuiteFiles {
  std::filesystem::path dir, problem_toml, cfg, witness;  ///< witness: the witness path (JSON)
  /// OMPL.app's robot centre of body.stl (ompl_app_center), in the design frame: the origin of
  /// the written problem's body frame and its reference point.
  Vec3 body_center = Vec3::Zero();
  Problem problem;            ///< the problem as written (mesh files relative to `dir`; body frame: the centred one)
  std::vector<Pose> witness_poses;  ///< the witness in the written body frame
  std::size_t body_triangles = 0, obstacle_triangles = 0;
};

/// Writes `p` into `dir` (created if missing): obstacles.stl, body.stl (binary STL),
/// problem.toml, NAME.cfg (OMPL.app: [problem] robot/world/start/goal/volume, plus [benchmark]
/// and [planner] sections that swept ignores) and witness.json. The body frame of both problem
/// files is OMPL.app's: the body mesh shifted by minus its robot centre, which is also the
/// reference point; start, goal and bounds are re-expressed for it, so that both files load to
/// the same placements. The .cfg cannot hold the clearance, rotation mode or time limit: those
/// are in problem.toml only. Files are written whole or not at all; existing ones are replaced.
Result<SuiteFiles> write_suite_problem(const SuiteProblem& p, const std::filesystem::path& dir);

/// The pose of a body frame whose origin is the design-frame point `centre`, for the body placed
/// by the design-frame pose `design`: the same placement of the body in the world.
Pose recentred(const Pose& design, const Vec3& centre);

namespace suite {
/// The problems one by one (all of them through suite_problem()).
SuiteProblem twisty_slot();
SuiteProblem bug_trap();
/// Interlocked C-hooks; `gap_ratio`: the hook's gap over the bar's thickness (> 1).
SuiteProblem hooks(double gap_ratio);
SuiteProblem house();
SuiteProblem cubicles();
/// Needs OpenCASCADE (the tube is a swept B-rep); throws std::runtime_error on its failure.
SuiteProblem spiral_tube();
}  // namespace suite

}  // namespace swept::scenes
