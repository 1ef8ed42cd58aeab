// OFF reader (Geomview's Object File Format, text), straight into double precision. Written here
// rather than through assimp, whose OFF reader (5.2) drops every face of more than nine corners
// with only a log line (a cylinder's 12-sided caps vanish, the body is left open), reads the
// coordinates in single precision and stops at a comment after a vertex's colour.
#include "format_checks.h"
#include "import_detail.h"
#include "polygon.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string_view>

namespace swept::io_detail {

namespace {

// The header keyword: Geomview's [ST][C][N][4][n]OFF. Only the coordinates are read; texture
// coordinates, normals and colours after them on a vertex line are skipped.
struct OffHeader {
  bool homogeneous = false;  ///< 4: each vertex has a fourth coordinate w, the point is (x, y, z) / w
  bool dimension = false;    ///< n: the vertex dimension follows the keyword
};

bool parse_header(std::string_view word, OffHeader& h) {
  if (word.size() < 3) return false;
  std::string_view off = word.substr(word.size() - 3);
  if (off != "OFF" && off != "off") return false;
  std::string_view prefix = word.substr(0, word.size() - 3);
  auto take = [&](std::string_view flag) {
    if (prefix.substr(0, flag.size()) != flag) return false;
    prefix.remove_prefix(flag.size());
    return true;
  };
  take("ST");
  take("C");
  take("N");
  h.homogeneous = take("4");
  h.dimension = take("n");
  return prefix.empty();
}

}  // namespace

Result<bool> read_off(const ReadContext& ctx, std::vector<TriangleSoup>& parts) {
  Result<std::string> bytes = read_file_bytes(ctx.file, ctx.display);
  if (!bytes) return bytes.error();
  const std::string& text = *bytes;
  TextLines lines(text, true);
  std::vector<std::string_view> tok;
  auto at = [&](const std::string& what) { return file_error(ctx.display, "line " + std::to_string(lines.line()) + ": " + what); };

  if (!lines.next(tok)) return file_error(ctx.display, "no 'OFF' header");
  OffHeader header;
  if (!parse_header(tok[0], header)) {
    if (lower(std::string(tok[0])).ends_with("off"))
      return at("unknown OFF header " + quoted(tok[0]) + " (Geomview's are [ST][C][N][4][n]OFF)");
    return at("expected the 'OFF' header, found " + quoted(tok[0]));
  }
  std::size_t used = 1;  // tokens of the current line already read
  if (tok.size() > used && lower(std::string(tok[used])) == "binary")
    return at("binary OFF is not read; write the file as text OFF");
  // The next token, on this line or the next ones; empty at end of file.
  auto next_token = [&]() -> std::string_view {
    while (used >= tok.size()) {
      if (!lines.next(tok)) return {};
      used = 0;
    }
    return tok[used++];
  };

  long long dim = 3;
  if (header.dimension) {
    const std::string_view d = next_token();
    if (!parse_int(d, dim) || dim < 1) return at("expected the vertex dimension after 'nOFF', found " + quoted(d));
    if (dim > 3) return at("vertices of " + std::to_string(dim) + " dimensions; swept reads 3");
  }
  long long nv = 0, nf = 0;
  {
    const std::string_view v = next_token(), f = next_token();
    if (!parse_int(v, nv) || !parse_int(f, nf) || nv < 0 || nf < 0) {
      if (v.empty()) return file_error(ctx.display, "unexpected end of file: no vertex and face counts");
      return at("expected the vertex and face counts");
    }
  }
  // The rest of the counts line (the edge count, unused) is skipped; vertices start on a new line.

  // A vertex line takes at least 6 bytes, a face line 8: no reservation past what the file can hold.
  const auto fits = [&](long long count, std::size_t bytes_each) {
    return static_cast<std::size_t>(std::min<long long>(count, static_cast<long long>(text.size() / bytes_each)));
  };
  std::vector<Vec3> vertices;
  vertices.reserve(fits(nv, 6));
  const std::size_t coordinates = static_cast<std::size_t>(dim) + (header.homogeneous ? 1 : 0);
  const double s = ctx.file_to_output;
  auto cut_short = [&](long long seen_v, long long seen_f) {
    return file_error(ctx.display, "unexpected end of file: header says " + std::to_string(nv) + " vertices and " +
                                       std::to_string(nf) + " faces, file holds " + std::to_string(seen_v) + " and " +
                                       std::to_string(seen_f));
  };
  for (long long i = 0; i < nv; ++i) {
    if (!lines.next(tok)) return cut_short(i, 0);
    if (tok.size() < coordinates)
      return at("a vertex needs " + std::to_string(coordinates) + " coordinates, found " + std::to_string(tok.size()));
    double x[4] = {0.0, 0.0, 0.0, 1.0};
    for (std::size_t k = 0; k < coordinates; ++k) {
      double& dest = (header.homogeneous && k + 1 == coordinates) ? x[3] : x[k];
      if (std::string e = parse_number(tok[k], dest); !e.empty()) return at(e + " (vertex " + std::to_string(i) + ")");
    }
    if (x[3] == 0.0) return at("vertex " + std::to_string(i) + " has w = 0 (a point at infinity)");
    Vec3 p(s * (x[0] / x[3]), s * (x[1] / x[3]), s * (x[2] / x[3]));
    if (!p.allFinite()) return at("vertex " + std::to_string(i) + " is not finite in the output unit");
    vertices.push_back(p);
  }

  if (nf == 0)  // after the vertices, so that a broken point cloud is reported as broken
    return file_error(ctx.display, "holds no faces, only " + std::to_string(nv) + (nv == 1 ? " vertex" : " vertices") +
                                       " (a point cloud)");

  TriangleSoup soup;
  soup.name = ctx.file.stem().string();
  soup.triangles.reserve(fits(nf, 8));
  std::vector<std::uint32_t> corners;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  long long crossed = 0;
  std::string first_crossed;
  for (long long f = 0; f < nf; ++f) {
    if (!lines.next(tok)) return cut_short(nv, f);
    long long k = 0;
    if (!parse_int(tok[0], k) || k < 3) return at("a face needs a vertex count of at least 3, found " + quoted(tok[0]));
    if (static_cast<long long>(tok.size()) < k + 1)
      return at("face " + std::to_string(f) + " lists fewer than its " + std::to_string(k) + " vertices");
    corners.clear();
    for (long long c = 1; c <= k; ++c) {
      long long idx = 0;
      if (!parse_int(tok[c], idx)) return at("malformed vertex index " + quoted(tok[c]));
      if (idx < 0 || idx >= nv)
        return at("face " + std::to_string(f) + " refers to vertex " + std::to_string(idx) + " of " + std::to_string(nv));
      corners.push_back(static_cast<std::uint32_t>(idx));
    }
    triangles.clear();
    if (!triangulate_polygon(vertices, corners, triangles) && crossed++ == 0)
      first_crossed = "face " + std::to_string(f) + " on line " + std::to_string(lines.line());
    for (const auto& t : triangles) soup.triangles.push_back({vertices[t[0]], vertices[t[1]], vertices[t[2]]});
  }
  // What follows the header's faces is not read (CGAL's own data has such files); said, not kept
  // silent.
  if (lines.next(tok) && ctx.warnings != nullptr)
    ctx.warnings->push_back(ctx.display + ": line " + std::to_string(lines.line()) + ": more data after the " +
                            std::to_string(nf) + " faces the header announces (starting " + quoted(tok[0]) +
                            "); not read");
  if (crossed > 0 && ctx.warnings != nullptr)
    ctx.warnings->push_back(ctx.display + ": " + std::to_string(crossed) +
                            (crossed == 1 ? " face is not a simple polygon" : " faces are not simple polygons") +
                            " (its edges cross in its plane; first: " + first_crossed +
                            "); the corners ear clipping left were fanned from one of them");
  parts.push_back(std::move(soup));
  return true;
}

}  // namespace swept::io_detail
