#pragma once
/// The three fitters of SPEC §2.1 and the RSS fit of SPEC §2.3, exposed for tests and tools.
#include "swept/bvh/bvh.h"

namespace swept {

/// A fitter's output for a set of triangles: the split position and three orthonormal
/// candidate axes, columns of `axes`, sorted by decreasing eigenvalue; right-handed.
struct Fit {
  Vec3 split_point = Vec3::Zero();
  Mat3 axes = Mat3::Identity();
  Vec3 eigenvalues = Vec3::Zero();  ///< λ1 ≥ λ2 ≥ λ3 of the fitter's matrix
  bool fell_back = false;           ///< degenerate input: PQP_FIT was used instead
};

/// Degeneracy threshold for areas, scale-aware: ε = 1e-12 · L², where L is the length of the
/// diagonal of the triangles' bounding box. Triangles with area < ε count as zero-area; a set
/// whose total area is < ε falls back to PQP_FIT (SPEC §2.1).
double degeneracy_epsilon(std::span<const Triangle> triangles);

/// Runs one fitter on a set of triangles (SPEC §2.1). Never fails: an empty set gives the
/// identity axes at the origin; zero-area sets fall back to PQP_FIT (`fell_back` is set).
Fit fit(std::span<const Triangle> triangles, Fitter fitter);

/// A tight RSS with frame `axes` (e1 long side, e2 short side, e3 normal) that contains
/// every vertex of every triangle (SPEC §2.3): the smallest radius for that frame, and a
/// rectangle no larger than the vertices' bounding box there; rounded corners are handled
/// greedily, so the rectangle is not always the smallest (docs/fitters.md). `axes` must be
/// orthonormal.
Rss fit_rss(std::span<const Triangle> triangles, const Mat3& axes);

}  // namespace swept
