#pragma once
/// Bounding-volume hierarchies of Rectangle Swept Spheres, built top-down with one of the
/// three fitters of the paper (SPEC §2): PQP_FIT, RAPID2_FIT and INERTIA_FIT.
#include "swept/geometry/result.h"
#include "swept/geometry/rss.h"
#include "swept/geometry/types.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace swept {

/// How a node's split position and candidate axes are computed (SPEC §2.1).
enum class Fitter : std::uint8_t {
  pqp,      ///< PQP_FIT: vertex mean and covariance (Gottschalk et al. 1996; PQP).
  rapid2,   ///< RAPID2_FIT: area-weighted covariance of the triangles, convex hull skipped.
  inertia,  ///< INERTIA_FIT: shell centroid and area-weighted tensor of inertia (the paper).
};

/// How a node's triangles are divided between its two children (SPEC §2.2).
enum class SplitRule : std::uint8_t {
  min_sa,      ///< IPS CDC: try e1, e2, e3; keep the smallest SA(left) + SA(right), each side's
               ///< RSS fitted as that child's own (the paper's eq. (4)).
  largest,     ///< PQP: split across e1 only.
  min_sa_box,  ///< min-sa costed by each side's bounding box in the node's frame (cheaper).
};

/// A fitter's matrix, as the fused two-pass kernel of src/bvh/fitter.cpp computes it (SPEC §2.1):
/// over a node's triangles i with area A_i, centroid m_i and vertex scatter
/// S_i = Σ_v (v − m_i)(v − m_i)ᵀ, the split point is c = Σ w_i m_i / Σ w_i and the matrix is
/// scale · Σ w_i (k_center (m_i − c)(m_i − c)ᵀ + k_scatter S_i), with w_i = A_i when
/// `area_weighted`, else 1; scale = 1 / (3n) when `per_vertex`, else 1, divided by the smallest
/// non-degenerate area when `by_min_area`. A recipe that weights by area falls back to PQP_FIT's
/// on sets of zero total area.
struct FitterRecipe {
  bool area_weighted = false;
  double k_center = 3.0;
  double k_scatter = 1.0;
  bool per_vertex = true;
  bool by_min_area = false;
};

/// One row of the fitter table: every CLI option, error message, benchmark table and test
/// iterates `all_fitters()`, so that adding a fitter is one row (and its recipe).
struct FitterInfo {
  Fitter fitter;
  std::string_view name;        ///< how files and the CLI spell it: "inertia"
  std::string_view paper_name;  ///< how the paper names it: "INERTIA_FIT"
  std::string_view summary;     ///< one line for --help and docs
  FitterRecipe recipe;
};
/// The fitters, in the paper's order (PQP_FIT first: the baseline of every ratio).
std::span<const FitterInfo> all_fitters();
const FitterInfo& info(Fitter f);

/// One row of the split-rule table.
struct SplitRuleInfo {
  SplitRule rule;
  std::string_view name;     ///< "min-sa"
  std::string_view summary;  ///< one line for --help and docs
};
std::span<const SplitRuleInfo> all_split_rules();
const SplitRuleInfo& info(SplitRule s);

std::string_view to_string(Fitter f);
std::string_view to_string(SplitRule s);
/// The table's names joined: "pqp, rapid2, inertia" (for messages and --help).
std::string fitter_names(std::string_view separator = ", ");
std::string split_rule_names(std::string_view separator = ", ");
/// Parses a name of the fitter table. Returns false on anything else.
bool parse_fitter(std::string_view text, Fitter& out);
/// Parses a name of the split-rule table. Returns false on anything else.
bool parse_split_rule(std::string_view text, SplitRule& out);

/// The largest leaf size a build accepts.
inline constexpr int kMaxLeafSize = 1 << 16;

/// Triangles per leaf when nothing else is asked for (docs/fitters.md, "Leaf size").
inline constexpr int kDefaultLeafSize = 1;

/// Build options. The defaults are the paper's method with IPS CDC's split rule.
struct BuildConfig {
  Fitter fitter = Fitter::inertia;
  SplitRule split = SplitRule::min_sa;
  int leaf_size = kDefaultLeafSize;  ///< a node with at most this many triangles is a leaf (1 … kMaxLeafSize)
  bool parallel = true;    ///< use oneTBB; the tree is identical either way
};

/// One node of the flat tree: 48 bytes. Its RSS is stored in single precision and rounded
/// outward (see `encode_rss`): the quaternion of its axes, its center relative to
/// `Bvh::origin`, its half-lengths and its radius. A leaf holds `count` > 0 triangles starting
/// at `first` in `Bvh::triangles`; an internal node has `count` == 0 and its children at
/// `first` and `first + 1` (siblings are adjacent).
struct Node {
  std::array<float, 4> rotation{1.0f, 0.0f, 0.0f, 0.0f};  ///< quaternion (w, x, y, z), any norm
  std::array<float, 3> center{0.0f, 0.0f, 0.0f};          ///< relative to the tree's origin
  std::array<float, 2> half_length{0.0f, 0.0f};
  float radius = 0.0f;
  std::int32_t first = 0;
  std::int32_t count = 0;

  bool is_leaf() const { return count > 0; }
  /// The RSS's surface area: a traversal splits the node of a pair with the larger one. (Its
  /// expected number of overlapping node pairs grows with it; on the shared CAD, robot and motor
  /// pairs it visits 5–27 % fewer node pairs than the half-lengths plus radius did.)
  float area() const {
    constexpr float k4pi = 12.566371f;
    return 8.0f * half_length[0] * half_length[1] + k4pi * radius * (half_length[0] + half_length[1] + radius);
  }
};
static_assert(sizeof(Node) == 48, "Node byte budget");

/// The rotation matrix of a quaternion (w, x, y, z) of any non-zero norm, computed in double
/// precision: orthonormal to rounding. Builds and queries share it, so a stored node decodes to
/// the same axes everywhere.
inline Mat3 rotation_of(const std::array<float, 4>& q) {
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  const double s = 2.0 / (w * w + x * x + y * y + z * z);
  const double xs = x * s, ys = y * s, zs = z * s;
  const double wx = w * xs, wy = w * ys, wz = w * zs;
  const double xx = x * xs, xy = x * ys, xz = x * zs;
  const double yy = y * ys, yz = y * zs, zz = z * zs;
  Mat3 r;
  r << 1.0 - (yy + zz), xy - wz, xz + wy,  //
      xy + wz, 1.0 - (xx + zz), yz - wx,   //
      xz - wy, yz + wx, 1.0 - (xx + yy);
  return r;
}

/// The RSS a node stores, in the model frame (`origin` is the tree's).
inline Rss decode_rss(const Node& n, const Vec3& origin) {
  Rss v;
  v.axes = rotation_of(n.rotation);
  v.center = origin + Vec3(n.center[0], n.center[1], n.center[2]);
  v.half_length = {n.half_length[0], n.half_length[1]};
  v.radius = n.radius;
  return v;
}

/// Stores `rss` (its center relative to `origin`) in `node`, rounded outward: the stored RSS
/// contains every point of `rss`. The quaternion is rounded to single precision and the axes it
/// decodes to differ from `rss.axes` by δ1, δ2 (columns) and the center by δc; the radius grows
/// by ‖δc‖ + a‖δ1‖ + b‖δ2‖ (a, b the half-lengths), which covers that, and every length is
/// rounded up. Any 3×3 `axes` is accepted; the closer to a rotation, the tighter the result.
void encode_rss(const Rss& rss, const Vec3& origin, Node& node);

/// A tree's triangles: each one three indices into a vertex array, vertices shared where their
/// coordinates are equal bit for bit (so every triangle reads back exactly as it was given).
struct IndexedTriangles {
  std::vector<Vec3> vertices;
  std::vector<std::array<std::uint32_t, 3>> corners;

  std::size_t size() const { return corners.size(); }
  bool empty() const { return corners.empty(); }
  Triangle operator[](std::size_t i) const {
    const std::array<std::uint32_t, 3>& c = corners[i];
    return {vertices[c[0]], vertices[c[1]], vertices[c[2]]};
  }
  /// Bytes held (capacity) by the two arrays.
  std::size_t memory_bytes() const {
    return vertices.capacity() * sizeof(Vec3) + corners.capacity() * sizeof(corners[0]);
  }
};

/// The bounding box of the triangles (of their vertices).
Aabb bounds(const IndexedTriangles& triangles);

/// An immutable RSS tree over a triangle soup. Safe to share between threads for queries.
struct Bvh {
  std::vector<Node> nodes;                ///< nodes[0] is the root
  Vec3 origin = Vec3::Zero();             ///< node centers are stored relative to it
  IndexedTriangles triangles;             ///< the input triangles, reordered leaf by leaf
  std::vector<std::uint32_t> triangle_ids;///< triangle_ids[i]: input index of triangles[i]
  BuildConfig config;                     ///< how it was built
  int depth = 0;                          ///< levels: 1 for a single leaf
  double extent = 0.0;                    ///< diagonal of the model's bounding box
  Rss root;                               ///< bv(0), decoded once by build_bvh: every query starts there

  bool empty() const { return nodes.empty(); }
  /// The RSS of node `i`, in the model frame (decoded: see `decode_rss`).
  Rss bv(std::size_t i) const { return decode_rss(nodes[i], origin); }
  /// Bytes held by the tree: its arrays' capacity (nodes, triangles and ids) and the struct.
  std::size_t memory_bytes() const;
};

/// Builds the RSS tree of a triangle soup (SPEC §2). Errors (never exceptions): empty input,
/// NaN or infinite coordinates, coordinates beyond ±1e30 (nodes are stored in single precision;
/// the triangle is named). Degenerate triangles are accepted.
/// With `config.parallel` the work is spread over oneTBB's threads; the tree is the same,
/// node for node, as a serial build.
Result<Bvh> build_bvh(std::span<const Triangle> triangles, const BuildConfig& config = {});

/// Tree figures reported by `swept bvh` (the paper's Tables II and IV).
struct BvhStats {
  std::size_t triangles = 0;
  std::size_t nodes = 0;
  int depth = 0;
  double total_surface_area = 0.0;  ///< sum of SA over all nodes' RSSs
  double total_volume = 0.0;        ///< sum of V over all nodes' RSSs
  std::size_t bytes = 0;
};
BvhStats stats(const Bvh& bvh);

}  // namespace swept
