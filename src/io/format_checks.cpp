// Our own checks of the formats assimp reads (format_checks.h): OBJ line by line,
// COLLADA's counts, glTF's references and declared faces; the tokenizer they share with the PLY
// (ply_check.cpp) and IGES (iges_check.cpp) checks.
#include "format_checks.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string_view>
#include <vector>

namespace swept::io_detail {

std::vector<std::string_view> split(std::string_view line) {
  std::vector<std::string_view> out;
  split(line, out);
  return out;
}

void split(std::string_view line, std::vector<std::string_view>& out) {
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    std::size_t j = i;
    while (j < line.size() && !std::isspace(static_cast<unsigned char>(line[j]))) ++j;
    if (j > i) out.push_back(line.substr(i, j - i));
    i = j;
  }
}

std::string quoted(std::string_view s) {
  std::string out(1, '\'');
  out.append(s.substr(0, 40));
  if (s.size() > 40) out.append("...");
  out.push_back('\'');
  return out;
}

// Parses a decimal number; "" on success, else the reason.
std::string parse_number(std::string_view s, double& x) {
  std::string_view t = s;
  if (!t.empty() && t[0] == '+') t.remove_prefix(1);
  const auto [ptr, ec] = std::from_chars(t.data(), t.data() + t.size(), x);
  if (ec == std::errc::result_out_of_range) return "number " + quoted(s) + " is out of range";
  if (ec != std::errc() || ptr != t.data() + t.size()) return "malformed number " + quoted(s);
  if (!std::isfinite(x)) return "non-finite coordinate " + quoted(s);
  return {};
}

// Parses an integer; false if it is not one.
bool parse_int(std::string_view s, long long& v) {
  if (!s.empty() && s[0] == '+') s.remove_prefix(1);
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  return ec == std::errc() && ptr == s.data() + s.size();
}

namespace {

// OBJ's statements: calls f(line_number, tokens, commented) for every statement with tokens, '#'
// comments stripped (`commented`: the statement had one after its tokens); a line ending in '\\'
// continues on the next (as assimp joins them), numbered by its first line. Stops at the first
// non-empty string f returns.
template <class F>
std::string for_each_statement(const std::string& text, F&& f) {
  std::size_t pos = 0;
  int line_no = 0;
  std::string joined;  // a statement continued over several lines
  std::vector<std::string_view> tokens;
  while (pos < text.size()) {
    const int first_line = line_no + 1;
    joined.clear();
    std::string_view line;
    bool commented = false;
    for (;;) {
      const auto [end, next] = line_end(text, pos);
      std::string_view part(text.data() + pos, end - pos);
      pos = next;
      ++line_no;
      if (const std::size_t hash = part.find('#'); hash != std::string_view::npos) {
        part = part.substr(0, hash);
        commented = commented || !split(part).empty() || !joined.empty();
      }
      std::size_t last = part.find_last_not_of(" \t\r");
      const bool continued = last != std::string_view::npos && part[last] == '\\' && pos < text.size();
      if (!continued && joined.empty()) {
        line = part;
        break;
      }
      joined.append(part.substr(0, continued ? last : part.size()));
      joined.push_back(' ');
      if (!continued) {
        line = joined;
        break;
      }
    }
    tokens.clear();
    split(line, tokens);
    if (tokens.empty()) continue;
    std::string err = f(first_line, tokens, commented);
    if (!err.empty()) return "line " + std::to_string(first_line) + ": " + err;
  }
  return {};
}

// OBJ: vertices need three finite numbers, faces at least three valid vertex references
// (1-based, or negative = relative to the last vertex, to a vertex already defined).
std::string check_obj(const std::string& text) {
  long long vertices = 0;
  return for_each_statement(text, [&](int, const std::vector<std::string_view>& tok, bool commented) -> std::string {
    if (tok[0] == "v") {
      if (tok.size() < 4) return "a vertex needs 3 coordinates, found " + std::to_string(tok.size() - 1);
      for (int k = 1; k <= 3; ++k) {
        double x;
        if (std::string e = parse_number(tok[k], x); !e.empty()) return e + " (vertex " + std::to_string(vertices + 1) + ")";
      }
      ++vertices;
    } else if (tok[0] == "f") {
      if (commented)  // assimp: "OBJ: Invalid face index.", without a line
        return "a comment after a face's vertices, which assimp's OBJ reader cannot read; put the comment on a "
               "line of its own";
      if (tok.size() < 4) return "a face needs at least 3 vertices, found " + std::to_string(tok.size() - 1);
      for (std::size_t k = 1; k < tok.size(); ++k) {
        std::string_view ref = tok[k].substr(0, tok[k].find('/'));
        long long idx = 0;
        if (!parse_int(ref, idx) || idx == 0) return "malformed face vertex " + quoted(tok[k]);
        const long long abs_idx = idx > 0 ? idx : vertices + 1 + idx;
        if (abs_idx < 1 || abs_idx > vertices)
          return "face refers to vertex " + std::to_string(idx) + " but " + std::to_string(vertices) +
                 " vertices are defined so far";
      }
    }
    return {};
  });
}

// COLLADA: every count attribute (float_array, accessor, triangles, polylist, ...) counts items
// that take at least one byte each in the file, so a count above the file's size is a lie; assimp
// would reserve memory for it first (std::bad_alloc, or gigabytes) and only then find the data short.
std::string check_dae_counts(const std::string& text) {
  const std::string key = "count=\"";
  for (std::size_t at = text.find(key); at != std::string::npos; at = text.find(key, at + key.size())) {
    if (at > 0 && !std::isspace(static_cast<unsigned char>(text[at - 1]))) continue;  // e.g. vcount="
    const std::size_t begin = at + key.size(), end = text.find('"', begin);
    if (end == std::string::npos) return {};
    unsigned long long count = 0;
    const auto [ptr, ec] = std::from_chars(text.data() + begin, text.data() + end, count);
    if (ec == std::errc::result_out_of_range || (ec == std::errc() && ptr == text.data() + end && count > text.size())) {
      const std::size_t open = text.rfind('<', at);
      const std::string element =
          open == std::string::npos ? std::string("?") : text.substr(open + 1, text.find_first_of(" \t\r\n>", open) - open - 1);
      return "line " + std::to_string(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n') + 1) + ": <" + element + "> declares count=\"" + text.substr(begin, end - begin) +
             "\", more items than the file's " + std::to_string(text.size()) + " bytes can hold";
    }
  }
  return {};
}

// GLB (the glTF binary container, Khronos glTF 2.0 §4.4 "GLB File Format Specification"): a
// 12-byte header (magic "glTF", version, total length equal to the file's size), then chunks of
// (length, type, data) that end exactly at the file's end, the first one JSON. glTF 1's binary
// extension (version 1) has a 20-byte header (magic, version, length, content length, content
// format 0 = JSON). assimp reads past the end of a short or lying container, so it is walked here
// first. "" when sound, else the reason.
std::string check_glb_container(const std::string& bytes) {
  auto u32 = [&](std::size_t at) {
    std::uint32_t v = 0;
    for (int b = 0; b < 4; ++b) v |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[at + b])) << (8 * b);
    return v;
  };
  if (bytes.size() < 12 || bytes.compare(0, 4, "glTF") != 0)
    return "not a binary glTF (GLB) file: it does not start with the 12-byte header 'glTF', version, length";
  const std::uint32_t version = u32(4), length = u32(8);
  if (length != bytes.size())
    return "GLB header says the file is " + std::to_string(length) + " bytes, it is " + std::to_string(bytes.size()) +
           (length > bytes.size() ? " (truncated)" : "");
  if (version == 1) {
    if (bytes.size() < 20) return "GLB 1 header is 20 bytes, the file has " + std::to_string(bytes.size());
    if (u32(16) != 0) return "GLB 1 content format " + std::to_string(u32(16)) + " is not 0 (JSON)";
    if (u32(12) > bytes.size() - 20)
      return "GLB 1 content length " + std::to_string(u32(12)) + " runs past the end of the file";
    return {};
  }
  if (version != 2) return "GLB version " + std::to_string(version) + " is not 1 or 2";
  std::size_t at = 12;
  int chunk = 0;
  while (at < bytes.size()) {
    if (bytes.size() - at < 8)
      return "GLB chunk " + std::to_string(chunk) + " at byte " + std::to_string(at) + ": its 8-byte header is cut short";
    const std::uint32_t chunk_length = u32(at);
    if (chunk_length > bytes.size() - at - 8)
      return "GLB chunk " + std::to_string(chunk) + " at byte " + std::to_string(at) + ": its length " +
             std::to_string(chunk_length) + " runs past the end of the file";
    if (chunk == 0 && bytes.compare(at + 4, 4, "JSON") != 0) return "GLB chunk 0 is not the JSON chunk";
    at += 8 + chunk_length;
    ++chunk;
  }
  if (chunk == 0) return "GLB file has no JSON chunk";
  return {};
}

// glTF: every buffer and image uri is a data: URI or a relative path that stays in the model's
// folder ("sub/mesh.bin"); an absolute path, a "../" that climbs out of the folder or a URL
// (http:, file:, ...) is an error naming it. "" when fine or not glTF we can parse (assimp then says).
std::string check_gltf_uris(const std::string& bytes, bool binary) {
  std::string_view text = bytes;
  if (binary) {
    if (bytes.size() < 20 || bytes.compare(0, 4, "glTF") != 0 || bytes.compare(16, 4, "JSON") != 0) return {};
    std::uint32_t length = 0;
    for (int b = 0; b < 4; ++b) length |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[12 + b])) << (8 * b);
    if (length > bytes.size() - 20) return {};
    text = std::string_view(bytes).substr(20, length);
  }
  const nlohmann::json doc = nlohmann::json::parse(text, nullptr, false);
  if (doc.is_discarded() || !doc.is_object()) return {};
  for (const char* kind : {"buffers", "images"}) {
    const auto list = doc.find(kind);
    if (list == doc.end() || !list->is_array()) continue;
    for (std::size_t i = 0; i < list->size(); ++i) {
      const auto uri_it = (*list)[i].find("uri");
      if (uri_it == (*list)[i].end() || !uri_it->is_string()) continue;
      const std::string uri = uri_it->get<std::string>();
      if (uri.rfind("data:", 0) == 0) continue;
      const std::string where = std::string(kind) + "[" + std::to_string(i) + "].uri " + io_detail::quoted(uri);
      const std::size_t colon = uri.find(':'), slash = uri.find('/');
      if (colon != std::string::npos && (slash == std::string::npos || colon < slash))
        return where + " is a URL: only data: URIs and files in the model's folder are read";
      // Percent-decoded, as assimp opens it; then no leading '/' and no climb above the folder.
      std::string path;
      for (std::size_t k = 0; k < uri.size(); ++k) {
        unsigned value = 0;
        if (uri[k] == '%' && k + 2 < uri.size() &&
            std::from_chars(uri.data() + k + 1, uri.data() + k + 3, value, 16).ptr == uri.data() + k + 3) {
          path.push_back(static_cast<char>(value));
          k += 2;
        } else {
          path.push_back(uri[k]);
        }
      }
      int depth = 0;
      bool escapes = !path.empty() && (path[0] == '/' || path[0] == '\\');
      for (std::size_t b = 0; b <= path.size() && !escapes;) {
        std::size_t e = path.find_first_of("/\\", b);
        if (e == std::string::npos) e = path.size();
        const std::string_view part(path.data() + b, e - b);
        if (part == "..") escapes = --depth < 0;
        else if (!part.empty() && part != ".") ++depth;
        b = e + 1;
      }
      if (escapes) return where + " is outside the model's folder (external files must be in its folder or below)";
    }
  }
  return {};
}

}  // namespace

std::optional<Error> precheck(const ReadContext& ctx) {
  const std::string ext = lower(ctx.file.extension().string());
  if (ext == ".stl" || ext == ".off") {
    std::vector<TriangleSoup> parts;
    if (Result<bool> read = ext == ".stl" ? read_stl(ctx, parts) : read_off(ctx, parts); !read) return read.error();
    return std::nullopt;
  }
  if (ext != ".obj" && ext != ".ply" && ext != ".dae" && ext != ".gltf" && ext != ".glb")
    return std::nullopt;
  Result<std::string> text = read_file_bytes(ctx.file, ctx.display);
  if (!text) return text.error();
  if ((ext == ".obj" || ext == ".ply") && text->starts_with(kUtf8Bom))  // assimp: "vertex index out of range", "Incorrect magic number"
    return file_error(ctx.display, "starts with a UTF-8 byte-order mark, which assimp's " +
                                       std::string(ext == ".obj" ? "OBJ" : "PLY") +
                                       " reader cannot read; save the file without it (\"UTF-8\", not \"UTF-8 with BOM\")");
  if (ext == ".glb") {
    if (std::string err = check_glb_container(*text); !err.empty()) return file_error(ctx.display, err);
  }
  if (ext == ".gltf" || ext == ".glb") {
    if (std::string err = check_gltf_uris(*text, ext == ".glb"); !err.empty()) return file_error(ctx.display, err);
    return std::nullopt;
  }
  const std::string err = ext == ".obj"   ? check_obj(*text)
                          : ext == ".dae" ? check_dae_counts(*text)
                                          : check_ply(*text);
  if (!err.empty()) return file_error(ctx.display, err);
  return std::nullopt;
}

std::vector<GltfPrimitive> gltf_declared_faces(const std::string& bytes, bool binary) {
  std::vector<GltfPrimitive> out;
  std::string_view text = bytes;
  if (binary) {  // 12-byte header, then the JSON chunk: length, type "JSON", data
    if (bytes.size() < 20 || bytes.compare(0, 4, "glTF") != 0 || bytes.compare(16, 4, "JSON") != 0) return out;
    std::uint32_t length = 0;
    for (int b = 0; b < 4; ++b) length |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[12 + b])) << (8 * b);
    if (length > bytes.size() - 20) return out;
    text = std::string_view(bytes).substr(20, length);
  }
  const nlohmann::json doc = nlohmann::json::parse(text, nullptr, false);
  if (doc.is_discarded() || !doc.is_object()) return out;
  try {
    if (doc.at("asset").at("version").get<std::string>().rfind("2", 0) != 0) return out;
    const auto& accessors = doc.at("accessors");
    auto count = [&](const nlohmann::json& index) { return accessors.at(index.get<std::size_t>()).at("count").get<std::size_t>(); };
    for (const auto& mesh : doc.value("meshes", nlohmann::json::array())) {
      const auto& primitives = mesh.at("primitives");
      for (std::size_t k = 0; k < primitives.size(); ++k) {
        const auto& prim = primitives.at(k);
        GltfPrimitive p;
        p.mesh = mesh.value("name", std::string());
        p.primitive = k;
        p.primitives = primitives.size();
        p.vertices = count(prim.at("attributes").at("POSITION"));
        const std::size_t n = prim.contains("indices") ? count(prim.at("indices")) : p.vertices;
        switch (prim.value("mode", 4)) {
          case 0: p.faces = n; break;                   // points
          case 1: p.faces = n / 2; break;               // lines
          case 2: p.faces = n; break;                   // line loop
          case 3: p.faces = n > 0 ? n - 1 : 0; break;   // line strip
          case 4:  // triangles
            p.faces = n / 3;
            p.leftover = n % 3;
            break;
          default: p.faces = n > 2 ? n - 2 : 0; break;  // triangle strip, fan
        }
        out.push_back(p);
      }
    }
  } catch (const nlohmann::json::exception&) {
    out.clear();  // malformed: assimp's own error says what
  }
  return out;
}

}  // namespace swept::io_detail
