// Closed components of a triangle soup and a point-in-solid test by ray parity.
#include "swept/geometry/solid.h"

#include <algorithm>
#include <array>
#include <numeric>

namespace swept {
namespace {

using Key = std::array<double, 3>;

Key key(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

// Union-find over triangle indices.
struct Components {
  std::vector<std::uint32_t> parent;
  explicit Components(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  std::uint32_t find(std::uint32_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  void join(std::uint32_t a, std::uint32_t b) {
    a = find(a), b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

// Does the ray p + s·d (s > 0) cross the triangle? Möller–Trumbore. Returns +1 when it leaves
// through the triangle's front (d · normal > 0, normal = (q − p) × (r − p)), −1 when it enters
// through it, 0 when it misses.
int ray_crossing(const Vec3& p, const Vec3& d, const Triangle& t) {
  const Vec3 e1 = t.q - t.p, e2 = t.r - t.p;
  const Vec3 h = d.cross(e2);
  const double det = e1.dot(h);  // = −d · (e1 × e2)
  if (det == 0.0) return 0;
  const double inv = 1.0 / det;
  const Vec3 s = p - t.p;
  const double u = inv * s.dot(h);
  if (u < 0.0 || u > 1.0) return 0;
  const Vec3 q = s.cross(e1);
  const double v = inv * d.dot(q);
  if (v < 0.0 || u + v > 1.0) return 0;
  if (!(inv * e2.dot(q) > 0.0)) return 0;
  return det < 0.0 ? 1 : -1;
}

}  // namespace

std::vector<SurfacePart> surface_parts(std::span<const Triangle> triangles) {
  const std::uint32_t n = static_cast<std::uint32_t>(triangles.size());
  // Vertex ids by exact coordinates: sort the 3n corners by coordinates (sorting, not hashing,
  // so the ids do not depend on a hash function).
  std::vector<std::uint32_t> corners(3 * static_cast<std::size_t>(n));
  std::iota(corners.begin(), corners.end(), 0u);
  auto corner = [&](std::uint32_t c) -> const Vec3& { return triangles[c / 3][static_cast<int>(c % 3)]; };
  std::sort(corners.begin(), corners.end(), [&](std::uint32_t x, std::uint32_t y) {
    const Key kx = key(corner(x)), ky = key(corner(y));
    return kx != ky ? kx < ky : x < y;
  });
  std::vector<std::uint32_t> vertex(corners.size());
  std::uint32_t next = 0;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    if (i > 0 && key(corner(corners[i])) != key(corner(corners[i - 1]))) ++next;
    vertex[corners[i]] = next;
  }
  // Edges (smaller vertex id first) with the triangle using them, sorted to group equal edges.
  struct Edge {
    std::uint32_t a, b, triangle;
  };
  std::vector<Edge> edges;
  edges.reserve(corners.size());
  std::vector<char> used(n, 0);
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t v[3] = {vertex[3 * i], vertex[3 * i + 1], vertex[3 * i + 2]};
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) continue;
    used[i] = 1;
    for (int k = 0; k < 3; ++k) edges.push_back({std::min(v[k], v[(k + 1) % 3]), std::max(v[k], v[(k + 1) % 3]), i});
  }
  std::sort(edges.begin(), edges.end(), [](const Edge& x, const Edge& y) {
    return x.a != y.a ? x.a < y.a : (x.b != y.b ? x.b < y.b : x.triangle < y.triangle);
  });
  Components c(n);
  std::vector<std::pair<std::size_t, std::size_t>> groups;  // [begin, end) of equal edges
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i + 1;
    while (j < edges.size() && edges[j].a == edges[i].a && edges[j].b == edges[i].b) ++j;
    for (std::size_t k = i + 1; k < j; ++k) c.join(edges[i].triangle, edges[k].triangle);
    groups.emplace_back(i, j);
    i = j;
  }
  std::vector<char> open(n, 0);  // indexed by component root
  for (const auto& [i, j] : groups)
    if (j - i != 2) open[c.find(edges[i].triangle)] = 1;
  std::vector<std::int64_t> slot(n, -1);  // root → index in out
  std::vector<SurfacePart> out;
  // Roots are the smallest index of their component, so parts come in order of first triangle.
  for (std::uint32_t i = 0; i < n; ++i) {
    if (!used[i]) continue;
    const std::uint32_t root = c.find(i);
    if (slot[root] < 0) {
      slot[root] = static_cast<std::int64_t>(out.size());
      out.push_back({{}, !open[root], Aabb{}});
    }
    SurfacePart& part = out[static_cast<std::size_t>(slot[root])];
    part.triangles.push_back(i);
    for (int k = 0; k < 3; ++k) part.box.extend(triangles[i][k]);
  }
  return out;
}

bool inside_closed(std::span<const Triangle> triangles, std::span<const std::uint32_t> component, const Vec3& p) {
  static const std::array<Vec3, 3> kRays = {Vec3(0.5773502691896258, 0.3141592653589793, 0.7536983).normalized(),
                                            Vec3(-0.2718281828459045, 0.8660254037844386, 0.41421356).normalized(),
                                            Vec3(0.1732050807568877, -0.6180339887498949, -0.76732698).normalized()};
  int inside_votes = 0;
  for (const Vec3& d : kRays) {
    long winding = 0;
    for (std::uint32_t i : component) winding += ray_crossing(p, d, triangles[i]);
    inside_votes += winding > 0;
  }
  return inside_votes >= 2;
}

}  // namespace swept
