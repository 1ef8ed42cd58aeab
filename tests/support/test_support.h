#pragma once
/// Helpers shared by the tests: seeded random meshes, the shared CAD data folder.
#include "swept/geometry/pose.h"
#include "swept/geometry/types.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace swept::test {

/// A small deterministic generator (SplitMix64); tests never use std::*_distribution so that
/// every platform sees the same meshes.
struct Rng {
  std::uint64_t state;
  explicit Rng(std::uint64_t seed) : state(seed) {}
  std::uint64_t next();
  double uniform(double lo = 0.0, double hi = 1.0);  ///< in [lo, hi)
  Vec3 vec(double lo, double hi);
  Mat3 rotation();  ///< uniformly random rotation
};

/// The shared CAD data folder, or nullopt (tests then GTEST_SKIP with a message).
std::optional<std::filesystem::path> shared_data();

/// An OpenCASCADE sample file by name ("screw.step"): the shared data's occt/ copy when present,
/// else Debian's occt-misc copy (/usr/share/opencascade/data/{occ,step,iges,stl}/, installed by
/// scripts/setup.sh, so present in a fresh clone's CI; the same bytes). nullopt when neither has it.
std::optional<std::filesystem::path> occt_sample(const std::string& name);

/// n random triangles in a cube of side `size` centred at `center`, edge lengths up to
/// `max_edge`.
std::vector<Triangle> random_triangles(Rng& rng, int n, double size, double max_edge,
                                       const Vec3& center = Vec3::Zero());

/// A mix that stresses fitters and queries: slivers of aspect ratio ~1e4, zero-area
/// triangles, repeated vertices, big and tiny triangles.
std::vector<Triangle> nasty_triangles(Rng& rng, int n, double size);

/// The 12 triangles of an axis-aligned box.
std::vector<Triangle> box_triangles(const Vec3& min, const Vec3& max);

/// Triangles transformed by a pose.
std::vector<Triangle> transformed(const std::vector<Triangle>& tris, const Pose& pose);

}  // namespace swept::test
