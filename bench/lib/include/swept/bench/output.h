#pragma once
/// Small helpers for the tools (the CLI and the benchmarks): aligned tables, number formatting,
/// writing output files.
#include "swept/io/file_write.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <ostream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace swept::bench {

/// An aligned text table: numbers right-aligned, text left-aligned. A column given a width limit
/// (`limit_width`) wraps a longer cell onto continuation lines, breaking after a list separator
/// (", " or " + ") where there is one, so that one long list does not widen every row.
class Table {
 public:
  explicit Table(std::vector<std::string> header) : rows_{std::move(header)} {}
  void add(std::vector<std::string> row) { rows_.push_back(std::move(row)); }
  void limit_width(std::size_t column, std::size_t width) {
    if (limits_.size() <= column) limits_.resize(column + 1, 0);
    limits_[column] = std::max<std::size_t>(width, 1);
  }
  void print(std::ostream& os) const {
    // Each row becomes one or more lines of cells.
    std::vector<std::vector<std::vector<std::string>>> lines(rows_.size());
    std::vector<std::size_t> width;
    for (std::size_t k = 0; k < rows_.size(); ++k) {
      const auto& r = rows_[k];
      for (std::size_t i = 0; i < r.size(); ++i) {
        const std::size_t limit = i < limits_.size() ? limits_[i] : 0;
        const std::vector<std::string> parts = limit ? wrap(r[i], limit) : std::vector<std::string>{r[i]};
        if (lines[k].size() < parts.size()) lines[k].resize(parts.size(), std::vector<std::string>(r.size()));
        for (std::size_t j = 0; j < parts.size(); ++j) lines[k][j][i] = parts[j];
        if (width.size() <= i) width.resize(i + 1, 0);
        for (const std::string& part : parts) width[i] = std::max(width[i], part.size());
      }
    }
    for (std::size_t k = 0; k < rows_.size(); ++k)
      for (const auto& cells : lines[k]) {
        std::string out;
        for (std::size_t i = 0; i < cells.size(); ++i) {
          const std::string& c = cells[i];
          const bool numeric = k > 0 && !c.empty() && (std::isdigit(static_cast<unsigned char>(c[0])) || c[0] == '-');
          const std::string pad(width[i] - c.size(), ' ');
          out += (i ? "  " : "") + (numeric ? pad + c : c + pad);
        }
        out.erase(out.find_last_not_of(' ') + 1);
        os << out << "\n";
      }
  }

 private:
  // `text` in lines of at most `limit` characters, broken only just after a separator; a piece
  // with no separator inside stays whole, however long.
  static std::vector<std::string> wrap(const std::string& text, std::size_t limit) {
    std::vector<std::string> pieces{""};
    for (std::size_t i = 0; i < text.size();) {
      const std::size_t sep = text.compare(i, 2, ", ") == 0 ? 2 : text.compare(i, 3, " + ") == 0 ? 3 : 0;
      pieces.back() += sep ? text.substr(i, sep) : text.substr(i, 1);
      i += sep ? sep : 1;
      if (sep && i < text.size()) pieces.emplace_back();
    }
    auto trimmed = [](std::string t) { return t.erase(t.find_last_not_of(' ') + 1); };
    std::vector<std::string> out{""};
    for (const std::string& piece : pieces) {
      if (!out.back().empty() && trimmed(out.back() + piece).size() > limit) out.emplace_back();
      out.back() += piece;
    }
    for (std::string& line : out) line = trimmed(line);
    return out;
  }

  std::vector<std::vector<std::string>> rows_;
  std::vector<std::size_t> limits_;  // per column, 0: no limit
};

inline std::string fmt_fixed(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

inline std::string fmt_sci(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

inline std::string fmt_int(std::size_t v) { return std::to_string(v); }

/// Writes an output file (path, JSON, HTML, SVG, ...) whole or not at all: through a temporary
/// file in the same folder renamed into place after a successful flush and close, or in place for
/// devices such as /dev/full (swept::write_file_atomically). Throws std::runtime_error naming the
/// file and the reason, which the CLI turns into exit code 1.
inline void write_output(const std::string& file, std::string_view bytes) {
  if (auto written = write_file_atomically(file, bytes); !written) throw std::runtime_error(written.error().message);
}

/// The text of a JSON document we write (stdout, results.json, the viewer's embedded scene).
/// Strings that are not valid UTF-8 — a file name with a byte such as 0xff, which POSIX allows —
/// carry U+FFFD in place of each invalid byte sequence, where nlohmann::json would throw
/// type_error 316. indent < 0: compact; else that many spaces per level.
inline std::string json_text(const nlohmann::json& doc, int indent = -1) {
  return doc.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

/// `text` as valid UTF-8, each invalid byte sequence replaced by U+FFFD (as json_text() does),
/// for text written outside JSON, such as an HTML title made from a file name.
inline std::string valid_utf8(const std::string& text) {
  return nlohmann::json::parse(json_text(nlohmann::json(text))).get<std::string>();
}

}  // namespace swept::bench
