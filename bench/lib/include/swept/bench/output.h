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

/// An aligned text table: numbers right-aligned, text left-aligned.
class Table {
 public:
  explicit Table(std::vector<std::string> header) : rows_{std::move(header)} {}
  void add(std::vector<std::string> row) { rows_.push_back(std::move(row)); }
  void print(std::ostream& os) const {
    std::vector<std::size_t> width;
    for (const auto& r : rows_)
      for (std::size_t i = 0; i < r.size(); ++i) {
        if (width.size() <= i) width.push_back(0);
        width[i] = std::max(width[i], r[i].size());
      }
    for (std::size_t k = 0; k < rows_.size(); ++k) {
      const auto& r = rows_[k];
      for (std::size_t i = 0; i < r.size(); ++i) {
        const bool numeric = k > 0 && !r[i].empty() && (std::isdigit(static_cast<unsigned char>(r[i][0])) || r[i][0] == '-');
        const std::string pad(width[i] - r[i].size(), ' ');
        os << (i ? "  " : "") << (numeric ? pad + r[i] : r[i] + (i + 1 < r.size() ? pad : ""));
      }
      os << "\n";
    }
  }

 private:
  std::vector<std::vector<std::string>> rows_;
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
