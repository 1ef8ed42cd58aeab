// STEP, IGES and OCCT .brep through OpenCASCADE, built as the module libswept_cad.so that
// swept_io loads on first use (src/io/cad_module.h). STEP and IGES go through XCAF so that assembly
// instances come out with their placements and part names; every unique part shape is
// tessellated once by BRepMesh (in parallel over faces, which is deterministic because each face
// is meshed independently), then each instance's faces are transformed into the common frame.
#include "cad_budget.h"
#include "format_checks.h"
#include "cad_module.h"
#include "import_detail.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepGProp.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <Message_ProgressIndicator.hxx>
#include <Message_ProgressScope.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESCAFControl_Reader.hxx>
#include <GProp_GProps.hxx>
#include <IMeshTools_Parameters.hxx>
#include <Interface_Check.hxx>
#include <Interface_CheckIterator.hxx>
#include <Interface_InterfaceModel.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_Printer.hxx>
#include <Message_PrinterOStream.hxx>
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
#include <gp_Ax3.hxx>
#include <gp_Cylinder.hxx>

#include <Eigen/Eigenvalues>
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
#include <optional>
#include <sstream>

namespace swept::io_detail {

namespace {

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

// OCCT's default messenger prints to std::cout: the IGES reader's "Total number of loaded
// entities", in colour, landed in the middle of `swept bvh --json`'s document. Its stream
// printers are removed, once; the failures a read sends still reach FailCollector.
void silence_occt_output() {
  static std::once_flag once;
  std::call_once(once, [] { Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream)); });
}

// OpenCASCADE's progress, handed to ImportOptions::progress: Show() is called under the
// indicator's own mutex, never concurrently; a report is passed on per whole per cent.
class ProgressToOptions : public Message_ProgressIndicator {
 public:
  ProgressToOptions(const ImportOptions& options, const char* phase) : options_(options), phase_(phase) {}
  void Show(const Message_ProgressScope&, const Standard_Boolean force) override {
    if (!options_.progress) return;
    const int percent = static_cast<int>(100.0 * GetPosition());
    if (!force && percent == last_percent_) return;
    last_percent_ = percent;
    options_.progress(ImportProgress{.phase = phase_, .fraction = GetPosition()});
  }

 private:
  const ImportOptions& options_;
  const char* phase_;
  int last_percent_ = -1;
};

template <class Reader>
Result<bool> read_xcaf(const ReadContext& ctx, const char* format, Handle(TDocStd_Document)& doc,
                       std::vector<Instance>& instances) {
  doc = new TDocStd_Document("XmlXCAF");
  silence_occt_output();
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
  Handle(ProgressToOptions) shapes = new ProgressToOptions(*ctx.options, "shapes");
  if (!reader.Transfer(doc, shapes->Start()))
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

// The cylinder a face lies on, in the frame of the face's location: an analytic cylinder, or a
// free-form face (B-spline, Bezier, ...: STEP files from many systems write every curved face so)
// that is one within `tolerance`, found from 17 × 17 samples of the face's parameter box: the
// axis is the direction the normals are perpendicular to (to 1e-7), the centre the point their
// lines pass nearest, the radius the samples' mean distance; `deviation` is the samples' largest
// distance from that radius (an estimate: the face is not examined between the samples; the
// caller also measures the face's mesh nodes). An analytic cylinder has deviation 0.
std::optional<gp_Cylinder> cylinder_of(const TopoDS_Face& face, double tolerance, double& deviation) {
  const BRepAdaptor_Surface surface(face);
  deviation = 0.0;
  switch (surface.GetType()) {
    case GeomAbs_Cylinder:
      return surface.Cylinder();
    case GeomAbs_Plane:
    case GeomAbs_Cone:
    case GeomAbs_Sphere:
    case GeomAbs_Torus:
      return std::nullopt;
    default:
      break;
  }
  constexpr int kSteps = 16;
  std::vector<Eigen::Vector3d> points, normals;
  const double u0 = surface.FirstUParameter(), u1 = surface.LastUParameter();
  const double v0 = surface.FirstVParameter(), v1 = surface.LastVParameter();
  if (!std::isfinite(u0) || !std::isfinite(u1) || !std::isfinite(v0) || !std::isfinite(v1)) return std::nullopt;
  for (int i = 0; i <= kSteps; ++i)
    for (int j = 0; j <= kSteps; ++j) {
      gp_Pnt p;
      gp_Vec du, dv;
      surface.D1(u0 + (u1 - u0) * i / kSteps, v0 + (v1 - v0) * j / kSteps, p, du, dv);
      const gp_Vec n = du.Crossed(dv);
      if (!(n.Magnitude() > 1e-12 * (1.0 + du.Magnitude() * dv.Magnitude()))) continue;  // a pole
      points.emplace_back(p.X(), p.Y(), p.Z());
      normals.emplace_back(Eigen::Vector3d(n.X(), n.Y(), n.Z()).normalized());
    }
  if (points.size() < 16) return std::nullopt;
  Eigen::Matrix3d moment = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& n : normals) moment += n * n.transpose();
  const Eigen::Vector3d axis = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(moment).eigenvectors().col(0);
  for (const Eigen::Vector3d& n : normals)
    if (!(std::abs(n.dot(axis)) <= 1e-7)) return std::nullopt;
  const Eigen::Vector3d e1 = axis.unitOrthogonal(), e2 = axis.cross(e1);
  Eigen::Matrix2d a = Eigen::Matrix2d::Zero();
  Eigen::Vector2d b = Eigen::Vector2d::Zero();
  for (std::size_t k = 0; k < points.size(); ++k) {
    const Eigen::Vector2d q(points[k].dot(e1), points[k].dot(e2));
    const Eigen::Vector2d m = Eigen::Vector2d(normals[k].dot(e1), normals[k].dot(e2)).normalized();
    const Eigen::Matrix2d across = Eigen::Matrix2d::Identity() - m * m.transpose();
    a += across;
    b += across * q;
  }
  // Normals of one direction only (a plane in disguise) leave the centre undetermined.
  if (!(std::abs(a.determinant()) > 1e-6 * a.squaredNorm())) return std::nullopt;
  const Eigen::Vector2d c = a.ldlt().solve(b);
  double radius = 0.0;
  for (const Eigen::Vector3d& p : points) radius += (Eigen::Vector2d(p.dot(e1), p.dot(e2)) - c).norm();
  radius /= static_cast<double>(points.size());
  for (const Eigen::Vector3d& p : points)
    deviation = std::max(deviation, std::abs((Eigen::Vector2d(p.dot(e1), p.dot(e2)) - c).norm() - radius));
  if (!(radius > 0.0) || !(deviation <= tolerance)) return std::nullopt;
  const Eigen::Vector3d o = c.x() * e1 + c.y() * e2;
  return gp_Cylinder(gp_Ax3(gp_Pnt(o.x(), o.y(), o.z()), gp_Dir(axis.x(), axis.y(), axis.z())), radius);
}

}  // namespace

Result<bool> read_cad_occt(const ReadContext& ctx, std::vector<TriangleSoup>& parts) {
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
      if (instances.empty()) {
        // A wireframe (OCCT's sample asahi.brep: edges and vertices only): say what it holds.
        TopTools_IndexedMapOfShape edges, vertices;
        TopExp::MapShapes(shape, TopAbs_EDGE, edges);
        TopExp::MapShapes(shape, TopAbs_VERTEX, vertices);
        auto count = [](int n, const char* one, const char* many) { return std::to_string(n) + " " + (n == 1 ? one : many); };
        return file_error(ctx.display, "holds no faces to mesh, only " + count(edges.Extent(), "edge", "edges") + " and " +
                                           count(vertices.Extent(), "vertex", "vertices") + " (a wireframe)");
      }
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
    Handle(ProgressToOptions) meshing = new ProgressToOptions(opt, "meshing");
    BRepMesh_IncrementalMesh mesher(prototypes, params, meshing->Start());
    if (!mesher.IsDone()) return file_error(ctx.display, "BRepMesh failed to tessellate the shapes");

    // A face BRepMesh left without triangles: of no area (a degenerate face the file holds, as
    // FreeCAD's SOD_323.stp has two: nothing is lost), or a real failure (a hole in the part).
    // Judged once per face of a part, by its area against the deflection's square.
    std::map<const void*, bool> empty_face;
    auto has_no_area = [&](const TopoDS_Face& face) {
      auto [it, added] = empty_face.emplace(face.TShape().get(), false);
      if (added) {
        GProp_GProps props;
        BRepGProp::SurfaceProperties(face, props);
        it->second = !(std::abs(props.Mass()) > 1e-6 * params.Deflection * params.Deflection);
      }
      return it->second;
    };
    std::size_t untriangulated = 0, empty = 0, total = 0;
    for (Instance& inst : instances) {
      TriangleSoup soup;
      soup.name = inst.name.empty() ? stem : inst.name;
      for (TopExp_Explorer ex(inst.shape, TopAbs_FACE); ex.More(); ex.Next()) {
        const TopoDS_Face& face = TopoDS::Face(ex.Current());
        TopLoc_Location loc;
        const Handle(Poly_Triangulation) tri = BRep_Tool::Triangulation(face, loc);
        if (tri.IsNull()) {
          ++(has_no_area(face) ? empty : untriangulated);
          continue;
        }
        // The estimate is not a bound: the triangles kept are counted too.
        total += static_cast<std::size_t>(tri->NbTriangles());
        if (total > opt.max_triangles)
          return file_error(ctx.display, "the tessellation at " + deflection_text(opt) + " has more than " + std::to_string(opt.max_triangles) +
                                             " triangles, over " + budget_advice(opt));
        // A cylindrical face keeps its surface (the contact model of assemblies slides mated
        // cylinders by it): the axis and radius in the same frame and unit as the triangles.
        std::int32_t cylinder = -1;
        double deviation = 0.0;
        // A face whose surface cannot be evaluated is no cylinder (its triangles still count).
        gp_Cylinder cyl;
        bool is_cylinder = false;
        try {
          if (const std::optional<gp_Cylinder> c = cylinder_of(face, 0.1 * params.Deflection, deviation)) {
            cyl = *c;
            is_cylinder = true;
          }
        } catch (const Standard_Failure&) {
          is_cylinder = false;
        }
        // A fitted (free-form) face is also measured at its mesh's nodes, which lie on it: between
        // the fit's samples, where the facets are. Beyond a tenth of the deflection it is no cylinder.
        const gp_Trsf trsf = loc.Transformation();
        if (is_cylinder && deviation > 0.0) {
          const gp_Ax1 axis = cyl.Axis();
          for (int i = 1; i <= tri->NbNodes() && is_cylinder; ++i) {
            const gp_Pnt p = tri->Node(i).Transformed(trsf);
            const gp_Vec w(axis.Location(), p);
            const double radial = w.Crossed(gp_Vec(axis.Direction())).Magnitude();
            deviation = std::max(deviation, std::abs(radial - cyl.Radius()));
            is_cylinder = deviation <= 0.1 * params.Deflection;
          }
        }
        if (is_cylinder) {
          const gp_Pnt o = cyl.Axis().Location();
          const gp_Dir d = cyl.Axis().Direction();
          cylinder = static_cast<std::int32_t>(soup.cylinders.size());
          soup.cylinders.push_back({output_per_shape_unit * Vec3(o.X(), o.Y(), o.Z()), Vec3(d.X(), d.Y(), d.Z()),
                                    output_per_shape_unit * cyl.Radius(), output_per_shape_unit * deviation});
        }
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
          soup.cylinder_of.push_back(cylinder);
        }
      }
      parts.push_back(std::move(soup));
    }
    if (untriangulated > 0)
      ctx.warnings->push_back(ctx.display + ": " + std::to_string(untriangulated) +
                              " face instance(s) could not be tessellated by BRepMesh and are left out");
    if (empty > 0)
      ctx.warnings->push_back(ctx.display + ": " + std::to_string(empty) +
                              " face instance(s) of no area (degenerate in the file) have no triangles; nothing is lost");
  } catch (const Standard_Failure& e) {
    return file_error(ctx.display, std::string("OpenCASCADE: ") + e.GetMessageString());
  } catch (const std::exception& e) {
    return file_error(ctx.display, std::string("OpenCASCADE: ") + e.what());
  }
  return true;
}

}  // namespace swept::io_detail

// The module's two entry points (the only symbols it exports; src/io/cad_module.cpp).
extern "C" __attribute__((visibility("default"))) const char* swept_cad_abi() { return swept::io_detail::cad_module_abi(); }

extern "C" __attribute__((visibility("default"))) void swept_cad_read(const swept::io_detail::ReadContext* ctx,
                                                                       std::vector<swept::TriangleSoup>* parts,
                                                                       swept::Result<bool>* out) {
  *out = swept::io_detail::read_cad_occt(*ctx, *parts);
}
