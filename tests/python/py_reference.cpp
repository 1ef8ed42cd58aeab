// The C++ API's answers for tests/python/test_module.py: reads two meshes, a fitter and poses
// (one line per pose: 7 numbers for A then 7 for B, x y z qx qy qz qw, read exactly as written)
// and prints one line per pose: distance, point_a, point_b, triangle_a, triangle_b, colliding,
// within (the tolerance given), as %.17g. Exit 1 with the library's message on bad input. With
// "motion" first: motion_clearance() instead (see main).
#include "swept/bvh/bvh.h"
#include "swept/io/mesh_io.h"
#include "swept/query/query.h"

#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>

using namespace swept;

namespace {

Pose pose7(const double* v) { return Pose::from_quaternion(Quat(v[6], v[3], v[4], v[5]), Vec3(v[0], v[1], v[2])); }

}  // namespace

int main(int argc, char** argv) {
  // "motion" mode: lines of 21 numbers (A's pose, B's start, B's end), margin as given; the
  // reference point is the centre of B's bounding box and the radius motion_radius(), as the
  // binding's defaults. Prints free, t_blocked, distance_at_block, min_distance, queries.
  const bool motion = argc == 7 && std::string(argv[1]) == "motion";
  if (motion) ++argv, --argc;
  if (argc != 6) {
    std::cerr << "usage: swept_py_reference [motion] A B FITTER TOLERANCE|MARGIN POSES\n";
    return 2;
  }
  Fitter fitter;
  if (!parse_fitter(argv[3], fitter)) {
    std::cerr << "unknown fitter\n";
    return 2;
  }
  Bvh trees[2];
  for (int i = 0; i < 2; ++i) {
    auto model = import_mesh(argv[1 + i]);
    if (!model) {
      std::cerr << model.error().message << "\n";
      return 1;
    }
    auto t = build_bvh(model->merged().triangles, {.fitter = fitter});
    if (!t) {
      std::cerr << t.error().message << "\n";
      return 1;
    }
    trees[i] = std::move(*t);
  }
  const double tol = std::stod(argv[4]);
  std::ifstream in(argv[5]);
  if (motion) {
    MotionRequest request;
    request.margin = tol;
    const Vec3 reference = bounds(trees[1].triangles).center();
    const double radius = motion_radius(trees[1], reference);
    double m[21];
    while (true) {
      for (double& x : m)
        if (!(in >> x)) return 0;
      const MotionResult r = motion_clearance(trees[0], pose7(m), trees[1], {pose7(m + 7), pose7(m + 14), reference, radius}, request);
      std::printf("%d %.17g %.17g %.17g %d\n", r.clear() ? 1 : 0, r.t_blocked, r.distance_at_block, r.min_distance,
                  r.distance_queries);
    }
  }
  double v[14];
  while (true) {
    for (double& x : v)
      if (!(in >> x)) return 0;
    const Pose pa = pose7(v), pb = pose7(v + 7);
    const DistanceResult d = distance(trees[0], pa, trees[1], pb);
    const CollideResult c = collide(trees[0], pa, trees[1], pb);
    const ToleranceResult t = tolerance(trees[0], pa, trees[1], pb, {.tolerance = tol});
    std::printf("%.17g %.17g %.17g %.17g %.17g %.17g %.17g %u %u %d %d\n", d.distance, d.point_a.x(), d.point_a.y(),
                d.point_a.z(), d.point_b.x(), d.point_b.y(), d.point_b.z(), d.triangle_a, d.triangle_b,
                c.colliding ? 1 : 0, t.within ? 1 : 0);
  }
}
