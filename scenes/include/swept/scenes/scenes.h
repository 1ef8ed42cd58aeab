#pragma once
/// The built-in CAD-like scenes (`swept scene`): stand-ins for the paper's three industrial test
/// cases (Table I), modelled as B-rep solids with OpenCASCADE, tessellated with BRepMesh, and
/// written as binary STL meshes plus a `problem.toml` for `swept plan` (docs/problem-format.md).
///
/// Units: millimetres. Output is deterministic: the same name and scale give byte-identical
/// files (serial booleans, serial BRepMesh, a deterministic deflection search).
#include "swept/geometry/result.h"

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace swept::scenes {

/// How finely the scene is tessellated.
enum class Scale {
  test,   ///< under 30,000 triangles per scene (body + obstacles), for tests and CI
  paper,  ///< body and obstacle triangle counts within 20 % of the paper's Table I
};

/// Parses "test" / "paper"; false for anything else.
bool parse_scale(const std::string& text, Scale& scale);

/// One catalogue entry.
struct SceneInfo {
  std::string name;         ///< e.g. "air-cleaner"
  std::string summary;      ///< one line: what moves, what is fixed, where it must go
  std::size_t paper_body_triangles = 0;      ///< Table I, rigid body (†)
  std::size_t paper_obstacle_triangles = 0;  ///< Table I, obstacles (‡)
};

/// The scenes, in a fixed order.
const std::vector<SceneInfo>& catalog();

/// What to generate.
struct GenerateRequest {
  std::string name;                  ///< a catalog() name
  Scale scale = Scale::test;
  std::filesystem::path output_dir;  ///< created if missing; existing files are overwritten
};

/// One written mesh file.
struct MeshFile {
  std::string file;           ///< file name, relative to the output directory
  bool body = false;          ///< part of the moving body (else an obstacle)
  std::size_t triangles = 0;
};

/// What generate_scene() produced.
struct SceneReport {
  std::string name;
  Scale scale = Scale::test;
  std::vector<MeshFile> meshes;
  std::size_t body_triangles = 0;
  std::size_t obstacle_triangles = 0;
  std::size_t target_body_triangles = 0;      ///< the count the deflection search aimed at
  std::size_t target_obstacle_triangles = 0;
  double body_deflection = 0.0;      ///< BRepMesh linear deflection used for the body, mm
  double obstacle_deflection = 0.0;  ///< ... and for the obstacles, mm
  double angular_deflection = 0.0;   ///< BRepMesh angular deflection, radians
  int tessellations = 0;             ///< BRepMesh runs spent by the deflection search
  double seconds = 0.0;              ///< wall time (not written to any file)
  std::filesystem::path problem_file;
};

/// Models, tessellates and writes one scene. Errors: unknown name, unwritable directory,
/// an OpenCASCADE failure.
Result<SceneReport> generate_scene(const GenerateRequest& request);

}  // namespace swept::scenes
