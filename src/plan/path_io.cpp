// Path files: our JSON and OMPL's .path.
#include "problem_detail.h"

#include "swept/io/file_write.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <sstream>
#include <string_view>

namespace swept {

namespace fs = std::filesystem;
using problem_detail::unit_quaternion;

Result<bool> write_path(const fs::path& file, const Path& path, const std::string& unit, const Vec3& reference) {
  std::ostringstream out;
  out << std::setprecision(17);
  if (file.extension() == ".path") {
    for (const Pose& p : path.poses) {
      const Quat q = p.quaternion();
      out << p.translation.x() << ' ' << p.translation.y() << ' ' << p.translation.z() << ' ' << q.x() << ' '
          << q.y() << ' ' << q.z() << ' ' << q.w() << '\n';
    }
  } else {
    nlohmann::json poses = nlohmann::json::array();
    for (const Pose& p : path.poses) {
      const Quat q = p.quaternion();
      poses.push_back({{"translation", {p.translation.x(), p.translation.y(), p.translation.z()}},
                       {"quaternion", {q.x(), q.y(), q.z(), q.w()}}});
    }
    nlohmann::json doc{{"unit", unit}, {"reference_point", {reference.x(), reference.y(), reference.z()}}, {"poses", poses}};
    out << doc.dump(1) << '\n';
  }
  return write_file_atomically(file, out.str());
}

namespace {

// The numbers of "NAME [a b c ...]" (OMPL's printState of one component), exactly `count` of
// them, finite; an error naming the line otherwise.
std::optional<std::string> bracketed(const std::string& line, const std::string& name, std::size_t count,
                                     const std::string& at, double* out) {
  const std::string open = name + " [";
  if (line.rfind(open, 0) != 0 || line.back() != ']')
    return at + "expected '" + name + " [" + (count == 3 ? "x y z" : "x y z w") + "]'";
  std::istringstream ls(line.substr(open.size(), line.size() - open.size() - 1));
  for (std::size_t k = 0; k < count; ++k)
    if (!(ls >> out[k])) return at + name + ": expected " + std::to_string(count) + " numbers";
  std::string extra;
  if (ls >> extra) return at + name + ": expected " + std::to_string(count) + " numbers, found more";
  for (std::size_t k = 0; k < count; ++k)
    if (!std::isfinite(out[k])) return at + name + ": non-finite number";
  return std::nullopt;
}

// OMPL's PathGeometric::print() of SE(3) states, the form of the .path files OMPL.app ships
// (resources/3D/*.path): per state "Compound state [", "RealVectorState [x y z]",
// "SO3State [qx qy qz qw]", "]", each on its own line.
Result<Path> read_ompl_printed_states(std::istream& in, const std::string& name) {
  Path path;
  std::string line;
  int lineno = 0;
  int part = -1;  // -1: between states; 0, 1, 2: the lines of a state read so far
  double v[7];
  auto trim = [](const std::string& x) {
    const auto b = x.find_first_not_of(" \t\r"), e = x.find_last_not_of(" \t\r");
    return b == std::string::npos ? std::string() : x.substr(b, e - b + 1);
  };
  while (std::getline(in, line)) {
    ++lineno;
    line = trim(line);
    if (line.empty()) continue;
    const std::string at = name + ":" + std::to_string(lineno) + ": ";
    if (part == -1) {
      if (line != "Compound state [") return Error{at + "expected 'Compound state [' (OMPL's printed SE(3) state)"};
      part = 0;
    } else if (part == 0) {
      if (auto err = bracketed(line, "RealVectorState", 3, at, v)) return Error{*err};
      part = 1;
    } else if (part == 1) {
      if (auto err = bracketed(line, "SO3State", 4, at, v + 3)) return Error{*err};
      part = 2;
    } else {
      if (line != "]") return Error{at + "expected ']' closing the state"};
      const auto q = unit_quaternion(v[3], v[4], v[5], v[6]);
      if (!q) return Error{at + "zero quaternion"};
      path.poses.push_back(Pose{q->toRotationMatrix(), Vec3(v[0], v[1], v[2])});
      part = -1;
    }
  }
  if (part != -1) return Error{name + ": the last state is cut short (line " + std::to_string(lineno) + ")"};
  return path;
}

}  // namespace

Result<Path> read_path(const fs::path& file) {
  std::ifstream in(file);
  if (!in) return Error{file.string() + ": cannot open"};
  Path path;
  if (file.extension() == ".path") {
    // A UTF-8 byte-order mark in front (a file saved by Notepad) is skipped.
    char mark[3] = {};
    in.read(mark, 3);
    const std::streamoff start = in.gcount() == 3 && std::string_view(mark, 3) == "\xEF\xBB\xBF" ? 3 : 0;
    in.clear();
    in.seekg(start);
    // OMPL writes two forms: printAsMatrix() (a line of 7 numbers per state, ours too) and
    // print() (the states as printed); the first non-blank line tells which.
    std::string first;
    while (std::getline(in, first) && first.find_first_not_of(" \t\r") == std::string::npos) {
    }
    in.clear();
    in.seekg(start);
    const bool printed_states = first.find("Compound state") != std::string::npos;
    if (printed_states) {
      Result<Path> printed = read_ompl_printed_states(in, file.string());
      if (!printed) return printed.error();
      path = std::move(*printed);
    }
    std::string line;
    int lineno = 0;
    while (!printed_states && std::getline(in, line)) {
      ++lineno;
      if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
      const std::string at = file.string() + ":" + std::to_string(lineno) + ": ";
      std::istringstream ls(line);
      double v[7];
      std::string extra;
      for (double& x : v)
        if (!(ls >> x)) return Error{at + "expected 7 numbers 'x y z qx qy qz qw'"};
      if (ls >> extra) return Error{at + "expected 7 numbers 'x y z qx qy qz qw', found more"};
      for (double x : v)
        if (!std::isfinite(x)) return Error{at + "non-finite number"};
      const auto q = unit_quaternion(v[3], v[4], v[5], v[6]);
      if (!q) return Error{at + "zero quaternion"};
      path.poses.push_back(Pose{q->toRotationMatrix(), Vec3(v[0], v[1], v[2])});
    }
  } else {
    try {
      const nlohmann::json doc = nlohmann::json::parse(in);
      std::size_t i = 0;
      for (const auto& p : doc.at("poses")) {
        const std::string at = file.string() + ": poses[" + std::to_string(i++) + "]: ";
        const auto& t = p.at("translation");
        const auto& q = p.at("quaternion");
        if (!t.is_array() || t.size() != 3) return Error{at + "translation must be [x, y, z]"};
        if (!q.is_array() || q.size() != 4) return Error{at + "quaternion must be [x, y, z, w]"};
        double v[7];
        for (std::size_t k = 0; k < 7; ++k) {
          v[k] = (k < 3 ? t.at(k) : q.at(k - 3)).get<double>();
          if (!std::isfinite(v[k])) return Error{at + "non-finite number"};
        }
        const auto unit = unit_quaternion(v[3], v[4], v[5], v[6]);
        if (!unit) return Error{at + "zero quaternion"};
        path.poses.push_back(Pose{unit->toRotationMatrix(), Vec3(v[0], v[1], v[2])});
      }
    } catch (const std::exception& e) {
      return Error{file.string() + ": malformed path JSON: " + e.what()};
    }
  }
  if (path.poses.empty()) return Error{file.string() + ": the path has no poses"};
  return path;
}

}  // namespace swept
