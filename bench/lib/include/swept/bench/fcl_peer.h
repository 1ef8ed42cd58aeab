#pragma once
/// FCL 0.7 as a peer for side-by-side comparisons (`swept bench queries`, `swept bench paper`,
/// bench_queries), behind a small interface that keeps FCL's headers out of the callers.
#include "swept/geometry/pose.h"
#include "swept/geometry/types.h"

#include <memory>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace swept::bench {

/// FCL's bounding-volume types compared against swept's RSS trees.
enum class FclVolume { obbrss, rss };

/// The engine name used in tables and JSON: "fcl-obbrss" or "fcl-rss".
std::string_view fcl_engine_name(FclVolume v);

/// One FCL distance query with FCL's own counters (its traversal node's statistics).
struct FclDistanceStats {
  double distance = 0.0;
  long bv_tests = 0;    ///< bounding-volume pair tests (FCL's num_bv_tests)
  long leaf_tests = 0;  ///< triangle pair tests (num_leaf_tests)
};

/// One FCL collide query with FCL's own counters.
struct FclCollideStats {
  bool colliding = false;
  long bv_tests = 0;    ///< bounding-volume pair tests (FCL's num_bv_tests)
  long leaf_tests = 0;  ///< triangle pair tests (num_leaf_tests)
};

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
  /// The same query run through FCL's traversal node directly, as fcl::distance runs it, to
  /// read its counters of bounding-volume and triangle pair tests (`other` has this volume type).
  FclDistanceStats distance_stats(const Pose& pose, const FclMesh& other, const Pose& other_pose) const;
  /// The collide query run through FCL's traversal node directly, as fcl::collide runs it for
  /// OBBRSS models (its oriented traversal), with its counters; nullopt for RSS models, whose
  /// fcl::collide copies both models and transforms their vertices on every call (that copy,
  /// not the traversal, is most of its time).
  std::optional<FclCollideStats> collide_stats(const Pose& pose, const FclMesh& other, const Pose& other_pose) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  FclVolume volume_;
};

}  // namespace swept::bench
