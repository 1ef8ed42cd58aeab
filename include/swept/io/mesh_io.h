#pragma once
/// Mesh and CAD import into triangle soups (double precision), one soup per part.
///
/// Meshes (STL ASCII/binary, OBJ, PLY, OFF, glTF/GLB, COLLADA) are read with assimp; CAD
/// (STEP, IGES, OCCT .brep) with OpenCASCADE, tessellated by BRepMesh, assembly placements
/// applied. Bad input gives an Error naming the file and the line, triangle or entity.
#include "swept/geometry/result.h"
#include "swept/geometry/types.h"

#include <filesystem>
#include <string>
#include <vector>

namespace swept {

/// Length units understood by the importer, with their size in metres.
/// Accepted spellings: "m", "cm", "mm", "um", "in", "ft".
/// Returns false for anything else.
bool unit_scale(std::string_view unit, double& metres_per_unit);

struct ImportOptions {
  /// Unit of the output coordinates.
  std::string unit = "mm";
  /// Unit of the file's coordinates, for formats that carry none (STL, OBJ, PLY, OFF, glTF
  /// assumes metres per its spec unless this is set). Empty: "mm" for mesh formats; STEP/IGES
  /// use the unit declared in the file, and .brep files are taken as mm.
  std::string file_unit;
  /// BRepMesh linear deflection, in the *output* unit, and angular deflection in radians.
  double linear_deflection = 0.1;
  double angular_deflection = 0.5;
};

/// What an import produced.
struct ImportedModel {
  std::string file;                  ///< the path as given
  std::string unit;                  ///< unit of the coordinates (ImportOptions::unit)
  std::vector<TriangleSoup> parts;   ///< one per part/solid/mesh, with its name
  std::size_t degenerate_triangles = 0;  ///< zero-area triangles kept in the parts

  std::size_t triangle_count() const;
  /// All parts in one soup (the file's stem as its name).
  TriangleSoup merged() const;
};

/// Reads a mesh or CAD file; the format is chosen from the extension (case-insensitive):
/// .stl .obj .ply .off .gltf .glb .dae → assimp; .step .stp .iges .igs .brep → OpenCASCADE.
Result<ImportedModel> import_mesh(const std::filesystem::path& file, const ImportOptions& options = {});

/// Writes a binary STL (little-endian, float32). Deterministic bytes for equal input.
Result<bool> write_stl_binary(const std::filesystem::path& file, const TriangleSoup& soup);

}  // namespace swept
