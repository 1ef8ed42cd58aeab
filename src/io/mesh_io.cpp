// import_mesh(): unit handling, format dispatch and the checks every format shares
// (non-finite coordinates, empty results, degenerate-triangle counting); write_stl_binary().
#include "swept/io/mesh_io.h"

#include "swept/geometry/pose.h"

#include "swept/io/file_write.h"

#include "import_detail.h"
#include "cad_module.h"
#include "isolate.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <system_error>

namespace swept {

namespace {

struct UnitEntry {
  std::string_view name;
  double metres;
};

constexpr std::array<UnitEntry, 6> kUnits{{
    {"m", 1.0}, {"cm", 1e-2}, {"mm", 1e-3}, {"um", 1e-6}, {"in", 0.0254}, {"ft", 0.3048}}};

std::string accepted_units() {
  std::string s;
  for (const UnitEntry& u : kUnits) {
    if (!s.empty()) s += ", ";
    s += u.name;
  }
  return s;
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

bool finite(const Vec3& v) { return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()); }

// Relative threshold on shape_quality() (2·area / longest edge²) below which a triangle counts
// as degenerate: exact zero-area triangles read from float data land around 1e-16 after the
// unit conversion, while real CAD slivers (aspect ratio up to ~1e6) stay far above it.
constexpr double kDegenerateQuality = 1e-12;

void put_u32(std::string& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xFFu));
}

void put_f32(std::string& out, float f) { put_u32(out, std::bit_cast<std::uint32_t>(f)); }

}  // namespace

bool unit_scale(std::string_view unit, double& metres_per_unit) {
  for (const UnitEntry& u : kUnits) {
    if (u.name == unit) {
      metres_per_unit = u.metres;
      return true;
    }
  }
  return false;
}

std::size_t ImportedModel::triangle_count() const {
  std::size_t n = 0;
  for (const TriangleSoup& p : parts) n += p.triangles.size();
  return n;
}

TriangleSoup ImportedModel::merged() const {
  TriangleSoup all;
  all.name = std::filesystem::path(file).stem().string();
  all.triangles.reserve(triangle_count());
  for (const TriangleSoup& p : parts) append_placed(all, p);
  return all;
}

namespace {

enum class Reader { stl, off, threemf, assimp, cad };  // stl, off, threemf: swept's own readers

// The checks every reader shares (units, format, deflections, the file itself) and the context
// the readers get; `reader` is set to the one the extension selects.
Result<io_detail::ReadContext> prepare(const std::filesystem::path& file, const ImportOptions& options, Reader& reader) {
  using io_detail::file_error;
  const std::string display = file.string();

  double metres_per_output = 0.0;
  if (!unit_scale(options.unit, metres_per_output))
    return file_error(display, "unknown output unit '" + options.unit + "' (accepted: " + accepted_units() + ")");

  const std::string ext = lower(file.extension().string());
  const bool is_cad = ext == ".step" || ext == ".stp" || ext == ".iges" || ext == ".igs" || ext == ".brep";
  const bool is_assimp = ext == ".obj" || ext == ".ply" || ext == ".gltf" || ext == ".glb" || ext == ".dae";
  const bool is_stl = ext == ".stl", is_off = ext == ".off", is_3mf = ext == ".3mf";
  if (!is_cad && !is_assimp && !is_stl && !is_off && !is_3mf)
    return file_error(display, "unknown format '" + (ext.empty() ? std::string("(no extension)") : ext) +
                                   "' (accepted: .stl .obj .ply .off .3mf .gltf .glb .dae .step .stp .iges .igs .brep)");
  reader = is_stl ? Reader::stl : is_off ? Reader::off : is_3mf ? Reader::threemf : is_assimp ? Reader::assimp : Reader::cad;

  // glTF and COLLADA coordinates are metres (glTF by its spec; assimp applies COLLADA's <unit>).
  std::string file_unit = options.file_unit;
  if (file_unit.empty()) file_unit = (ext == ".gltf" || ext == ".glb" || ext == ".dae") ? "m" : "mm";
  double metres_per_file = 0.0;
  if (!unit_scale(file_unit, metres_per_file))
    return file_error(display, "unknown file unit '" + file_unit + "' (accepted: " + accepted_units() + ")");

  if (is_cad) {
    if (!(options.linear_deflection > 0.0) || !std::isfinite(options.linear_deflection))
      return file_error(display, "linear deflection must be a positive finite length, got " +
                                     std::to_string(options.linear_deflection));
    if (!(options.angular_deflection > 0.0) || !std::isfinite(options.angular_deflection))
      return file_error(display, "angular deflection must be a positive finite angle in radians, got " +
                                     std::to_string(options.angular_deflection));
    if (options.max_triangles == 0) return file_error(display, "max_triangles must be at least 1");
  }

  std::error_code ec;
  const auto status = std::filesystem::status(file, ec);
  if (!std::filesystem::exists(status)) return file_error(display, "no such file");
  if (std::filesystem::is_directory(status)) return file_error(display, "is a directory, not a file");
  const auto size = std::filesystem::file_size(file, ec);
  if (ec) return file_error(display, "cannot read file size: " + ec.message());
  if (size == 0) return file_error(display, "file is empty");

  io_detail::ReadContext ctx;
  ctx.file = file;
  ctx.display = display;
  ctx.file_to_output = metres_per_file / metres_per_output;
  ctx.metres_per_output = metres_per_output;
  ctx.options = &options;
  return ctx;
}

}  // namespace

// A third-party reader (assimp or OpenCASCADE) run in a child process (isolate.h), its parts
// and warnings sent back as bytes; in the caller's process when options.isolate_readers is off.
Result<bool> read_isolated(io_detail::ReadContext& ctx, Reader reader, std::vector<TriangleSoup>& parts,
                           std::vector<std::string>& warnings) {
  auto read_here = [&ctx, reader](std::vector<TriangleSoup>& out) {
    return reader == Reader::assimp ? io_detail::read_with_assimp(ctx, out) : io_detail::read_cad(ctx, out);
  };
  if (!ctx.options->isolate_readers) return read_here(parts);
  // The CAD reader's module is loaded here, before the fork: loading a library in a child forked
  // from a threaded process is not safe, and the next CAD file's child inherits it. Without it
  // read_cad says why, with no child.
  if (reader == Reader::cad && io_detail::cad_module().entry == nullptr) return io_detail::read_cad(ctx, parts);
  const char* name = reader == Reader::assimp ? "assimp" : "OpenCASCADE";
  const Result<std::size_t> memory = io_detail::reader_memory_bytes(ctx.options->reader_memory);
  if (!memory) return memory.error();
  // A CAD file's tessellation grows with a finer deflection, whatever the file.
  const io_detail::ChildLimits limits{ctx.options->reader_timeout, *memory,
                                      reader == Reader::cad ? "; a larger deflection makes fewer triangles" : ""};
  auto bytes = io_detail::run_isolated(ctx.display, name, limits, [&]() -> Result<std::string> {
    ctx.single_threaded = true;  // no oneTBB after fork
    std::vector<TriangleSoup> out;
    Result<bool> r = read_here(out);
    if (!r) return r.error();
    io_detail::ByteWriter w;
    w.u64(out.size());
    for (const TriangleSoup& part : out) {
      w.str(part.name);
      w.u64(part.triangles.size());
      for (const Triangle& t : part.triangles)
        for (int k = 0; k < 3; ++k) w.put(t[k].data(), 3 * sizeof(double));
      w.u64(part.cylinder_of.size());
      if (!part.cylinder_of.empty()) w.put(part.cylinder_of.data(), part.cylinder_of.size() * sizeof(std::int32_t));
      w.u64(part.cylinders.size());
      for (const CadCylinder& c : part.cylinders) {
        w.put(c.origin.data(), 3 * sizeof(double));
        w.put(c.axis.data(), 3 * sizeof(double));
        w.put(&c.radius, sizeof(double));
        w.put(&c.deviation, sizeof(double));
      }
    }
    w.u64(warnings.size());
    for (const std::string& s : warnings) w.str(s);
    return w.take();
  });
  if (!bytes) return bytes.error();
  io_detail::ByteReader r(*bytes);
  const Error cut = io_detail::file_error(ctx.display, std::string("internal: the ") + name + " reader's answer was cut short");
  std::uint64_t count = 0;
  if (!r.u64(count)) return cut;
  for (std::uint64_t i = 0; i < count; ++i) {
    TriangleSoup part;
    std::uint64_t n = 0;
    if (!r.str(part.name) || !r.u64(n) || n > bytes->size() / (9 * sizeof(double))) return cut;
    part.triangles.resize(n);
    for (Triangle& t : part.triangles)
      for (int k = 0; k < 3; ++k)
        if (!r.get(t[k].data(), 3 * sizeof(double))) return cut;
    std::uint64_t faces = 0;
    if (!r.u64(faces) || (faces != 0 && faces != n)) return cut;
    part.cylinder_of.resize(faces);
    if ((faces != 0 && !r.get(part.cylinder_of.data(), faces * sizeof(std::int32_t))) || !r.u64(faces) ||
        faces > bytes->size() / (8 * sizeof(double)))
      return cut;
    part.cylinders.resize(faces);
    for (CadCylinder& c : part.cylinders)
      if (!r.get(c.origin.data(), 3 * sizeof(double)) || !r.get(c.axis.data(), 3 * sizeof(double)) ||
          !r.get(&c.radius, sizeof(double)) || !r.get(&c.deviation, sizeof(double)))
        return cut;
    for (std::int32_t k : part.cylinder_of)
      if (k < -1 || k >= static_cast<std::int64_t>(part.cylinders.size())) return cut;
    parts.push_back(std::move(part));
  }
  if (!r.u64(count)) return cut;
  warnings.clear();
  for (std::uint64_t i = 0; i < count; ++i) {
    std::string s;
    if (!r.str(s)) return cut;
    warnings.push_back(std::move(s));
  }
  if (!r.done()) return cut;
  return true;
}

Result<ImportedModel> import_mesh(const std::filesystem::path& file, const ImportOptions& options) {
  using io_detail::file_error;
  Reader reader = Reader::stl;
  Result<io_detail::ReadContext> prepared = prepare(file, options, reader);
  if (!prepared) return prepared.error();
  io_detail::ReadContext& ctx = *prepared;
  const std::string& display = ctx.display;

  ImportedModel model;
  model.file = display;
  model.unit = options.unit;
  ctx.warnings = &model.warnings;
  Result<bool> read = reader == Reader::stl   ? io_detail::read_stl(ctx, model.parts)
                     : reader == Reader::off ? io_detail::read_off(ctx, model.parts)
                     : reader == Reader::threemf ? io_detail::read_3mf(ctx, model.parts)
                                             : read_isolated(ctx, reader, model.parts, model.warnings);
  if (!read) return read.error();

  // Drop parts without triangles (empty solids, point clouds, a solid that did not mesh), each
  // named in a warning; a file without any is an error.
  for (const TriangleSoup& p : model.parts)
    if (p.triangles.empty() && model.parts.size() > 1)
      model.warnings.push_back(display + ": part '" + p.name + "' has no triangles (no faces, or they did not tessellate); left out");
  std::erase_if(model.parts, [](const TriangleSoup& p) { return p.triangles.empty(); });
  if (model.parts.empty()) return file_error(display, "contains no triangles");

  // Part names are unique: repeats (assembly instances, meshes sharing a node) get "#2", "#3", ...
  std::map<std::string, int> name_uses;
  for (TriangleSoup& part : model.parts) {
    const int use = ++name_uses[part.name];
    if (use > 1) part.name += "#" + std::to_string(use);
  }

  for (const TriangleSoup& part : model.parts) {
    for (std::size_t i = 0; i < part.triangles.size(); ++i) {
      const Triangle& t = part.triangles[i];
      if (!finite(t.p) || !finite(t.q) || !finite(t.r)) {
        std::string where = model.parts.size() > 1 ? "part '" + part.name + "' " : std::string();
        return file_error(display, where + "triangle " + std::to_string(i) + " has a non-finite coordinate");
      }
      if (shape_quality(t) <= kDegenerateQuality) ++model.degenerate_triangles;
    }
  }
  return model;
}

Result<OmplAppVertices> ompl_app_vertices(const std::filesystem::path& file, const ImportOptions& options) {
  Reader reader = Reader::stl;
  Result<io_detail::ReadContext> ctx = prepare(file, options, reader);
  if (!ctx) return ctx.error();
  if (reader != Reader::cad) {
    // assimp, isolated like every third-party read (isolate.h).
    if (!options.isolate_readers) return io_detail::ompl_app_vertices_with_assimp(*ctx);
    const io_detail::ReadContext& c = *ctx;
    const Result<std::size_t> memory = io_detail::reader_memory_bytes(options.reader_memory);
    if (!memory) return memory.error();
    const io_detail::ChildLimits limits{options.reader_timeout, *memory, {}};
    auto bytes = io_detail::run_isolated(c.display, "assimp", limits, [&c]() -> Result<std::string> {
      Result<OmplAppVertices> v = io_detail::ompl_app_vertices_with_assimp(c);
      if (!v) return v.error();
      io_detail::ByteWriter w;
      for (const Vec3* x : {&v->center, &v->box.min, &v->box.max})
        for (int i = 0; i < 3; ++i) w.f64((*x)[i]);
      return w.take();
    });
    if (!bytes) return bytes.error();
    io_detail::ByteReader r(*bytes);
    OmplAppVertices v;
    bool whole = true;
    for (Vec3* x : {&v.center, &v.box.min, &v.box.max})
      for (int i = 0; i < 3; ++i) whole = whole && r.f64((*x)[i]);
    if (!whole || !r.done()) return io_detail::file_error(c.display, "internal: the assimp reader's answer was cut short");
    return v;
  }

  // OMPL.app cannot read CAD files: the nearest rule is the mean of the tessellation's distinct
  // vertex positions (each corner once, whatever the faces around it), and their box.
  Result<ImportedModel> model = import_mesh(file, options);
  if (!model) return model.error();
  std::vector<std::array<double, 3>> corners;
  for (const TriangleSoup& part : model->parts)
    for (const Triangle& t : part.triangles)
      for (int v = 0; v < 3; ++v) corners.push_back({t[v].x(), t[v].y(), t[v].z()});
  std::sort(corners.begin(), corners.end());
  corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
  OmplAppVertices out;
  Vec3 sum = Vec3::Zero();
  for (const auto& c : corners) {
    sum += Vec3(c[0], c[1], c[2]);
    out.box.extend(Vec3(c[0], c[1], c[2]));
  }
  out.center = sum / static_cast<double>(corners.size());
  return out;
}

Result<Vec3> ompl_app_center(const std::filesystem::path& file, const ImportOptions& options) {
  Result<OmplAppVertices> v = ompl_app_vertices(file, options);
  if (!v) return v.error();
  return v->center;
}

Result<bool> write_stl_binary(const std::filesystem::path& file, const TriangleSoup& soup) {
  using io_detail::file_error;
  const std::string display = file.string();
  if (soup.triangles.size() > std::numeric_limits<std::uint32_t>::max())
    return file_error(display, "too many triangles for a binary STL (" + std::to_string(soup.triangles.size()) + ")");

  std::string out;
  out.reserve(84 + 50 * soup.triangles.size());
  // The header must not start with "solid", or readers may take the file for ASCII STL.
  std::array<char, 80> header{};
  const std::string title = "binary STL written by swept: " + soup.name;
  std::memcpy(header.data(), title.data(), std::min(title.size(), header.size()));
  out.append(header.data(), header.size());
  put_u32(out, static_cast<std::uint32_t>(soup.triangles.size()));

  for (std::size_t i = 0; i < soup.triangles.size(); ++i) {
    const Triangle& t = soup.triangles[i];
    if (!finite(t.p) || !finite(t.q) || !finite(t.r))
      return file_error(display, "triangle " + std::to_string(i) + " has a non-finite coordinate; nothing written");
    Vec3 n = (t.q - t.p).cross(t.r - t.p);
    const double len = n.norm();
    n = len > 0.0 ? Vec3(n / len) : Vec3::Zero();
    for (int k = 0; k < 3; ++k) put_f32(out, static_cast<float>(n[k]));
    for (int v = 0; v < 3; ++v)
      for (int k = 0; k < 3; ++k) put_f32(out, static_cast<float>(t[v][k]));
    out.push_back('\0');
    out.push_back('\0');
  }

  return write_file_atomically(file, out);
}

}  // namespace swept
