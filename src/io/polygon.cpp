// Triangles of a polygon face (polygon.h): ear clipping in the plane across the polygon's Newell
// normal. Only corners that are not convex can lie inside an ear, so only they are tested, and
// only those in the grid cells the ear's box covers: a convex polygon is clipped in linear time.
#include "polygon.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace swept::io_detail {

namespace {

struct Point2 {
  double u, v;
  bool operator==(const Point2&) const = default;
};

// Twice the signed area of the triangle (a, b, c): positive when counterclockwise.
double orient(const Point2& a, const Point2& b, const Point2& c) {
  return (b.u - a.u) * (c.v - a.v) - (b.v - a.v) * (c.u - a.u);
}

// Point tests one polygon may spend before the corners left are fanned: a few tenths of a second
// on the worst polygon, far more than any simple polygon of a real file needs.
constexpr long long kBudget = 50'000'000;

}  // namespace

bool triangulate_polygon(std::span<const Vec3> points, std::span<const std::uint32_t> corners,
                         std::vector<std::array<std::uint32_t, 3>>& out) {
  const std::size_t k = corners.size();
  if (k < 3) return true;
  if (k == 3) {  // as the file has it
    out.push_back({corners[0], corners[1], corners[2]});
    return true;
  }
  auto at = [&](std::size_t i) -> const Vec3& { return points[corners[i]]; };

  // Newell's normal: its components are twice the polygon's signed areas projected on the
  // planes x = 0, y = 0 and z = 0 (in the orders (y, z), (z, x), (x, y)).
  Vec3 normal = Vec3::Zero();
  for (std::size_t i = 0; i < k; ++i) {
    const Vec3& a = at(i);
    const Vec3& b = at(i + 1 == k ? 0 : i + 1);
    normal.x() += (a.y() - b.y()) * (a.z() + b.z());
    normal.y() += (a.z() - b.z()) * (a.x() + b.x());
    normal.z() += (a.x() - b.x()) * (a.y() + b.y());
  }
  int axis = 0;
  for (int c = 1; c < 3; ++c)
    if (std::abs(normal[c]) > std::abs(normal[axis])) axis = c;
  std::vector<std::size_t> next(k), prev(k);
  for (std::size_t i = 0; i < k; ++i) {
    next[i] = i + 1 == k ? 0 : i + 1;
    prev[i] = i == 0 ? k - 1 : i - 1;
  }
  // The corners left, from `first` on, fanned from it.
  auto fan = [&](std::size_t first) {
    for (std::size_t j = next[first]; next[j] != first; j = next[j])
      out.push_back({corners[first], corners[j], corners[next[j]]});
  };
  if (!(normal[axis] != 0.0) || !std::isfinite(normal[axis])) {
    fan(0);  // all corners on one line: no area to cover
    return true;
  }

  const int u_axis = (axis + 1) % 3, v_axis = (axis + 2) % 3;
  const double sign = normal[axis] > 0.0 ? 1.0 : -1.0;  // counterclockwise in (u, v) after it
  std::vector<Point2> q(k);
  for (std::size_t i = 0; i < k; ++i) q[i] = {at(i)[u_axis], at(i)[v_axis]};
  auto turn = [&](std::size_t i) { return sign * orient(q[prev[i]], q[i], q[next[i]]); };

  // Corners that are not convex, the only ones an ear could hold, in a grid of cells over the
  // polygon's box, so that an ear tests only those near it.
  double lo_u = q[0].u, hi_u = q[0].u, lo_v = q[0].v, hi_v = q[0].v;
  for (const Point2& x : q) {
    lo_u = std::min(lo_u, x.u), hi_u = std::max(hi_u, x.u);
    lo_v = std::min(lo_v, x.v), hi_v = std::max(hi_v, x.v);
  }
  const int cells = static_cast<int>(std::clamp(std::sqrt(static_cast<double>(k)), 1.0, 1024.0));
  const double scale_u = hi_u > lo_u ? cells / (hi_u - lo_u) : 0.0, scale_v = hi_v > lo_v ? cells / (hi_v - lo_v) : 0.0;
  auto cell = [&](double x, double lo, double scale) {
    return std::clamp(static_cast<int>((x - lo) * scale), 0, cells - 1);
  };
  std::vector<std::vector<std::size_t>> grid(static_cast<std::size_t>(cells) * cells);
  std::vector<char> listed(k, 0);
  auto list = [&](std::size_t i) {
    listed[i] = 1;
    grid[static_cast<std::size_t>(cell(q[i].v, lo_v, scale_v)) * cells + cell(q[i].u, lo_u, scale_u)].push_back(i);
  };
  for (std::size_t i = 0; i < k; ++i)
    if (turn(i) <= 0.0) list(i);
  std::vector<char> clipped(k, 0);
  long long budget = kBudget;

  // An ear: a convex corner (or, when `flat` is allowed, one on the line of its neighbours)
  // whose triangle holds no other corner, on its boundary or inside; corners at the same place
  // as one of the ear's (a hole joined to the outline by a bridge) do not count.
  auto is_ear = [&](std::size_t i, bool flat) {
    const double t = turn(i);
    if (t < 0.0 || (t == 0.0 && !flat)) return false;
    const std::size_t p = prev[i], n = next[i];
    const Point2 &a = q[p], &b = q[i], &c = q[n];
    const int u0 = cell(std::min({a.u, b.u, c.u}), lo_u, scale_u), u1 = cell(std::max({a.u, b.u, c.u}), lo_u, scale_u);
    const int v0 = cell(std::min({a.v, b.v, c.v}), lo_v, scale_v), v1 = cell(std::max({a.v, b.v, c.v}), lo_v, scale_v);
    for (int cv = v0; cv <= v1; ++cv)
      for (int cu = u0; cu <= u1; ++cu)
        for (const std::size_t j : grid[static_cast<std::size_t>(cv) * cells + cu]) {
          if (!listed[j] || clipped[j] || j == p || j == i || j == n) continue;
          --budget;
          const Point2& x = q[j];
          if (x == a || x == b || x == c) continue;
          if (sign * orient(a, b, x) >= 0.0 && sign * orient(b, c, x) >= 0.0 && sign * orient(c, a, x) >= 0.0)
            return false;
        }
    --budget;
    return true;
  };

  std::size_t remaining = k, i = 0, misses = 0;
  bool flat = false;
  while (remaining > 3) {
    if (budget <= 0) {
      fan(i);
      return false;
    }
    if (is_ear(i, flat)) {
      const std::size_t p = prev[i], n = next[i];
      out.push_back({corners[p], corners[i], corners[n]});
      clipped[i] = 1;
      next[p] = n;
      prev[n] = p;
      --remaining;
      for (const std::size_t j : {p, n}) {
        const bool convex = turn(j) > 0.0;
        if (convex) listed[j] = 0;
        if (!convex && !listed[j]) list(j);
      }
      i = n;
      misses = 0;
      flat = false;
    } else {
      i = next[i];
      if (++misses >= remaining) {  // a whole turn without an ear
        if (flat) {
          fan(i);
          return false;
        }
        flat = true;
        misses = 0;
      }
    }
  }
  out.push_back({corners[prev[i]], corners[i], corners[next[i]]});
  return true;
}

}  // namespace swept::io_detail
