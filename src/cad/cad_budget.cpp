// The triangle budget of a CAD tessellation (cad_budget.h).
#include "cad_budget.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRep_Tool.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace swept::io_detail {
namespace {

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

}  // namespace

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

}  // namespace swept::io_detail
