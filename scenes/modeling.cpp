// OpenCASCADE modelling helpers for the built-in scenes (see swept/scenes/modeling.h).
// Failures of OCCT algorithms are programming errors in a scene's construction; they throw
// std::runtime_error, which generate_scene() turns into an Error value.
#include "swept/scenes/modeling.h"

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepFilletAPI_MakeChamfer.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepOffsetAPI_MakePipe.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRepPrimAPI_MakeRevol.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GC_MakeArcOfCircle.hxx>
#include <Poly_Triangulation.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Ax2.hxx>
#include <gp_Ax1.hxx>
#include <gp_Circ.hxx>
#include <gp_Trsf.hxx>

#include <cmath>
#include <stdexcept>

namespace swept::scenes::detail {
namespace {

gp_Pnt pnt(const Vec3& v) { return gp_Pnt(v.x(), v.y(), v.z()); }
gp_Dir dir(const Vec3& v) { return gp_Dir(v.x(), v.y(), v.z()); }
Vec3 vec(const gp_Pnt& p) { return Vec3(p.X(), p.Y(), p.Z()); }

void require(bool ok, const char* what) {
  if (!ok) throw std::runtime_error(std::string("scene modelling failed: ") + what);
}

// A planar annulus (or disc when inner == 0) centred at `c` with normal `n`.
TopoDS_Face ring_face(const Vec3& c, const Vec3& n, double outer, double inner) {
  const gp_Ax2 ax(pnt(c), dir(n));
  BRepBuilderAPI_MakeWire outer_wire(BRepBuilderAPI_MakeEdge(gp_Circ(ax, outer)).Edge());
  BRepBuilderAPI_MakeFace face(outer_wire.Wire(), Standard_True);
  if (inner > 0.0) {
    TopoDS_Wire hole = BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(gp_Circ(ax, inner)).Edge()).Wire();
    hole.Reverse();
    face.Add(hole);
  }
  require(face.IsDone(), "ring face");
  return face.Face();
}

bool inside(const Vec3& v, const Vec3& lo, const Vec3& hi) {
  return (v.array() >= lo.array()).all() && (v.array() <= hi.array()).all();
}

// Edges of `shape` (in a deterministic, indexed order) whose end vertices lie in [lo, hi].
std::vector<TopoDS_Edge> edges_in(const TopoDS_Shape& shape, const Vec3& lo, const Vec3& hi) {
  TopTools_IndexedMapOfShape edges;
  TopExp::MapShapes(shape, TopAbs_EDGE, edges);
  std::vector<TopoDS_Edge> out;
  for (int i = 1; i <= edges.Extent(); ++i) {
    const TopoDS_Edge& e = TopoDS::Edge(edges(i));
    if (BRep_Tool::Degenerated(e)) continue;
    TopoDS_Vertex a, b;
    TopExp::Vertices(e, a, b);
    if (a.IsNull() || b.IsNull()) continue;
    if (inside(vec(BRep_Tool::Pnt(a)), lo, hi) && inside(vec(BRep_Tool::Pnt(b)), lo, hi)) out.push_back(e);
  }
  return out;
}

}  // namespace

TopoDS_Shape box(const Vec3& min, const Vec3& max) {
  BRepPrimAPI_MakeBox mk(pnt(min), pnt(max));
  return mk.Shape();
}

TopoDS_Shape rounded_box(const Vec3& min, const Vec3& max, double radius) {
  TopoDS_Shape b = box(min, max);
  if (radius <= 0.0) return b;
  return fillet_edges_in(b, min, max, radius);
}

TopoDS_Shape chamfered_box(const Vec3& min, const Vec3& max, double distance) {
  return chamfer_edges_in(box(min, max), min, max, distance);
}

TopoDS_Shape cylinder(const Vec3& base, const Vec3& direction, double radius, double height) {
  BRepPrimAPI_MakeCylinder mk(gp_Ax2(pnt(base), dir(direction)), radius, height);
  return mk.Shape();
}

TopoDS_Shape sphere(const Vec3& centre, double radius) {
  BRepPrimAPI_MakeSphere mk(pnt(centre), radius);
  return mk.Shape();
}

TopoDS_Shape tube(const Vec3& a, const Vec3& b, double outer_radius, double inner_radius) {
  const Vec3 d = b - a;
  require(d.norm() > 0.0, "tube of zero length");
  if (inner_radius <= 0.0) return cylinder(a, d, outer_radius, d.norm());
  const TopoDS_Face f = ring_face(a, d, outer_radius, inner_radius);
  BRepPrimAPI_MakePrism mk(f, gp_Vec(d.x(), d.y(), d.z()));
  require(mk.IsDone(), "tube prism");
  return mk.Shape();
}

TopoDS_Shape bent_tube(const std::vector<Vec3>& points, double bend_radius, double outer_radius,
                       double inner_radius, bool closed) {
  const std::size_t n = points.size();
  require(n >= 2, "bent tube needs two points");
  // For every corner (interior, or all of them for a loop), the arc replacing it.
  struct Bend {
    Vec3 a, mid, b;
    bool present = false;
  };
  std::vector<Bend> bends(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (!closed && (i == 0 || i + 1 == n)) continue;
    const Vec3& prev = points[(i + n - 1) % n];
    const Vec3& next = points[(i + 1) % n];
    const Vec3 u = (points[i] - prev).normalized();
    const Vec3 v = (next - points[i]).normalized();
    const double c = std::clamp(u.dot(v), -1.0, 1.0);
    const double turn = std::acos(c);
    if (turn < 1e-9) continue;  // collinear: no bend
    const double t = bend_radius * std::tan(0.5 * turn);
    const Vec3 w = (v - u).normalized();
    const Vec3 centre = points[i] + w * (bend_radius / std::cos(0.5 * turn));
    bends[i] = {points[i] - u * t, centre - w * bend_radius, points[i] + v * t, true};
  }
  BRepBuilderAPI_MakeWire wire;
  const std::size_t segments = closed ? n : n - 1;
  for (std::size_t s = 0; s < segments; ++s) {
    const std::size_t i = s, j = (s + 1) % n;
    const Vec3 from = bends[i].present ? bends[i].b : points[i];
    const Vec3 to = bends[j].present ? bends[j].a : points[j];
    if ((to - from).norm() > 1e-9) wire.Add(BRepBuilderAPI_MakeEdge(pnt(from), pnt(to)).Edge());
    if (bends[j].present && (closed || j + 1 < n)) {
      Handle(Geom_TrimmedCurve) arc = GC_MakeArcOfCircle(pnt(bends[j].a), pnt(bends[j].mid), pnt(bends[j].b)).Value();
      wire.Add(BRepBuilderAPI_MakeEdge(arc).Edge());
    }
  }
  require(wire.IsDone(), "bent tube spine");
  // The profile sits at the start of the spine, perpendicular to it.
  const Vec3 start = bends[0].present ? bends[0].b : points[0];
  const Vec3 first_dir = (points[1 % n] - points[0]).normalized();
  const TopoDS_Face profile = ring_face(start, first_dir, outer_radius, inner_radius);
  BRepOffsetAPI_MakePipe pipe(wire.Wire(), profile);
  pipe.Build();
  require(pipe.IsDone(), "bent tube pipe");
  return pipe.Shape();
}

TopoDS_Shape revolved(const std::vector<Vec3>& profile, const Vec3& base) {
  BRepBuilderAPI_MakePolygon poly;
  for (const Vec3& p : profile) poly.Add(pnt(base + p));
  poly.Close();
  BRepBuilderAPI_MakeFace face(poly.Wire(), Standard_True);
  require(face.IsDone(), "revolved profile face");
  BRepPrimAPI_MakeRevol mk(face.Face(), gp_Ax1(pnt(base), gp_Dir(0, 0, 1)));
  require(mk.IsDone(), "revolution");
  return mk.Shape();
}

TopoDS_Shape fuse(const std::vector<TopoDS_Shape>& shapes) {
  require(!shapes.empty(), "fuse of nothing");
  if (shapes.size() == 1) return shapes[0];
  TopTools_ListOfShape args, tools;
  args.Append(shapes[0]);
  for (std::size_t i = 1; i < shapes.size(); ++i) tools.Append(shapes[i]);
  BRepAlgoAPI_Fuse op;
  op.SetRunParallel(Standard_False);
  op.SetArguments(args);
  op.SetTools(tools);
  op.Build();
  require(op.IsDone() && !op.HasErrors(), "fuse");
  return op.Shape();
}

TopoDS_Shape cut(const TopoDS_Shape& base, const std::vector<TopoDS_Shape>& tools) {
  if (tools.empty()) return base;
  TopTools_ListOfShape args, tl;
  args.Append(base);
  for (const TopoDS_Shape& t : tools) tl.Append(t);
  BRepAlgoAPI_Cut op;
  op.SetRunParallel(Standard_False);
  op.SetArguments(args);
  op.SetTools(tl);
  op.Build();
  require(op.IsDone() && !op.HasErrors(), "cut");
  return op.Shape();
}

TopoDS_Shape fillet_edges_in(const TopoDS_Shape& shape, const Vec3& lo, const Vec3& hi, double radius) {
  const double eps = 1e-6;
  const std::vector<TopoDS_Edge> edges = edges_in(shape, lo - Vec3::Constant(eps), hi + Vec3::Constant(eps));
  if (edges.empty()) return shape;
  BRepFilletAPI_MakeFillet mk(shape);
  for (const TopoDS_Edge& e : edges) mk.Add(radius, e);
  mk.Build();
  require(mk.IsDone(), "fillet");
  return mk.Shape();
}

TopoDS_Shape chamfer_edges_in(const TopoDS_Shape& shape, const Vec3& lo, const Vec3& hi, double distance) {
  const double eps = 1e-6;
  const std::vector<TopoDS_Edge> edges = edges_in(shape, lo - Vec3::Constant(eps), hi + Vec3::Constant(eps));
  if (edges.empty()) return shape;
  BRepFilletAPI_MakeChamfer mk(shape);
  for (const TopoDS_Edge& e : edges) mk.Add(distance, e);
  mk.Build();
  require(mk.IsDone(), "chamfer");
  return mk.Shape();
}

TopoDS_Shape placed(const TopoDS_Shape& shape, const Pose& pose) {
  gp_Trsf t;
  const Mat3& r = pose.rotation;
  const Vec3& x = pose.translation;
  t.SetValues(r(0, 0), r(0, 1), r(0, 2), x.x(), r(1, 0), r(1, 1), r(1, 2), x.y(), r(2, 0), r(2, 1), r(2, 2), x.z());
  return BRepBuilderAPI_Transform(shape, t, Standard_True).Shape();
}

TopoDS_Shape compound(const std::vector<TopoDS_Shape>& shapes) {
  BRep_Builder b;
  TopoDS_Compound c;
  b.MakeCompound(c);
  for (const TopoDS_Shape& s : shapes) b.Add(c, s);
  return c;
}

std::size_t mesh(const TopoDS_Shape& shape, double linear_deflection, double angular_deflection) {
  BRepTools::Clean(shape);
  BRepMesh_IncrementalMesh mesher(shape, linear_deflection, Standard_False, angular_deflection, Standard_False);
  require(mesher.IsDone(), "BRepMesh");
  std::size_t count = 0;
  for (TopExp_Explorer ex(shape, TopAbs_FACE); ex.More(); ex.Next()) {
    TopLoc_Location loc;
    const Handle(Poly_Triangulation) tri = BRep_Tool::Triangulation(TopoDS::Face(ex.Current()), loc);
    if (!tri.IsNull()) count += static_cast<std::size_t>(tri->NbTriangles());
  }
  return count;
}

TriangleSoup triangles_of(const TopoDS_Shape& shape, const std::string& name) {
  TriangleSoup soup;
  soup.name = name;
  for (TopExp_Explorer ex(shape, TopAbs_FACE); ex.More(); ex.Next()) {
    const TopoDS_Face& face = TopoDS::Face(ex.Current());
    TopLoc_Location loc;
    const Handle(Poly_Triangulation) tri = BRep_Tool::Triangulation(face, loc);
    if (tri.IsNull()) continue;
    const gp_Trsf trsf = loc.Transformation();
    const bool reversed = face.Orientation() == TopAbs_REVERSED;
    for (int i = 1; i <= tri->NbTriangles(); ++i) {
      int a = 0, b = 0, c = 0;
      tri->Triangle(i).Get(a, b, c);
      if (reversed) std::swap(b, c);
      Triangle t;
      t.p = vec(tri->Node(a).Transformed(trsf));
      t.q = vec(tri->Node(b).Transformed(trsf));
      t.r = vec(tri->Node(c).Transformed(trsf));
      soup.triangles.push_back(t);
    }
  }
  return soup;
}

}  // namespace swept::scenes::detail
