// PLY checked before assimp reads it (format_checks.h).
#include "format_checks.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string_view>
#include <vector>

namespace swept::io_detail {
namespace {

// The PLY header: its elements and their properties.
struct PlyProperty {
  std::string name;
  int size = 0;       // scalar size in bytes, or the list's item size
  int count_size = 0; // > 0 for a list: size of its count
  bool is_signed = false;  // the (list item) type is signed
  bool is_float = false;   // the (list item) type is float or double
  bool vertex_refs = false;  // a list of vertex indices (face/tristrips "vertex_indices"/"vertex_index")
};
struct PlyElement {
  std::string name;
  long long count = 0;
  std::vector<PlyProperty> properties;
};

bool ply_type_signed(std::string_view t) {
  return t == "char" || t == "short" || t == "int" || t == "int8" || t == "int16" || t == "int32";
}

bool ply_type_float(std::string_view t) { return t == "float" || t == "double" || t == "float32" || t == "float64"; }

// Reads one binary PLY scalar of `size` bytes as an integer (for list counts and vertex indices).
long long ply_binary_int(const char* p, int size, bool is_signed, bool little) {
  unsigned long long n = 0;
  for (int b = 0; b < size; ++b) {
    const auto byte = static_cast<unsigned char>(p[b]);
    n |= static_cast<unsigned long long>(byte) << (8 * (little ? b : size - 1 - b));
  }
  if (is_signed && size < 8 && (n >> (8 * size - 1)) != 0) n |= ~0ull << (8 * size);  // sign-extend
  return static_cast<long long>(n);
}

// A face's vertex reference must name one of the `vertices` vertices; tristrips use -1 as a
// strip separator (assimp's PLY reader does). "" when fine, else the reason.
std::string check_vertex_ref(long long index, long long vertices, const PlyElement& e, long long item) {
  if (index == -1 && e.name == "tristrips") return {};
  if (index >= 0 && index < vertices) return {};
  return "element '" + e.name + "' " + std::to_string(item) + " refers to vertex " + std::to_string(index) +
         " but the file has " + std::to_string(vertices) + " vertices (0 to " + std::to_string(vertices - 1) + ")";
}

int ply_type_size(std::string_view t) {
  if (t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
  if (t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
  if (t == "int" || t == "uint" || t == "float" || t == "int32" || t == "uint32" || t == "float32") return 4;
  if (t == "double" || t == "float64") return 8;
  return 0;
}

}  // namespace

std::string check_ply(const std::string& bytes) {
  std::size_t pos = 0;
  int line_no = 0;
  std::string format;
  std::vector<PlyElement> elements;
  bool ended = false;
  while (!ended) {
    if (pos >= bytes.size()) return "unexpected end of file inside the header (no 'end_header')";
    const auto [end, next] = line_end(bytes, pos);
    const auto tok = split(std::string_view(bytes.data() + pos, end - pos));
    pos = next;
    ++line_no;
    const std::string at = "line " + std::to_string(line_no) + ": ";
    if (line_no == 1) {
      if (tok.empty() || lower(std::string(tok[0])) != "ply") return "not a PLY file (no 'ply' magic)";
      continue;
    }
    if (tok.empty() || tok[0] == "comment" || tok[0] == "obj_info") continue;
    if (tok[0] == "format") {
      if (tok.size() < 2) return at + "incomplete 'format' line";
      format = std::string(tok[1]);
      if (format != "ascii" && format != "binary_little_endian" && format != "binary_big_endian")
        return at + "unknown PLY format " + quoted(tok[1]);
    } else if (tok[0] == "element") {
      PlyElement e;
      if (tok.size() < 3 || !parse_int(tok[2], e.count) || e.count < 0) return at + "malformed 'element' line";
      e.name = std::string(tok[1]);
      elements.push_back(std::move(e));
    } else if (tok[0] == "property") {
      if (elements.empty()) return at + "'property' before any 'element'";
      PlyProperty p;
      if (tok.size() >= 5 && tok[1] == "list") {
        p.count_size = ply_type_size(tok[2]);
        p.size = ply_type_size(tok[3]);
        p.is_signed = ply_type_signed(tok[3]);
        p.is_float = ply_type_float(tok[3]);
        p.name = std::string(tok[4]);
        if (p.count_size == 0 || p.size == 0) return at + "unknown list type";
        p.vertex_refs = (elements.back().name == "face" || elements.back().name == "tristrips") &&
                        (p.name == "vertex_indices" || p.name == "vertex_index");
      } else if (tok.size() >= 3) {
        p.size = ply_type_size(tok[1]);
        p.name = std::string(tok[2]);
        if (p.size == 0) return at + "unknown property type " + quoted(tok[1]);
      } else {
        return at + "malformed 'property' line";
      }
      elements.back().properties.push_back(p);
    } else if (tok[0] == "end_header") {
      ended = true;
    } else {
      return at + "unexpected header keyword " + quoted(tok[0]) +
             " (a PLY header holds format, element, property, comment, obj_info and end_header lines; free text "
             "needs 'comment' in front)";
    }
  }
  if (format.empty()) return "the header has no 'format' line";
  long long vertices = 0, faces = 0;  // the 'vertex' element's count, which face indices refer to
  for (const PlyElement& e : elements) {
    if (e.name == "vertex") vertices = e.count;
    if (e.name == "face" || e.name == "tristrips") faces += e.count;
  }
  // A whole point cloud (assimp: "Validation failed: Mesh  contains no faces"); a broken one is
  // reported as broken first.
  const std::string cloud =
      faces == 0 && vertices > 0
          ? "holds no faces, only " + std::to_string(vertices) + (vertices == 1 ? " vertex" : " vertices") + " (a point cloud)"
          : std::string();

  if (format == "ascii") {
    for (const PlyElement& e : elements) {
      for (long long i = 0; i < e.count; ++i) {
        std::vector<std::string_view> tok;
        while (tok.empty()) {
          if (pos >= bytes.size())
            return "unexpected end of file: element '" + e.name + "' " + std::to_string(i) + " of " +
                   std::to_string(e.count) + " is missing";
          const auto [end, next] = line_end(bytes, pos);
          tok = split(std::string_view(bytes.data() + pos, end - pos));
          pos = next;
          ++line_no;
        }
        const std::string at = "line " + std::to_string(line_no) + ": ";
        std::size_t k = 0;
        for (const PlyProperty& p : e.properties) {
          if (k >= tok.size()) return at + "element '" + e.name + "' " + std::to_string(i) + " has too few values";
          if (p.count_size > 0) {
            long long n = 0;
            if (!parse_int(tok[k], n) || n < 0) return at + "malformed list count " + quoted(tok[k]);
            if (static_cast<unsigned long long>(n) > tok.size() - k - 1)
              return at + "list '" + p.name + "' has fewer than its " + std::to_string(n) + " values";
            for (std::size_t j = k + 1; j <= k + static_cast<std::size_t>(n); ++j) {
              if (!p.vertex_refs) continue;
              long long index = 0;
              if (!parse_int(tok[j], index)) return at + "malformed vertex index " + quoted(tok[j]);
              if (std::string err = check_vertex_ref(index, vertices, e, i); !err.empty()) return at + err;
            }
            k += 1 + static_cast<std::size_t>(n);
          } else {
            double x = 0.0;
            if (std::string err = parse_number(tok[k], x); !err.empty())
              return at + err + " (element '" + e.name + "' " + std::to_string(i) + ", property '" + p.name + "')";
            ++k;
          }
        }
      }
    }
    return cloud;
  }

  const bool little = format == "binary_little_endian";
  for (const PlyElement& e : elements) {
    if (e.properties.empty()) continue;  // takes no bytes, however many it declares
    for (long long i = 0; i < e.count; ++i) {
      for (const PlyProperty& p : e.properties) {
        std::size_t need = static_cast<std::size_t>(p.count_size > 0 ? p.count_size : p.size);
        if (pos + need > bytes.size())
          return "truncated binary PLY: element '" + e.name + "' " + std::to_string(i) + " of " +
                 std::to_string(e.count) + " ends past the end of the file";
        if (p.count_size > 0) {
          const auto n = static_cast<unsigned long long>(ply_binary_int(bytes.data() + pos, p.count_size, false, little));
          if (n > bytes.size())  // also keeps n * size below overflow
            return "truncated binary PLY: element '" + e.name + "' " + std::to_string(i) + " of " +
                   std::to_string(e.count) + " ends past the end of the file";
          need += static_cast<std::size_t>(n) * static_cast<std::size_t>(p.size);
          if (pos + need > bytes.size())
            return "truncated binary PLY: element '" + e.name + "' " + std::to_string(i) + " of " +
                   std::to_string(e.count) + " ends past the end of the file";
          if (p.vertex_refs && !p.is_float) {
            for (unsigned long long j = 0; j < n; ++j) {
              const char* item = bytes.data() + pos + static_cast<std::size_t>(p.count_size) + j * static_cast<std::size_t>(p.size);
              const long long index = ply_binary_int(item, p.size, p.is_signed, little);
              if (std::string err = check_vertex_ref(index, vertices, e, i); !err.empty()) return err;
            }
          }
        }
        pos += need;
      }
    }
  }
  return cloud;
}

}  // namespace swept::io_detail
