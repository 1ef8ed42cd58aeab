#pragma once
// Internal to swept_io: the per-format readers behind import_mesh(). Each reader fills
// `parts` with coordinates already converted to the output unit, or returns an Error that
// names the file and the line, triangle or entity.
#include "swept/geometry/result.h"
#include "swept/geometry/types.h"
#include "swept/io/mesh_io.h"

#include <filesystem>
#include <string>
#include <vector>

namespace swept::io_detail {

/// Everything a reader needs: the file, its display name for messages, the scale from the
/// file's unit to the output unit (for formats without a declared unit), and the options.
struct ReadContext {
  std::filesystem::path file;
  std::string display;           ///< the path as given, used in every message
  double file_to_output = 1.0;   ///< output units per file unit (mesh formats)
  double metres_per_output = 1e-3;
  const ImportOptions* options = nullptr;
  std::vector<std::string>* warnings = nullptr;  ///< ImportedModel::warnings
  /// In a reader's child process (isolate.h): no oneTBB, so BRepMesh meshes on one thread.
  bool single_threaded = false;
};

/// STL, ASCII or binary (detected from the content, not the first five bytes alone).
Result<bool> read_stl(const ReadContext& ctx, std::vector<TriangleSoup>& parts);

/// OFF (text; Geomview's header variants), polygons triangulated by ear clipping (polygon.h).
Result<bool> read_off(const ReadContext& ctx, std::vector<TriangleSoup>& parts);

/// 3MF (core specification and the production extension's model parts); the model's declared
/// unit, not the file unit, scales it.
Result<bool> read_3mf(const ReadContext& ctx, std::vector<TriangleSoup>& parts);

/// OBJ, PLY, glTF/GLB, COLLADA through assimp.
Result<bool> read_with_assimp(const ReadContext& ctx, std::vector<TriangleSoup>& parts);

/// ompl_app_vertices() for the formats assimp reads (STL too: OMPL.app reads it with assimp).
Result<OmplAppVertices> ompl_app_vertices_with_assimp(const ReadContext& ctx);

/// STEP, IGES (through XCAF) and OCCT .brep, tessellated with BRepMesh.
Result<bool> read_cad(const ReadContext& ctx, std::vector<TriangleSoup>& parts);

/// Reads a whole file into memory; Error naming the file when it cannot be opened.
Result<std::string> read_file_bytes(const std::filesystem::path& file, const std::string& display);

/// "what" prefixed with the file's display name: "<file>: <what>".
inline Error file_error(const std::string& display, const std::string& what) {
  return Error{display + ": " + what};
}

}  // namespace swept::io_detail
