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
#include <utility>
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
/// The UTF-8 byte-order mark some Windows editors put in front of a text file.
constexpr std::string_view kUtf8Bom = "\xEF\xBB\xBF";

/// The end of the line that starts at `pos` (the position of its CR or LF, or text.size()), and
/// where the next line starts: lines end in LF, CR LF or a lone CR (classic Mac OS).
inline std::pair<std::size_t, std::size_t> line_end(std::string_view text, std::size_t pos) {
  const std::size_t end = text.find_first_of("\r\n", pos);
  if (end == std::string_view::npos) return {text.size(), text.size()};
  return {end, end + (text[end] == '\r' && end + 1 < text.size() && text[end + 1] == '\n' ? 2 : 1)};
}

/// The lines of a whole text split into tokens, with 1-based line numbers (line_end's lines): a
/// UTF-8 byte-order mark in front and blank lines are skipped, and with `strip_comments` what
/// follows a '#' on a line (OFF).
class TextLines {
 public:
  TextLines(const std::string& text, bool strip_comments)
      : text_(text), strip_comments_(strip_comments), pos_(text.starts_with(kUtf8Bom) ? kUtf8Bom.size() : 0) {}

  /// The next line with tokens, into `tokens` (cleared first); false at end of file.
  bool next(std::vector<std::string_view>& tokens) {
    tokens.clear();
    while (pos_ < text_.size()) {
      const auto [end, next] = line_end(text_, pos_);
      std::string_view line(text_.data() + pos_, end - pos_);
      pos_ = next;
      ++line_;
      if (strip_comments_)
        if (const std::size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
      split(line, tokens);
      if (!tokens.empty()) return true;
    }
    return false;
  }
  /// The line `next` returned last.
  int line() const { return line_; }

 private:
  const std::string& text_;
  bool strip_comments_;
  std::size_t pos_;
  int line_ = 0;
};

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
