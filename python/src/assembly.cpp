// swept.Assembly (read_assembly) and swept.disassemble (disassemble): as `swept disassemble`.
#include "convert.h"

#include "swept/assembly/disassemble.h"

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cmath>
#include <map>
#include <set>

namespace swept::py {

namespace {

struct PyAssembly {
  std::shared_ptr<const Assembly> assembly;
  std::string path;           ///< as given to Assembly.load
  double deflection = 0.1;    ///< the import's linear deflection: the default mating tolerance is twice it
};

PyAssembly assembly_load(const std::filesystem::path& path, const std::string& unit, std::optional<double> deflection,
                         std::optional<std::string> file_unit, std::optional<double> angular_deflection,
                         std::optional<std::size_t> max_triangles) {
  // The command line's checks on its import options (CLI::PositiveNumber), with its wording.
  auto positive = [](std::optional<double> v, const char* name) {
    if (v && !(*v > 0 && std::isfinite(*v)))
      throw InputError(std::string(name) + " must be a positive number, not " + std::to_string(*v));
  };
  positive(deflection, "deflection");
  positive(angular_deflection, "angular_deflection");
  if (max_triangles && *max_triangles == 0) throw InputError("max_triangles must be a positive number");
  AssemblyReadOptions options;
  options.import.unit = unit;
  if (file_unit) options.import.file_unit = *file_unit;
  if (deflection) options.import.linear_deflection = *deflection;
  if (angular_deflection) options.import.angular_deflection = *angular_deflection;
  if (max_triangles) options.import.max_triangles = *max_triangles;
  Result<Assembly> a = Error{};
  {
    pyb::gil_scoped_release release;
    a = read_assembly(path, options);
  }
  PyAssembly out;
  out.assembly = std::make_shared<const Assembly>(value_or_raise(std::move(a)));
  out.path = path.string();
  out.deflection = options.import.linear_deflection;
  return out;
}

std::size_t part_index(const Assembly& a, const pyb::handle& key) {
  if (pyb::isinstance<pyb::str>(key)) {
    const std::string name = key.cast<std::string>();
    for (std::size_t i = 0; i < a.parts.size(); ++i)
      if (a.parts[i].name == name) return i;
    throw InputError("no part is named '" + name + "'");
  }
  if (pyb::isinstance<pyb::int_>(key) && !pyb::isinstance<pyb::bool_>(key)) {
    long long i = key.cast<long long>();
    const auto n = static_cast<long long>(a.parts.size());
    if (i < 0) i += n;
    if (i < 0 || i >= n)
      throw InputError("part index " + std::string(pyb::str(key)) + " out of range (" + std::to_string(n) + " parts)");
    return static_cast<std::size_t>(i);
  }
  throw InputError("a part is named by its name (str) or index (int), not " +
                   std::string(pyb::str(key.get_type().attr("__name__"))));
}

PyMesh part_mesh(const PyAssembly& pa, const pyb::handle& key) {
  const AssemblyPart& part = pa.assembly->parts[part_index(*pa.assembly, key)];
  auto data = std::make_shared<MeshData>();
  data->soup = part.mesh;
  data->file = part.source;
  data->unit = pa.assembly->unit;
  return mesh_from_data(std::move(data));
}

pyb::list names(const Assembly& a, const std::vector<std::size_t>& parts) {
  pyb::list out;
  for (std::size_t i : parts) out.append(a.parts[i].name);
  return out;
}

pyb::dict disassemble_py(const PyAssembly& pa, double clearance, std::optional<double> tolerance, int jobs,
                         double plan_time, std::int64_t plan_queries, bool subassemblies,
                         std::optional<std::vector<pyb::object>> fixed, std::optional<std::vector<pyb::object>> target) {
  const Assembly& a = *pa.assembly;
  if (!(clearance >= 0) || !std::isfinite(clearance))
    throw InputError("clearance must be a finite number >= 0, not " + std::to_string(clearance));
  if (tolerance && (!(*tolerance >= 0) || !std::isfinite(*tolerance)))
    throw InputError("tolerance must be a finite number >= 0, not " + std::to_string(*tolerance));
  if (jobs < 0) throw InputError("jobs must be >= 0 (0: all cores), not " + std::to_string(jobs));
  if (!(plan_time >= 0) || !std::isfinite(plan_time))
    throw InputError("plan_time must be a finite number of seconds >= 0, not " + std::to_string(plan_time));
  if (plan_queries < 0) throw InputError("plan_queries must be >= 0 (0: no limit), not " + std::to_string(plan_queries));
  DisassemblyOptions options;
  options.clearance = clearance;
  // As the command line: a tolerance of 0 (or none) is twice the import's deflection.
  options.tolerance = tolerance && *tolerance > 0 ? *tolerance : 2.0 * pa.deflection;
  options.jobs = jobs;
  options.plan_time_limit = plan_time;
  options.plan_max_queries = static_cast<std::uint64_t>(plan_queries);
  options.subassemblies = subassemblies;
  if (fixed) {
    std::set<std::size_t> chosen;
    for (const pyb::object& key : *fixed) chosen.insert(part_index(a, key));
    options.fixed = std::vector<std::size_t>(chosen.begin(), chosen.end());
  }
  if (target)
    for (const pyb::object& key : *target) {
      const std::size_t t = part_index(a, key);
      if (std::find(options.targets.begin(), options.targets.end(), t) == options.targets.end()) options.targets.push_back(t);
    }
  DisassemblyResult r;
  {
    pyb::gil_scoped_release release;
    r = disassemble(a, options);
  }
  for (std::size_t t : r.targets)
    if (std::find(r.fixed.begin(), r.fixed.end(), t) != r.fixed.end())
      throw InputError("the target '" + a.parts[t].name + "' is fixed (the base, or marked fixed = true): it is never moved");

  pyb::list interferences;
  for (const Interference& f : r.interferences) {
    pyb::dict d;
    d["parts"] = pyb::make_tuple(a.parts[f.part_a].name, a.parts[f.part_b].name);
    d["depth"] = f.depth;
    d["extent"] = f.extent;
    d["triangle_pairs"] = f.triangle_pairs;
    interferences.append(d);
  }
  auto step_dict = [&](const SequenceStep& s) {
    pyb::dict d;
    d["round"] = s.round;
    d["parts"] = pyb::tuple(names(a, s.parts));
    d["removed"] = s.removed;
    d["method"] = s.removed ? pyb::object(pyb::str(s.method == RemovalMethod::pull ? "pull" : "plan")) : pyb::none();
    d["direction"] = s.removed && s.method == RemovalMethod::pull ? pyb::object(vec3_array(s.direction)) : pyb::none();
    d["distance"] = s.distance;
    d["path"] = poses_array(s.path.poses);
    d["reference"] = vec3_array(s.reference);
    std::set<std::size_t> all;
    pyb::list blocking;
    for (const auto& b : s.blocking) {
      all.insert(b.blockers.begin(), b.blockers.end());
      blocking.append(pyb::make_tuple(vec3_array(b.direction), pyb::tuple(names(a, b.blockers))));
    }
    d["blockers"] = pyb::tuple(names(a, std::vector<std::size_t>(all.begin(), all.end())));
    d["blocking"] = blocking;
    d["time_ms"] = s.time_ms;
    return d;
  };
  pyb::list sequence, why;
  for (const SequenceStep& s : r.sequence) sequence.append(step_dict(s));
  for (const SequenceStep& s : r.why) why.append(step_dict(s));
  pyb::list parts;
  for (const AssemblyPart& p : a.parts) parts.append(p.name);
  pyb::dict t;
  t["build"] = r.time_ms.build, t["interference"] = r.time_ms.interference, t["sequence"] = r.time_ms.sequence;
  pyb::dict d;
  d["complete"] = r.complete;
  d["unit"] = a.unit;
  d["parts"] = pyb::tuple(parts);
  d["fixed"] = pyb::tuple(names(a, r.fixed));
  d["clearance"] = options.clearance;
  d["tolerance"] = r.tolerance;
  d["interferences"] = interferences;
  d["sequence"] = sequence;
  d["warnings"] = a.warnings;
  d["time_ms"] = t;
  d["distance_queries"] = r.distance_queries;
  d["targets"] = pyb::tuple(names(a, r.targets));
  d["fewest"] = r.fewest;
  d["lower_bound"] = r.lower_bound;
  d["why"] = why;
  return d;
}

}  // namespace

void bind_assembly(pyb::module_& m) {
  using pyb::arg;
  pyb::class_<PyAssembly>(m, "Assembly", R"doc(
Parts in their mounted poses (docs/assembly-format.md): Assembly.load(path) reads a TOML assembly
file, a folder of placed meshes, or a STEP / IGES / BREP file with several solids, as
`swept disassemble` does. Immutable; swept.disassemble(assembly) takes it apart.)doc")
      .def_static("load", &assembly_load, arg("path"), arg("unit") = "mm", arg("deflection") = pyb::none(),
                  arg("file_unit") = pyb::none(), arg("angular_deflection") = pyb::none(),
                  arg("max_triangles") = pyb::none(), R"doc(
Reads an assembly. `unit`: the assembly's length unit (a TOML file's own `unit` wins);
`deflection`: BRepMesh linear deflection for CAD files, in `unit` (default 0.1; a TOML file's
own `deflection` wins), which also sets the default mating tolerance of swept.disassemble
(twice it, as `swept disassemble --deflection`). Raises swept.Error with the message
`swept disassemble` prints (the file, the line and key, or the part) on bad input.)doc")
      .def_property_readonly("source", [](const PyAssembly& p) { return p.path; }, "the path given to Assembly.load")
      .def_property_readonly("unit", [](const PyAssembly& p) { return p.assembly->unit; })
      .def_property_readonly("deflection", [](const PyAssembly& p) { return p.deflection; },
                             "the linear deflection given to Assembly.load (default 0.1)")
      .def_property_readonly("names", [](const PyAssembly& p) {
            std::vector<std::string> v;
            for (const AssemblyPart& part : p.assembly->parts) v.push_back(part.name);
            return v;
          }, "the parts' names, in the assembly's order")
      .def_property_readonly("fixed", [](const PyAssembly& p) {
            std::vector<std::string> v;
            for (const AssemblyPart& part : p.assembly->parts)
              if (part.fixed) v.push_back(part.name);
            return v;
          }, "the parts marked `fixed = true` (empty: disassemble takes the largest as the base)")
      .def_property_readonly("files", [](const PyAssembly& p) {
            std::vector<std::string> v;
            for (const AssemblyPart& part : p.assembly->parts) v.push_back(part.source);
            return v;
          }, "the file each part was read from")
      .def_property_readonly("warnings", [](const PyAssembly& p) { return p.assembly->warnings; })
      .def_property_readonly("triangles", [](const PyAssembly& p) { return p.assembly->triangle_count(); })
      .def("mesh", &part_mesh, arg("part"), R"doc(
The part (by name or index) as a swept.Mesh, in the world frame at its mounted pose.)doc")
      .def("__len__", [](const PyAssembly& p) { return p.assembly->parts.size(); })
      .def("__repr__", [](const PyAssembly& p) {
        return "swept.Assembly('" + p.path + "', " + std::to_string(p.assembly->parts.size()) + " parts, " +
               std::to_string(p.assembly->triangle_count()) + " triangles, unit='" + p.assembly->unit + "')";
      });

  m.def("_disassemble", &disassemble_py, arg("assembly"), arg("clearance"), arg("tolerance"), arg("jobs"),
        arg("plan_time"), arg("plan_queries"), arg("subassemblies"), arg("fixed"), arg("target"));
}

}  // namespace swept::py
