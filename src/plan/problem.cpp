// Problem files: TOML (docs/problem-format.md) and OMPL.app .cfg; path files.
#include "swept/plan/problem.h"

#include "swept/io/mesh_io.h"

#include <nlohmann/json.hpp>
#include <toml++/toml.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <map>
#include <numbers>
#include <sstream>

namespace swept {
namespace {

namespace fs = std::filesystem;

constexpr double kDeg = std::numbers::pi / 180.0;

struct TomlReader {
  std::string file;
  std::string error;  // the first error met

  bool fail(const std::string& key, const std::string& what) {
    if (error.empty()) error = file + ": " + key + ": " + what;
    return false;
  }

  bool number(const toml::node* n, const std::string& key, double& out) {
    if (!n) return true;  // absent: keep the default
    if (auto v = n->value<double>()) {
      if (!std::isfinite(*v)) return fail(key, "must be a finite number");
      out = *v;
      return true;
    }
    return fail(key, "must be a number");
  }

  bool vec3(const toml::node* n, const std::string& key, Vec3& out) {
    if (!n) return true;
    const toml::array* a = n->as_array();
    if (!a || a->size() != 3) return fail(key, "must be an array of 3 numbers");
    for (std::size_t i = 0; i < 3; ++i) {
      auto v = (*a)[i].value<double>();
      if (!v || !std::isfinite(*v)) return fail(key, "must be an array of 3 finite numbers");
      out[static_cast<Eigen::Index>(i)] = *v;
    }
    return true;
  }

  bool pose(const toml::node* n, const std::string& key, Pose& out) {
    out = Pose{};
    if (!n) return true;
    const toml::table* t = n->as_table();
    if (!t) return fail(key, "must be a table with translation and quaternion or axis + angle_deg");
    for (auto&& [k, v] : *t) {
      const std::string name(k.str());
      if (name != "translation" && name != "quaternion" && name != "axis" && name != "angle_deg")
        return fail(key + "." + name, "unknown key (translation, quaternion, axis, angle_deg)");
    }
    if (!vec3(t->get("translation"), key + ".translation", out.translation)) return false;
    if (const toml::node* q = t->get("quaternion")) {
      const toml::array* a = q->as_array();
      if (!a || a->size() != 4) return fail(key + ".quaternion", "must be [x, y, z, w]");
      double c[4];
      for (std::size_t i = 0; i < 4; ++i) {
        auto v = (*a)[i].value<double>();
        if (!v || !std::isfinite(*v)) return fail(key + ".quaternion", "must be 4 finite numbers [x, y, z, w]");
        c[i] = *v;
      }
      Quat quat(c[3], c[0], c[1], c[2]);
      if (quat.norm() < 1e-12) return fail(key + ".quaternion", "must not be zero");
      if (t->get("axis") || t->get("angle_deg"))
        return fail(key, "give either quaternion or axis + angle_deg, not both");
      out.rotation = quat.normalized().toRotationMatrix();
    } else if (t->get("axis") || t->get("angle_deg")) {
      Vec3 axis = Vec3::UnitZ();
      double angle = 0.0;
      if (!vec3(t->get("axis"), key + ".axis", axis) || !number(t->get("angle_deg"), key + ".angle_deg", angle))
        return false;
      if (axis.norm() < 1e-12) return fail(key + ".axis", "must not be zero");
      out.rotation = Eigen::AngleAxisd(angle * kDeg, axis.normalized()).toRotationMatrix();
    }
    return true;
  }
};

fs::path resolve(const fs::path& base, const std::string& file) {
  fs::path p(file);
  if (p.is_absolute()) return p;
  return base.parent_path() / p;
}

Result<Problem> load_toml(const fs::path& file) {
  toml::table root;
  try {
    root = toml::parse_file(file.string());
  } catch (const toml::parse_error& e) {
    std::ostringstream os;
    os << file.string() << ":" << e.source().begin.line << ":" << e.source().begin.column
       << ": malformed TOML: " << e.description();
    return Error{os.str()};
  }
  TomlReader r{file.string(), {}};
  Problem p;
  p.source = file;
  static const char* known[] = {"unit", "obstacle", "body", "body_frame", "start", "goal",
                                "bounds", "rotation", "planner"};
  for (auto&& [k, v] : root) {
    const std::string name(k.str());
    if (std::find_if(std::begin(known), std::end(known), [&](const char* s) { return name == s; }) == std::end(known))
      return Error{file.string() + ": unknown key '" + name + "'"};
  }
  if (auto u = root["unit"].value<std::string>()) p.unit = *u;
  double metres;
  if (!unit_scale(p.unit, metres)) return Error{file.string() + ": unit: unknown unit '" + p.unit + "' (m, cm, mm, um, in, ft)"};

  auto meshes = [&](const char* key, std::vector<MeshRef>& out) -> bool {
    const toml::array* arr = root[key].as_array();
    if (!arr) return r.fail(key, "missing: give at least one [[" + std::string(key) + "]] with a file");
    for (std::size_t i = 0; i < arr->size(); ++i) {
      const std::string where = std::string(key) + "[" + std::to_string(i) + "]";
      const toml::table* t = (*arr)[i].as_table();
      if (!t) return r.fail(where, "must be a table");
      MeshRef m;
      auto f = (*t)["file"].value<std::string>();
      if (!f) return r.fail(where + ".file", "missing");
      m.file = resolve(file, *f);
      if (!fs::exists(m.file)) return r.fail(where + ".file", "no such file: " + m.file.string());
      if (auto fu = (*t)["file_unit"].value<std::string>()) m.file_unit = *fu;
      if (!r.number(t->get("deflection"), where + ".deflection", m.deflection)) return false;
      if (!r.pose(t->get("pose"), where + ".pose", m.pose)) return false;
      out.push_back(std::move(m));
    }
    if (out.empty()) return r.fail(key, "needs at least one mesh");
    return true;
  };
  if (!meshes("obstacle", p.obstacles) || !meshes("body", p.body)) return Error{r.error};

  if (const toml::table* bf = root["body_frame"].as_table()) {
    if (bf->get("reference_point")) {
      Vec3 c;
      if (!r.vec3(bf->get("reference_point"), "body_frame.reference_point", c)) return Error{r.error};
      p.reference_point = c;
    }
  }
  if (!root["start"].as_table()) return Error{file.string() + ": start: missing [start] pose"};
  if (!r.pose(root.get("start"), "start", p.start)) return Error{r.error};
  const toml::table* goal = root["goal"].as_table();
  if (!goal) return Error{file.string() + ": goal: missing [goal] (a pose, or outside = true)"};
  if (goal->get("outside")) {
    auto o = (*goal)["outside"].value<bool>();
    if (!o) return Error{file.string() + ": goal.outside: must be true or false"};
    p.goal_outside = *o;
    if (!r.number(goal->get("margin"), "goal.margin", p.goal_margin)) return Error{r.error};
    if (p.goal_margin < 0) return Error{file.string() + ": goal.margin: must be ≥ 0"};
  }
  if (!p.goal_outside) {
    Pose g;
    TomlReader gr{file.string(), {}};
    toml::table pose_only;
    for (auto&& [k, v] : *goal)
      if (k.str() != "outside" && k.str() != "margin") pose_only.insert(k, v);
    if (!gr.pose(&pose_only, "goal", g)) return Error{gr.error};
    if (!goal->get("translation")) return Error{file.string() + ": goal: give translation (+ rotation) or outside = true"};
    p.goal = g;
  }
  if (const toml::table* b = root["bounds"].as_table()) {
    Aabb box;
    if (!b->get("min") || !b->get("max")) return Error{file.string() + ": bounds: give both min and max"};
    if (!r.vec3(b->get("min"), "bounds.min", box.min) || !r.vec3(b->get("max"), "bounds.max", box.max))
      return Error{r.error};
    if ((box.min.array() >= box.max.array()).any()) return Error{file.string() + ": bounds: min must be below max on every axis"};
    p.bounds = box;
  }
  if (const toml::table* rot = root["rotation"].as_table()) {
    const std::string mode = (*rot)["mode"].value_or(std::string("free"));
    if (mode == "none") p.rotation = RotationMode::none;
    else if (mode == "free") p.rotation = RotationMode::free;
    else if (mode == "limits") p.rotation = RotationMode::limits;
    else return Error{file.string() + ": rotation.mode: '" + mode + "' (none, free or limits)"};
    if (p.rotation == RotationMode::limits) {
      const toml::array* lim = (*rot)["limits_deg"].as_array();
      if (!lim || lim->size() != 3) return Error{file.string() + ": rotation.limits_deg: give [[lo, hi], [lo, hi], [lo, hi]] in degrees"};
      for (std::size_t i = 0; i < 3; ++i) {
        const toml::array* pair = (*lim)[i].as_array();
        if (!pair || pair->size() != 2) return Error{file.string() + ": rotation.limits_deg: each entry is [lo, hi]"};
        for (std::size_t j = 0; j < 2; ++j) {
          auto v = (*pair)[j].value<double>();
          if (!v || !std::isfinite(*v)) return Error{file.string() + ": rotation.limits_deg: numbers in degrees"};
          p.rotation_limits[i][j] = *v * kDeg;
        }
        if (p.rotation_limits[i][0] > 0 || p.rotation_limits[i][1] < 0 || p.rotation_limits[i][0] >= p.rotation_limits[i][1])
          return Error{file.string() + ": rotation.limits_deg: each range must contain 0 (the start orientation) and lo < hi"};
      }
    }
  }
  if (const toml::table* pl = root["planner"].as_table()) {
    if (!r.number(pl->get("clearance"), "planner.clearance", p.clearance) ||
        !r.number(pl->get("contact_tolerance"), "planner.contact_tolerance", p.contact_tolerance) ||
        !r.number(pl->get("time_limit"), "planner.time_limit", p.time_limit) ||
        !r.number(pl->get("deflection"), "planner.deflection", p.deflection))
      return Error{r.error};
    if (auto f = (*pl)["fitter"].value<std::string>())
      if (!parse_fitter(*f, p.fitter)) return Error{file.string() + ": planner.fitter: '" + *f + "' (pqp, rapid2, inertia)"};
    if (auto t = (*pl)["threads"].value<int64_t>()) p.threads = static_cast<int>(*t);
    if (p.clearance < 0 || p.contact_tolerance < 0) return Error{file.string() + ": planner: clearance and contact_tolerance must be ≥ 0"};
    if (p.time_limit <= 0) return Error{file.string() + ": planner.time_limit: must be > 0 seconds"};
    if (p.threads < 0) return Error{file.string() + ": planner.threads: must be ≥ 0"};
    if (p.deflection <= 0) return Error{file.string() + ": planner.deflection: must be > 0"};
  }
  for (auto* list : {&p.obstacles, &p.body})
    for (MeshRef& m : *list)
      if (m.deflection <= 0) m.deflection = p.deflection;
  return p;
}

// OMPL.app's .cfg: an INI file with a [problem] section (robot, world, start.*, goal.*,
// volume.*); angles in radians about an axis.
Result<Problem> load_cfg(const fs::path& file) {
  std::ifstream in(file);
  if (!in) return Error{file.string() + ": cannot open"};
  std::map<std::string, std::pair<std::string, int>> kv;  // key → (value, line)
  std::string line, section;
  int lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    auto hash = line.find_first_of("#;");
    if (hash != std::string::npos) line.erase(hash);
    auto trim = [](std::string s) {
      const auto b = s.find_first_not_of(" \t\r"), e = s.find_last_not_of(" \t\r");
      return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
    };
    line = trim(line);
    if (line.empty()) continue;
    if (line.front() == '[') {
      if (line.back() != ']') return Error{file.string() + ":" + std::to_string(lineno) + ": malformed section header"};
      section = trim(line.substr(1, line.size() - 2));
      continue;
    }
    const auto eq = line.find('=');
    if (eq == std::string::npos)
      return Error{file.string() + ":" + std::to_string(lineno) + ": expected 'key = value', got '" + line + "'"};
    if (section == "problem") kv[trim(line.substr(0, eq))] = {trim(line.substr(eq + 1)), lineno};
  }
  if (kv.empty()) return Error{file.string() + ": no [problem] section with keys (robot, world, start.*, goal.*)"};
  std::string error;
  auto num = [&](const std::string& key, double& out, bool required) {
    auto it = kv.find(key);
    if (it == kv.end()) {
      if (required && error.empty()) error = file.string() + ": missing " + key;
      return;
    }
    char* end = nullptr;
    const double v = std::strtod(it->second.first.c_str(), &end);
    if (end == it->second.first.c_str() || *end != '\0' || !std::isfinite(v)) {
      if (error.empty())
        error = file.string() + ":" + std::to_string(it->second.second) + ": " + key + ": not a number: '" + it->second.first + "'";
      return;
    }
    out = v;
  };
  auto pose = [&](const std::string& prefix) {
    Vec3 t = Vec3::Zero(), axis = Vec3::UnitZ();
    double theta = 0.0;
    num(prefix + ".x", t.x(), true);
    num(prefix + ".y", t.y(), true);
    num(prefix + ".z", t.z(), true);
    num(prefix + ".theta", theta, false);
    num(prefix + ".axis.x", axis.x(), false);
    num(prefix + ".axis.y", axis.y(), false);
    num(prefix + ".axis.z", axis.z(), false);
    if (axis.norm() < 1e-12) axis = Vec3::UnitZ();
    return Pose::from_axis_angle(axis, theta, t);
  };
  Problem p;
  p.source = file;
  p.unit = "mm";
  for (const char* key : {"robot", "world"}) {
    auto it = kv.find(key);
    if (it == kv.end()) return Error{file.string() + ": missing " + std::string(key) + " = MESH"};
    MeshRef m;
    m.file = resolve(file, it->second.first);
    if (!fs::exists(m.file))
      return Error{file.string() + ":" + std::to_string(it->second.second) + ": " + key + ": no such file: " + m.file.string()};
    m.file_unit = "mm";  // OMPL.app is unit-less: keep the numbers as they are
    m.center_on_vertex_mean = std::string(key) == "robot";
    m.deflection = p.deflection;
    (std::string(key) == "robot" ? p.body : p.obstacles).push_back(m);
  }
  p.start = pose("start");
  p.goal = pose("goal");
  p.reference_point = Vec3::Zero();  // the robot's frame origin: its vertex mean
  Aabb box;
  bool any = false;
  for (const char* axis : {"x", "y", "z"}) any = any || kv.count(std::string("volume.min.") + axis);
  if (any) {
    const char* names[3] = {"x", "y", "z"};
    for (int i = 0; i < 3; ++i) {
      num(std::string("volume.min.") + names[i], box.min[i], true);
      num(std::string("volume.max.") + names[i], box.max[i], true);
    }
    p.bounds = box;
  }
  if (!error.empty()) return Error{error};
  if (p.bounds && (p.bounds->min.array() >= p.bounds->max.array()).any())
    return Error{file.string() + ": volume.min must be below volume.max on every axis"};
  return p;
}

}  // namespace

Result<Problem> load_problem(const fs::path& file) {
  std::error_code ec;
  if (!fs::exists(file, ec)) return Error{file.string() + ": no such file"};
  const std::string ext = file.extension().string();
  if (ext == ".cfg") return load_cfg(file);
  if (ext == ".toml") return load_toml(file);
  return Error{file.string() + ": unknown problem format '" + ext + "' (.toml or OMPL.app .cfg)"};
}

Result<bool> write_path(const fs::path& file, const Path& path, const std::string& unit, const Vec3& reference) {
  std::ofstream out(file);
  if (!out) return Error{file.string() + ": cannot write"};
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
  if (!out) return Error{file.string() + ": write failed"};
  return true;
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
      std::istringstream ls(line);
      double v[7];
      for (double& x : v)
        if (!(ls >> x) || !std::isfinite(x)) return Error{file.string() + ":" + std::to_string(lineno) + ": expected 'x y z qx qy qz qw'"};
      Quat q(v[6], v[3], v[4], v[5]);
      if (q.norm() < 1e-12) return Error{file.string() + ":" + std::to_string(lineno) + ": zero quaternion"};
      path.poses.push_back(Pose::from_quaternion(q, Vec3(v[0], v[1], v[2])));
    }
  } else {
    try {
      const nlohmann::json doc = nlohmann::json::parse(in);
      for (const auto& p : doc.at("poses")) {
        const auto& t = p.at("translation");
        const auto& q = p.at("quaternion");
        Quat quat(q.at(3).get<double>(), q.at(0).get<double>(), q.at(1).get<double>(), q.at(2).get<double>());
        if (quat.norm() < 1e-12) return Error{file.string() + ": zero quaternion"};
        path.poses.push_back(Pose::from_quaternion(quat, Vec3(t.at(0).get<double>(), t.at(1).get<double>(), t.at(2).get<double>())));
      }
    } catch (const std::exception& e) {
      return Error{file.string() + ": malformed path JSON: " + e.what()};
    }
  }
  if (path.poses.empty()) return Error{file.string() + ": the path has no poses"};
  return path;
}

}  // namespace swept
