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

Result<Path> read_path(const fs::path& file) {
  std::ifstream in(file);
  if (!in) return Error{file.string() + ": cannot open"};
  Path path;
  if (file.extension() == ".path") {
    std::string line;
    int lineno = 0;
    while (std::getline(in, line)) {
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
