#include "swept/bench/fcl_model.h"

#include <stdexcept>
#include <vector>

namespace swept::bench {

template <class Bv>
std::shared_ptr<fcl::BVHModel<Bv>> fcl_model(std::span<const Triangle> triangles) {
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

template std::shared_ptr<fcl::BVHModel<fcl::OBBRSSd>> fcl_model<fcl::OBBRSSd>(std::span<const Triangle>);
template std::shared_ptr<fcl::BVHModel<fcl::RSSd>> fcl_model<fcl::RSSd>(std::span<const Triangle>);

fcl::Transform3d to_fcl(const Pose& pose) {
  fcl::Transform3d tf = fcl::Transform3d::Identity();
  tf.linear() = pose.rotation;
  tf.translation() = pose.translation;
  return tf;
}

}  // namespace swept::bench
