#pragma once
/// FCL 0.7 as a peer for side-by-side comparisons (`swept bench queries`, `swept bench paper`,
/// bench_queries), behind a small interface that keeps FCL's headers out of the callers.
#include "swept/geometry/pose.h"
#include "swept/geometry/types.h"

#include <memory>
#include <span>
#include <string_view>
#include <vector>

namespace swept::bench {

/// FCL's bounding-volume types compared against swept's RSS trees.
enum class FclVolume { obbrss, rss };

/// The engine name used in tables and JSON: "fcl-obbrss" or "fcl-rss".
std::string_view fcl_engine_name(FclVolume v);

/// An FCL BVHModel of a triangle soup (built once, immutable afterwards).
class FclMesh {
 public:
  FclMesh(std::span<const Triangle> triangles, FclVolume volume);
  ~FclMesh();
  FclMesh(const FclMesh&) = delete;
  FclMesh& operator=(const FclMesh&) = delete;

  /// fcl::collide with a default request (first contact).
  bool collide(const Pose& pose, const FclMesh& other, const Pose& other_pose) const;
  /// fcl::distance with a default request and nearest points enabled (swept always computes
  /// them). Returns FCL's min_distance.
  double distance(const Pose& pose, const FclMesh& other, const Pose& other_pose) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace swept::bench
