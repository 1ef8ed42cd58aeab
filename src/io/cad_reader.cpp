// STEP, IGES and OCCT .brep through OpenCASCADE. STEP and IGES go through XCAF so that assembly
// instances come out with their placements and part names; every unique part shape is
// tessellated once by BRepMesh (in parallel over faces, which is deterministic because each face
// is meshed independently), then each instance's faces are transformed into the common frame.
#include "import_detail.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESCAFControl_Reader.hxx>
#include <IMeshTools_Parameters.hxx>
#include <Interface_Check.hxx>
#include <Interface_CheckIterator.hxx>
#include <Interface_InterfaceModel.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_Printer.hxx>
#include <Poly_Triangulation.hxx>
#include <STEPCAFControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <TCollection_HAsciiString.hxx>
#include <TDF_Label.hxx>
#include <TDF_LabelSequence.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopLoc_Location.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_MapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <UnitsMethods.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <XSControl_WorkSession.hxx>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <numbers>
#include <map>
#include <mutex>
#include <sstream>

namespace swept::io_detail {

namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

/// One placed part: the shape (with its instance location applied) and its name.
struct Instance {
  TopoDS_Shape shape;
  std::string name;
};

std::string label_name(const TDF_Label& label) {
  Handle(TDataStd_Name) attr;
  if (!label.FindAttribute(TDataStd_Name::GetID(), attr)) return {};
  const TCollection_ExtendedString& ext = attr->Get();
  // Part names are ASCII in practice; non-ASCII characters become '?'.
  std::string out;
  out.reserve(static_cast<std::size_t>(ext.Length()));
  for (int i = 1; i <= ext.Length(); ++i) {
    const char16_t c = ext.Value(i);
    out.push_back(c < 128 ? static_cast<char>(c) : '?');
  }
  return out;
}

void collect_instances(const Handle(XCAFDoc_ShapeTool)& tool, const TDF_Label& label, const TopLoc_Location& loc,
                       const std::string& name, std::vector<Instance>& out) {
  if (XCAFDoc_ShapeTool::IsAssembly(label)) {
    TDF_LabelSequence components;
    XCAFDoc_ShapeTool::GetComponents(label, components, false);
    for (int i = 1; i <= components.Length(); ++i) {
      const TDF_Label& comp = components.Value(i);
      TDF_Label referred;
      if (!XCAFDoc_ShapeTool::GetReferredShape(comp, referred)) continue;
      std::string child = label_name(referred);
      if (child.empty()) child = label_name(comp);
      collect_instances(tool, referred, loc * XCAFDoc_ShapeTool::GetLocation(comp), child, out);
    }
    return;
  }
  const TopoDS_Shape shape = XCAFDoc_ShapeTool::GetShape(label);
  if (shape.IsNull()) return;
  out.push_back({shape.Moved(loc), name});
}

// Collects the failure messages OCCT's file parsers send to the default messenger (the STEP
// parser reports syntax errors with their line only there).
class FailCollector : public Message_Printer {
 public:
  mutable std::vector<std::string> fails;

 protected:
  void send(const TCollection_AsciiString& text, const Message_Gravity gravity) const override {
    if (gravity >= Message_Fail && fails.size() < 5) {
      std::string line(text.ToCString());
      // "**** ERR StepFile : Undefined Parsing: Line 5: ... ****" -> "Line 5: ..."
      while (!line.empty() && (line.back() == '\n' || line.back() == ' ' || line.back() == '*')) line.pop_back();
      for (const char* prefix : {"Undefined Parsing: ", ": "}) {
        if (const std::size_t at = line.find(prefix); at != std::string::npos && line.compare(0, 4, "****") == 0) {
          line.erase(0, at + std::strlen(prefix));
          break;
        }
      }
      fails.push_back(line);
    }
  }
};

// The XSTEP readers share static state (parameters, the parser's messenger): one read at a time.
std::mutex& xstep_mutex() {
  static std::mutex m;
  return m;
}

// Failure messages of the reader's syntax and semantic checks, with the file's entity labels.
std::string check_messages(const XSControl_Reader& reader) {
  Handle(XSControl_WorkSession) ws = reader.WS();
  if (ws.IsNull()) return {};
  Handle(Interface_InterfaceModel) model = ws->Model();
  Interface_CheckIterator checks = ws->ModelCheckList();
  std::string out;
  int shown = 0;
  for (checks.Start(); checks.More() && shown < 5; checks.Next()) {
    const Handle(Interface_Check)& check = checks.Value();
    for (int i = 1; i <= check->NbFails() && shown < 5; ++i, ++shown) {
      if (std::string_view(check->CFail(i)).find("NOT AVAILABLE") != std::string_view::npos) continue;
      std::string where;
      const int number = checks.Number();
      if (number > 0 && !model.IsNull() && number <= model->NbEntities())
      {
        const Handle(TCollection_HAsciiString) label = model->StringLabel(model->Value(number));
        where = "entity " + (label.IsNull() ? std::to_string(number) : std::string(label->ToCString()));
      }
      else if (number > 0)
        where = "entity " + std::to_string(number);
      out += "; " + (where.empty() ? std::string() : where + ": ") + check->CFail(i);
    }
  }
  return out;
}

std::string status_text(IFSelect_ReturnStatus s) {
  switch (s) {
    case IFSelect_RetVoid: return "nothing to read";
    case IFSelect_RetDone: return "done";
    case IFSelect_RetError: return "syntax error or unreadable file";
    case IFSelect_RetFail: return "read failed";
    case IFSelect_RetStop: return "read stopped";
  }
  return "unknown status";
}

const XSControl_Reader& base_reader(const STEPCAFControl_Reader& r) { return r.Reader(); }
const XSControl_Reader& base_reader(const IGESCAFControl_Reader& r) { return r; }

template <class Reader>
Result<bool> read_xcaf(const ReadContext& ctx, const char* format, Handle(TDocStd_Document)& doc,
                       std::vector<Instance>& instances) {
  doc = new TDocStd_Document("XmlXCAF");
  std::lock_guard<std::mutex> lock(xstep_mutex());
  Reader reader;
  reader.SetNameMode(true);
  reader.SetColorMode(false);
  reader.SetLayerMode(false);
  Handle(FailCollector) collector = new FailCollector;
  const Handle(Message_Messenger)& messenger = Message::DefaultMessenger();
  messenger->AddPrinter(collector);
  IFSelect_ReturnStatus status = IFSelect_RetFail;
  try {
    status = reader.ReadFile(ctx.file.string().c_str());
  } catch (...) {
    messenger->RemovePrinter(collector);
    throw;
  }
  messenger->RemovePrinter(collector);
  if (status != IFSelect_RetDone) {
    std::string details;
    for (const std::string& f : collector->fails) details += "; " + f;
    return file_error(ctx.display, std::string(format) + " " + status_text(status) + details +
                                       check_messages(base_reader(reader)));
  }
  if (!reader.Transfer(doc))
    return file_error(ctx.display, std::string(format) + " transfer to shapes failed" + check_messages(base_reader(reader)));
  Handle(XCAFDoc_ShapeTool) tool = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
  TDF_LabelSequence roots;
  tool->GetFreeShapes(roots);
  for (int i = 1; i <= roots.Length(); ++i)
    collect_instances(tool, roots.Value(i), TopLoc_Location(), label_name(roots.Value(i)), instances);
  return true;
}

// .brep: one part per solid, plus one for faces that belong to no solid (surface models).
void brep_instances(const TopoDS_Shape& shape, const std::string& stem, std::vector<Instance>& out) {
  int solids = 0;
  for (TopExp_Explorer ex(shape, TopAbs_SOLID); ex.More(); ex.Next())
    out.push_back({ex.Current(), stem + "_solid" + std::to_string(++solids)});
  BRep_Builder builder;
  TopoDS_Compound loose;
  builder.MakeCompound(loose);
  bool any = false;
  for (TopExp_Explorer ex(shape, TopAbs_FACE, TopAbs_SOLID); ex.More(); ex.Next()) {
    builder.Add(loose, ex.Current());
    any = true;
  }
  if (any) out.push_back({loose, solids == 0 ? stem : stem + "_faces"});
  if (solids == 1 && !any) out.back().name = stem;
}

// ---- Triangle budget: how many triangles BRepMesh will make, estimated before it runs. ----
//
// A chord of angle θ on a circle of radius r deviates r·(1 − cos(θ/2)) from the arc, so with
// chord deflection d the step is θ = 2·acos(1 − d/r), at most the angular deflection; a curve
// of curvature κ = 1/r therefore needs κ/θ segments per unit length (π/acos(1 − d/r) per half
// turn), and a flat direction none. BRepMesh places a face's interior nodes on a grid in its
// parameter space with those steps (the range splitters of BRepMesh_*RangeSplitter), and
// triangulates a planar face from its boundary alone; so a face makes about 2·Nu·Nv triangles,
// with Nu, Nv the segment counts across its two parameter directions (at least 1), plus about
// one per boundary segment. Curvatures and speeds are sampled on a grid of the face (and along
// each edge), the largest count over the rows taken: the estimate is of the right size, not a
// bound, so the triangles are counted again as they are collected.

// Segments per unit length along a curve of curvature `kappa` (1/length).
double segments_per_length(double kappa, double deflection, double angle) {
  if (!(kappa > 0.0) || !std::isfinite(kappa)) return 0.0;
  const double c = 1.0 - deflection * kappa;
  const double theta = std::min(angle, c <= -1.0 ? 2.0 * std::numbers::pi : 2.0 * std::acos(c));
  return kappa / theta;
}

constexpr int kEstimateSamples = 8;  // per parameter direction of a face, and along an edge

// Segments of an edge's discretisation.
double edge_segments(const TopoDS_Edge& edge, double deflection, double angle) {
  if (BRep_Tool::Degenerated(edge)) return 0.0;
  BRepAdaptor_Curve curve(edge);
  const double t0 = curve.FirstParameter(), t1 = curve.LastParameter();
  if (!std::isfinite(t0) || !std::isfinite(t1) || !(t1 > t0)) return 1.0;
  const double dt = (t1 - t0) / kEstimateSamples;
  double segments = 0.0;
  for (int i = 0; i < kEstimateSamples; ++i) {
    gp_Pnt p;
    gp_Vec d1, d2;
    curve.D2(t0 + (i + 0.5) * dt, p, d1, d2);
    const double speed = d1.Magnitude();
    if (!(speed > 0.0)) continue;
    const double kappa = d1.Crossed(d2).Magnitude() / (speed * speed * speed);
    const double add = speed * dt * segments_per_length(kappa, deflection, angle);
    if (std::isfinite(add)) segments += add;  // a singular point (a pole, a cusp) says nothing
  }
  return std::max(1.0, std::ceil(segments));
}

// Triangles of one face: the interior grid plus the boundary.
double face_triangles(const TopoDS_Face& face, double deflection, double angle, double angle_interior) {
  double boundary = 0.0;
  for (TopExp_Explorer ex(face, TopAbs_EDGE); ex.More(); ex.Next())
    boundary += edge_segments(TopoDS::Edge(ex.Current()), deflection, angle);
  BRepAdaptor_Surface surface(face, Standard_True);
  const double u0 = surface.FirstUParameter(), u1 = surface.LastUParameter();
  const double v0 = surface.FirstVParameter(), v1 = surface.LastVParameter();
  if (!std::isfinite(u0) || !std::isfinite(u1) || !std::isfinite(v0) || !std::isfinite(v1) || !(u1 > u0) || !(v1 > v0))
    return boundary;
  const bool cylinder = surface.GetType() == GeomAbs_Cylinder;
  const int n = kEstimateSamples;
  const double du = (u1 - u0) / n, dv = (v1 - v0) / n;
  std::array<double, kEstimateSamples> rows_u{}, columns_v{};  // segments along u in row j, along v in column i
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      gp_Pnt p;
      gp_Vec su, sv, suu, svv, suv;
      surface.D2(u0 + (i + 0.5) * du, v0 + (j + 0.5) * dv, p, su, sv, suu, svv, suv);
      const gp_Vec normal = su.Crossed(sv);
      const double lu = su.Magnitude(), lv = sv.Magnitude(), ln = normal.Magnitude();
      if (!(lu > 0.0) || !(lv > 0.0) || !(ln > 0.0)) continue;
      // Normal curvature along each parameter line: (S_uu · N) / |S_u|².
      const double ku = std::abs(suu.Dot(normal)) / (ln * lu * lu);
      const double kv = std::abs(svv.Dot(normal)) / (ln * lv * lv);
      double rho_u = segments_per_length(ku, deflection, angle_interior);
      double rho_v = segments_per_length(kv, deflection, angle_interior);
      // Curved both ways, a grid cell's triangles deviate most at their centres, s/√2 from the
      // corners rather than s/2 along a chord: √2 shorter steps (measured: spheres and tori
      // make twice the triangles of the chord rule).
      if (rho_u > 0.0 && rho_v > 0.0) rho_u *= std::numbers::sqrt2, rho_v *= std::numbers::sqrt2;
      // BRepMesh keeps the cells of other surfaces near square: a straight direction (a cone's
      // rulings) takes the curved one's step; a cylinder's rulings are not split at all.
      if (!cylinder && (rho_u == 0.0 || rho_v == 0.0)) rho_u = rho_v = std::max(rho_u, rho_v);
      const double add_u = lu * du * rho_u, add_v = lv * dv * rho_v;
      if (!std::isfinite(add_u) || !std::isfinite(add_v)) continue;  // a singular point (a pole)
      rows_u[static_cast<std::size_t>(j)] += add_u;
      columns_v[static_cast<std::size_t>(i)] += add_v;
    }
  const double nu = *std::max_element(rows_u.begin(), rows_u.end());
  const double nv = *std::max_element(columns_v.begin(), columns_v.end());
  // A flat face is triangulated from its boundary alone: n boundary nodes, n − 2 triangles.
  if (nu < 1.0 && nv < 1.0) return std::max(1.0, boundary - 2.0);
  return 2.0 * std::max(1.0, nu) * std::max(1.0, nv) + boundary;
}

std::string count_text(double n) {
  char buf[32];
  std::snprintf(buf, sizeof buf, n < 1e6 ? "%.0f" : "%.2g", n);
  return buf;
}

std::string deflection_text(const ImportOptions& opt) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%g", opt.linear_deflection);
  return std::string("deflection ") + buf + " " + opt.unit;
}

std::string budget_advice(const ImportOptions& opt) {
  return "the limit of " + std::to_string(opt.max_triangles) +
         " (max_triangles; on the command line --max-triangles): use a larger deflection or raise the limit";
}

// IGES is made of 80-column records; column 73 names the section (Start, Global, Directory,
// Parameter, Terminate) and the Terminate record holds each section's line count. OCCT's IGES
// reader can crash on truncated files, so the structure is checked first.
std::string check_iges(const std::string& bytes) {
  const std::string letters = "SGDPT";
  std::array<long long, 5> counts{};
  int last = 0;
  std::string terminate;
  std::vector<std::pair<int, std::string>> directory_first_lines;  // (line number, record)
  std::size_t pos = 0;
  int line_no = 0;
  while (pos < bytes.size()) {
    std::size_t end = bytes.find('\n', pos);
    if (end == std::string::npos) end = bytes.size();
    std::string line = bytes.substr(pos, end - pos);
    pos = end + 1;
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(' ') == std::string::npos) continue;
    const std::string at = "line " + std::to_string(line_no) + ": ";
    if (line.size() < 73) return at + "IGES records are 80 columns wide, this one has " + std::to_string(line.size());
    const std::size_t section = letters.find(line[72]);
    if (line[72] == 'C') return at + "compressed IGES is not supported";
    if (section == std::string::npos) return at + "unknown IGES section letter '" + std::string(1, line[72]) + "' in column 73";
    if (static_cast<int>(section) < last)
      return at + "section '" + std::string(1, line[72]) + "' after section '" + std::string(1, letters[last]) + "'";
    last = static_cast<int>(section);
    if (section == 2 && counts[2] % 2 == 0) directory_first_lines.emplace_back(line_no, line);
    if (section == 4) terminate = line;
    ++counts[section];
  }
  if (counts[4] == 0) return "truncated IGES file: no terminate (T) section";
  for (int s = 0; s < 4; ++s) {
    // Fixed columns: "S" + 7 digits, "G" + 7, "D" + 7, "P" + 7 (digits may be space-padded).
    const std::size_t at = 8 * static_cast<std::size_t>(s);
    if (terminate[at] != letters[static_cast<std::size_t>(s)]) return "malformed IGES terminate section";
    long long declared = 0;
    std::string digits = terminate.substr(at + 1, 7);
    digits.erase(0, digits.find_first_not_of(' '));
    if (std::from_chars(digits.data(), digits.data() + digits.size(), declared).ec != std::errc())
      return "malformed IGES terminate section";
    if (declared != counts[static_cast<std::size_t>(s)])
      return "truncated IGES file: terminate section says section " + std::string(1, letters[static_cast<std::size_t>(s)]) +
             " has " + std::to_string(declared) + " lines, file holds " + std::to_string(counts[static_cast<std::size_t>(s)]);
  }
  if (counts[2] % 2 != 0) return "malformed IGES file: odd number of directory lines";
  for (const auto& [line_no, record] : directory_first_lines) {
    long long pointer = 0;
    std::string field = record.substr(8, 8);
    field.erase(0, field.find_first_not_of(' '));
    if (std::from_chars(field.data(), field.data() + field.size(), pointer).ec != std::errc() || pointer < 1 ||
        pointer > counts[3])
      return "line " + std::to_string(line_no) + ": directory entry points to parameter line '" + field + "' of " +
             std::to_string(counts[3]);
  }
  return {};
}

}  // namespace

Result<bool> read_cad(const ReadContext& ctx, std::vector<TriangleSoup>& parts) {
  const std::string ext = lower(ctx.file.extension().string());
  const ImportOptions& opt = *ctx.options;
  const std::string stem = ctx.file.stem().string();
  try {
    std::vector<Instance> instances;
    double output_per_shape_unit = ctx.file_to_output;  // .brep carries no unit
    Handle(TDocStd_Document) doc_holder;
    if (ext == ".brep") {
      Result<std::string> bytes = read_file_bytes(ctx.file, ctx.display);
      if (!bytes) return bytes.error();
      // OCCT's .brep parser loops forever on a truncated stream that merely sets failbit; make
      // every failed extraction throw instead.
      std::istringstream in(*bytes);
      in.exceptions(std::ios::failbit | std::ios::badbit);
      TopoDS_Shape shape;
      BRep_Builder builder;
      try {
        BRepTools::Read(shape, in, builder);
      } catch (const std::ios_base::failure&) {
        return file_error(ctx.display, "not a readable OCCT .brep file: malformed or truncated");
      }
      if (shape.IsNull()) return file_error(ctx.display, "not a readable OCCT .brep file");
      brep_instances(shape, stem, instances);
    } else {
      const bool step = ext == ".step" || ext == ".stp";
      if (!step) {
        Result<std::string> bytes = read_file_bytes(ctx.file, ctx.display);
        if (!bytes) return bytes.error();
        if (std::string err = check_iges(*bytes); !err.empty()) return file_error(ctx.display, err);
      }
      Result<bool> r = step ? read_xcaf<STEPCAFControl_Reader>(ctx, "STEP", doc_holder, instances)
                            : read_xcaf<IGESCAFControl_Reader>(ctx, "IGES", doc_holder, instances);
      if (!r) return r.error();
      // The readers convert the file's declared unit into the document's length unit (OCCT's
      // session unit, "xstep.cascade.unit", when the document has none).
      double mm_per_shape_unit = UnitsMethods::GetCasCadeLengthUnit(UnitsMethods_LengthUnit_Millimeter);
      if (double doc_unit = 0.0; XCAFDoc_DocumentTool::GetLengthUnit(doc_holder, doc_unit, UnitsMethods_LengthUnit_Millimeter) &&
                                 doc_unit > 0.0)
        mm_per_shape_unit = doc_unit;
      output_per_shape_unit = mm_per_shape_unit * 1e-3 / ctx.metres_per_output;
    }
    if (instances.empty()) return file_error(ctx.display, "contains no shapes");

    // Mesh every distinct part once; instances share the triangulation of their faces.
    BRep_Builder builder;
    TopoDS_Compound prototypes;
    builder.MakeCompound(prototypes);
    TopTools_MapOfShape seen;
    for (const Instance& inst : instances) {
      const TopoDS_Shape proto = inst.shape.Located(TopLoc_Location());
      if (seen.Add(proto)) builder.Add(prototypes, proto);
    }
    IMeshTools_Parameters params;
    params.Deflection = opt.linear_deflection / output_per_shape_unit;
    params.Angle = opt.angular_deflection;

    // Refuse before meshing what would not fit: every instance holds its part's triangles.
    {
      std::map<const void*, double> part_triangles;  // by the part's TShape: parts are estimated once
      double estimate = 0.0;
      for (const Instance& inst : instances) {
        auto [it, added] = part_triangles.emplace(inst.shape.TShape().get(), 0.0);
        if (added) {
          TopTools_IndexedMapOfShape faces;
          TopExp::MapShapes(inst.shape.Located(TopLoc_Location()), TopAbs_FACE, faces);
          // BRepMesh_IncrementalMesh's default interior angle is twice the edges' angle.
          for (int i = 1; i <= faces.Extent(); ++i)
            it->second += face_triangles(TopoDS::Face(faces(i)), params.Deflection, params.Angle, 2.0 * params.Angle);
        }
        estimate += it->second;
      }
      if (estimate > static_cast<double>(opt.max_triangles))
        return file_error(ctx.display, "tessellating at " + deflection_text(opt) + " would make about " + count_text(estimate) +
                                           " triangles, over " + budget_advice(opt));
    }
    params.InParallel = ctx.single_threaded ? Standard_False : Standard_True;
    // Explicit, so that the CSF_MeshAlgo environment variable cannot change the result.
    params.MeshAlgo = IMeshTools_MeshAlgoType_Watson;
    BRepMesh_IncrementalMesh mesher(prototypes, params);
    if (!mesher.IsDone()) return file_error(ctx.display, "BRepMesh failed to tessellate the shapes");

    std::size_t untriangulated = 0, total = 0;
    for (Instance& inst : instances) {
      TriangleSoup soup;
      soup.name = inst.name.empty() ? stem : inst.name;
      for (TopExp_Explorer ex(inst.shape, TopAbs_FACE); ex.More(); ex.Next()) {
        const TopoDS_Face& face = TopoDS::Face(ex.Current());
        TopLoc_Location loc;
        const Handle(Poly_Triangulation) tri = BRep_Tool::Triangulation(face, loc);
        if (tri.IsNull()) {
          ++untriangulated;
          continue;
        }
        // The estimate is not a bound: the triangles kept are counted too.
        total += static_cast<std::size_t>(tri->NbTriangles());
        if (total > opt.max_triangles)
          return file_error(ctx.display, "the tessellation at " + deflection_text(opt) + " has more than " + std::to_string(opt.max_triangles) +
                                             " triangles, over " + budget_advice(opt));
        const gp_Trsf trsf = loc.Transformation();
        const bool reversed = face.Orientation() == TopAbs_REVERSED;
        for (int i = 1; i <= tri->NbTriangles(); ++i) {
          int n[3];
          tri->Triangle(i).Get(n[0], n[1], n[2]);
          if (reversed) std::swap(n[1], n[2]);
          Triangle t;
          for (int v = 0; v < 3; ++v) {
            const gp_Pnt p = tri->Node(n[v]).Transformed(trsf);
            t[v] = output_per_shape_unit * Vec3(p.X(), p.Y(), p.Z());
          }
          soup.triangles.push_back(t);
        }
      }
      parts.push_back(std::move(soup));
    }
    if (untriangulated > 0)
      ctx.warnings->push_back(ctx.display + ": " + std::to_string(untriangulated) +
                              " face instance(s) could not be tessellated by BRepMesh and are left out");
  } catch (const Standard_Failure& e) {
    return file_error(ctx.display, std::string("OpenCASCADE: ") + e.GetMessageString());
  } catch (const std::exception& e) {
    return file_error(ctx.display, std::string("OpenCASCADE: ") + e.what());
  }
  return true;
}

}  // namespace swept::io_detail
