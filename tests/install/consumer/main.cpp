// Builds a tree and answers a distance query through the installed library.
#include <swept/bvh/bvh.h>
#include <swept/query/query.h>

#include <cmath>
#include <cstdio>

int main() {
  std::vector<swept::Triangle> tri{{swept::Vec3(0, 0, 0), swept::Vec3(1, 0, 0), swept::Vec3(0, 1, 0)}};
  auto tree = swept::build_bvh(tri);
  if (!tree) return 1;
  auto d = swept::distance(*tree, swept::Pose{}, *tree, swept::Pose::from_translation(swept::Vec3(0, 0, 2)));
  std::printf("distance %.3f\n", d.distance);
  return std::abs(d.distance - 2.0) < 1e-12 ? 0 : 1;
}
