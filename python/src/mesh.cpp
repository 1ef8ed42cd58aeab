// swept.Mesh (import_mesh, or arrays) and swept.BVH (build_bvh, stats).
#include "convert.h"

#include "swept/io/mesh_io.h"

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <chrono>
#include <cmath>
#include <sstream>

namespace swept::py {

namespace {

static_assert(sizeof(Triangle) == 9 * sizeof(double), "Triangle must be nine packed doubles for the array views");

/// A read-only NumPy view onto the soup's doubles, keeping the soup alive.
pyb::array soup_view(const std::shared_ptr<const MeshData>& data, std::vector<pyb::ssize_t> shape) {
  auto* keep = new std::shared_ptr<const MeshData>(data);
  pyb::capsule owner(keep, [](void* p) { delete static_cast<std::shared_ptr<const MeshData>*>(p); });
  const double* first = data->soup.triangles.empty() ? nullptr : &data->soup.triangles.front().p.x();
  std::vector<pyb::ssize_t> strides(shape.size());
  pyb::ssize_t step = sizeof(double);
  for (std::size_t i = shape.size(); i-- > 0;) strides[i] = step, step *= shape[i];
  pyb::array a(pyb::dtype::of<double>(), shape, strides, first, owner);
  a.attr("setflags")(pyb::arg("write") = false);
  return a;
}

std::string dtype_name(const pyb::array& a) { return pyb::str(a.dtype()).cast<std::string>(); }

PyMesh mesh_from_model(ImportedModel model) {
  auto data = std::make_shared<MeshData>();
  data->soup = model.merged();
  data->file = model.file;
  data->unit = model.unit;
  data->degenerate_triangles = model.degenerate_triangles;
  data->warnings = std::move(model.warnings);
  return mesh_from_data(std::move(data));
}

}  // namespace

PyMesh mesh_from_data(std::shared_ptr<const MeshData> data) {
  PyMesh m;
  m.data = data;
  const auto count = static_cast<pyb::ssize_t>(data->soup.triangles.size());
  m.vertices = soup_view(data, {3 * count, 3});
  auto faces = new_array<std::int64_t>({count, 3});
  std::int64_t* f = faces.mutable_data();
  for (pyb::ssize_t i = 0; i < 3 * count; ++i) f[i] = i;
  faces.attr("setflags")(pyb::arg("write") = false);
  m.faces = faces;
  return m;
}

namespace {

PyMesh mesh_load(const std::filesystem::path& path, const std::string& unit, std::optional<double> deflection,
                 std::optional<std::string> file_unit, std::optional<double> angular_deflection,
                 std::optional<std::size_t> max_triangles) {
  ImportOptions io;
  io.unit = unit;
  if (file_unit) io.file_unit = *file_unit;
  if (deflection) io.linear_deflection = *deflection;
  if (angular_deflection) io.angular_deflection = *angular_deflection;
  if (max_triangles) io.max_triangles = *max_triangles;
  Result<ImportedModel> model = Error{};
  {
    pyb::gil_scoped_release release;
    model = import_mesh(path, io);
  }
  return mesh_from_model(value_or_raise(std::move(model)));
}

PyMesh mesh_from_arrays(const pyb::handle& vertices_in, const pyb::handle& faces_in, const std::string& name,
                        const std::string& unit) {
  double scale = 0;
  if (!unit_scale(unit, scale)) throw InputError("unknown unit '" + unit + "' (m, cm, mm, um, in, ft)");
  pyb::array vraw = pyb::array::ensure(vertices_in);
  pyb::array fraw = pyb::array::ensure(faces_in);
  if (!vraw) throw InputError("vertices: not an array");
  if (!fraw) throw InputError("faces: not an array");
  const char vk = vraw.dtype().kind(), fk = fraw.dtype().kind();
  if (vk != 'f' && vk != 'i' && vk != 'u')
    throw InputError("vertices: an array of numbers is needed, not " + dtype_name(vraw));
  if (fk != 'i' && fk != 'u' && !(fraw.size() == 0 && fk == 'f'))
    throw InputError("faces: an array of integers is needed, not " + dtype_name(fraw));
  auto v = pyb::array_t<double, pyb::array::c_style | pyb::array::forcecast>::ensure(vraw);
  auto f = pyb::array_t<std::int64_t, pyb::array::c_style | pyb::array::forcecast>::ensure(fraw);
  if (!v || !f) throw InputError("vertices, faces: cannot convert to float64 and int64 arrays");
  if (v.ndim() != 2 || v.shape(1) != 3) throw InputError("vertices: the shape must be (N, 3), not " + std::string(pyb::str(vraw.attr("shape"))));
  if (f.ndim() != 2 || f.shape(1) != 3) throw InputError("faces: the shape must be (M, 3), not " + std::string(pyb::str(fraw.attr("shape"))));
  const std::int64_t n = v.shape(0);
  const double* vd = v.data();
  for (std::int64_t i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c)
      if (!std::isfinite(vd[3 * i + c])) {
        std::ostringstream os;
        os << "vertices[" << i << "] has a non-finite coordinate (" << vd[3 * i] << ", " << vd[3 * i + 1] << ", "
           << vd[3 * i + 2] << ")";
        throw InputError(os.str());
      }
  auto data = std::make_shared<MeshData>();
  data->soup.name = name;
  data->unit = unit;
  const std::int64_t* fd = f.data();
  const std::int64_t m = f.shape(0);
  data->soup.triangles.resize(static_cast<std::size_t>(m));
  for (std::int64_t t = 0; t < m; ++t) {
    Triangle& tri = data->soup.triangles[static_cast<std::size_t>(t)];
    for (int c = 0; c < 3; ++c) {
      const std::int64_t idx = fd[3 * t + c];
      if (idx < 0 || idx >= n) {
        std::ostringstream os;
        os << "faces[" << t << "] = (" << fd[3 * t] << ", " << fd[3 * t + 1] << ", " << fd[3 * t + 2] << "): vertex "
           << idx << (idx < 0 ? " is negative" : " is past the " + std::to_string(n) + " vertices");
        throw InputError(os.str());
      }
      tri[c] = Vec3(vd[3 * idx], vd[3 * idx + 1], vd[3 * idx + 2]);
    }
    if (shape_quality(tri) <= 1e-12) ++data->degenerate_triangles;
  }
  PyMesh out;
  out.data = data;
  out.vertices = v;
  out.faces = f;
  return out;
}

PyBvh build(const pyb::object& mesh_obj, const std::string& fitter, const std::string& split, int leaf_size,
            bool parallel) {
  const PyMesh& mesh = mesh_obj.cast<const PyMesh&>();
  BuildConfig config;
  if (!parse_fitter(fitter, config.fitter)) throw InputError("unknown fitter '" + fitter + "' (" + fitter_names() + ")");
  if (!parse_split_rule(split, config.split)) throw InputError("unknown split rule '" + split + "' (" + split_rule_names() + ")");
  if (leaf_size < 1) throw InputError("leaf_size must be >= 1, not " + std::to_string(leaf_size));
  config.leaf_size = leaf_size;
  config.parallel = parallel;
  Result<Bvh> tree = Error{};
  double ms = 0;
  {
    pyb::gil_scoped_release release;
    const auto t0 = std::chrono::steady_clock::now();
    tree = build_bvh(mesh.data->soup.triangles, config);
    ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  }
  // `swept bvh` names the file in front of the builder's message.
  const std::string prefix = mesh.data->file.empty() ? "" : mesh.data->file + ": ";
  PyBvh out;
  out.bvh = std::make_shared<const Bvh>(value_or_raise(std::move(tree), prefix));
  out.mesh = mesh.data;
  out.build_ms = ms;
  return out;
}

pyb::dict bvh_stats(const PyBvh& b) {
  const BvhStats st = stats(*b.bvh);
  pyb::dict d;
  d["triangles"] = st.triangles;
  d["fitter"] = std::string(to_string(b.bvh->config.fitter));
  d["split"] = std::string(to_string(b.bvh->config.split));
  d["nodes"] = st.nodes;
  d["depth"] = st.depth;
  d["total_surface_area"] = st.total_surface_area;
  d["total_volume"] = st.total_volume;
  d["build_ms"] = b.build_ms;
  d["bytes"] = st.bytes;
  return d;
}

// ---- pickling (for Dask and multiprocessing): the triangles travel, trees are rebuilt -------------
pyb::tuple mesh_getstate(const PyMesh& s) {
  return pyb::make_tuple(s.vertices, s.faces, s.data->soup.name, s.data->unit, s.data->file, s.data->warnings);
}

PyMesh mesh_setstate(const pyb::tuple& t) {
  if (t.size() != 6) throw std::runtime_error("swept.Mesh: bad pickle state");
  PyMesh m = mesh_from_arrays(t[0], t[1], t[2].cast<std::string>(), t[3].cast<std::string>());
  auto data = std::const_pointer_cast<MeshData>(m.data);  // not shared yet
  data->file = t[4].cast<std::string>();
  data->warnings = t[5].cast<std::vector<std::string>>();
  return m;
}

/// The tree's triangles back in input order (Bvh::triangle_ids), as an (M, 3, 3) array.
pyb::array_t<double> input_triangles(const Bvh& b) {
  auto a = new_array<double>({static_cast<pyb::ssize_t>(b.triangles.size()), 3, 3});
  double* out = a.mutable_data();
  for (std::size_t i = 0; i < b.triangles.size(); ++i)
    for (int c = 0; c < 3; ++c)
      for (int d = 0; d < 3; ++d) out[9 * b.triangle_ids[i] + 3 * c + d] = b.triangles[i][c][d];
  return a;
}

pyb::tuple bvh_getstate(const PyBvh& b) {
  return pyb::make_tuple(input_triangles(*b.bvh), std::string(to_string(b.bvh->config.fitter)),
                         std::string(to_string(b.bvh->config.split)), b.bvh->config.leaf_size,
                         b.mesh ? b.mesh->file : std::string(), b.mesh ? b.mesh->unit : std::string("mm"));
}

PyBvh bvh_setstate(const pyb::tuple& t) {
  if (t.size() != 6) throw std::runtime_error("swept.BVH: bad pickle state");
  auto tri = t[0].cast<pyb::array_t<double, pyb::array::c_style | pyb::array::forcecast>>();
  const auto count = tri.ndim() == 3 ? tri.shape(0) : 0;
  auto faces = new_array<std::int64_t>({count, 3});
  for (pyb::ssize_t i = 0; i < 3 * count; ++i) faces.mutable_data()[i] = i;
  PyMesh mesh = mesh_from_arrays(tri.attr("reshape")(-1, 3), faces, "", t[5].cast<std::string>());
  std::const_pointer_cast<MeshData>(mesh.data)->file = t[4].cast<std::string>();
  // The same triangles in the same order and the same configuration: the same tree, node for node.
  return build(pyb::cast(mesh), t[1].cast<std::string>(), t[2].cast<std::string>(), t[3].cast<int>(), true);
}

}  // namespace

void bind_mesh(pyb::module_& m) {
  pyb::class_<PyMesh>(m, "Mesh", R"doc(
A triangle mesh (a soup of triangles in double precision, in the length unit `unit`).

Mesh(vertices, faces, name="", unit="mm") makes one from an (N, 3) float array of vertices and an
(M, 3) integer array of vertex indices. The triangles are copied once into the library's soup;
`.vertices` / `.faces` return the arrays given (no copy when they already are C-contiguous float64
/ int64). Mesh.load() reads a file; its `.vertices` is then a read-only view onto the triangles
(three vertices per triangle, not welded) and `.faces` is arange(3 M).reshape(M, 3).)doc")
      .def(pyb::init(&mesh_from_arrays), pyb::arg("vertices"), pyb::arg("faces"), pyb::arg("name") = "",
           pyb::arg("unit") = "mm")
      .def_static("load", &mesh_load, pyb::arg("path"), pyb::arg("unit") = "mm", pyb::arg("deflection") = pyb::none(),
                  pyb::arg("file_unit") = pyb::none(), pyb::arg("angular_deflection") = pyb::none(),
                  pyb::arg("max_triangles") = pyb::none(), R"doc(
Reads a mesh or CAD file (STL, OBJ, PLY, OFF, 3MF, glTF/GLB, DAE, STEP, IGES, BREP), every part merged
into one mesh, coordinates in `unit` (m, cm, mm, um, in, ft). `deflection`: BRepMesh linear
deflection for CAD files, in `unit` (default 0.1); `file_unit`: the unit of a mesh file's
coordinates (default: mm, or m for glTF; a 3MF declares its own, which a file_unit given must match). Raises swept.Error with the message `swept bvh` prints
(naming the file and the line, triangle or entity) on bad input.)doc")
      .def_property_readonly("vertices", [](const PyMesh& s) { return s.vertices; }, "(N, 3) float64 array")
      .def_property_readonly("faces", [](const PyMesh& s) { return s.faces; }, "(M, 3) int64 array of vertex indices")
      .def_property_readonly("triangles", [](const PyMesh& s) {
            return soup_view(s.data, {static_cast<pyb::ssize_t>(s.data->soup.triangles.size()), 3, 3});
          }, "(M, 3, 3) float64 read-only view: triangle, corner, coordinate (the library's soup, no copy)")
      .def_property_readonly("name", [](const PyMesh& s) { return s.data->soup.name; })
      .def_property_readonly("file", [](const PyMesh& s) { return s.data->file; }, "the path given to Mesh.load ('' otherwise)")
      .def_property_readonly("unit", [](const PyMesh& s) { return s.data->unit; })
      .def_property_readonly("degenerate_triangles", [](const PyMesh& s) { return s.data->degenerate_triangles; },
                             "triangles with shape quality <= 1e-12 (kept)")
      .def_property_readonly("warnings", [](const PyMesh& s) { return s.data->warnings; })
      .def_property_readonly("bounds", [](const PyMesh& s) {
            const Aabb box = swept::bounds(s.data->soup.triangles);
            auto a = new_array<double>({2, 3});
            for (int i = 0; i < 3; ++i) a.mutable_at(0, i) = box.min[i], a.mutable_at(1, i) = box.max[i];
            return a;
          }, "(2, 3) array: min and max corner (inf, -inf for an empty mesh)")
      .def("__len__", [](const PyMesh& s) { return s.data->soup.triangles.size(); })
      .def(pyb::pickle(&mesh_getstate, &mesh_setstate))
      .def("__repr__", [](const PyMesh& s) {
        std::ostringstream os;
        os << "swept.Mesh(" << s.data->soup.triangles.size() << " triangles, unit='" << s.data->unit << "'"
           << (s.data->file.empty() ? "" : ", file='" + s.data->file + "'") << ")";
        return os.str();
      });

  pyb::class_<PyBvh>(m, "BVH", R"doc(
The RSS tree of a mesh, built once (in parallel unless parallel=False; the tree is the same) and
immutable: queries on it may run from many threads at once.

fitter: "pqp" | "rapid2" | "inertia" (the paper's INERTIA_FIT, default);
split: "min-sa" (try the three axes, keep the smallest SA(left) + SA(right); default) | "largest".)doc")
      .def(pyb::init(&build), pyb::arg("mesh"), pyb::arg("fitter") = "inertia", pyb::arg("split") = "min-sa",
           pyb::arg("leaf_size") = 1, pyb::arg("parallel") = true)
      .def(pyb::pickle(&bvh_getstate, &bvh_setstate))
      .def("stats", &bvh_stats, R"doc(
The figures of `swept bvh --json`: triangles, fitter, split, nodes, depth, total_surface_area,
total_volume (sums over every node's RSS), build_ms, bytes.)doc")
      .def_property_readonly("fitter", [](const PyBvh& b) { return std::string(to_string(b.bvh->config.fitter)); })
      .def_property_readonly("split", [](const PyBvh& b) { return std::string(to_string(b.bvh->config.split)); })
      .def_property_readonly("triangle_count", [](const PyBvh& b) { return b.bvh->triangles.size(); })
      .def_property_readonly("depth", [](const PyBvh& b) { return b.bvh->depth; })
      .def_property_readonly("extent", [](const PyBvh& b) { return b.bvh->extent; }, "diagonal of the model's box")
      .def("__repr__", [](const PyBvh& b) {
        std::ostringstream os;
        os << "swept.BVH(" << b.bvh->triangles.size() << " triangles, fitter='" << to_string(b.bvh->config.fitter)
           << "', split='" << to_string(b.bvh->config.split) << "', " << b.bvh->nodes.size() << " nodes)";
        return os.str();
      });
}

}  // namespace swept::py
