// Our TOML problem format (docs/problem-format.md), read strictly.
#include "problem_detail.h"

#include "swept/io/mesh_io.h"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <sstream>

namespace swept::problem_detail {
namespace {

namespace fs = std::filesystem;

// Past ten turns an angle's sine and cosine lose their digits, and a number that large in a
// problem file is a mistake, not a rotation; so is a quaternion whose length is far from 1.
constexpr double kMaxAngleDeg = 3600.0;
constexpr double kMinQuaternionLength = 1e-3;

// Reads our TOML problem strictly: every table's keys are checked against the keys it may hold,
// every value's type and range is checked, and the first problem becomes the error, naming the
// file, the line and column, and the key ("p.toml:12:1: planner.clearence: unknown key ...").
struct TomlReader {
  std::string file;
  std::string error;  // the first error met

  static std::string at(const toml::source_region& where) {
    if (where.begin.line == 0) return {};
    return ":" + std::to_string(where.begin.line) + ":" + std::to_string(where.begin.column);
  }

  bool fail(const toml::source_region& where, const std::string& key, const std::string& what) {
    if (error.empty()) error = file + at(where) + ": " + key + ": " + what;
    return false;
  }
  bool fail(const toml::node& n, const std::string& key, const std::string& what) { return fail(n.source(), key, what); }
  /// fail() as the Error to return.
  Error err(const toml::source_region& where, const std::string& key, const std::string& what) {
    fail(where, key, what);
    return Error{error};
  }
  Error err(const toml::node& n, const std::string& key, const std::string& what) { return err(n.source(), key, what); }

  /// Every key of `t` must be one of `known`.
  bool keys(const toml::table& t, const std::string& prefix, std::initializer_list<std::string_view> known) {
    for (auto&& [k, v] : t) {
      if (std::find(known.begin(), known.end(), k.str()) != known.end()) continue;
      std::string list;
      for (std::string_view name : known) list += (list.empty() ? "" : ", ") + std::string(name);
      return fail(k.source(), prefix + std::string(k.str()), "unknown key (known here: " + list + ")");
    }
    return true;
  }

  /// A finite number (integer or float) at least `lo` (or above it when `lo_open`); absent: keep `out`.
  bool number(const toml::node* n, const std::string& key, double& out, double lo = -INFINITY, bool lo_open = false) {
    if (!n) return true;
    double v;
    if (auto i = n->as_integer()) v = static_cast<double>(i->get());
    else if (auto f = n->as_floating_point()) v = f->get();
    else return fail(*n, key, "must be a number");
    if (!std::isfinite(v)) return fail(*n, key, "must be a finite number");
    if (lo_open ? !(v > lo) : !(v >= lo))
      return fail(*n, key, std::string("must be ") + (lo_open ? "> " : "≥ ") + format(lo) + ", got " + format(v));
    out = v;
    return true;
  }

  bool integer(const toml::node* n, const std::string& key, int& out, int lo, int hi) {
    if (!n) return true;
    const auto* i = n->as_integer();
    if (!i) return fail(*n, key, "must be a whole number");
    if (i->get() < lo || i->get() > hi)
      return fail(*n, key, "must be from " + std::to_string(lo) + " to " + std::to_string(hi) + ", got " +
                               std::to_string(i->get()));
    out = static_cast<int>(i->get());
    return true;
  }

  bool integer(const toml::node* n, const std::string& key, std::uint64_t& out) {
    if (!n) return true;
    const auto* i = n->as_integer();
    if (!i) return fail(*n, key, "must be a whole number");
    if (i->get() < 0) return fail(*n, key, "must be 0 or more, got " + std::to_string(i->get()));
    out = static_cast<std::uint64_t>(i->get());
    return true;
  }

  bool string(const toml::node* n, const std::string& key, std::string& out) {
    if (!n) return true;
    const auto* v = n->as_string();
    if (!v) return fail(*n, key, "must be a string");
    out = v->get();
    return true;
  }

  bool strings(const toml::node* n, const std::string& key, std::vector<std::string>& out) {
    if (!n) return true;
    const auto* a = n->as_array();
    if (!a) return fail(*n, key, "must be an array of strings");
    for (std::size_t i = 0; i < a->size(); ++i) {
      const auto* v = a->get(i)->as_string();
      if (!v) return fail(*a->get(i), key + "[" + std::to_string(i) + "]", "must be a string");
      out.push_back(v->get());
    }
    return true;
  }

  bool boolean(const toml::node* n, const std::string& key, bool& out) {
    if (!n) return true;
    const auto* v = n->as_boolean();
    if (!v) return fail(*n, key, "must be true or false");
    out = v->get();
    return true;
  }

  bool unit(const toml::node* n, const std::string& key, std::string& out) {
    if (!string(n, key, out)) return false;
    double metres;
    if (n && !unit_scale(out, metres)) return fail(*n, key, "unknown unit '" + out + "' (m, cm, mm, um, in, ft)");
    return true;
  }

  /// A table, or an error naming what it must be.
  const toml::table* table(const toml::node* n, const std::string& key, const std::string& what) {
    if (!n) return nullptr;
    const toml::table* t = n->as_table();
    if (!t) fail(*n, key, "must be " + what);
    return t;
  }

  bool numbers(const toml::node* n, const std::string& key, double* out, std::size_t count, const std::string& what) {
    if (!n) return true;
    const toml::array* a = n->as_array();
    if (!a || a->size() != count) return fail(*n, key, "must be " + what);
    for (std::size_t i = 0; i < count; ++i)
      if (!number(a->get(i), key + "[" + std::to_string(i) + "]", out[i])) return false;
    return true;
  }

  bool vec3(const toml::node* n, const std::string& key, Vec3& out) {
    double v[3] = {out.x(), out.y(), out.z()};
    if (!numbers(n, key, v, 3, "an array of 3 numbers [x, y, z]")) return false;
    out = Vec3(v[0], v[1], v[2]);
    return true;
  }

  /// The pose keys of `t` (translation, quaternion or axis + angle_deg); other keys are the caller's.
  bool pose_keys(const toml::table& t, const std::string& key, Pose& out) {
    out = Pose{};
    if (!vec3(t.get("translation"), key + ".translation", out.translation)) return false;
    const toml::node* q = t.get("quaternion");
    const toml::node* axis = t.get("axis");
    const toml::node* angle = t.get("angle_deg");
    if (q && (axis || angle)) return fail(*q, key, "give either quaternion or axis + angle_deg, not both");
    if (q) {
      double c[4];
      if (!numbers(q, key + ".quaternion", c, 4, "[x, y, z, w]")) return false;
      const double big = std::max({std::abs(c[0]), std::abs(c[1]), std::abs(c[2]), std::abs(c[3])});
      const double length = big > 0.0 ? big * Eigen::Vector4d(c[0] / big, c[1] / big, c[2] / big, c[3] / big).norm() : 0.0;
      if (!(length >= kMinQuaternionLength && length <= 1.0 / kMinQuaternionLength))
        return fail(*q, key + ".quaternion",
                    "must have a length near 1 (it is normalized, and any length in [" + format(kMinQuaternionLength) +
                        ", " + format(1.0 / kMinQuaternionLength) + "] is taken), got " + format(length) +
                        ": [x, y, z, w] with w the real part, [0, 0, 0, 1] for no rotation");
      const auto unit = unit_quaternion(c[0], c[1], c[2], c[3]);
      if (!unit) return fail(*q, key + ".quaternion", "must not be zero");
      out.rotation = unit->toRotationMatrix();
    } else if (axis || angle) {
      if (!axis) return fail(*angle, key, "angle_deg needs axis = [x, y, z]");
      if (!angle) return fail(*axis, key, "axis needs angle_deg");
      Vec3 a = Vec3::Zero();
      double deg = 0.0;
      if (!vec3(axis, key + ".axis", a) || !number(angle, key + ".angle_deg", deg)) return false;
      if (std::abs(deg) > kMaxAngleDeg)
        return fail(*angle, key + ".angle_deg",
                    "an angle of " + format(deg) + " degrees is more than " + format(kMaxAngleDeg / 360.0) +
                        " turns: give it within one turn (|angle_deg| <= 360)");
      const auto unit = unit_axis(a);
      if (!unit) return fail(*axis, key + ".axis", "must not be zero");
      out.rotation = Eigen::AngleAxisd(deg * kDeg, *unit).toRotationMatrix();
    }
    return true;
  }

  bool pose(const toml::node* n, const std::string& key, Pose& out) {
    out = Pose{};
    const toml::table* t = table(n, key, "a table with translation and quaternion or axis + angle_deg");
    if (!t) return n == nullptr;
    return keys(*t, key + ".", {"translation", "quaternion", "axis", "angle_deg"}) && pose_keys(*t, key, out);
  }

  static std::string format(double v) { return format_number(v); }
};

}  // namespace

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
  auto failed = [&] { return Error{r.error}; };
  if (!r.keys(root, "", {"unit", "obstacle", "body", "body_frame", "start", "goal", "bounds", "rotation", "planner"}))
    return failed();
  if (!r.unit(root.get("unit"), "unit", p.unit)) return failed();

  // [planner] first: its deflection is the default of the meshes'.
  if (const toml::node* n = root.get("planner")) {
    const toml::table* pl = r.table(n, "planner", "a table [planner]");
    int max_triangles = static_cast<int>(std::min<std::size_t>(p.max_triangles, std::numeric_limits<int>::max()));
    if (!pl ||
        !r.keys(*pl, "planner.", {"clearance", "contact_tolerance", "fitter", "split", "leaf_size", "time_limit", "deflection", "threads", "max_triangles", "seed"}) ||
        !r.number(pl->get("clearance"), "planner.clearance", p.clearance, 0.0) ||
        !r.number(pl->get("contact_tolerance"), "planner.contact_tolerance", p.contact_tolerance, 0.0) ||
        !r.number(pl->get("time_limit"), "planner.time_limit", p.time_limit, 0.0, true) ||
        !r.number(pl->get("deflection"), "planner.deflection", p.deflection, 0.0, true) ||
        !r.integer(pl->get("threads"), "planner.threads", p.threads, 0, std::numeric_limits<int>::max()) ||
        !r.integer(pl->get("seed"), "planner.seed", p.seed) ||
        !r.integer(pl->get("max_triangles"), "planner.max_triangles", max_triangles, 1, std::numeric_limits<int>::max()) ||
        !r.integer(pl->get("leaf_size"), "planner.leaf_size", p.build.leaf_size, 1, kMaxLeafSize))
      return failed();
    p.max_triangles = static_cast<std::size_t>(max_triangles);
    if (const toml::node* f = pl->get("fitter")) {
      std::string fitter;
      if (!r.string(f, "planner.fitter", fitter)) return failed();
      if (!parse_fitter(fitter, p.build.fitter))
        return r.err(*f, "planner.fitter", "unknown fitter '" + fitter + "' (" + fitter_names() + ")");
    }
    if (const toml::node* f = pl->get("split")) {
      std::string split;
      if (!r.string(f, "planner.split", split)) return failed();
      if (!parse_split_rule(split, p.build.split))
        return r.err(*f, "planner.split", "unknown split rule '" + split + "' (" + split_rule_names() + ")");
    }
  }

  auto meshes = [&](const char* key, std::vector<MeshRef>& out) -> bool {
    const toml::node* n = root.get(key);
    if (!n) return r.fail(toml::source_region{}, key, "missing: give at least one [[" + std::string(key) + "]] with a file");
    const toml::array* arr = n->as_array();
    if (!arr) return r.fail(*n, key, "must be an array of tables: write [[" + std::string(key) + "]]");
    for (std::size_t i = 0; i < arr->size(); ++i) {
      const std::string where = std::string(key) + "[" + std::to_string(i) + "]";
      const toml::table* t = r.table(arr->get(i), where, "a table with file (and file_unit, deflection, pose, part or except)");
      if (!t || !r.keys(*t, where + ".", {"file", "file_unit", "deflection", "pose", "part", "except"})) return false;
      MeshRef m;
      const toml::node* f = t->get("file");
      if (!f) return r.fail(t->source(), where + ".file", "missing");
      std::string name;
      if (!r.string(f, where + ".file", name)) return false;
      if (name.empty()) return r.fail(*f, where + ".file", "must not be empty");
      m.file = resolve(file, name);
      std::error_code ec;
      if (!fs::is_regular_file(m.file, ec))
        return r.fail(*f, where + ".file", (fs::exists(m.file, ec) ? "not a file: " : "no such file: ") + m.file.string());
      if (!r.unit(t->get("file_unit"), where + ".file_unit", m.file_unit)) return false;
      m.deflection = p.deflection;
      if (!r.number(t->get("deflection"), where + ".deflection", m.deflection, 0.0, true)) return false;
      if (!r.pose(t->get("pose"), where + ".pose", m.pose)) return false;
      if (!r.string(t->get("part"), where + ".part", m.part) || !r.strings(t->get("except"), where + ".except", m.except))
        return false;
      if (const toml::node* e = t->get("part"); e && m.part.empty()) return r.fail(*e, where + ".part", "must not be empty");
      if (const toml::node* e = t->get("except"); e && !m.part.empty())
        return r.fail(*e, where + ".except", "give either part or except, not both");
      out.push_back(std::move(m));
    }
    if (out.empty()) return r.fail(*n, key, "needs at least one mesh");
    return true;
  };
  if (!meshes("obstacle", p.obstacles) || !meshes("body", p.body)) return failed();

  if (const toml::node* n = root.get("body_frame")) {
    const toml::table* bf = r.table(n, "body_frame", "a table [body_frame]");
    if (!bf || !r.keys(*bf, "body_frame.", {"reference_point"})) return failed();
    if (const toml::node* c = bf->get("reference_point")) {
      Vec3 point = Vec3::Zero();
      if (!r.vec3(c, "body_frame.reference_point", point)) return failed();
      p.reference_point = point;
    }
  }

  if (!root.get("start")) return Error{file.string() + ": start: missing [start] pose"};
  if (!r.pose(root.get("start"), "start", p.start)) return failed();

  const toml::node* goal_node = root.get("goal");
  if (!goal_node) return Error{file.string() + ": goal: missing [goal] (a pose, or outside = true)"};
  const toml::table* goal = r.table(goal_node, "goal", "a table [goal]: a pose, or outside = true");
  if (!goal || !r.keys(*goal, "goal.", {"translation", "quaternion", "axis", "angle_deg", "outside", "margin"}) ||
      !r.boolean(goal->get("outside"), "goal.outside", p.goal_outside))
    return failed();
  if (p.goal_outside) {
    if (!r.number(goal->get("margin"), "goal.margin", p.goal_margin, 0.0)) return failed();
    for (const char* k : {"translation", "quaternion", "axis", "angle_deg"})
      if (const toml::node* n = goal->get(k))
        return r.err(*n, std::string("goal.") + k, "give either a goal pose or outside = true, not both");
  } else {
    if (const toml::node* m = goal->get("margin"))
      return r.err(*m, "goal.margin", "only used with outside = true");
    if (!goal->get("translation"))
      return r.err(goal->source(), "goal", "give translation (+ rotation) or outside = true");
    Pose g;
    if (!r.pose_keys(*goal, "goal", g)) return failed();
    p.goal = g;
  }

  if (const toml::node* n = root.get("bounds")) {
    const toml::table* b = r.table(n, "bounds", "a table [bounds] with min and max");
    if (!b || !r.keys(*b, "bounds.", {"min", "max"})) return failed();
    if (!b->get("min") || !b->get("max")) return r.err(b->source(), "bounds", "give both min and max");
    Aabb box;
    if (!r.vec3(b->get("min"), "bounds.min", box.min) || !r.vec3(b->get("max"), "bounds.max", box.max)) return failed();
    if ((box.min.array() >= box.max.array()).any())
      return r.err(b->source(), "bounds", "min must be below max on every axis");
    p.bounds = box;
  }

  if (const toml::node* n = root.get("rotation")) {
    const toml::table* rot = r.table(n, "rotation", "a table [rotation]");
    if (!rot || !r.keys(*rot, "rotation.", {"mode", "limits_deg"})) return failed();
    std::string mode = "free";
    if (!r.string(rot->get("mode"), "rotation.mode", mode)) return failed();
    if (mode == "none") p.rotation = RotationMode::none;
    else if (mode == "free") p.rotation = RotationMode::free;
    else if (mode == "limits") p.rotation = RotationMode::limits;
    else return r.err(*rot->get("mode"), "rotation.mode", "unknown mode '" + mode + "' (none, free or limits)");
    const toml::node* lim_node = rot->get("limits_deg");
    if (p.rotation != RotationMode::limits && lim_node)
      return r.err(*lim_node, "rotation.limits_deg", "only used with mode = \"limits\"");
    if (p.rotation == RotationMode::limits) {
      const std::string what = "[[lo, hi], [lo, hi], [lo, hi]] in degrees (roll, pitch, yaw)";
      if (!lim_node) return r.err(rot->source(), "rotation.limits_deg", "missing: give " + what);
      const toml::array* lim = lim_node->as_array();
      if (!lim || lim->size() != 3) return r.err(*lim_node, "rotation.limits_deg", "must be " + what);
      for (std::size_t i = 0; i < 3; ++i) {
        const std::string key = "rotation.limits_deg[" + std::to_string(i) + "]";
        double range[2];
        if (!r.numbers(lim->get(i), key, range, 2, "[lo, hi] in degrees")) return failed();
        if (range[0] > 0 || range[1] < 0 || range[0] >= range[1])
          return r.err(*lim->get(i), key, "the range must contain 0 (the start orientation) and lo < hi");
        p.rotation_limits[i] = {range[0] * kDeg, range[1] * kDeg};
      }
    }
  }
  return p;
}

}  // namespace swept::problem_detail
