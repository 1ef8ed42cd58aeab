#pragma once
// Test assemblies built from tessellated prisms and rings (a shaft is an n-gon prism, a bore the
// inside of a ring of m segments: two tessellations of one circle, which cross by up to their
// sag), and an independent sampled check of straight pulls with the oracle's triangle distance.
#include "oracle/path_oracle.h"
#include "swept/assembly/disassemble.h"
#include "swept/contact/mate_rule.h"
#include "swept/geometry/distance.h"
#include "swept/scenes/box_problems.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>
#include <tuple>
#include <numbers>
#include <string>
#include <vector>

namespace swept::test {

inline Vec3 on_circle(double radius, int k, int n, double z) {
  const double a = 2.0 * std::numbers::pi * (k % n) / n;  // the same point for k and k + n
  return {radius * std::cos(a), radius * std::sin(a), z};
}

/// A closed n-gon prism about the z axis (vertices on the circle of `radius`), z ∈ [z0, z1],
/// outward normals (counter-clockwise seen from outside).
inline void add_prism(std::vector<Triangle>& out, double radius, int n, double z0, double z1) {
  const Vec3 bottom(0, 0, z0), top(0, 0, z1);
  for (int k = 0; k < n; ++k) {
    const Vec3 a0 = on_circle(radius, k, n, z0), b0 = on_circle(radius, k + 1, n, z0);
    const Vec3 a1 = on_circle(radius, k, n, z1), b1 = on_circle(radius, k + 1, n, z1);
    out.push_back({a0, b0, b1});
    out.push_back({a0, b1, a1});
    out.push_back({top, a1, b1});
    out.push_back({bottom, b0, a0});
  }
}

/// A closed ring about the z axis: inner radius r (the bore, normals toward the axis), outer R,
/// n segments both, z ∈ [z0, z1].
inline void add_ring(std::vector<Triangle>& out, double r, double R, int n, double z0, double z1) {
  for (int k = 0; k < n; ++k) {
    const Vec3 i0 = on_circle(r, k, n, z0), j0 = on_circle(r, k + 1, n, z0);
    const Vec3 i1 = on_circle(r, k, n, z1), j1 = on_circle(r, k + 1, n, z1);
    const Vec3 o0 = on_circle(R, k, n, z0), p0 = on_circle(R, k + 1, n, z0);
    const Vec3 o1 = on_circle(R, k, n, z1), p1 = on_circle(R, k + 1, n, z1);
    out.push_back({o0, p0, p1});  // outer wall
    out.push_back({o0, p1, o1});
    out.push_back({i0, j1, j0});  // bore, facing the axis
    out.push_back({i0, i1, j1});
    out.push_back({i1, o1, p1});  // top
    out.push_back({i1, p1, j1});
    out.push_back({i0, p0, o0});  // bottom
    out.push_back({i0, j0, p0});
  }
}

inline AssemblyPart part(std::string name, std::vector<Triangle> triangles, bool fixed = false) {
  AssemblyPart p;
  p.name = name;
  p.source = "test";
  p.mesh.name = std::move(name);
  p.mesh.triangles = std::move(triangles);
  p.fixed = fixed;
  return p;
}

/// A base plate, a ring (r 3, R 10, 16 segments) standing on it, and a bolt through the ring:
/// a 24-gon shaft of the bore's radius on the base, with a head (radius 5) resting on the ring's
/// top. Known answer: the bolt up (+z), then the ring up; the base stays (it is the largest).
/// The same parts as meshes only: their triangles without the CAD's cylinders (contact.h, case 4).
inline Assembly without_cylinders(Assembly a) {
  for (AssemblyPart& p : a.parts) p.mesh.cylinder_of.clear(), p.mesh.cylinders.clear();
  return a;
}

inline Assembly bolted_ring() {
  Assembly a;
  a.source = "bolted_ring";
  std::vector<Triangle> base, ring, bolt;
  scenes::add_box(base, Vec3(-20, -20, -5), Vec3(20, 20, 0));
  add_ring(ring, 3, 10, 16, 0, 10);
  add_prism(bolt, 3, 24, 0, 10);
  add_prism(bolt, 5, 24, 10, 12);
  a.parts = {part("base", base), part("ring", ring), part("bolt", bolt)};
  return a;
}

/// A rivet through two plates: plate A (ring r 3, R 15, z ∈ [-5, 0]), plate B (ring r 3, R 10,
/// z ∈ [0, 10]), the rivet's shank in both bores, a head under A and a head on B. Nothing comes
/// out, alone or in a group: B is held by the rivet's head and A, the rivet by both plates.
inline Assembly riveted_plates() {
  Assembly a;
  a.source = "riveted_plates";
  std::vector<Triangle> plate_a, plate_b, rivet;
  add_ring(plate_a, 3, 15, 16, -5, 0);
  add_ring(plate_b, 3, 10, 16, 0, 10);
  add_prism(rivet, 3, 24, -5, 10);
  add_prism(rivet, 5, 24, 10, 12);
  add_prism(rivet, 5, 24, -7, -5);
  a.parts = {part("plate_a", plate_a), part("plate_b", plate_b), part("rivet", rivet)};
  return a;
}

/// Which edges of each triangle are convex creases of its part, found here on its own: an edge
/// (exact end points) used by exactly one other triangle, whose plane has this triangle's third
/// vertex behind it.
inline std::vector<std::array<bool, 3>> creases_of(const std::vector<Triangle>& tris) {
  std::map<std::array<double, 6>, std::vector<std::pair<std::size_t, int>>> uses;
  auto key = [](Vec3 a, Vec3 b) {
    if (std::make_tuple(b.x(), b.y(), b.z()) < std::make_tuple(a.x(), a.y(), a.z())) std::swap(a, b);
    return std::array<double, 6>{a.x(), a.y(), a.z(), b.x(), b.y(), b.z()};
  };
  for (std::size_t t = 0; t < tris.size(); ++t)
    for (int i = 0; i < 3; ++i) uses[key(tris[t][i], tris[t][(i + 1) % 3])].push_back({t, i});
  std::vector<std::array<bool, 3>> out(tris.size(), {false, false, false});
  for (const auto& [k, u] : uses) {
    if (u.size() != 2) continue;  // open or non-manifold: no crease
    for (int s = 0; s < 2; ++s) {
      const Triangle& t = tris[u[s].first];
      const Triangle& o = tris[u[1 - s].first];
      const Vec3 n = (o.q - o.p).cross(o.r - o.p);
      const Vec3 nt = (t.q - t.p).cross(t.r - t.p);
      const int i = u[s].second;
      const double edge = (t[(i + 1) % 3] - t[i]).norm();
      out[u[s].first][i] = n.norm() > 0 && nt.norm() > 0 && n.normalized().dot(t[(i + 2) % 3] - o.p) < -1e-9 * edge;
    }
  }
  return out;
}

/// The independent check of a straight pull (docs/planner.md, "The contact
/// model"): at `samples` + 1 poses along it, every triangle pair of the moving parts and the parts
/// still in place, by the oracle's exact triangle distance. A pair closer than the clearance must
/// not interpenetrate by more than the tolerance: on some separating axis oriented by the solids'
/// sides (the staying triangle's normal, minus the moving one's, the outward in-plane normals of
/// their convex crease edges, crease edge × crease edge), the moving triangle is outside the
/// staying one up to the tolerance; or one of them slides along the pull and the part of the other
/// in the strip it sweeps is in front of its plane up to the tolerance; or the column the moving
/// one sweeps along the pull, shrunk by the tolerance, misses the staying one (its own arithmetic
/// here). Returns the number of (sample, pair) that are not: pairs through material.
inline int pull_violations(const Assembly& a, const std::vector<std::size_t>& moving,
                           const std::vector<std::size_t>& staying, const Vec3& direction, double length,
                           double clearance, double tolerance, int samples) {
  auto tri = [](const Triangle& t, const Vec3& shift) { return oracle::Tri{{t.p + shift, t.q + shift, t.r + shift}}; };
  // How far the part of `b` in the strip that `a` sweeps along `d` (a's extent across d, d in a's
  // plane) reaches behind a's plane: b's polygon cut to the strip, its lowest point along a's normal.
  auto strip_depth = [&direction](const oracle::Tri& a, const oracle::Tri& b) -> double {
    const Eigen::Vector3d n = (a.v[1] - a.v[0]).cross(a.v[2] - a.v[0]);
    if (!(n.norm() > 0)) return INFINITY;
    const Eigen::Vector3d nu = n.normalized();
    if (std::abs(nu.dot(direction)) > 0.05) return INFINITY;  // a does not slide
    const Eigen::Vector3d u = nu.cross(direction).normalized();
    double lo = INFINITY, hi = -INFINITY;
    for (const auto& v : a.v) lo = std::min(lo, u.dot(v)), hi = std::max(hi, u.dot(v));
    std::vector<Eigen::Vector3d> poly(b.v, b.v + 3);
    for (int side = 0; side < 2; ++side) {  // keep u·x ≥ lo, then u·x ≤ hi
      std::vector<Eigen::Vector3d> next;
      auto f = [&](const Eigen::Vector3d& x) { return side == 0 ? u.dot(x) - lo : hi - u.dot(x); };
      for (std::size_t i = 0; i < poly.size(); ++i) {
        const Eigen::Vector3d& p = poly[i];
        const Eigen::Vector3d& q = poly[(i + 1) % poly.size()];
        if (f(p) >= 0) next.push_back(p);
        if ((f(p) < 0) != (f(q) < 0)) next.push_back(p + (f(p) / (f(p) - f(q))) * (q - p));
      }
      poly = next;
    }
    if (poly.empty()) return -INFINITY;
    double lowest = INFINITY;
    for (const auto& x : poly) lowest = std::min(lowest, nu.dot(x - a.v[0]));
    return -lowest;
  };
  // Does the column the moving triangle `a` sweeps along the pull (shrunk by the tolerance) miss
  // `b`? Cut b by the column's three side planes, each moved inward by the tolerance.
  auto column_misses = [&direction, tolerance](const oracle::Tri& a, const oracle::Tri& b) -> bool {
    const Eigen::Vector3d n = (a.v[1] - a.v[0]).cross(a.v[2] - a.v[0]);
    if (!(n.norm() > 0) || std::abs(n.normalized().dot(direction)) < 0.05) return false;
    std::vector<Eigen::Vector3d> poly(b.v, b.v + 3);
    for (int i = 0; i < 3 && !poly.empty(); ++i) {
      Eigen::Vector3d m = direction.cross(a.v[(i + 1) % 3] - a.v[i]).normalized();
      if (m.dot(a.v[(i + 2) % 3] - a.v[i]) < 0) m = -m;
      const double c = m.dot(a.v[i]) + tolerance;
      std::vector<Eigen::Vector3d> next;
      for (std::size_t k = 0; k < poly.size(); ++k) {
        const Eigen::Vector3d& p = poly[k];
        const Eigen::Vector3d& q = poly[(k + 1) % poly.size()];
        const double fp = m.dot(p) - c, fq = m.dot(q) - c;
        if (fp >= 0) next.push_back(p);
        if ((fp < 0) != (fq < 0)) next.push_back(p + (fp / (fp - fq)) * (q - p));
      }
      poly = next;
    }
    return poly.empty();
  };
  auto penetration = [&strip_depth, &column_misses](const oracle::Tri& x, const std::array<bool, 3>& cx, const oracle::Tri& y,
                                    const std::array<bool, 3>& cy) -> double {
    auto unit = [](const Eigen::Vector3d& v) { return v.norm() > 1e-300 ? Eigen::Vector3d(v.normalized()) : Eigen::Vector3d::Zero(); };
    const Eigen::Vector3d nx = unit((x.v[1] - x.v[0]).cross(x.v[2] - x.v[0]));
    const Eigen::Vector3d ny = unit((y.v[1] - y.v[0]).cross(y.v[2] - y.v[0]));
    std::vector<Eigen::Vector3d> axes{nx, -ny};
    for (int i = 0; i < 3; ++i) {
      if (cx[i]) axes.push_back(unit((x.v[(i + 1) % 3] - x.v[i]).cross(nx)));
      if (cy[i]) axes.push_back(-unit((y.v[(i + 1) % 3] - y.v[i]).cross(ny)));
    }
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        if (!cx[i] || !cy[j]) continue;
        const Eigen::Vector3d ea = x.v[(i + 1) % 3] - x.v[i], eb = y.v[(j + 1) % 3] - y.v[j];
        const Eigen::Vector3d c = ea.cross(eb);
        if (!(c.norm() > 1e-9 * ea.norm() * eb.norm())) continue;
        const Eigen::Vector3d u = c.normalized();
        const double side = u.dot(nx - ny);
        if (side >= -1e-12) axes.push_back(u);
        if (side <= 1e-12) axes.push_back(-u);
      }
    double best = INFINITY;
    for (const Eigen::Vector3d& u : axes) {
      if (u.isZero()) continue;
      double xh = -INFINITY, yl = INFINITY;
      for (int i = 0; i < 3; ++i) xh = std::max(xh, u.dot(x.v[i])), yl = std::min(yl, u.dot(y.v[i]));
      best = std::min(best, xh - yl);
    }
    // A triangle the pull slides along: only the strip it sweeps counts; a moving triangle whose
    // column misses the other does not reach into it.
    if (column_misses(y, x)) return -INFINITY;
    return std::min({best, strip_depth(x, y), strip_depth(y, x)});
  };
  std::vector<std::vector<std::array<bool, 3>>> creases(a.parts.size());
  for (std::size_t i : moving) creases[i] = creases_of(a.parts[i].mesh.triangles);
  for (std::size_t i : staying) creases[i] = creases_of(a.parts[i].mesh.triangles);
  // Boxes of the triangles, to skip pairs that are plainly apart.
  auto box = [](const Triangle& t) {
    Aabb b;
    for (int v = 0; v < 3; ++v) b.extend(t[v]);
    return b;
  };
  auto apart = [clearance](const Aabb& x, const Aabb& y, const Vec3& shift) {
    return ((y.min + shift).array() > x.max.array() + clearance).any() ||
           (x.min.array() > (y.max + shift).array() + clearance).any();
  };
  int bad = 0;
  for (int k = 0; k <= samples; ++k) {
    const Vec3 shift = (length * k / samples) * direction;
    for (std::size_t m : moving)
      for (std::size_t jp = 0; jp < a.parts[m].mesh.triangles.size(); ++jp) {
        const Triangle& tp = a.parts[m].mesh.triangles[jp];
        const oracle::Tri p = tri(tp, shift);
        const Aabb bp = box(tp);
        for (std::size_t s : staying)
          for (std::size_t jo = 0; jo < a.parts[s].mesh.triangles.size(); ++jo) {
            const Triangle& to = a.parts[s].mesh.triangles[jo];
            if (apart(box(to), bp, shift)) continue;
            const oracle::Tri o = tri(to, Vec3::Zero());
            if (oracle::triangle_distance(o, p) >= clearance) continue;
            if (penetration(o, creases[s][jo], p, creases[m][jp]) <= tolerance * (1 + 1e-9)) continue;
            ++bad;
          }
      }
  }
  return bad;
}

/// The shared as1 STEP read as an assembly, or nothing with why not (no shared data, not found,
/// or "does not read: ..." when it is there but fails).
inline std::optional<Assembly> read_as1(std::string& why) {
  const auto data = shared_data();
  if (!data) return why = "../shared/data is absent: as1 not taken apart", std::nullopt;
  const auto file = *data / "as1" / "as1-oc-214.stp";
  if (!std::filesystem::exists(file)) return why = file.string() + " not found", std::nullopt;
  auto a = read_assembly(file);
  if (!a) return why = "as1 does not read: " + a.error().message, std::nullopt;
  return std::move(*a);
}

}  // namespace swept::test
