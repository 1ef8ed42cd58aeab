#pragma once
// Internal building blocks of the fitters and the builder. Everything here works in a local
// frame (the model's bounding-box centre at the origin) so that a model far from the origin is
// fitted exactly like the same model near it.
#include "swept/bvh/fitter.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace swept::detail {

/// A triangle in the local frame with its area, computed once per build. The fitters derive
/// everything else on the fly: the centroid m and the vertices' scatter about it
/// S = Σ_v (v − m)(v − m)ᵀ (so that any fitter's matrix is a sum of 3(m − c)(m − c)ᵀ and S
/// terms: exact algebra, no cancellation). 80 bytes, read by both the fit and the projection.
struct TriInfo {
  Triangle t;
  double area;

  Vec3 centroid() const { return (t.p + t.q + t.r) / 3.0; }
};

TriInfo make_tri_info(const Triangle& local);

/// Passes over a node's triangles read `info` through the node's ids: increasing, but with gaps
/// the hardware prefetcher does not follow on large nodes, so they ask for a record this many
/// triangles ahead.
inline constexpr std::size_t kPrefetchAhead = 16;
inline void prefetch(const TriInfo* record) {
#if defined(__GNUC__)
  __builtin_prefetch(record);
  __builtin_prefetch(reinterpret_cast<const char*>(record) + sizeof(TriInfo) - 1);
#else
  (void)record;
#endif
}

/// ε = 1e-12 · L² for a box diagonal L (SPEC §2.1: scale-aware degeneracy threshold).
inline double epsilon_for_extent(double extent) { return 1e-12 * extent * extent; }

/// Fitter over the triangles `ids` (indices into `info`).
Fit fit_ids(const TriInfo* info, const std::uint32_t* ids, std::size_t n, Fitter fitter);

/// A triangle's centroid m and its vertex scatter about it, S = Σ_v (v − m)(v − m)ᵀ, as the six
/// unique entries xx, xy, xz, yy, yz, zz: what every fitter's second pass adds per triangle.
struct TriMoments {
  Vec3 m;
  double scatter[6];
};
TriMoments tri_moments(const TriInfo& t);

/// `fit_ids` in its pieces, for callers that fit several subsets in the same passes over their
/// union (min-sa's candidate children): first() every triangle of the subset, in order, then
/// middle(), then second() every triangle again in the same order, then finish(). The same
/// arithmetic in the same order as `fit_ids`, so the same Fit to the last bit (fit_ids is
/// written with it).
class FitAccumulator {
 public:
  void first(const TriInfo& t);
  void middle(Fitter fitter);
  void second(const TriInfo& t, const TriMoments& mo);
  Fit finish();

 private:
  std::size_t n_ = 0;
  Vec3 sum_m_ = Vec3::Zero();
  double sum_a_ = 0.0;
  Vec3 sum_am_ = Vec3::Zero();
  double max_a_ = 0.0;
  Vec3 lo_ = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 hi_ = Vec3::Constant(-std::numeric_limits<double>::infinity());
  FitterRecipe used_{};
  bool fell_back_ = false;
  double eps_ = 0.0, scale_ = 1.0;
  Vec3 c_ = Vec3::Zero();
  double acc_[6] = {0, 0, 0, 0, 0, 0};
  double a_min_ = std::numeric_limits<double>::infinity();
};

/// An RSS in its own frame: rectangle [xlo, xhi] × [ylo, yhi] at height zc, radius r.
struct RectExtents {
  double xlo = 0, xhi = 0, ylo = 0, yhi = 0, zc = 0, r = 0;
};

/// The RSS extents of a point set in three steps, for callers that fuse them with other passes:
/// construct from the set's bounding box; add() every point (the tightest edges ignoring the
/// rounded corners; true when the point lies outside the starting rectangle and so may sit at a
/// corner); finish() with the points add() returned true for (or all points), in order.
struct RssEdges {
  double r, zc, r2, xlo, xhi, ylo, yhi;

  RssEdges(const Vec3& lo, const Vec3& hi);

  /// A point may stick out of an edge by at most its in-plane radius ρ = √(r² − dz²).
  bool add(const Vec3& p) {
    if (p.x() >= xlo && p.x() <= xhi && p.y() >= ylo && p.y() <= yhi) return false;
    const double dz = p.z() - zc;
    const double rho = std::sqrt(std::max(r2 - dz * dz, 0.0));
    xlo = std::min(xlo, p.x() + rho);
    xhi = std::max(xhi, p.x() - rho);
    ylo = std::min(ylo, p.y() + rho);
    yhi = std::max(yhi, p.y() - rho);
    return true;
  }

  /// Corners. `outside`: indices into `pts` of the points add() returned true for, or null for
  /// all `count` points.
  RectExtents finish(const Vec3* pts, const std::uint32_t* outside, std::size_t count);
};

/// The smallest RSS (in the frame the points are given in) containing the points (SPEC §2.3).
/// `lo`/`hi`: the points' bounding box when the caller has it (saves a pass), else null.
RectExtents rss_extents(const Vec3* points, std::size_t count, const Vec3* lo = nullptr, const Vec3* hi = nullptr);

/// The RSS of extents given in the frame `axes` with origin `origin`.
Rss make_rss(const RectExtents& e, const Mat3& axes, const Vec3& origin);

/// Projects the vertices of triangles `ids` onto `axes`, relative to `origin`: 3 per triangle;
/// also their bounding box in that frame when `lo`/`hi` are given.
void project_vertices(const TriInfo* info, const std::uint32_t* ids, std::size_t n, const Mat3& axes,
                      const Vec3& origin, std::vector<Vec3>& out, Vec3* lo = nullptr, Vec3* hi = nullptr);

/// The axes every fitter gives a single non-degenerate triangle (closed form, no eigen solve).
/// False for a degenerate triangle.
bool single_triangle_axes(const Triangle& t, Mat3& axes);

/// Eigenvectors of a symmetric 3×3 matrix as columns, sorted by decreasing eigenvalue,
/// right-handed (third = first × second).
void sorted_eigen(const Mat3& m, Mat3& axes, Vec3& values);

}  // namespace swept::detail
