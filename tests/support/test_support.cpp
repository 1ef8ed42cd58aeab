#include "support/test_support.h"

#include <cmath>
#include <numbers>

namespace swept::test {

std::uint64_t Rng::next() {
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

double Rng::uniform(double lo, double hi) {
  return lo + (hi - lo) * (static_cast<double>(next() >> 11) * 0x1.0p-53);
}

Vec3 Rng::vec(double lo, double hi) { return {uniform(lo, hi), uniform(lo, hi), uniform(lo, hi)}; }

Mat3 Rng::rotation() {
  // Shoemake's uniform random quaternion.
  const double u1 = uniform(), u2 = uniform(), u3 = uniform();
  const double a = std::sqrt(1 - u1), b = std::sqrt(u1);
  const double t2 = 2 * std::numbers::pi * u2, t3 = 2 * std::numbers::pi * u3;
  Quat q(b * std::cos(t3), a * std::sin(t2), a * std::cos(t2), b * std::sin(t3));
  return q.normalized().toRotationMatrix();
}

std::optional<std::filesystem::path> shared_data() {
  std::filesystem::path p = SWEPT_SHARED_DATA;
  if (std::filesystem::is_directory(p)) return p;
  return std::nullopt;
}

std::optional<std::filesystem::path> occt_sample(const std::string& name) {
  if (const auto data = shared_data(); data && std::filesystem::exists(*data / "occt" / name)) return *data / "occt" / name;
  for (const char* folder : {"occ", "step", "iges", "stl"}) {
    const std::filesystem::path p = std::filesystem::path("/usr/share/opencascade/data") / folder / name;
    if (std::filesystem::exists(p)) return p;
  }
  return std::nullopt;
}

std::vector<Triangle> random_triangles(Rng& rng, int n, double size, double max_edge,
                                       const Vec3& center) {
  std::vector<Triangle> out;
  out.reserve(n);
  for (int i = 0; i < n; ++i) {
    Vec3 c = center + rng.vec(-size / 2, size / 2);
    Triangle t{c + rng.vec(-max_edge / 2, max_edge / 2), c + rng.vec(-max_edge / 2, max_edge / 2),
               c + rng.vec(-max_edge / 2, max_edge / 2)};
    out.push_back(t);
  }
  return out;
}

std::vector<Triangle> nasty_triangles(Rng& rng, int n, double size) {
  std::vector<Triangle> out;
  out.reserve(n);
  for (int i = 0; i < n; ++i) {
    Vec3 c = rng.vec(-size / 2, size / 2);
    Vec3 d = rng.vec(-1, 1).normalized();
    Vec3 e = d.unitOrthogonal();
    const int kind = static_cast<int>(rng.next() % 6);
    const double len = size * rng.uniform(0.01, 0.5);
    switch (kind) {
      case 0:  // sliver, aspect ratio ~1e4
        out.push_back({c, c + len * d, c + 0.5 * len * d + 1e-4 * len * e});
        break;
      case 1:  // zero area: collinear
        out.push_back({c, c + len * d, c + 0.3 * len * d});
        break;
      case 2:  // repeated vertices
        out.push_back({c, c, c + len * d});
        break;
      case 3:  // a point
        out.push_back({c, c, c});
        break;
      case 4:  // tiny
        out.push_back({c, c + 1e-6 * size * d, c + 1e-6 * size * e});
        break;
      default:  // big ordinary
        out.push_back({c, c + len * d, c + len * e + 0.3 * len * d});
        break;
    }
  }
  return out;
}

std::vector<Triangle> box_triangles(const Vec3& lo, const Vec3& hi) {
  auto v = [&](int i) { return Vec3(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(), i & 4 ? hi.z() : lo.z()); };
  const int f[12][3] = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                        {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  std::vector<Triangle> out;
  for (auto& t : f) out.push_back({v(t[0]), v(t[1]), v(t[2])});
  return out;
}

std::vector<Triangle> transformed(const std::vector<Triangle>& tris, const Pose& pose) {
  std::vector<Triangle> out;
  out.reserve(tris.size());
  for (const Triangle& t : tris) out.push_back({pose.apply(t.p), pose.apply(t.q), pose.apply(t.r)});
  return out;
}

}  // namespace swept::test
