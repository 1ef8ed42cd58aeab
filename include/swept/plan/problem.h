#pragma once
/// Planning problems: our TOML format (docs/problem-format.md) and OMPL.app `.cfg` files, and
/// path files (our JSON, OMPL `.path`).
#include "swept/bvh/bvh.h"
#include "swept/geometry/pose.h"
#include "swept/geometry/result.h"
#include "swept/io/mesh_io.h"

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace swept {

/// A mesh of the problem, placed by `pose` (world for obstacles, body frame for the body).
struct MeshRef {
  std::filesystem::path file;  ///< absolute, or relative to the working directory
  Pose pose;
  std::string file_unit;       ///< unit of the file's coordinates; empty: the importer's default
  double deflection = 0.0;     ///< BRepMesh linear deflection for CAD files; 0: problem default
  /// Of a file with several parts (an assembly: STEP products, 3MF build items, OBJ groups), only
  /// the part of this name (as `swept disassemble` prints it); empty: every part ...
  std::string part;
  /// ... but these (names as above). At most one of `part` and `except` is given.
  std::vector<std::string> except;
};

enum class RotationMode { none, free, limits };

/// A disassembly/assembly problem (SPEC §4). Lengths in `unit`, angles in radians.
struct Problem {
  std::filesystem::path source;       ///< the file it was read from
  std::string unit = "mm";
  std::vector<MeshRef> obstacles;
  std::vector<MeshRef> body;
  std::optional<Vec3> reference_point;  ///< body frame; default: centre of the body's bounding box
  Pose start;                           ///< pose of the body frame in the world
  std::optional<Pose> goal;             ///< a goal pose, or ...
  bool goal_outside = false;            ///< ... the body entirely outside the obstacles' box
  double goal_margin = 0.0;             ///< ... grown by this margin
  std::optional<Aabb> bounds;           ///< where the reference point may go; default: automatic
  RotationMode rotation = RotationMode::free;
  std::array<std::array<double, 2>, 3> rotation_limits{{{-1, 1}, {-1, 1}, {-1, 1}}};  ///< radians
  double clearance = 0.0;         ///< certified margin along the whole path
  double contact_tolerance = 0.0; ///< the body may start this close (touching) to the obstacles
  BuildConfig build;             ///< how both trees are built: fitter, split rule, leaf size
  double time_limit = 60.0;       ///< seconds
  int threads = 0;                ///< 0: all cores
  /// Which draw of the trees' sample sequence: 0, the Halton sequence itself; another value
  /// shifts every sample by the same pseudo-random offset, modulo 1 in each coordinate (a
  /// Cranley–Patterson rotation: the same low dispersion). The path is the same for the same
  /// seed at any thread count; another seed is another path (and time) wherever the trees
  /// solve the problem.
  std::uint64_t seed = 0;
  double deflection = 0.1;        ///< default BRepMesh linear deflection for CAD meshes
  /// Triangle budget of each CAD mesh's tessellation (ImportOptions::max_triangles).
  std::size_t max_triangles = ImportOptions{}.max_triangles;
  /// What the file asks for that swept does not do, one line each, naming the file and line: an
  /// OMPL.app .cfg's settings for OMPL's own planners (`objective`, `sampler`, `threshold`,
  /// the [benchmark] and [planner] sections). `swept plan` prints them.
  std::vector<std::string> notes;
};

/// Reads a problem: `.toml` (our format) or `.cfg` (OMPL.app). Errors name the file, the line and
/// the key. For a `.cfg` the robot mesh is read once here: its pose is the translation by minus
/// ompl_app_center(), OMPL.app's robot frame, whose origin is the reference point.
Result<Problem> load_problem(const std::filesystem::path& file);

/// A path: poses of the body frame in the world, in order.
struct Path {
  std::vector<Pose> poses;
};

/// Writes a path: OMPL `.path` (one `x y z qx qy qz qw` line per pose) when the file name ends
/// in `.path`, otherwise our JSON ({"unit", "reference_point", "poses": [{"translation",
/// "quaternion" (x, y, z, w)}]}). Written whole or not at all (write_file_atomically()).
Result<bool> write_path(const std::filesystem::path& file, const Path& path, const std::string& unit,
                        const Vec3& reference_point);

/// Reads a path written by `write_path` (either format).
Result<Path> read_path(const std::filesystem::path& file);

}  // namespace swept
