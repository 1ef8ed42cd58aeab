// 3MF reader (3D Manufacturing Format: the core specification, and the production extension's
// model parts that slicers write objects to), straight into double precision: the package opened
// with minizip, its model parts parsed with expat. Written here rather than through assimp, whose
// 3MF reader (5.2) ignores the model's unit (a file in microns would come in 1000 times too large),
// reads vertex indices with atoi (a malformed index becomes vertex 0) and holds single precision.
#include "format_checks.h"
#include "import_detail.h"

#include <expat.h>
#include <minizip/unzip.h>

#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <cstring>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string_view>

namespace swept::io_detail {

namespace {

constexpr std::string_view kCore = "http://schemas.microsoft.com/3dmanufacturing/core/2015/02";
constexpr std::string_view kProduction = "http://schemas.microsoft.com/3dmanufacturing/production/2015/06";
constexpr std::string_view kModelRelation = "http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel";
constexpr int kMaxNesting = 32;

using Affine = Eigen::Matrix<double, 3, 4>;  // p' = A.leftCols<3>() p + A.col(3)

struct Component {
  std::string part;  ///< the model part that defines the object ("" = the same part)
  long long object = 0;
  Affine transform = Affine::Identity();
  long line = 0;
};

struct Object {
  std::string name;
  std::vector<Vec3> vertices;
  std::vector<std::array<long long, 3>> triangles;
  std::vector<long> triangle_lines;  ///< the line of each triangle, for messages
  std::vector<Component> components;
};

struct ModelPart {
  std::string unit = "millimeter";
  std::map<long long, Object> objects;
  std::vector<Component> items;  ///< the build (root part only)
};

// The metres per unit of a 3MF `unit` attribute; 0 for an unknown one.
double metres_per(std::string_view unit) {
  if (unit == "micron") return 1e-6;
  if (unit == "millimeter") return 1e-3;
  if (unit == "centimeter") return 1e-2;
  if (unit == "inch") return 0.0254;
  if (unit == "foot") return 0.3048;
  if (unit == "meter") return 1.0;
  return 0.0;
}

// A part name of the package as a ZIP entry name ("/3D/3dmodel.model" → "3D/3dmodel.model").
std::string entry_name(std::string_view part) {
  while (!part.empty() && part.front() == '/') part.remove_prefix(1);
  return std::string(part);
}

struct Package {
  unzFile zip = nullptr;
  ~Package() {
    if (zip != nullptr) unzClose(zip);
  }
};

// Streams the entry `name` into `sink` in pieces; "" on success, else the reason.
std::string read_entry(Package& pkg, const std::string& name, const std::function<std::string(const char*, int, bool)>& sink) {
  if (unzLocateFile(pkg.zip, name.c_str(), 2) != UNZ_OK) return "the package has no part '" + name + "'";
  if (unzOpenCurrentFile(pkg.zip) != UNZ_OK) return "cannot open the package's part '" + name + "'";
  std::array<char, 1 << 16> buffer;
  std::string err;
  for (;;) {
    const int n = unzReadCurrentFile(pkg.zip, buffer.data(), static_cast<unsigned>(buffer.size()));
    if (n < 0) {
      err = "the package's part '" + name + "' is corrupt (ZIP error " + std::to_string(n) + ")";
      break;
    }
    err = sink(buffer.data(), n, n == 0);
    if (!err.empty() || n == 0) break;
  }
  if (unzCloseCurrentFile(pkg.zip) == UNZ_CRCERROR && err.empty()) err = "the package's part '" + name + "' fails its CRC check";
  return err;
}

// An XML part parsed by expat with namespaces ("uri|local" names); `start` sees every element.
class XmlPart {
 public:
  using Start = std::function<std::string(std::string_view ns, std::string_view name, const XML_Char** attrs, long line)>;
  explicit XmlPart(Start start) : start_(std::move(start)), parser_(XML_ParserCreateNS(nullptr, '|')) {
    XML_SetUserData(parser_, this);
    XML_SetStartElementHandler(parser_, &XmlPart::on_start);
    XML_SetEndElementHandler(parser_, &XmlPart::on_end);
  }
  ~XmlPart() { XML_ParserFree(parser_); }
  XmlPart(const XmlPart&) = delete;
  XmlPart& operator=(const XmlPart&) = delete;

  std::function<void(std::string_view ns, std::string_view name)> end;

  std::string feed(const char* data, int n, bool last) {
    if (XML_Parse(parser_, data, n, last ? 1 : 0) == XML_STATUS_ERROR) {
      if (!error_.empty()) return error_;
      return "line " + std::to_string(XML_GetCurrentLineNumber(parser_)) + ": not well-formed XML (" +
             XML_ErrorString(XML_GetErrorCode(parser_)) + ")";
    }
    return {};
  }

 private:
  static std::pair<std::string_view, std::string_view> split_name(const XML_Char* name) {
    std::string_view s(name);
    const std::size_t bar = s.find('|');
    if (bar == std::string_view::npos) return {{}, s};
    return {s.substr(0, bar), s.substr(bar + 1)};
  }
  static void on_start(void* self_ptr, const XML_Char* name, const XML_Char** attrs) {
    auto* self = static_cast<XmlPart*>(self_ptr);
    const auto [ns, local] = split_name(name);
    const long line = static_cast<long>(XML_GetCurrentLineNumber(self->parser_));
    if (std::string err = self->start_(ns, local, attrs, line); !err.empty()) {
      self->error_ = "line " + std::to_string(line) + ": " + err;
      XML_StopParser(self->parser_, XML_FALSE);
    }
  }
  static void on_end(void* self_ptr, const XML_Char* name) {
    auto* self = static_cast<XmlPart*>(self_ptr);
    const auto [ns, local] = split_name(name);
    if (self->end) self->end(ns, local);
  }

  Start start_;
  XML_Parser parser_;
  std::string error_;
};

// An attribute's value, or nullptr; `ns` empty for an unprefixed attribute.
const XML_Char* attribute(const XML_Char** attrs, std::string_view ns, std::string_view name) {
  for (int i = 0; attrs[i] != nullptr; i += 2) {
    std::string_view a(attrs[i]);
    const std::size_t bar = a.find('|');
    const std::string_view a_ns = bar == std::string_view::npos ? std::string_view() : a.substr(0, bar);
    const std::string_view a_name = bar == std::string_view::npos ? a : a.substr(bar + 1);
    if (a_ns == ns && a_name == name) return attrs[i + 1];
  }
  return nullptr;
}

// A 3MF transform, "m00 m01 m02 m10 m11 m12 m20 m21 m22 m30 m31 m32": a row vector [x y z 1]
// times the 4 × 3 matrix of those rows, so that x' = m00 x + m10 y + m20 z + m30.
std::string parse_transform(const char* text, Affine& out) {
  const std::vector<std::string_view> tok = split(text);
  if (tok.size() != 12) return "a transform needs 12 numbers, found " + std::to_string(tok.size());
  double m[12];
  for (int i = 0; i < 12; ++i)
    if (std::string e = parse_number(tok[i], m[i]); !e.empty()) return e + " in a transform";
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) out(r, c) = m[3 * c + r];
  for (int r = 0; r < 3; ++r) out(r, 3) = m[9 + r];
  return {};
}

std::string parse_model(Package& pkg, const std::string& entry, bool root, ModelPart& model) {
  Object* object = nullptr;
  long long object_id = 0;
  bool in_build = false;
  XmlPart xml([&](std::string_view ns, std::string_view name, const XML_Char** attrs, long line) -> std::string {
    if (ns != kCore) return {};  // other extensions' elements (materials, slicer data) carry no geometry we read
    if (name == "model") {
      if (const char* unit = attribute(attrs, {}, "unit")) model.unit = unit;
      if (metres_per(model.unit) == 0.0)
        return "unknown unit '" + model.unit + "' (3MF's are micron, millimeter, centimeter, inch, foot, meter)";
    } else if (name == "object") {
      const char* id = attribute(attrs, {}, "id");
      if (id == nullptr || !parse_int(id, object_id)) return "an object without a valid id";
      if (model.objects.contains(object_id)) return "two objects have id " + std::to_string(object_id);
      object = &model.objects[object_id];
      if (const char* n = attribute(attrs, {}, "name")) object->name = n;
    } else if (name == "vertex" && object != nullptr) {
      double x[3];
      const char* keys[3] = {"x", "y", "z"};
      for (int k = 0; k < 3; ++k) {
        const char* v = attribute(attrs, {}, keys[k]);
        if (v == nullptr) return std::string("a vertex without ") + keys[k];
        if (std::string e = parse_number(v, x[k]); !e.empty())
          return e + " (object " + std::to_string(object_id) + ", vertex " + std::to_string(object->vertices.size()) + ")";
      }
      object->vertices.emplace_back(x[0], x[1], x[2]);
    } else if (name == "triangle" && object != nullptr) {
      std::array<long long, 3> v{};
      const char* keys[3] = {"v1", "v2", "v3"};
      for (int k = 0; k < 3; ++k) {
        const char* s = attribute(attrs, {}, keys[k]);
        if (s == nullptr || !parse_int(s, v[k]))
          return std::string("a triangle without a valid ") + keys[k] + " (object " + std::to_string(object_id) +
                 ", triangle " + std::to_string(object->triangles.size()) + ")";
      }
      object->triangles.push_back(v);
      object->triangle_lines.push_back(line);
    } else if ((name == "component" && object != nullptr) || (name == "item" && in_build)) {
      if (name == "item" && !root) return "a build item in a model part other than the root";
      Component c;
      c.line = line;
      const char* id = attribute(attrs, {}, "objectid");
      if (id == nullptr || !parse_int(id, c.object)) return "a " + std::string(name) + " without a valid objectid";
      if (const char* t = attribute(attrs, {}, "transform"))
        if (std::string e = parse_transform(t, c.transform); !e.empty()) return e;
      if (const char* p = attribute(attrs, kProduction, "path")) c.part = entry_name(p);
      (name == "item" ? model.items : object->components).push_back(std::move(c));
    } else if (name == "build") {  // (empty in the other model parts)
      in_build = true;
    }
    return {};
  });
  xml.end = [&](std::string_view ns, std::string_view name) {
    if (ns != kCore) return;
    if (name == "object") object = nullptr;
    if (name == "build") in_build = false;
  };
  return read_entry(pkg, entry, [&](const char* data, int n, bool last) { return xml.feed(data, n, last); });
}

// The root model part named by the package's relationships, or "3D/3dmodel.model".
std::string root_part(Package& pkg) {
  std::string target;
  XmlPart xml([&](std::string_view, std::string_view name, const XML_Char** attrs, long) -> std::string {
    if (name != "Relationship" || !target.empty()) return {};
    const char* type = attribute(attrs, {}, "Type");
    const char* to = attribute(attrs, {}, "Target");
    if (type != nullptr && to != nullptr && std::string_view(type) == kModelRelation) target = entry_name(to);
    return {};
  });
  const std::string err = read_entry(pkg, "_rels/.rels", [&](const char* data, int n, bool last) { return xml.feed(data, n, last); });
  if (!err.empty() || target.empty()) return "3D/3dmodel.model";
  return target;
}

}  // namespace

Result<bool> read_3mf(const ReadContext& ctx, std::vector<TriangleSoup>& parts) {
  Package pkg;
  pkg.zip = unzOpen64(ctx.file.c_str());
  if (pkg.zip == nullptr) return file_error(ctx.display, "not a 3MF package (not a ZIP archive, or a damaged one)");

  const std::string root = root_part(pkg);
  std::map<std::string, ModelPart> models;
  auto model_of = [&](const std::string& entry) -> Result<ModelPart*> {
    auto found = models.find(entry);
    if (found != models.end()) return &found->second;
    ModelPart& m = models[entry];
    if (std::string err = parse_model(pkg, entry, entry == root, m); !err.empty()) return file_error(ctx.display, entry + ": " + err);
    if (m.unit != models[root].unit)
      return file_error(ctx.display, entry + ": unit '" + m.unit + "' differs from the root model's '" + models[root].unit + "'");
    return &m;
  };
  Result<ModelPart*> root_model = model_of(root);
  if (!root_model) return root_model.error();
  const std::string unit = (*root_model)->unit;
  const double scale = metres_per(unit) / ctx.metres_per_output;
  if (!ctx.options->file_unit.empty()) {
    double given = 0.0;
    if (unit_scale(ctx.options->file_unit, given) && std::abs(given - metres_per(unit)) > 1e-12 * metres_per(unit))
      return file_error(ctx.display, "the model declares unit '" + unit + "', which the file unit '" + ctx.options->file_unit +
                                         "' given for it contradicts");
  }
  if ((*root_model)->items.empty()) return file_error(ctx.display, root + ": the build holds no items");

  // Each build item is a part: its object and, through components, the objects it is made of.
  // Components may repeat objects (n levels of two components each place 2^n copies): the placed
  // triangles are counted against the CAD formats' triangle limit before they are made.
  std::size_t placed = 0;
  const std::size_t limit = ctx.options->max_triangles;
  std::function<std::optional<Error>(const std::string&, const Component&, const Affine&, int, TriangleSoup&)> place;
  place = [&](const std::string& entry, const Component& ref, const Affine& outer, int depth,
              TriangleSoup& soup) -> std::optional<Error> {
    const std::string where = ref.part.empty() ? entry : ref.part;
    if (depth > kMaxNesting)
      return file_error(ctx.display, entry + ": line " + std::to_string(ref.line) + ": components nest deeper than " +
                                         std::to_string(kMaxNesting) + " levels (a cycle?)");
    Result<ModelPart*> m = model_of(where);
    if (!m) return m.error();
    const auto found = (*m)->objects.find(ref.object);
    if (found == (*m)->objects.end())
      return file_error(ctx.display, entry + ": line " + std::to_string(ref.line) + ": refers to object " +
                                         std::to_string(ref.object) + ", which " + where + " does not define");
    const Object& object = found->second;
    placed += object.triangles.size();
    if (placed > limit)
      return file_error(ctx.display, "the build places more than " + std::to_string(limit) +
                                         " triangles (the triangle limit; --max-triangles or ImportOptions::max_triangles "
                                         "raises it)");
    Affine world;
    world.leftCols<3>() = outer.leftCols<3>() * ref.transform.leftCols<3>();
    world.col(3) = outer.leftCols<3>() * ref.transform.col(3) + outer.col(3);
    const long long nv = static_cast<long long>(object.vertices.size());
    for (std::size_t t = 0; t < object.triangles.size(); ++t) {
      Triangle tri;
      for (int k = 0; k < 3; ++k) {
        const long long v = object.triangles[t][k];
        if (v < 0 || v >= nv)
          return file_error(ctx.display, where + ": line " + std::to_string(object.triangle_lines[t]) + ": object " +
                                             std::to_string(ref.object) + " triangle " + std::to_string(t) +
                                             " refers to vertex " + std::to_string(v) + " of " + std::to_string(nv));
        tri[k] = scale * (world.leftCols<3>() * object.vertices[static_cast<std::size_t>(v)] + world.col(3));
        if (!tri[k].allFinite())
          return file_error(ctx.display, where + ": object " + std::to_string(ref.object) + " triangle " +
                                             std::to_string(t) + " is not finite once placed");
      }
      soup.triangles.push_back(tri);
    }
    for (const Component& c : object.components)
      if (auto err = place(where, c, world, depth + 1, soup)) return err;
    return std::nullopt;
  };
  for (const Component& item : (*root_model)->items) {
    TriangleSoup soup;
    const auto found = (*root_model)->objects.find(item.object);
    soup.name = found != (*root_model)->objects.end() && !found->second.name.empty()
                    ? found->second.name
                    : "object " + std::to_string(item.object);
    if (auto err = place(root, item, Affine::Identity(), 0, soup)) return *err;
    parts.push_back(std::move(soup));
  }
  return true;
}

}  // namespace swept::io_detail
