// Helpers of swept_io that the CAD reader module (src/cad/) compiles in as well: read_file_bytes
// (import_detail.h) and lower (format_checks.h).
#include "format_checks.h"
#include "import_detail.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <iterator>

namespace swept::io_detail {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

Result<std::string> read_file_bytes(const std::filesystem::path& file, const std::string& display) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return file_error(display, "cannot open file for reading");
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) return file_error(display, "read error");
  return bytes;
}

}  // namespace swept::io_detail
