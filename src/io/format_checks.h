#pragma once
// Internal to swept_io: our own checks of the text and binary formats assimp reads, run before
// assimp (which parses malformed or non-finite numbers without complaint, cannot say on which
// line they were, hangs on some truncated PLY files and reserves memory for declared counts
// before finding the data short), and the glTF facts the assimp reader compares its result with.
#include "import_detail.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace swept::io_detail {

/// `s` in lower case (ASCII).
std::string lower(std::string s);

/// The whitespace-separated tokens of a line.
std::vector<std::string_view> split(std::string_view line);
/// The same, appended to `out` (a reused buffer: no allocation per line).
void split(std::string_view line, std::vector<std::string_view>& out);
/// `s` in quotes for a message, shortened when long.
std::string quoted(std::string_view s);
/// Parses a decimal number; "" on success, else the reason.
std::string parse_number(std::string_view s, double& x);
/// Parses an integer; false if it is not one.
bool parse_int(std::string_view s, long long& v);

/// PLY: the header, then every element's data, walked without interpreting it (assimp's PLY
/// reader can loop forever on a truncated ASCII body and reads past a truncated binary one).
/// "" when fine, else the reason with its line or element.
std::string check_ply(const std::string& bytes);

/// OBJ, PLY and COLLADA counts checked line by line, glTF's external references confined to the
/// model's folder, and STL and OFF read by swept's readers (assimp takes a truncated binary STL
/// silently; it reads STL and OFF only for ompl_app_center()). nullopt when fine or not ours to
/// check.
std::optional<Error> precheck(const ReadContext& ctx);

/// IGES's record structure: 80-column records, sections in order, the Terminate record's line
/// counts, directory entries pointing into the parameter section (OpenCASCADE's IGES reader can
/// crash on truncated files). "" when fine, else the reason with its line.
std::string check_iges(const std::string& bytes);

/// glTF 2: the faces each primitive declares (its index count, or its vertex count without
/// indices, by its mode), one entry per primitive in file order (assimp's importer makes one
/// mesh per primitive, but orders them as the scene first refers to them). Empty when the file
/// is not glTF 2 JSON we can read (assimp then reports).
struct GltfPrimitive {
  std::string mesh;            ///< the mesh's name ("" when it has none)
  std::size_t primitive = 0;   ///< its index among the mesh's primitives
  std::size_t primitives = 1;  ///< how many primitives the mesh has
  std::size_t faces = 0;
  std::size_t vertices = 0;
  /// TRIANGLES only: indices (or vertices) past the last whole triangle, count mod 3 (the Khronos
  /// validator's MESH_PRIMITIVE_INCOMPATIBLE_MODE, a warning); they make no triangle.
  std::size_t leftover = 0;
};
std::vector<GltfPrimitive> gltf_declared_faces(const std::string& bytes, bool binary);

}  // namespace swept::io_detail
