#pragma once
/// Assemblies: parts in their mounted poses, read from a multi-solid CAD file, a TOML assembly
/// file (docs/assembly-format.md) or a folder of placed meshes (SPEC §6).
///
/// Every part's triangles are in the world frame at its mounted pose, in the assembly's unit.
#include "swept/geometry/result.h"
#include "swept/geometry/types.h"
#include "swept/io/mesh_io.h"

#include <filesystem>
#include <string>
#include <vector>

namespace swept {

/// One part, placed where it is mounted.
struct AssemblyPart {
  std::string name;       ///< unique within the assembly
  std::string source;     ///< the file it was read from (as written)
  TriangleSoup mesh;      ///< world frame, the assembly's unit; never empty
  bool fixed = false;     ///< the base or fixture: never moved (`fixed = true` in TOML)
};

struct Assembly {
  std::filesystem::path source;  ///< the file or folder read
  std::string unit = "mm";
  std::vector<AssemblyPart> parts;
  /// Non-fatal problems, each naming the file and part (a solid that could not be meshed, left out).
  std::vector<std::string> warnings;

  std::size_t triangle_count() const;
};

struct AssemblyReadOptions {
  /// Units, deflections and the triangle budget of the mesh and CAD imports. A TOML assembly's
  /// own `unit` and `deflection` override `import.unit` and `import.linear_deflection`.
  ImportOptions import;
};

/// Reads an assembly:
/// - a `.toml` file: `[[part]]` tables with `file`, optional `name`, `pose` and `fixed`
///   (docs/assembly-format.md), read strictly (unknown keys, wrong types: errors with the line);
/// - a folder: every mesh or CAD file in it (not in subfolders), in name order, each file a
///   part named by its stem (a file holding several parts gives `stem/part` names);
/// - any other file (STEP, IGES, BREP, or a mesh format import_mesh() reads): every solid of it
///   a part, named from the STEP product structure (XCAF) when present, else `<stem>_solid<k>`.
/// Errors (nothing returned) name the file and part: an unreadable file, an assembly without
/// parts, a part without triangles, two parts with the same name. A CAD solid that does not
/// tessellate is left out with a warning naming it.
Result<Assembly> read_assembly(const std::filesystem::path& path, const AssemblyReadOptions& options = {});

/// The mesh and CAD extensions a folder assembly picks up (lower case, with the dot).
const std::vector<std::string>& assembly_mesh_extensions();

}  // namespace swept
