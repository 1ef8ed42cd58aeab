// Loading a problem's meshes and building their trees.
#include "swept/io/mesh_io.h"
#include "swept/plan/planner.h"

#include <chrono>
#include <cmath>
#include <cstring>

namespace swept {

Result<PlanScene> load_scene(const Problem& problem, Fitter fitter) {
  using Clock = std::chrono::steady_clock;
  PlanScene scene;
  const auto t0 = Clock::now();
  auto gather = [&](const std::vector<MeshRef>& refs, TriangleSoup& out) -> std::optional<Error> {
    for (const MeshRef& ref : refs) {
      ImportOptions io;
      io.unit = problem.unit;
      io.file_unit = ref.file_unit;
      io.linear_deflection = ref.deflection > 0 ? ref.deflection : problem.deflection;
      auto model = import_mesh(ref.file, io);
      if (!model) return model.error();
      TriangleSoup soup = model->merged();
      if (soup.triangles.empty()) return Error{ref.file.string() + ": the mesh has no triangles"};
      for (const Triangle& t : soup.triangles)
        out.triangles.push_back({ref.pose.apply(t.p), ref.pose.apply(t.q), ref.pose.apply(t.r)});
      if (!out.name.empty()) out.name += "+";
      out.name += soup.name;
    }
    return std::nullopt;
  };
  if (auto e = gather(problem.obstacles, scene.obstacles)) return *e;
  if (auto e = gather(problem.body, scene.body)) return *e;
  const auto t1 = Clock::now();
  auto made = make_scene(std::move(scene.obstacles), std::move(scene.body), fitter, problem.reference_point);
  if (!made) return made.error();
  made->load_ms = std::chrono::duration<double, std::milli>(t1 - t0).count();
  return made;
}

Result<PlanScene> make_scene(TriangleSoup obstacles, TriangleSoup body, Fitter fitter,
                             std::optional<Vec3> reference_point) {
  using Clock = std::chrono::steady_clock;
  PlanScene scene;
  scene.obstacles = std::move(obstacles);
  scene.body = std::move(body);
  const auto t1 = Clock::now();
  auto ob = build_bvh(scene.obstacles.triangles, {.fitter = fitter});
  if (!ob) return Error{"obstacles: " + ob.error().message};
  auto bb = build_bvh(scene.body.triangles, {.fitter = fitter});
  if (!bb) return Error{"body: " + bb.error().message};
  const auto t2 = Clock::now();
  scene.obstacle_tree = std::move(*ob);
  scene.body_tree = std::move(*bb);
  scene.obstacle_box = bounds(scene.obstacles.triangles);
  if (reference_point) {
    scene.reference = *reference_point;
  } else {
    // Centre of a bounding sphere: the centre of the body's bounding box (within √3/2 of the
    // smallest; only r_max depends on it, and only mildly).
    scene.reference = bounds(scene.body.triangles).center();
  }
  double r2 = 0.0;
  for (const Triangle& t : scene.body.triangles)
    for (int v = 0; v < 3; ++v) r2 = std::max(r2, (t[v] - scene.reference).squaredNorm());
  scene.radius = std::sqrt(r2);
  scene.build_ms = std::chrono::duration<double, std::milli>(t2 - t1).count();
  return scene;
}

std::uint64_t path_hash(const Path& path) {
  std::uint64_t h = 14695981039346656037ull;  // the FNV-1a 64 offset basis
  auto mix = [&](double v) {
    v += 0.0;  // −0.0 → +0.0: equal poses, equal bytes
    unsigned char bytes[sizeof(double)];
    std::memcpy(bytes, &v, sizeof v);
    for (unsigned char b : bytes) {
      h ^= b;
      h *= 1099511628211ull;
    }
  };
  for (const Pose& p : path.poses) {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) mix(p.rotation(i, j));
    for (int i = 0; i < 3; ++i) mix(p.translation[i]);
  }
  return h;
}

}  // namespace swept
