// Reading assemblies: a TOML assembly file (docs/assembly-format.md), a folder of placed meshes,
// or a multi-solid CAD file (assembly.h).
#include "swept/assembly/assembly.h"
#include "swept/geometry/pose.h"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>

namespace swept {
namespace {

namespace fs = std::filesystem;

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

// A strict reader of the few keys of an assembly file: the first problem becomes the error,
// naming the file, line and key.
struct TomlAssembly {
  std::string file;
  std::string error;

  bool fail(const toml::source_region& where, const std::string& key, const std::string& what) {
    if (error.empty())
      error = file + (where.begin.line ? ":" + std::to_string(where.begin.line) : std::string()) + ": " + key + ": " + what;
    return false;
  }
  bool keys(const toml::table& t, const std::string& prefix, std::initializer_list<std::string_view> known) {
    for (auto&& [k, v] : t) {
      if (std::find(known.begin(), known.end(), k.str()) != known.end()) continue;
      std::string list;
      for (std::string_view name : known) list += (list.empty() ? "" : ", ") + std::string(name);
      return fail(k.source(), prefix + std::string(k.str()), "unknown key (known here: " + list + ")");
    }
    return true;
  }
  bool number(const toml::node* n, const std::string& key, double& out) {
    if (!n) return true;
    if (auto v = n->value<double>(); v && std::isfinite(*v) && (n->is_floating_point() || n->is_integer())) {
      out = *v;
      return true;
    }
    return fail(n->source(), key, "expected a finite number");
  }
  bool string(const toml::node* n, const std::string& key, std::string& out) {
    if (!n) return true;
    if (auto v = n->value<std::string>(); v && n->is_string()) {
      out = *v;
      return true;
    }
    return fail(n->source(), key, "expected a string");
  }
  bool vec3(const toml::node* n, const std::string& key, Vec3& out) {
    const toml::array* a = n ? n->as_array() : nullptr;
    if (!a || a->size() != 3) return fail(n->source(), key, "expected an array of 3 numbers");
    for (std::size_t i = 0; i < 3; ++i) {
      const toml::node* e = a->get(i);
      auto v = e->value<double>();
      if (!v || !std::isfinite(*v) || !(e->is_floating_point() || e->is_integer()))
        return fail(e->source(), key, "expected an array of 3 finite numbers");
      out[static_cast<int>(i)] = *v;
    }
    return true;
  }
  // pose = { translation = [x, y, z], quaternion = [x, y, z, w] } or { ..., axis = [..], angle_deg = A }
  bool pose(const toml::node* n, const std::string& key, Pose& out) {
    if (!n) return true;
    const toml::table* t = n->as_table();
    if (!t) return fail(n->source(), key, "expected a table with translation and quaternion or axis + angle_deg");
    if (!keys(*t, key + ".", {"translation", "quaternion", "axis", "angle_deg"})) return false;
    Vec3 translation = Vec3::Zero();
    if (const toml::node* tr = t->get("translation"); tr && !vec3(tr, key + ".translation", translation)) return false;
    const toml::node* q = t->get("quaternion");
    const toml::node* axis = t->get("axis");
    const toml::node* angle = t->get("angle_deg");
    Mat3 rotation = Mat3::Identity();
    if (q && (axis || angle)) return fail(n->source(), key, "either quaternion or axis + angle_deg, not both");
    if (q) {
      const toml::array* a = q->as_array();
      if (!a || a->size() != 4) return fail(q->source(), key + ".quaternion", "expected [x, y, z, w]");
      double c[4];
      for (std::size_t i = 0; i < 4; ++i) {
        auto v = a->get(i)->value<double>();
        if (!v || !std::isfinite(*v)) return fail(q->source(), key + ".quaternion", "expected 4 finite numbers");
        c[i] = *v;
      }
      const double s = std::max({std::abs(c[0]), std::abs(c[1]), std::abs(c[2]), std::abs(c[3])});
      if (!(s > 0)) return fail(q->source(), key + ".quaternion", "a zero quaternion is no rotation");
      rotation = Quat(c[3] / s, c[0] / s, c[1] / s, c[2] / s).normalized().toRotationMatrix();
    } else if (axis || angle) {
      if (!axis || !angle) return fail(n->source(), key, "axis and angle_deg go together");
      Vec3 a;
      double deg = 0;
      if (!vec3(axis, key + ".axis", a) || !number(angle, key + ".angle_deg", deg)) return false;
      const double s = a.cwiseAbs().maxCoeff();
      if (!(s > 0)) return fail(axis->source(), key + ".axis", "a zero axis");
      rotation = Eigen::AngleAxisd(deg * std::numbers::pi / 180.0, (a / s).normalized()).toRotationMatrix();
    }
    out = Pose{rotation, translation};
    return true;
  }
};

Triangle placed(const Triangle& t, const Pose& pose) {
  Triangle out = t;
  for (int v = 0; v < 3; ++v) out[v] = pose.apply(t[v]);
  return out;
}

// The parts of one file as assembly parts: named `name` when the file holds one part, else
// `name/part` (or the part's own name, without `prefix`). Empty parts were dropped by the
// importer with a warning naming them.
Result<std::vector<AssemblyPart>> parts_of(const fs::path& file, const std::string& shown, const std::string& name,
                                           const Pose& pose, bool fixed, const ImportOptions& import,
                                           std::vector<std::string>& warnings, bool prefix = true) {
  auto model = import_mesh(file, import);
  if (!model) return model.error();
  for (const std::string& w : model->warnings) warnings.push_back(w);
  std::vector<AssemblyPart> out;
  for (TriangleSoup& soup : model->parts) {
    AssemblyPart p;
    p.name = model->parts.size() == 1 ? name : (prefix ? name + "/" + soup.name : soup.name);
    p.source = shown;
    p.fixed = fixed;
    p.mesh.name = p.name;
    p.mesh.triangles.reserve(soup.triangles.size());
    for (const Triangle& t : soup.triangles) p.mesh.triangles.push_back(placed(t, pose));
    p.mesh.cylinder_of = std::move(soup.cylinder_of);
    for (const CadCylinder& c : soup.cylinders)
      p.mesh.cylinders.push_back({pose.apply(c.origin), (pose.rotation * c.axis).normalized(), c.radius, c.deviation});
    out.push_back(std::move(p));
  }
  return out;
}

Result<Assembly> read_toml(const fs::path& file, const AssemblyReadOptions& options) {
  TomlAssembly r{file.string(), {}};
  toml::table root;
  try {
    root = toml::parse_file(file.string());
  } catch (const toml::parse_error& e) {
    return Error{file.string() + ":" + std::to_string(e.source().begin.line) + ": " + std::string(e.description())};
  }
  Assembly a;
  a.source = file;
  ImportOptions import = options.import;
  if (!r.keys(root, "", {"unit", "deflection", "part"})) return Error{r.error};
  if (!r.string(root.get("unit"), "unit", import.unit)) return Error{r.error};
  double metres = 0;
  if (!unit_scale(import.unit, metres))
    return Error{file.string() + ": unit: unknown unit '" + import.unit + "' (known: m, cm, mm, um, in, ft)"};
  if (!r.number(root.get("deflection"), "deflection", import.linear_deflection)) return Error{r.error};
  if (!(import.linear_deflection > 0)) return Error{file.string() + ": deflection: must be > 0"};
  a.unit = import.unit;
  const toml::node* parts = root.get("part");
  if (!parts) return Error{file.string() + ": the assembly has no parts (no [[part]] table)"};
  const toml::array* list = parts->as_array();
  if (!list || !list->is_array_of_tables())
    return Error{file.string() + ": part: expected [[part]] tables"};
  for (std::size_t i = 0; i < list->size(); ++i) {
    const toml::table& t = *list->get(i)->as_table();
    const std::string key = "part[" + std::to_string(i) + "]";
    if (!r.keys(t, key + ".", {"file", "name", "pose", "fixed", "file_unit"})) return Error{r.error};
    std::string rel, name, file_unit;
    if (!t.get("file")) {
      r.fail(t.source(), key, "missing key 'file'");
      return Error{r.error};
    }
    if (!r.string(t.get("file"), key + ".file", rel) || !r.string(t.get("name"), key + ".name", name) ||
        !r.string(t.get("file_unit"), key + ".file_unit", file_unit))
      return Error{r.error};
    Pose pose;
    if (!r.pose(t.get("pose"), key + ".pose", pose)) return Error{r.error};
    bool fixed = false;
    if (const toml::node* f = t.get("fixed")) {
      if (!f->is_boolean()) {
        r.fail(f->source(), key + ".fixed", "expected true or false");
        return Error{r.error};
      }
      fixed = *f->value<bool>();
    }
    const fs::path mesh = fs::path(rel).is_absolute() ? fs::path(rel) : file.parent_path() / rel;
    if (name.empty()) name = fs::path(rel).stem().string();
    ImportOptions part_import = import;
    part_import.file_unit = file_unit;
    auto got = parts_of(mesh, rel, name, pose, fixed, part_import, a.warnings);
    if (!got) return Error{file.string() + ": " + key + " (" + name + "): " + got.error().message};
    for (AssemblyPart& p : *got) a.parts.push_back(std::move(p));
  }
  return a;
}

Result<Assembly> read_folder(const fs::path& folder, const AssemblyReadOptions& options) {
  std::vector<fs::path> files;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    if (!entry.is_regular_file()) continue;
    const std::string ext = lower(entry.path().extension().string());
    const auto& known = assembly_mesh_extensions();
    if (std::find(known.begin(), known.end(), ext) != known.end()) files.push_back(entry.path());
  }
  if (ec) return Error{folder.string() + ": cannot list the folder: " + ec.message()};
  std::sort(files.begin(), files.end());
  Assembly a;
  a.source = folder;
  a.unit = options.import.unit;
  for (const fs::path& f : files) {
    auto got = parts_of(f, f.string(), f.stem().string(), Pose{}, false, options.import, a.warnings);
    if (!got) return got.error();
    for (AssemblyPart& p : *got) a.parts.push_back(std::move(p));
  }
  if (a.parts.empty()) {
    std::string list;
    for (const std::string& e : assembly_mesh_extensions()) list += (list.empty() ? "" : " ") + e;
    return Error{folder.string() + ": the assembly is empty: no mesh or CAD file in the folder (" + list + ")"};
  }
  return a;
}

}  // namespace

const std::vector<std::string>& assembly_mesh_extensions() {
  static const std::vector<std::string> kExtensions{".stl", ".obj", ".ply", ".off", ".3mf", ".gltf", ".glb", ".dae",
                                                    ".step", ".stp", ".iges", ".igs", ".brep"};
  return kExtensions;
}

std::size_t Assembly::triangle_count() const {
  std::size_t n = 0;
  for (const AssemblyPart& p : parts) n += p.mesh.triangles.size();
  return n;
}

Result<Assembly> read_assembly(const fs::path& path, const AssemblyReadOptions& options) {
  std::error_code ec;
  if (!fs::exists(path, ec)) return Error{path.string() + ": no such file or folder"};
  Result<Assembly> got = Error{};
  if (fs::is_directory(path, ec)) {
    got = read_folder(path, options);
  } else if (lower(path.extension().string()) == ".toml") {
    got = read_toml(path, options);
  } else {
    Assembly a;
    a.source = path;
    a.unit = options.import.unit;
    auto parts = parts_of(path, path.string(), path.stem().string(), Pose{}, false, options.import, a.warnings,
                          /*prefix=*/false);
    if (!parts) return parts.error();
    a.parts = std::move(*parts);
    got = std::move(a);
  }
  if (!got) return got;
  Assembly& a = *got;
  if (a.parts.empty()) return Error{path.string() + ": the assembly is empty (no parts)"};
  std::map<std::string, std::size_t> seen;
  for (AssemblyPart& part : a.parts) {
    // The CAD's cylinders only add mates (contact.h): where they are not what the contact model
    // can trust (a count that does not match, a degenerate surface), the part goes without them.
    TriangleSoup& m = part.mesh;
    if (!cylinders_usable(m)) m.cylinder_of.clear(), m.cylinders.clear();
  }
  for (std::size_t i = 0; i < a.parts.size(); ++i) {
    const AssemblyPart& p = a.parts[i];
    if (p.mesh.triangles.empty()) return Error{path.string() + ": part '" + p.name + "' (" + p.source + ") has no triangles"};
    for (const Triangle& t : p.mesh.triangles)
      for (int v = 0; v < 3; ++v)
        if (!t[v].allFinite())
          return Error{path.string() + ": part '" + p.name + "' has a non-finite coordinate after its pose"};
    auto [it, added] = seen.emplace(p.name, i);
    if (!added)
      return Error{path.string() + ": two parts are named '" + p.name + "' (parts " + std::to_string(it->second + 1) +
                   " and " + std::to_string(i + 1) + ", from " + a.parts[it->second].source + " and " + p.source +
                   "); part names must be unique"};
  }
  return got;
}

}  // namespace swept
