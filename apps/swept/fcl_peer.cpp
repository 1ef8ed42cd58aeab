#include "fcl_peer.h"

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/math/bv/OBBRSS.h>
#include <fcl/math/bv/RSS.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/distance.h>

#include <stdexcept>

namespace swept::cli {

std::string_view fcl_engine_name(FclVolume v) {
  return v == FclVolume::obbrss ? "fcl-obbrss" : "fcl-rss";
}

struct FclMesh::Impl {
  std::shared_ptr<fcl::CollisionGeometryd> geometry;
};

namespace {

template <class Bv>
std::shared_ptr<fcl::CollisionGeometryd> make_model(const std::vector<Triangle>& triangles) {
  auto model = std::make_shared<fcl::BVHModel<Bv>>();
  std::vector<fcl::Vector3d> vertices;
  std::vector<fcl::Triangle> faces;
  vertices.reserve(3 * triangles.size());
  faces.reserve(triangles.size());
  for (const Triangle& t : triangles) {
    const std::size_t base = vertices.size();
    vertices.push_back(t.p);
    vertices.push_back(t.q);
    vertices.push_back(t.r);
    faces.emplace_back(base, base + 1, base + 2);
  }
  if (model->beginModel(static_cast<int>(faces.size()), static_cast<int>(vertices.size())) != fcl::BVH_OK ||
      model->addSubModel(vertices, faces) != fcl::BVH_OK || model->endModel() != fcl::BVH_OK)
    throw std::runtime_error("FCL could not build its BVHModel");
  model->computeLocalAABB();
  return model;
}

fcl::Transform3d to_fcl(const Pose& p) {
  fcl::Transform3d tf = fcl::Transform3d::Identity();
  tf.linear() = p.rotation;
  tf.translation() = p.translation;
  return tf;
}

}  // namespace

FclMesh::FclMesh(const std::vector<Triangle>& triangles, FclVolume volume) : impl_(std::make_unique<Impl>()) {
  impl_->geometry = volume == FclVolume::obbrss ? make_model<fcl::OBBRSSd>(triangles)
                                                : make_model<fcl::RSSd>(triangles);
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

}  // namespace swept::cli
