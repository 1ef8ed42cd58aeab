// Problem files: the format is chosen by the extension (TOML: problem_toml.cpp; OMPL.app .cfg:
// problem_cfg.cpp); the helpers they share.
#include "problem_detail.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace swept {
namespace problem_detail {

std::optional<Quat> unit_quaternion(double x, double y, double z, double w) {
  const double big = std::max({std::abs(x), std::abs(y), std::abs(z), std::abs(w)});
  if (!(big > 0.0)) return std::nullopt;
  Quat q(w / big, x / big, y / big, z / big);
  q.normalize();
  return q;
}

std::optional<Vec3> unit_axis(const Vec3& axis) {
  const double big = axis.cwiseAbs().maxCoeff();
  if (!(big > 0.0)) return std::nullopt;
  return Vec3((axis / big).normalized());
}

std::filesystem::path resolve(const std::filesystem::path& base, const std::string& file) {
  std::filesystem::path p(file);
  if (p.is_absolute()) return p;
  return base.parent_path() / p;
}

std::string format_number(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

}  // namespace problem_detail

Result<Problem> load_problem(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) return Error{file.string() + ": no such file"};
  const std::string ext = file.extension().string();
  if (ext == ".cfg") return problem_detail::load_cfg(file);
  if (ext == ".toml") return problem_detail::load_toml(file);
  return Error{file.string() + ": unknown problem format '" + ext + "' (.toml or OMPL.app .cfg)"};
}

}  // namespace swept
