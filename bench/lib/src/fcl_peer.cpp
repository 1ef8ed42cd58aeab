#include "swept/bench/fcl_peer.h"

#include "swept/bench/fcl_model.h"

#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/distance.h>

namespace swept::bench {

std::string_view fcl_engine_name(FclVolume v) {
  return v == FclVolume::obbrss ? "fcl-obbrss" : "fcl-rss";
}

struct FclMesh::Impl {
  std::shared_ptr<fcl::CollisionGeometryd> geometry;
};

FclMesh::FclMesh(std::span<const Triangle> triangles, FclVolume volume) : impl_(std::make_unique<Impl>()) {
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

}  // namespace swept::bench
