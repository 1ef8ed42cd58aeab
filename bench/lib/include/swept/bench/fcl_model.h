#pragma once
/// FCL 0.7 models of swept's triangle soups: the one place the benchmarks turn triangles into an
/// fcl::BVHModel (the paper benchmark, `swept bench queries`, bench_queries and the OMPL side of
/// bench_plan all build theirs here). Only the CLI and the benchmarks use FCL; the swept
/// libraries never do.
#include "swept/geometry/pose.h"
#include "swept/geometry/types.h"

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/math/bv/OBBRSS.h>
#include <fcl/math/bv/RSS.h>

#include <memory>
#include <span>

namespace swept::bench {

/// An FCL BVHModel of the triangles (three vertices per triangle, as swept stores them), with its
/// local AABB computed. Instantiated for fcl::OBBRSSd and fcl::RSSd. Throws std::runtime_error
/// when FCL refuses to build it.
template <class Bv>
std::shared_ptr<fcl::BVHModel<Bv>> fcl_model(std::span<const Triangle> triangles);

extern template std::shared_ptr<fcl::BVHModel<fcl::OBBRSSd>> fcl_model<fcl::OBBRSSd>(std::span<const Triangle>);
extern template std::shared_ptr<fcl::BVHModel<fcl::RSSd>> fcl_model<fcl::RSSd>(std::span<const Triangle>);

/// The same rigid transform in FCL's type.
fcl::Transform3d to_fcl(const Pose& pose);

}  // namespace swept::bench
