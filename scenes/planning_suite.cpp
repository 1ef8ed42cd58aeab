// The planner benchmark suite's catalogue and files: problem.toml and an OMPL.app .cfg that load
// to the same problem. See swept/scenes/planning_suite.h.
#include "swept/scenes/planning_suite.h"
#include "swept/scenes/problem_toml.h"

#include "swept/io/file_write.h"
#include "swept/io/mesh_io.h"

#include <Standard_Failure.hxx>

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace swept::scenes {
namespace {

namespace fs = std::filesystem;

/// A number that reads back exactly (17 significant digits).
std::string num(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

/// A number for a comment.
std::string short_num(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

/// OMPL.app's pose keys: position, and the rotation as an angle (radians) about an axis.
std::string cfg_pose(const std::string& prefix, const Pose& p) {
  const Eigen::AngleAxisd aa(p.rotation);
  const bool turned = aa.angle() != 0.0;
  const Vec3 axis = turned ? Vec3(aa.axis()) : Vec3::UnitX();
  std::string s;
  for (int i = 0; i < 3; ++i) s += prefix + "." + "xyz"[i] + " = " + num(p.translation[i]) + "\n";
  s += prefix + ".theta = " + num(turned ? aa.angle() : 0.0) + "\n";
  for (int i = 0; i < 3; ++i) s += prefix + ".axis." + "xyz"[i] + " = " + num(axis[i]) + "\n";
  return s;
}

std::string cfg_text(const SuiteProblem& sp, const Problem& p, const std::string& info) {
  std::string s = "# " + sp.problem.name + ": " + info +
                  "\n# OMPL.app problem written by `swept scene " + sp.problem.name +
                  "` (the same problem as problem.toml,\n# which also holds the clearance " +
                  short_num(p.clearance) + " that a .cfg cannot express).\n[problem]\nname = " + sp.problem.name +
                  "\nrobot = body.stl\nworld = obstacles.stl\n";
  s += cfg_pose("start", p.start);
  s += cfg_pose("goal", *p.goal);
  for (int i = 0; i < 3; ++i) s += std::string("volume.min.") + "xyz"[i] + " = " + num(p.bounds->min[i]) + "\n";
  for (int i = 0; i < 3; ++i) s += std::string("volume.max.") + "xyz"[i] + " = " + num(p.bounds->max[i]) + "\n";
  s += "\n[benchmark]\ntime_limit = 60.0\nmem_limit = 1000.0\nrun_count = 5\n\n[planner]\nrrtconnect =\n";
  return s;
}

const SuiteInfo* find(const std::string& name) {
  const auto& cat = suite_catalog();
  const auto it = std::find_if(cat.begin(), cat.end(), [&](const SuiteInfo& s) { return s.name == name; });
  return it == cat.end() ? nullptr : &*it;
}

}  // namespace

const std::vector<SuiteInfo>& suite_catalog() {
  static const std::vector<SuiteInfo> problems{
      {"twisty-slot", "Twistycool",
       "a slab through a vertical slot, turned 90 deg in the chamber behind it, through a horizontal slot"},
      {"bug-trap", "BugTrap",
       "a rod in a closed cage whose only exit is a 2 x 2 funnel tube pointing inwards; goal: outside", true},
      {"hooks-1.5", "alpha-1.5", "two interlocked C-hooks, slanted slit 1.5 x the bar (0.5 of play a side, turned 30 deg); goal: apart", true},
      {"hooks-1.2", "alpha-1.2", "two interlocked C-hooks, slanted slit 1.2 x the bar (0.2 of play a side, turned 30 deg); goal: apart", true},
      {"hooks-1.1", "alpha-1.1", "two interlocked C-hooks, slanted slit 1.1 x the bar (0.1 of play a side, turned 30 deg); goal: apart", true},
      {"house", "Home",
       "a table carried through a furnished house, two doorways, into another room, turned 90 deg"},
      {"cubicles", "cubicles",
       "an L-shaped robot from a cubicle downstairs through the stairwell into a cubicle upstairs"},
      {"spiral-tube", "(spiral)", "a rod through a capped tube bent along a 2-turn helix, out of its open end"},
  };
  return problems;
}

bool is_suite_problem(const std::string& name) { return find(name) != nullptr; }

Result<SuiteProblem> suite_problem(const std::string& name) {
  if (!find(name)) {
    std::string names;
    for (const SuiteInfo& s : suite_catalog()) names.append(names.empty() ? "" : ", ").append(s.name);
    return Error{"unknown benchmark problem '" + name + "' (known: " + names + ")"};
  }
  try {
    if (name == "twisty-slot") return suite::twisty_slot();
    if (name == "bug-trap") return suite::bug_trap();
    if (name == "hooks-1.5") return suite::hooks(1.5);
    if (name == "hooks-1.2") return suite::hooks(1.2);
    if (name == "hooks-1.1") return suite::hooks(1.1);
    if (name == "house") return suite::house();
    if (name == "cubicles") return suite::cubicles();
    return suite::spiral_tube();
  } catch (const Standard_Failure& e) {
    return Error{"benchmark problem '" + name + "': OpenCASCADE " + e.DynamicType()->Name() + ": " + e.GetMessageString()};
  } catch (const std::exception& e) {
    return Error{"benchmark problem '" + name + "': " + e.what()};
  }
}

Pose recentred(const Pose& design, const Vec3& centre) {
  return {design.rotation, design.translation + design.rotation * centre};
}

Result<SuiteFiles> write_suite_problem(const SuiteProblem& sp, const fs::path& dir) {
  const SuiteInfo* info = find(sp.problem.name);
  if (!info) return Error{"unknown benchmark problem '" + sp.problem.name + "'"};
  if (!sp.problem.problem.goal || !sp.problem.problem.bounds || sp.witness.size() < 2)
    return Error{"benchmark problem '" + sp.problem.name + "': needs a goal pose, bounds and a witness path"};
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) return Error{"cannot create directory " + dir.string() + ": " + ec.message()};
  SuiteFiles f;
  f.dir = dir;
  if (auto w = write_stl_binary(dir / "obstacles.stl", sp.problem.obstacles); !w) return w.error();
  if (auto w = write_stl_binary(dir / "body.stl", sp.problem.body); !w) return w.error();
  f.body_triangles = sp.problem.body.triangles.size();
  f.obstacle_triangles = sp.problem.obstacles.triangles.size();
  // OMPL.app's robot frame: the body mesh as read back from the file, centred on its vertex mean.
  auto centre = ompl_app_center(dir / "body.stl", {.unit = "mm", .file_unit = "mm"});
  if (!centre) return centre.error();
  f.body_center = *centre;

  Problem p = sp.problem.problem;
  p.obstacles = {mesh_ref("obstacles.stl", "mm")};
  const Vec3 shift = (-f.body_center).array() + 0.0;  // + 0.0: no "-0.0" in the file
  p.body = {mesh_ref("body.stl", "mm", Pose::from_translation(shift))};
  p.reference_point = Vec3::Zero();
  p.start = recentred(p.start, f.body_center);
  p.goal = recentred(*p.goal, f.body_center);
  for (const Pose& w : sp.witness) f.witness_poses.push_back(recentred(w, f.body_center));
  f.problem = p;

  char widths[160];
  std::snprintf(widths, sizeof widths, "narrowest passage %g wide for a body %g across", sp.passage_width, sp.body_width);
  const std::string comment = "swept scene " + sp.problem.name + ": counterpart of OMPL.app's " + info->counterpart +
                              "\n" + info->summary + "\n" + sp.passage + "; " + widths + ".\nTriangles: body " +
                              std::to_string(f.body_triangles) + ", obstacles " + std::to_string(f.obstacle_triangles) +
                              ". The body frame is OMPL.app's (origin at the body mesh's vertex mean),\nso that " +
                              sp.problem.name + ".cfg describes the same problem.";
  f.problem_toml = dir / "problem.toml";
  if (auto w = write_file_atomically(f.problem_toml, problem_toml(p, comment)); !w) return w.error();
  f.cfg = dir / (sp.problem.name + ".cfg");
  if (auto w = write_file_atomically(f.cfg, cfg_text(sp, p, info->summary)); !w) return w.error();
  f.witness = dir / "witness.json";
  if (auto w = write_path(f.witness, Path{f.witness_poses}, p.unit, Vec3::Zero()); !w) return w.error();
  return f;
}

}  // namespace swept::scenes
