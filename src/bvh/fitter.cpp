// The three fitters of the paper (SPEC §2.1) and the RSS fit (SPEC §2.3).
//
// Every fitter's matrix is written as a sum over triangles of  k·(m_i − c)(m_i − c)ᵀ + S_i
// (m_i the centroid, S_i the triangle's own vertex scatter, c the split position): this is
// algebraically the paper's formula and needs no subtraction of large nearly-equal numbers.
//   PQP_FIT     C  = 1/(3n) Σ [3(m_i − µ)(m_i − µ)ᵀ + S_i]                       (eq. 1–2)
//   RAPID2_FIT  C' = Σ A_i (m_i − m_H)(m_i − m_H)ᵀ + Σ (A_i/12) S_i               (eq. 5–9)
//   INERTIA_FIT I  = 1/(3n) Σ (A_i/A_min) [3(m_i − CM)(m_i − CM)ᵀ + S_i]          (eq. 10)
#include "fit_internal.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace swept::detail {

TriInfo make_tri_info(const Triangle& t) { return TriInfo{t, 0.5 * (t.p - t.q).cross(t.p - t.r).norm()}; }

void sorted_eigen(const Mat3& m, Mat3& axes, Vec3& values) {
  // Eigen's closed-form 3×3 solver (with its own refinement of nearly repeated roots): several
  // times faster than the iterative one, and within 1e-9 of it on the fitters' tests.
  Eigen::SelfAdjointEigenSolver<Mat3> solver;
  solver.computeDirect(m, Eigen::ComputeEigenvectors);
  const Vec3 ev = solver.eigenvalues();  // ascending
  const Mat3 vec = solver.eigenvectors();
  values = Vec3(ev[2], ev[1], ev[0]);
  Vec3 e1 = vec.col(2), e2 = vec.col(1);
  if (!(e1.allFinite() && e2.allFinite()) || solver.info() != Eigen::Success) {
    axes = Mat3::Identity();
    values = Vec3::Zero();
    return;
  }
  // Deterministic sign convention: the largest component of e1 and e2 is positive.
  Eigen::Index i;
  e1.cwiseAbs().maxCoeff(&i);
  if (e1[i] < 0) e1 = -e1;
  e2 = (e2 - e2.dot(e1) * e1).normalized();
  e2.cwiseAbs().maxCoeff(&i);
  if (e2[i] < 0) e2 = -e2;
  axes.col(0) = e1;
  axes.col(1) = e2;
  axes.col(2) = e1.cross(e2).normalized();
}

bool single_triangle_axes(const Triangle& t, Mat3& axes) {
  // Every fitter's matrix for one triangle is a positive multiple of the triangle's own vertex
  // scatter S (PQP_FIT: S/3; RAPID2_FIT: A·S/12; INERTIA_FIT: S/3), so the axes are S's
  // eigenvectors: the normal, and the in-plane principal directions in closed form.
  const Vec3 e = t.q - t.p, f = t.r - t.p;
  const Vec3 normal = e.cross(f);
  const double nn = normal.norm();
  const double scale = std::max(e.squaredNorm(), f.squaredNorm());
  if (!(nn > 1e-9 * scale) || !std::isfinite(nn)) return false;  // degenerate: the general path
  const Vec3 n = normal / nn;
  const Vec3 u = e.normalized();
  const Vec3 v = n.cross(u);
  const Vec3 m = (t.p + t.q + t.r) / 3.0;
  double a = 0, b = 0, c = 0;
  for (int k = 0; k < 3; ++k) {
    const Vec3 d = t[k] - m;
    const double x = d.dot(u), y = d.dot(v);
    a += x * x, b += x * y, c += y * y;
  }
  // The major axis of [[a b] [b c]] is at θ = ½·atan2(2b, a − c); cos θ and sin θ by the
  // half-angle formulas (each from the better-conditioned side), without calling trigonometry.
  const double h = std::hypot(2.0 * b, a - c);
  double cos_t = 1.0, sin_t = 0.0;
  if (h > 0.0) {
    const double cos2 = (a - c) / h, sin2 = 2.0 * b / h;
    if (cos2 >= 0.0) {
      cos_t = std::sqrt(0.5 * (1.0 + cos2));
      sin_t = sin2 / (2.0 * cos_t);
    } else {
      sin_t = std::copysign(std::sqrt(0.5 * (1.0 - cos2)), sin2);
      cos_t = sin2 / (2.0 * sin_t);
    }
  }
  Vec3 e1 = cos_t * u + sin_t * v;
  Eigen::Index i;
  e1.cwiseAbs().maxCoeff(&i);
  if (e1[i] < 0) e1 = -e1;
  Vec3 e2 = n.cross(e1);
  e2.cwiseAbs().maxCoeff(&i);
  if (e2[i] < 0) e2 = -e2;
  axes.col(0) = e1;
  axes.col(1) = e2;
  axes.col(2) = e1.cross(e2).normalized();
  return true;
}

TriMoments tri_moments(const TriInfo& t) {
  TriMoments out;
  out.m = t.centroid();
  const Vec3 a = t.t.p - out.m, b = t.t.q - out.m, e = t.t.r - out.m;  // S from the vertices about m
  out.scatter[0] = a.x() * a.x() + b.x() * b.x() + e.x() * e.x();
  out.scatter[1] = a.x() * a.y() + b.x() * b.y() + e.x() * e.y();
  out.scatter[2] = a.x() * a.z() + b.x() * b.z() + e.x() * e.z();
  out.scatter[3] = a.y() * a.y() + b.y() * b.y() + e.y() * e.y();
  out.scatter[4] = a.y() * a.z() + b.y() * b.z() + e.y() * e.z();
  out.scatter[5] = a.z() * a.z() + b.z() * b.z() + e.z() * e.z();
  return out;
}

// Pass 1: means, total area and the box (for ε).
void FitAccumulator::first(const TriInfo& t) {
  const Vec3 m = t.centroid();
  ++n_;
  sum_m_ += m;
  sum_a_ += t.area;
  sum_am_ += t.area * m;
  max_a_ = std::max(max_a_, t.area);
  lo_ = lo_.cwiseMin(t.t.p).cwiseMin(t.t.q).cwiseMin(t.t.r);
  hi_ = hi_.cwiseMax(t.t.p).cwiseMax(t.t.q).cwiseMax(t.t.r);
}

void FitAccumulator::middle(Fitter fitter) {
  eps_ = epsilon_for_extent((hi_ - lo_).norm());
  used_ = swept::info(fitter).recipe;
  if (used_.area_weighted && !(sum_a_ >= eps_ && sum_a_ > 0.0)) {
    used_ = swept::info(Fitter::pqp).recipe;
    fell_back_ = true;
  }
  c_ = used_.area_weighted ? Vec3(sum_am_ / sum_a_) : Vec3(sum_m_ / static_cast<double>(n_));
  scale_ = used_.per_vertex ? 1.0 / (3.0 * static_cast<double>(n_)) : 1.0;
}

// Pass 2: the matrix, six unique entries. INERTIA_FIT's weights A_i / A_min share the factor
// 1 / A_min, applied once at the end, so A_min is found in the same pass: the smallest area
// that is ≥ ε (smaller, degenerate triangles do not lower it).
void FitAccumulator::second(const TriInfo& t, const TriMoments& mo) {
  double w = 1.0;
  if (used_.area_weighted) {
    w = t.area;
    if (t.area >= eps_ && t.area < a_min_) a_min_ = t.area;
  }
  const Vec3 d = mo.m - c_;
  const double wc = w * used_.k_center, ws = w * used_.k_scatter;
  acc_[0] += wc * d.x() * d.x() + ws * mo.scatter[0];
  acc_[1] += wc * d.x() * d.y() + ws * mo.scatter[1];
  acc_[2] += wc * d.x() * d.z() + ws * mo.scatter[2];
  acc_[3] += wc * d.y() * d.y() + ws * mo.scatter[3];
  acc_[4] += wc * d.y() * d.z() + ws * mo.scatter[4];
  acc_[5] += wc * d.z() * d.z() + ws * mo.scatter[5];
}

Fit FitAccumulator::finish() {
  Fit out;
  if (n_ == 0) return out;
  double scale = scale_;
  if (used_.by_min_area) {
    double a_min = a_min_;
    if (!std::isfinite(a_min)) a_min = max_a_;  // every triangle below ε, but their sum is not
    scale /= a_min;
  }
  Mat3 m;
  m << acc_[0], acc_[1], acc_[2], acc_[1], acc_[3], acc_[4], acc_[2], acc_[4], acc_[5];
  m *= scale;
  out.split_point = c_;
  out.fell_back = fell_back_;
  sorted_eigen(m, out.axes, out.eigenvalues);
  return out;
}

Fit fit_ids(const TriInfo* info, const std::uint32_t* ids, std::size_t n, Fitter fitter) {
  FitAccumulator acc;
  if (n == 0) return acc.finish();
  for (std::size_t j = 0; j < n; ++j) {
    if (j + kPrefetchAhead < n) prefetch(info + ids[j + kPrefetchAhead]);
    acc.first(info[ids[j]]);
  }
  acc.middle(fitter);
  for (std::size_t j = 0; j < n; ++j) {
    if (j + kPrefetchAhead < n) prefetch(info + ids[j + kPrefetchAhead]);
    const TriInfo& t = info[ids[j]];
    acc.second(t, tri_moments(t));
  }
  return acc.finish();
}

RssEdges::RssEdges(const Vec3& lo, const Vec3& hi) {
  r = 0.5 * (hi.z() - lo.z());
  zc = 0.5 * (hi.z() + lo.z());
  r2 = r * r;
  // Start from bounds the result cannot exceed (the extreme vertex, moved by at most r), so
  // that vertices well inside skip the square root in add().
  xlo = lo.x() + r;
  xhi = hi.x() - r;
  ylo = lo.y() + r;
  yhi = hi.y() - r;
}

RectExtents RssEdges::finish(const Vec3* pts, const std::uint32_t* outside, std::size_t count) {
  if (xlo > xhi) xlo = xhi = 0.5 * (xlo + xhi);
  if (ylo > yhi) ylo = yhi = 0.5 * (ylo + yhi);
  // Corners: a vertex outside both an x and a y edge must be within ρ of the corner; if not,
  // push one edge outwards (the cheaper in area) just enough. Edges only ever move outwards, so
  // earlier vertices stay inside, and a vertex add() found inside stays inside: only the
  // vertices add() reported need a look.
  for (std::size_t i = 0; i < count; ++i) {
    const Vec3& p = outside ? pts[outside[i]] : pts[i];
    const double dx = std::max(std::max(xlo - p.x(), p.x() - xhi), 0.0);
    const double dy = std::max(std::max(ylo - p.y(), p.y() - yhi), 0.0);
    if (dx == 0.0 || dy == 0.0) continue;  // beside an edge: inside by add()
    const double dz = p.z() - zc;
    const double rho2 = std::max(r2 - dz * dz, 0.0);
    if (dx * dx + dy * dy <= rho2) continue;
    const double rho = std::sqrt(rho2);
    const double w = xhi - xlo, h = yhi - ylo;
    // Either edge alone can take the vertex (add() keeps dx, dy ≤ ρ up to rounding).
    const double need_x = dx - std::sqrt(std::max(rho2 - dy * dy, 0.0));
    const double need_y = dy - std::sqrt(std::max(rho2 - dx * dx, 0.0));
    if (dy <= rho && (dx > rho || need_x * h <= need_y * w)) {
      const double allowed = std::sqrt(std::max(rho2 - dy * dy, 0.0));
      if (p.x() < xlo) xlo = p.x() + allowed;
      else xhi = p.x() - allowed;
    } else if (dx <= rho) {
      const double allowed = std::sqrt(std::max(rho2 - dx * dx, 0.0));
      if (p.y() < ylo) ylo = p.y() + allowed;
      else yhi = p.y() - allowed;
    } else {  // rounding pushed both beyond ρ: take the vertex's x in, then y to within ρ
      if (p.x() < xlo) xlo = p.x();
      else xhi = p.x();
      if (p.y() < ylo) ylo = p.y() + rho;
      else yhi = p.y() - rho;
    }
  }
  return RectExtents{xlo, xhi, ylo, yhi, zc, r};
}

RectExtents rss_extents(const Vec3* pts, std::size_t count, const Vec3* lo, const Vec3* hi) {
  if (count == 0) return RectExtents{};
  Vec3 box_lo, box_hi;
  if (lo && hi) {  // the caller measured the box already
    box_lo = *lo, box_hi = *hi;
  } else {
    box_lo = box_hi = pts[0];
    for (std::size_t i = 1; i < count; ++i) {
      box_lo = box_lo.cwiseMin(pts[i]);
      box_hi = box_hi.cwiseMax(pts[i]);
    }
  }
  RssEdges edges(box_lo, box_hi);
  for (std::size_t i = 0; i < count; ++i) edges.add(pts[i]);
  return edges.finish(pts, nullptr, count);
}

Rss make_rss(const RectExtents& e, const Mat3& axes, const Vec3& origin) {
  Rss rss;
  rss.axes = axes;
  const Vec3 local_center(0.5 * (e.xlo + e.xhi), 0.5 * (e.ylo + e.yhi), e.zc);
  rss.center = origin + axes * local_center;
  rss.half_length = {0.5 * (e.xhi - e.xlo), 0.5 * (e.yhi - e.ylo)};
  // A hair of slack for the rounding of the projections: 4 ulps of the set's extent.
  const double extent = std::max({e.xhi - e.xlo, e.yhi - e.ylo, 2.0 * e.r});
  rss.radius = e.r + 4.0 * std::numeric_limits<double>::epsilon() * (extent + std::abs(e.zc));
  // The long side first.
  if (rss.half_length[1] > rss.half_length[0]) {
    std::swap(rss.half_length[0], rss.half_length[1]);
    const Vec3 e1 = rss.axes.col(1), e2 = rss.axes.col(0);
    rss.axes.col(0) = e1;
    rss.axes.col(1) = e2;
    rss.axes.col(2) = -rss.axes.col(2);  // keep it right-handed
  }
  return rss;
}

void project_vertices(const TriInfo* info, const std::uint32_t* ids, std::size_t n, const Mat3& axes,
                      const Vec3& origin, std::vector<Vec3>& out, Vec3* lo, Vec3* hi) {
  const Mat3 at = axes.transpose();
  out.reserve(3 * n);
  out.resize(3 * n);
  Vec3 box_lo = Vec3::Constant(std::numeric_limits<double>::infinity()), box_hi = -box_lo;
  for (std::size_t j = 0; j < n; ++j) {
    if (j + kPrefetchAhead < n) prefetch(info + ids[j + kPrefetchAhead]);
    const Triangle& t = info[ids[j]].t;
    for (int v = 0; v < 3; ++v) {
      const Vec3 p = at * (t[v] - origin);
      out[3 * j + v] = p;
      box_lo = box_lo.cwiseMin(p);
      box_hi = box_hi.cwiseMax(p);
    }
  }
  if (lo) *lo = box_lo;
  if (hi) *hi = box_hi;
}

}  // namespace swept::detail

namespace swept {

double degeneracy_epsilon(std::span<const Triangle> triangles) {
  Aabb box;
  for (const Triangle& t : triangles) {
    box.extend(t.p);
    box.extend(t.q);
    box.extend(t.r);
  }
  return detail::epsilon_for_extent(box.extent());
}

namespace {
// A local frame for fitting: centre of the bounding box at the origin.
std::vector<Triangle> localised(std::span<const Triangle> triangles, Vec3& offset) {
  Aabb box;
  for (const Triangle& t : triangles) {
    box.extend(t.p);
    box.extend(t.q);
    box.extend(t.r);
  }
  offset = box.empty() ? Vec3::Zero() : box.center();
  std::vector<Triangle> out(triangles.begin(), triangles.end());
  for (Triangle& t : out) {
    t.p -= offset;
    t.q -= offset;
    t.r -= offset;
  }
  return out;
}
}  // namespace

Fit fit(std::span<const Triangle> triangles, Fitter fitter) {
  Vec3 offset;
  const std::vector<Triangle> local = localised(triangles, offset);
  std::vector<detail::TriInfo> info;
  info.reserve(local.size());
  for (const Triangle& t : local) info.push_back(detail::make_tri_info(t));
  std::vector<std::uint32_t> ids(local.size());
  std::iota(ids.begin(), ids.end(), 0u);
  Fit f = detail::fit_ids(info.data(), ids.data(), ids.size(), fitter);
  f.split_point += offset;
  return f;
}

Rss fit_rss(std::span<const Triangle> triangles, const Mat3& axes) {
  if (triangles.empty()) return Rss{axes};
  Vec3 offset;
  const std::vector<Triangle> local = localised(triangles, offset);
  std::vector<detail::TriInfo> info;
  info.reserve(local.size());
  for (const Triangle& t : local) info.push_back(detail::make_tri_info(t));
  std::vector<std::uint32_t> ids(local.size());
  std::iota(ids.begin(), ids.end(), 0u);
  // Projected relative to a vertex of the set, for precision.
  const Vec3 origin = local[0].p;
  std::vector<Vec3> projected;
  detail::project_vertices(info.data(), ids.data(), ids.size(), axes, origin, projected);
  Rss rss = detail::make_rss(detail::rss_extents(projected.data(), projected.size()), axes, origin);
  rss.center += offset;
  return rss;
}

}  // namespace swept
