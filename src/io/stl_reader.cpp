// STL reader, ASCII and binary, straight into double precision. Written here rather than
// through assimp so that a truncated binary file, a malformed line or a non-finite vertex is
// reported with its triangle or line number (assimp accepts truncated binary STL silently and
// parses bad ASCII numbers as 0), and so that ASCII coordinates keep their double precision.
#include "format_checks.h"
#include "import_detail.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string_view>

namespace swept::io_detail {

namespace {

std::uint32_t get_u32(const char* p) {
  std::uint32_t v = 0;
  for (int i = 0; i < 4; ++i) v |= static_cast<std::uint32_t>(static_cast<unsigned char>(p[i])) << (8 * i);
  return v;
}

float get_f32(const char* p) {
  const std::uint32_t bits = get_u32(p);
  float f;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}

// An ASCII STL keyword, in any case: the format writes them in lower case, some exporters in upper.
bool is_keyword(std::string_view token, std::string_view keyword) {
  return token.size() == keyword.size() &&
         std::equal(token.begin(), token.end(), keyword.begin(),
                    [](char a, char b) { return std::tolower(static_cast<unsigned char>(a)) == b; });
}

bool starts_with_solid(const std::string& bytes) {
  std::size_t i = bytes.starts_with(kUtf8Bom) ? kUtf8Bom.size() : 0;
  while (i < bytes.size() && (bytes[i] == ' ' || bytes[i] == '\t' || bytes[i] == '\r' || bytes[i] == '\n')) ++i;
  return is_keyword(std::string_view(bytes).substr(i, 5), "solid");
}

// A binary STL may also start with "solid". Its float data nearly always holds NUL bytes, which
// ASCII STL never does; bytes >= 0x80 (possible in UTF-8 solid names) only count when the size
// also fits the binary layout.
bool looks_binary(const std::string& bytes, bool size_matches) {
  const std::size_t end = std::min<std::size_t>(bytes.size(), 84 + 50 * 64);
  bool high = false;
  for (std::size_t i = 80; i < end; ++i) {
    const auto c = static_cast<unsigned char>(bytes[i]);
    if (c == 0) return true;
    high = high || c >= 0x80;
  }
  return high && size_matches;
}

// Text rather than binary: its first 512 bytes are all printable ASCII, whitespace or UTF-8
// (a binary STL's floats after its 84-byte header hold other bytes).
bool looks_like_text(const std::string& bytes) {
  const std::size_t end = std::min<std::size_t>(bytes.size(), 512);
  for (std::size_t i = 0; i < end; ++i) {
    const auto c = static_cast<unsigned char>(bytes[i]);
    if (c < 0x20 && c != '\n' && c != '\r' && c != '\t') return false;
    if (c == 0x7f) return false;
  }
  return end > 0;
}

Result<bool> read_binary(const ReadContext& ctx, const std::string& bytes, std::vector<TriangleSoup>& parts) {
  if (bytes.size() < 84)
    return file_error(ctx.display, "truncated binary STL: " + std::to_string(bytes.size()) +
                                       " bytes, shorter than the 84-byte header");
  // The size must be exactly 84 + 50 * count: a shorter file is truncated, and records past the
  // count (or a partial record) mean the header lies, so which triangles are meant is unknown.
  const std::uint64_t count = get_u32(bytes.data() + 80);
  const std::uint64_t expected = 84 + 50 * count;
  const std::uint64_t holds = (bytes.size() - 84) / 50;
  const std::uint64_t rest = (bytes.size() - 84) % 50;
  const std::string sizes = " (" + std::to_string(bytes.size()) + " bytes; " + std::to_string(count) +
                            " triangles take 84 + 50 * " + std::to_string(count) + " = " + std::to_string(expected) + ")";
  if (holds < count)
    return file_error(ctx.display, "truncated binary STL: header says " + std::to_string(count) +
                                       " triangles, file holds " + std::to_string(holds) + sizes);
  if (bytes.size() != expected)
    return file_error(ctx.display, "binary STL size does not match its header: header says " + std::to_string(count) +
                                       " triangles, file holds " + std::to_string(holds) +
                                       (rest ? " and " + std::to_string(rest) + " more bytes" : std::string()) + sizes);
  TriangleSoup soup;
  soup.name = ctx.file.stem().string();
  soup.triangles.resize(count);
  const double s = ctx.file_to_output;
  for (std::uint64_t i = 0; i < count; ++i) {
    const char* rec = bytes.data() + 84 + 50 * i + 12;  // skip the normal
    Triangle& t = soup.triangles[i];
    for (int v = 0; v < 3; ++v)
      for (int k = 0; k < 3; ++k) {
        const float f = get_f32(rec + 12 * v + 4 * k);
        if (!std::isfinite(f))
          return file_error(ctx.display, "triangle " + std::to_string(i) + " has a non-finite coordinate");
        t[v][k] = s * static_cast<double>(f);
      }
  }
  parts.push_back(std::move(soup));
  return true;
}

Result<bool> read_ascii(const ReadContext& ctx, const std::string& text, std::vector<TriangleSoup>& parts) {
  TextLines lines(text, false);
  std::vector<std::string_view> tok;
  auto at = [&](const std::string& what) { return file_error(ctx.display, "line " + std::to_string(lines.line()) + ": " + what); };
  auto expect = [&](std::string_view keyword, std::string_view after, std::size_t min_tokens) -> Result<bool> {
    if (!lines.next(tok))
      return file_error(ctx.display, "unexpected end of file after line " + std::to_string(lines.line()) +
                                         ": expected '" + std::string(keyword) + "'");
    if (!is_keyword(tok[0], keyword) || (!after.empty() && (tok.size() < 2 || !is_keyword(tok[1], after))) ||
        tok.size() < min_tokens) {
      std::string want(keyword);
      if (!after.empty()) {
        want.push_back(' ');
        want.append(after);
      }
      return at("expected '" + want + "', found " + quoted(tok[0]));
    }
    return true;
  };

  bool any_solid = false;
  while (lines.next(tok)) {
    if (!is_keyword(tok[0], "solid")) return at("expected 'solid', found " + quoted(tok[0]));
    any_solid = true;
    TriangleSoup soup;
    for (std::size_t i = 1; i < tok.size(); ++i) {
      if (i > 1) soup.name.push_back(' ');
      soup.name.append(tok[i]);
    }
    if (soup.name.empty()) soup.name = ctx.file.stem().string();
    bool closed = false;
    while (lines.next(tok)) {
      if (is_keyword(tok[0], "endsolid")) {
        closed = true;
        break;
      }
      if (!is_keyword(tok[0], "facet")) return at("expected 'facet' or 'endsolid', found " + quoted(tok[0]));
      if (auto r = expect("outer", "loop", 2); !r) return r;
      Triangle t;
      for (int v = 0; v < 3; ++v) {
        if (!lines.next(tok))
          return file_error(ctx.display, "unexpected end of file after line " + std::to_string(lines.line()) +
                                             " inside facet " + std::to_string(soup.triangles.size()));
        if (!is_keyword(tok[0], "vertex")) return at("expected 'vertex', found " + quoted(tok[0]));
        if (tok.size() != 4) return at("a vertex needs 3 coordinates, found " + std::to_string(tok.size() - 1));
        for (int k = 0; k < 3; ++k) {
          std::string_view s = tok[1 + k];
          if (!s.empty() && s[0] == '+') s.remove_prefix(1);
          double x = 0.0;
          const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), x);
          if (ec == std::errc::result_out_of_range)
            return at("coordinate " + quoted(tok[1 + k]) + " is out of range (triangle " +
                      std::to_string(soup.triangles.size()) + ")");
          if (ec != std::errc() || ptr != s.data() + s.size()) return at("malformed number " + quoted(tok[1 + k]));
          if (!std::isfinite(x))
            return at("triangle " + std::to_string(soup.triangles.size()) + " has a non-finite coordinate " +
                      quoted(tok[1 + k]));
          t[v][k] = ctx.file_to_output * x;
        }
      }
      if (auto r = expect("endloop", "", 1); !r) return r;
      if (auto r = expect("endfacet", "", 1); !r) return r;
      soup.triangles.push_back(t);
    }
    if (!closed)
      return file_error(ctx.display, "unexpected end of file after line " + std::to_string(lines.line()) +
                                         ": solid '" + soup.name + "' has no 'endsolid'");
    parts.push_back(std::move(soup));
  }
  if (!any_solid) return file_error(ctx.display, "ASCII STL without any 'solid'");
  return true;
}

}  // namespace

Result<bool> read_stl(const ReadContext& ctx, std::vector<TriangleSoup>& parts) {
  Result<std::string> bytes = read_file_bytes(ctx.file, ctx.display);
  if (!bytes) return bytes.error();
  const std::string& b = *bytes;
  const bool size_matches = b.size() >= 84 && b.size() == 84 + 50 * std::uint64_t{get_u32(b.data() + 80)};
  if (starts_with_solid(b)) {
    if (!looks_binary(b, size_matches)) return read_ascii(ctx, b, parts);
  } else if (!size_matches && looks_like_text(b)) {
    // Not read as a binary header: its first bytes would make a count of billions of triangles.
    std::vector<std::string_view> first;
    TextLines lines(b, false);
    lines.next(first);
    return file_error(ctx.display, "line " + std::to_string(lines.line()) + ": text that is not an ASCII STL: it starts with " +
                                       quoted(first.empty() ? std::string_view() : first[0]) + ", where an ASCII STL starts with 'solid'");
  }
  return read_binary(ctx, b, parts);
}

}  // namespace swept::io_detail
