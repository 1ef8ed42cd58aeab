// OMPL.app's .cfg problems, read as OMPL.app reads them.
#include "problem_detail.h"

#include "swept/io/mesh_io.h"

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
#include <vector>

namespace swept::problem_detail {

namespace fs = std::filesystem;

namespace {

// The keys of OMPL.app's [problem] section, as its benchmark's option reader declares them.
constexpr std::string_view kCfgKeys[] = {
    "name", "world", "robot", "objective", "objective.threshold", "control",
    "start.x", "start.y", "start.z", "start.axis.x", "start.axis.y", "start.axis.z", "start.theta",
    "goal.x", "goal.y", "goal.z", "goal.axis.x", "goal.axis.y", "goal.axis.z", "goal.theta",
    "threshold", "solution_length",
    "volume.min.x", "volume.min.y", "volume.min.z", "volume.max.x", "volume.max.y", "volume.max.z"};

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// The declared key nearest to `key` within two edits (a typo), if any.
std::optional<std::string_view> nearest_cfg_key(std::string_view key) {
  std::optional<std::string_view> best;
  std::size_t best_distance = 3;
  for (std::string_view k : kCfgKeys)
    if (const std::size_t d = edit_distance(key, k); d < best_distance) best = k, best_distance = d;
  return best;
}

// The most turns an angle may make: past it, sin and cos of the angle lose their digits, and a
// number that large in a problem file is a mistake, not a rotation.
constexpr double kMaxTurns = 10.0;

}  // namespace

// OMPL.app's .cfg: an INI file with a [problem] section (robot, world, start.*, goal.*,
// volume.*); angles in radians about an axis. OMPL.app reads it with boost::program_options,
// which rejects a key given twice and ignores keys it does not know; so do we. The settings
// OMPL.app passes to OMPL's planners (its benchmark's CFGBenchmark: the state sampler, the goal
// threshold, an optimization objective, run limits and the planners to run) mean nothing to
// swept's planner: each one present becomes a note (Problem::notes), so that a user is told.
Result<Problem> load_cfg(const fs::path& file) {
  std::ifstream in(file);
  if (!in) return Error{file.string() + ": cannot open"};
  const std::string name = file.string();
  auto at = [&](int line) { return name + ":" + std::to_string(line) + ": "; };
  std::map<std::string, std::pair<std::string, int>> kv;  // key → (value, line)
  std::map<std::string, int> other_sections;               // [benchmark], [planner]: first line
  std::string line, section;
  int lineno = 0;
  auto trim = [](std::string s) {
    const auto b = s.find_first_not_of(" \t\r"), e = s.find_last_not_of(" \t\r");
    return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
  };
  while (std::getline(in, line)) {
    ++lineno;
    if (lineno == 1 && line.starts_with("\xEF\xBB\xBF")) line.erase(0, 3);  // a UTF-8 byte-order mark (Notepad's)
    auto hash = line.find_first_of("#;");
    if (hash != std::string::npos) line.erase(hash);
    line = trim(line);
    if (line.empty()) continue;
    if (line.front() == '[') {
      if (line.back() != ']') return Error{at(lineno) + "malformed section header"};
      section = trim(line.substr(1, line.size() - 2));
      if (section != "problem") other_sections.try_emplace(section, lineno);
      continue;
    }
    const auto eq = line.find('=');
    if (eq == std::string::npos) return Error{at(lineno) + "expected 'key = value', got '" + line + "'"};
    if (section != "problem") continue;
    const std::string key = trim(line.substr(0, eq));
    const auto [it, fresh] = kv.try_emplace(key, trim(line.substr(eq + 1)), lineno);
    if (!fresh)
      return Error{at(lineno) + key + ": given twice (first on line " + std::to_string(it->second.second) + ")"};
  }
  if (kv.empty()) return Error{name + ": no [problem] section with keys (robot, world, start.*, goal.*)"};
  std::string error;
  // Reads a number; absent and not required: keeps `out`, returns false.
  auto num = [&](const std::string& key, double& out, bool required) {
    auto it = kv.find(key);
    if (it == kv.end()) {
      if (required && error.empty()) error = name + ": " + key + ": missing";
      return false;
    }
    const std::string& text = it->second.first;
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (end == text.c_str() || *end != '\0') {
      if (error.empty()) error = at(it->second.second) + key + ": not a number: '" + text + "'";
      return false;
    }
    if (!std::isfinite(v)) {
      if (error.empty()) error = at(it->second.second) + key + ": must be a finite number, got '" + text + "'";
      return false;
    }
    if (key.ends_with(".theta") && std::abs(v) > kMaxTurns * 2.0 * std::numbers::pi) {
      if (error.empty())
        error = at(it->second.second) + key + ": an angle of " + text + " rad is more than " + format_number(kMaxTurns) +
                " turns: give it within one turn (radians, |theta| <= 2 pi)";
      return false;
    }
    out = v;
    return true;
  };
  auto pose = [&](const std::string& prefix) {
    Vec3 t = Vec3::Zero(), axis = Vec3::Zero();
    double theta = 0.0;
    num(prefix + ".x", t.x(), true);
    num(prefix + ".y", t.y(), true);
    num(prefix + ".z", t.z(), true);
    num(prefix + ".theta", theta, false);
    bool has_axis = false;
    for (int i = 0; i < 3; ++i)
      has_axis = num(prefix + ".axis." + "xyz"[i], axis[i], false) || has_axis;
    // OMPL's setAxisAngle() turns an axis shorter than 1e-9 into the identity whatever the
    // angle; a non-zero angle about no axis is a mistake in the file, not a rotation.
    if (!error.empty() || theta == 0.0) return Pose::from_translation(t);
    const double big = axis.cwiseAbs().maxCoeff();
    const auto unit = unit_axis(axis);
    if (!unit || big * (axis / big).norm() < 1e-9) {
      const int where = kv.at(prefix + ".theta").second;
      error = at(where) + prefix + ".theta: a rotation of " + format_number(theta) + " rad needs a non-zero " +
              prefix + ".axis.x/y/z" +
              (has_axis ? " (the axis given is shorter than 1e-9)" : " (none given)");
      return Pose::from_translation(t);
    }
    return Pose{Eigen::AngleAxisd(theta, *unit).toRotationMatrix(), t};
  };
  Problem p;
  p.source = file;
  p.unit = "mm";
  for (const char* key : {"robot", "world"}) {
    auto it = kv.find(key);
    if (it == kv.end()) return Error{name + ": " + key + ": missing (" + key + " = MESH)"};
    if (it->second.first.empty()) return Error{at(it->second.second) + key + ": no mesh file given"};
    MeshRef m;
    m.file = resolve(file, it->second.first);
    std::error_code ec;
    if (!fs::is_regular_file(m.file, ec))
      return Error{at(it->second.second) + key + ": " + (fs::exists(m.file, ec) ? "not a file: " : "no such file: ") +
                   m.file.string()};
    m.file_unit = "mm";  // OMPL.app is unit-less: keep the numbers as they are
    m.deflection = p.deflection;
    if (std::string(key) == "robot") {
      // OMPL.app's robot frame: the mesh moved so that the mean of its vertices, as OMPL.app's
      // assimp post-processing joins them, is at the origin (ompl_app_center()).
      auto center = ompl_app_center(m.file, {.unit = p.unit, .file_unit = m.file_unit, .linear_deflection = m.deflection});
      if (!center) return Error{at(it->second.second) + key + ": " + center.error().message};
      m.pose = Pose::from_translation(-*center);
    }
    (std::string(key) == "robot" ? p.body : p.obstacles).push_back(m);
  }
  p.start = pose("start");
  p.goal = pose("goal");
  p.reference_point = Vec3::Zero();  // the robot's frame origin: its vertex mean
  bool any = false;
  for (const char* axis : {"x", "y", "z"})
    any = any || kv.count(std::string("volume.min.") + axis) || kv.count(std::string("volume.max.") + axis);
  if (any) {
    Aabb box;
    for (int i = 0; i < 3; ++i) {
      num(std::string("volume.min.") + "xyz"[i], box.min[i], true);
      num(std::string("volume.max.") + "xyz"[i], box.max[i], true);
    }
    p.bounds = box;
  }
  if (!error.empty()) return Error{error};
  if (!any) {
    // No volume: the bounds OMPL.app infers (InferEnvironmentBounds, then
    // InferProblemDefinitionBounds, both with its default factor 1 and addition 0): the box of
    // the world mesh's vertices as assimp reads them, stretched to hold the start and the goal.
    // (Our TOML's default, a box grown well past the obstacles, would let the robot go round
    // them: OMPL.app's Twistycool has no volume, and its wall then no longer closes the way.)
    const MeshRef& world = p.obstacles.front();
    auto vertices =
        ompl_app_vertices(world.file, {.unit = p.unit, .file_unit = world.file_unit, .linear_deflection = world.deflection});
    if (!vertices) return Error{at(kv.at("world").second) + "world: " + vertices.error().message};
    Aabb box = vertices->box;
    box.extend(p.start.translation);
    if (p.goal) box.extend(p.goal->translation);
    for (int i = 0; i < 3; ++i)
      if (!(box.min[i] < box.max[i]))
        return Error{name + ": no volume.* given, and the box OMPL.app would infer (the world mesh's, with the start "
                            "and the goal) is flat along " + std::string(1, "xyz"[i]) +
                     ": give volume.min.* and volume.max.*"};
    p.bounds = box;
  }
  if (p.bounds && (p.bounds->min.array() >= p.bounds->max.array()).any())
    return Error{name + ": volume.min must be below volume.max on every axis"};
  const std::pair<const char*, const char*> unused[] = {
      {"objective", "OMPL's optimization objective, not used: swept certifies a path and shortens it by "
                    "smoothing, it does not optimize a cost"},
      {"objective.threshold", "OMPL's cost threshold, not used (no cost is optimized)"},
      {"sampler", "OMPL's valid-state sampler, not used: swept's planner samples on its own"},
      {"threshold", "OMPL's goal threshold, not used: swept's path ends exactly at the goal pose"},
  };
  std::vector<std::pair<int, std::string>> notes;
  auto has_own_note = [&](const std::string& key) {
    return std::any_of(std::begin(unused), std::end(unused), [&](const auto& u) { return key == u.first; });
  };
  // A key OMPL.app does not declare is, there, a parameter handed to its planners; here it means
  // nothing, and is most often a typo that silently drops what was meant (start.thetaa).
  for (const auto& [key, value] : kv) {
    if (std::find(std::begin(kCfgKeys), std::end(kCfgKeys), key) != std::end(kCfgKeys) || has_own_note(key)) continue;
    const auto near = nearest_cfg_key(key);
    notes.emplace_back(value.second, at(value.second) + key + ": not a key of OMPL.app's [problem] section, ignored" +
                                         (near ? "; did you mean " + std::string(*near) + "?" : ""));
  }
  const std::pair<const char*, const char*> control_notes[] = {
      {"control", "OMPL.app's control-based systems are not planned: swept plans the free rigid body"},
      {"solution_length", "OMPL's desired solution length, not used: swept shortens the path it finds by smoothing"},
  };
  for (const auto& [key, why] : control_notes)
    if (auto it = kv.find(key); it != kv.end())
      notes.emplace_back(it->second.second, at(it->second.second) + key + " = " + it->second.first + ": " + why);
  for (const auto& [key, why] : unused)
    if (auto it = kv.find(key); it != kv.end())
      notes.emplace_back(it->second.second, at(it->second.second) + key + " = " + it->second.first + ": " + why);
  if (!other_sections.empty()) {
    std::string names;
    int first = std::numeric_limits<int>::max();
    for (const auto& [sec, l] : other_sections) {
      names += (names.empty() ? "[" : " and [") + sec + "]";
      first = std::min(first, l);
    }
    notes.emplace_back(first, at(first) + names + ": OMPL.app's benchmark settings and OMPL's planners, not used: "
                                              "swept plans with its own planner (`swept plan --time-limit` sets its limit)");
  }
  std::sort(notes.begin(), notes.end());
  for (auto& [l, text] : notes) p.notes.push_back(std::move(text));
  return p;
}

}  // namespace swept::problem_detail
