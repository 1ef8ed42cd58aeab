#pragma once
/// The mate rule of the contact model (docs/planner.md, "The contact model"): which triangle
/// pairs may stay within the clearance along a straight pull from a pose in contact.
///
/// Parts touch where they mate: planar faces face to face, a shaft in a bore of the same radius,
/// tessellations of two mating surfaces that overlap by up to the meshing deflection. The model
/// decides pair of triangles by pair of triangles, from the triangles (CAD triangles carry their
/// B-rep face's orientation, outward) and, for CAD parts, the cylinders they lie on (case 4;
/// src/assembly/cylinders.cpp). A mesh-only input gets cases 1–3: what its triangles support.
/// A pair (o, p) of a fixed triangle o and a triangle p of the moving part is a *mate* for a
/// straight pull of length L along the unit direction d when one of these holds:
///
/// 1. **Separated, and the pull does not close the gap.** A separating axis m of the two
///    triangles, oriented by the solids' sides, has p outside o up to the mating tolerance τ at
///    the mounted pose, and  min_v∈p m·v − max_v∈o m·v + L·min(0, m·d) ≥ −τ. The axes (the
///    separating axes of two triangles, Gottschalk, Lin & Manocha 1996, restricted to the
///    solids' real features): o's outward normal; minus p's; the outward in-plane normal of each
///    *convex crease* edge of o and minus that of p's (an edge whose neighbour in the same part
///    turns away: a face's boundary, never a diagonal inside a flat face, part_planes()); the
///    cross product of a convex crease edge of each, with the sign that has m·(n_o − n_p) ≥ 0.
/// 2. **Sliding.** One triangle's plane holds the pull (|n·d| ≤ 0.05: a tessellated cylinder's
///    facets are not exactly parallel to its axis) and the part of the other inside the strip it
///    sweeps (its extent across d) is in front of that plane up to τ, counting how far the plane
///    advances over the pull (L·max(0, n·d)).
/// 3. **Missing.** The column p sweeps along d (|n_p·d| ≥ 0.05), shrunk by τ on every side, does
///    not meet o: the end of a shaft coming out of its bore past the rim of the face round it.
/// 4. **A shaft in its bore, by the CAD's cylinders** (parts read from STEP, IGES or BREP, whose
///    triangles know their cylindrical B-rep face — analytic, or a B-spline the reader fits a
///    cylinder to, with its deviation: TriangleSoup::cylinders). The moving part and
///    the other hold a shaft face and a bore face (which side the solid is on, from the face's
///    outward normals) with parallel axes (|a × b| ≤ 1e-6; how far the angle moves a triangle
///    off the mate's axis is measured), the shaft's axis within τ of the bore's and its radius at
///    most the bore's + τ; the pull runs along the bore's axis (drift L·|d × a| ≤ τ).
///    A translation along the axis keeps every point's distance ρ from it, so the pair is a mate
///    when the inner triangle's largest ρ (at a vertex) exceeds the outer triangle's smallest by
///    at most τ − drift, where a triangle on a bore coaxial with the mate counts at its surface
///    (the bore's radius less its deviation, not the facet's middle, which lies inside the circle
///    by the sag), and a triangle at such a bore's rim (an edge of it is a boundary edge of the
///    bore's triangles, and it comes nearest the axis on such an edge) at the smaller of the
///    radius and its other edges' distance: what lies nearer is the rim's sag between that chord
///    and the cylinder.
///
/// So no mate reaches more than τ into the other along the whole pull (case 4: by the CAD's
/// surfaces, where the facets of two tessellations of one circle cross by their sag). A mate slides along its
/// plane (a nut along its bolt, a shaft along its bore, whose tessellations of one circle cross
/// by less than their sag) or separates from it (a cover lifted off its housing); it never
/// presses (m·d < 0 over more than τ). Contact normals thus bound the directions a part can
/// move in (local freedom, Wilson & Latombe 1994): a planar mate forbids d·n < 0, facets all
/// round an axis leave only the axis. Every other pair keeps the clearance along the whole
/// motion.
#include "swept/geometry/types.h"

#include <cstdint>
#include <string>
#include <vector>

namespace swept {

/// A triangle's plane: outward unit normal (vertex order; zero for a degenerate triangle) and
/// offset n·p, and which of its edges are convex creases of its part (bit i: the edge from
/// vertex i to vertex i + 1).
struct TrianglePlane {
  Vec3 normal = Vec3::Zero();
  double offset = 0.0;
  std::uint8_t creases = 0;
  /// A triangle of an open surface (a sheet: its connected part has an edge of one triangle),
  /// which has no inside: the rule takes its normal with either sign.
  bool two_sided = false;
};
/// The plane of one triangle, without crease edges (they need the part: part_planes()).
TrianglePlane plane_of(const Triangle& t);

/// The planes of a part's triangles with their convex crease edges: an edge (matched by exact
/// vertex coordinates) shared with exactly one other triangle whose plane has this triangle's
/// third vertex behind it by more than 1e-9 of the edge's length (a convex dihedral). Edges
/// between coplanar triangles, concave edges, and open or non-manifold edges (vertices that do not
/// match exactly) are not creases: fewer axes, fewer mates, the conservative side. A triangle whose
/// connected part (through edges shared by exactly two triangles, or more) has an edge of one
/// triangle is `two_sided`. Deterministic.
std::vector<TrianglePlane> part_planes(const std::vector<Triangle>& triangles);

/// How far `b` reaches behind the plane of `a` (−(min over b's vertices of n_a·v − offset_a)):
/// ≤ 0 when the plane separates them, +∞ for a degenerate `a`.
double depth_behind(const TrianglePlane& a, const Triangle& b);

/// The mate rule above for one pair at the mounted pose (`o` fixed, `p` of the moving part,
/// both world frame; `po`, `pp` their plane_of()) and a pull of `length` along the unit `direction`.
bool mate_allows(const Triangle& o, const TrianglePlane& po, const Triangle& p, const TrianglePlane& pp,
                 const Vec3& direction, double length, double tolerance);

/// How deep `b` reaches into `a`: the smallest overlap of their projections on the oriented
/// separating axes above (a as o, b as p); ≤ 0 when they are apart.
double pair_overlap(const Triangle& a, const TrianglePlane& pa, const Triangle& b, const TrianglePlane& pb);


}  // namespace swept
