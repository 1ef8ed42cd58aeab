// IGES checked before OpenCASCADE reads it (format_checks.h).
#include "format_checks.h"

#include <array>
#include <charconv>
#include <string>
#include <utility>
#include <vector>

namespace swept::io_detail {

// IGES is made of 80-column records; column 73 names the section (Start, Global, Directory,
// Parameter, Terminate) and the Terminate record holds each section's line count. OCCT's IGES
// reader can crash on truncated files, so the structure is checked first.
std::string check_iges(const std::string& bytes) {
  const std::string letters = "SGDPT";
  std::array<long long, 5> counts{};
  int last = 0;
  std::string terminate;
  std::vector<std::pair<int, std::string>> directory_first_lines;  // (line number, record)
  std::size_t pos = 0;
  int line_no = 0;
  while (pos < bytes.size()) {
    std::size_t end = bytes.find('\n', pos);
    if (end == std::string::npos) end = bytes.size();
    std::string line = bytes.substr(pos, end - pos);
    pos = end + 1;
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(' ') == std::string::npos) continue;
    const std::string at = "line " + std::to_string(line_no) + ": ";
    if (line.size() < 73) return at + "IGES records are 80 columns wide, this one has " + std::to_string(line.size());
    const std::size_t section = letters.find(line[72]);
    if (line[72] == 'C') return at + "compressed IGES is not supported";
    if (section == std::string::npos) return at + "unknown IGES section letter '" + std::string(1, line[72]) + "' in column 73";
    if (static_cast<int>(section) < last)
      return at + "section '" + std::string(1, line[72]) + "' after section '" + std::string(1, letters[last]) + "'";
    last = static_cast<int>(section);
    if (section == 2 && counts[2] % 2 == 0) directory_first_lines.emplace_back(line_no, line);
    if (section == 4) terminate = line;
    ++counts[section];
  }
  if (counts[4] == 0) return "truncated IGES file: no terminate (T) section";
  for (int s = 0; s < 4; ++s) {
    // Fixed columns: "S" + 7 digits, "G" + 7, "D" + 7, "P" + 7 (digits may be space-padded).
    const std::size_t at = 8 * static_cast<std::size_t>(s);
    if (terminate[at] != letters[static_cast<std::size_t>(s)]) return "malformed IGES terminate section";
    long long declared = 0;
    std::string digits = terminate.substr(at + 1, 7);
    digits.erase(0, digits.find_first_not_of(' '));
    if (std::from_chars(digits.data(), digits.data() + digits.size(), declared).ec != std::errc())
      return "malformed IGES terminate section";
    if (declared != counts[static_cast<std::size_t>(s)])
      return "truncated IGES file: terminate section says section " + std::string(1, letters[static_cast<std::size_t>(s)]) +
             " has " + std::to_string(declared) + " lines, file holds " + std::to_string(counts[static_cast<std::size_t>(s)]);
  }
  if (counts[2] % 2 != 0) return "malformed IGES file: odd number of directory lines";
  for (const auto& [line_no, record] : directory_first_lines) {
    long long pointer = 0;
    std::string field = record.substr(8, 8);
    field.erase(0, field.find_first_not_of(' '));
    if (std::from_chars(field.data(), field.data() + field.size(), pointer).ec != std::errc() || pointer < 1 ||
        pointer > counts[3])
      return "line " + std::to_string(line_no) + ": directory entry points to parameter line '" + field + "' of " +
             std::to_string(counts[3]);
  }
  return {};
}

}  // namespace swept::io_detail
