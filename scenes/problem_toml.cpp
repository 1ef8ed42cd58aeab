#include "swept/scenes/problem_toml.h"

#include <charconv>
#include <initializer_list>
#include <numbers>

namespace swept::scenes {
namespace {

/// The shortest text that reads back as exactly `v` (std::to_chars' round-trip guarantee), as a
/// TOML float ("60.0", not the integer "60").
std::string num(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  std::string s(buf, r.ptr);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";  // n: inf, nan
  return s;
}

/// "[a, b, c]". (Appended piece by piece: GCC 12's -Wrestrict misfires on "[" + std::string.)
std::string list(std::initializer_list<double> values) {
  std::string s = "[";
  for (const double v : values) s.append(s.size() > 1 ? ", " : "").append(num(v));
  return s.append("]");
}

std::string vec(const Vec3& v) { return list({v.x(), v.y(), v.z()}); }

std::string quat(const Pose& p) {
  const Quat q = p.quaternion();
  return list({q.x(), q.y(), q.z(), q.w()});
}

std::string pose_lines(const Pose& p) { return "translation = " + vec(p.translation) + "\nquaternion = " + quat(p) + "\n"; }

bool is_identity(const Pose& p) { return p.translation.isZero(0.0) && p.rotation.isIdentity(0.0); }

std::string mesh_table(const char* table, const MeshRef& m) {
  std::string s = std::string("[[") + table + "]]\nfile = \"" + m.file.generic_string() + "\"\n";
  if (!m.file_unit.empty()) s += "file_unit = \"" + m.file_unit + "\"\n";
  if (m.deflection > 0) s += "deflection = " + num(m.deflection) + "\n";
  if (!is_identity(m.pose))
    s += "pose = { translation = " + vec(m.pose.translation) + ", quaternion = " + quat(m.pose) + " }\n";
  return s + "\n";
}

std::string_view rotation_mode(RotationMode m) {
  switch (m) {
    case RotationMode::none: return "none";
    case RotationMode::free: return "free";
    case RotationMode::limits: return "limits";
  }
  return "free";
}

}  // namespace

MeshRef mesh_ref(const std::filesystem::path& file, const std::string& file_unit, const Pose& pose) {
  MeshRef m;
  m.file = file;
  m.file_unit = file_unit;
  m.pose = pose;
  return m;
}

std::string problem_toml(const Problem& p, std::string_view comment) {
  std::string s = "# ";
  for (const char c : comment) s += c == '\n' ? std::string("\n# ") : std::string(1, c);
  s += "\n\nunit = \"" + p.unit + "\"\n\n";
  for (const MeshRef& m : p.obstacles) s += mesh_table("obstacle", m);
  for (const MeshRef& m : p.body) s += mesh_table("body", m);
  if (p.reference_point) s += "[body_frame]\nreference_point = " + vec(*p.reference_point) + "\n\n";
  s += "[start]\n" + pose_lines(p.start) + "\n[goal]\n";
  if (p.goal_outside) s += "outside = true\nmargin = " + num(p.goal_margin) + "\n\n";
  else if (p.goal) s += pose_lines(*p.goal) + "\n";
  if (p.bounds) s += "[bounds]\nmin = " + vec(p.bounds->min) + "\nmax = " + vec(p.bounds->max) + "\n\n";
  s += "[rotation]\nmode = \"" + std::string(rotation_mode(p.rotation)) + "\"\n";
  if (p.rotation == RotationMode::limits) {
    s += "limits_deg = [";
    for (std::size_t i = 0; i < 3; ++i)
      s += std::string(i ? ", " : "") + "[" + num(p.rotation_limits[i][0] * 180 / std::numbers::pi) + ", " +
           num(p.rotation_limits[i][1] * 180 / std::numbers::pi) + "]";
    s += "]\n";
  }
  s += "\n[planner]\nclearance = " + num(p.clearance) + "\ncontact_tolerance = " + num(p.contact_tolerance) +
       "\nfitter = \"" + std::string(to_string(p.build.fitter)) + "\"\nsplit = \"" +
       std::string(to_string(p.build.split)) + "\"\nleaf_size = " + std::to_string(p.build.leaf_size) +
       "\ntime_limit = " + num(p.time_limit) + "\nthreads = " + std::to_string(p.threads) + "\n";
  if (p.deflection != Problem{}.deflection) s += "deflection = " + num(p.deflection) + "\n";
  if (p.max_triangles != Problem{}.max_triangles) s += "max_triangles = " + std::to_string(p.max_triangles) + "\n";
  if (p.seed != 0) s += "seed = " + std::to_string(p.seed) + "\n";
  return s;
}

}  // namespace swept::scenes
