#include "swept/bench/fcl_peer.h"

#include "swept/bench/fcl_model.h"

#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/detail/traversal/collision/mesh_collision_traversal_node.h>
#include <fcl/narrowphase/detail/traversal/collision_node.h>
#include <fcl/narrowphase/detail/traversal/distance/mesh_distance_traversal_node.h>
#include <fcl/narrowphase/distance.h>

namespace swept::bench {

std::string_view fcl_engine_name(FclVolume v) {
  return v == FclVolume::obbrss ? "fcl-obbrss" : "fcl-rss";
}

struct FclMesh::Impl {
  std::shared_ptr<fcl::CollisionGeometryd> geometry;
};

FclMesh::FclMesh(std::span<const Triangle> triangles, FclVolume volume)
    : impl_(std::make_unique<Impl>()), volume_(volume) {
  if (volume == FclVolume::obbrss)
    impl_->geometry = fcl_model<fcl::OBBRSSd>(triangles);
  else
    impl_->geometry = fcl_model<fcl::RSSd>(triangles);
}

FclMesh::~FclMesh() = default;

bool FclMesh::collide(const Pose& pose, const FclMesh& other, const Pose& other_pose) const {
  fcl::CollisionRequestd request;
  fcl::CollisionResultd result;
  fcl::collide(impl_->geometry.get(), to_fcl(pose), other.impl_->geometry.get(), to_fcl(other_pose),
               request, result);
  return result.isCollision();
}

double FclMesh::distance(const Pose& pose, const FclMesh& other, const Pose& other_pose) const {
  fcl::DistanceRequestd request;
  request.enable_nearest_points = true;
  fcl::DistanceResultd result;
  fcl::distance(impl_->geometry.get(), to_fcl(pose), other.impl_->geometry.get(), to_fcl(other_pose),
                request, result);
  return result.min_distance;
}

namespace {

// fcl::distance for two meshes of one volume type, as FCL's own orientedMeshDistance runs it
// (its traversal node, initialize, fcl::detail::distance), with the node's statistics on.
template <class TraversalNode, class BV>
FclDistanceStats counted_distance(const fcl::CollisionGeometryd* a, const Pose& pose, const fcl::CollisionGeometryd* b,
                                  const Pose& other_pose) {
  fcl::DistanceRequestd request;
  request.enable_nearest_points = true;
  fcl::DistanceResultd result;
  TraversalNode node;
  fcl::detail::initialize(node, *static_cast<const fcl::BVHModel<BV>*>(a), to_fcl(pose),
                          *static_cast<const fcl::BVHModel<BV>*>(b), to_fcl(other_pose), request, result);
  node.enableStatistics(true);
  fcl::detail::distance(&node);
  return {result.min_distance, node.num_bv_tests, node.num_leaf_tests};
}

}  // namespace

FclDistanceStats FclMesh::distance_stats(const Pose& pose, const FclMesh& other, const Pose& other_pose) const {
  if (volume_ == FclVolume::obbrss)
    return counted_distance<fcl::detail::MeshDistanceTraversalNodeOBBRSS<double>, fcl::OBBRSSd>(
        impl_->geometry.get(), pose, other.impl_->geometry.get(), other_pose);
  return counted_distance<fcl::detail::MeshDistanceTraversalNodeRSS<double>, fcl::RSSd>(
      impl_->geometry.get(), pose, other.impl_->geometry.get(), other_pose);
}

std::optional<FclCollideStats> FclMesh::collide_stats(const Pose& pose, const FclMesh& other, const Pose& other_pose) const {
  if (volume_ != FclVolume::obbrss) return std::nullopt;
  // fcl::collide's orientedMeshCollide for OBBRSS: its traversal node, initialize, collide.
  fcl::CollisionRequestd request;
  fcl::CollisionResultd result;
  fcl::detail::MeshCollisionTraversalNodeOBBRSS<double> node;
  fcl::detail::initialize(node, *static_cast<const fcl::BVHModel<fcl::OBBRSSd>*>(impl_->geometry.get()), to_fcl(pose),
                          *static_cast<const fcl::BVHModel<fcl::OBBRSSd>*>(other.impl_->geometry.get()), to_fcl(other_pose),
                          request, result);
  node.enableStatistics(true);
  fcl::detail::collide(&node);
  return FclCollideStats{result.isCollision(), node.num_bv_tests, node.num_leaf_tests};
}

}  // namespace swept::bench
