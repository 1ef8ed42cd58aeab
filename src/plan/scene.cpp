// Loading a problem's meshes and building their trees.
#include "swept/io/mesh_io.h"
#include "swept/plan/planner.h"

#include "swept/geometry/solid.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <cmath>
#include <cstring>
#include <sstream>

namespace swept {
namespace {

std::string part_names(const ImportedModel& model) {
  std::string out;
  for (const TriangleSoup& p : model.parts) out += (out.empty() ? "" : ", ") + p.name;
  return out;
}

// The parts of `model` that `ref` asks for (MeshRef::part, MeshRef::except), as a model of those.
Result<ImportedModel> chosen_parts(const ImportedModel& model, const MeshRef& ref) {
  auto known = [&](const std::string& name) {
    return std::any_of(model.parts.begin(), model.parts.end(), [&](const TriangleSoup& p) { return p.name == name; });
  };
  for (const std::string& name : ref.part.empty() ? ref.except : std::vector<std::string>{ref.part})
    if (!known(name))
      return Error{ref.file.string() + ": no part named '" + name + "' (its parts: " + part_names(model) + ")"};
  ImportedModel out;
  out.file = model.file;
  out.unit = model.unit;
  for (const TriangleSoup& p : model.parts) {
    const bool excepted = std::find(ref.except.begin(), ref.except.end(), p.name) != ref.except.end();
    if (ref.part.empty() ? !excepted : p.name == ref.part) out.parts.push_back(p);
  }
  if (out.parts.empty()) return Error{ref.file.string() + ": except leaves no part (its parts: " + part_names(model) + ")"};
  return out;
}

// A part of the body's file that an obstacle of the same file also holds (the body would be its
// own obstacle): the error saying so.
std::optional<Error> part_in_both(const Problem& problem) {
  auto same = [](const std::filesystem::path& a, const std::filesystem::path& b) {
    std::error_code ec;
    return std::filesystem::equivalent(a, b, ec);
  };
  for (const MeshRef& body : problem.body) {
    if (body.part.empty()) continue;
    for (const MeshRef& obstacle : problem.obstacles) {
      if (!same(body.file, obstacle.file)) continue;
      const bool held = obstacle.part.empty() ? std::find(obstacle.except.begin(), obstacle.except.end(), body.part) == obstacle.except.end()
                                              : obstacle.part == body.part;
      if (held)
        return Error{body.file.string() + ": part '" + body.part + "' is the body and also an obstacle (add it to the obstacle's except = [...])"};
    }
  }
  return std::nullopt;
}

}  // namespace

Result<PlanScene> load_scene(const Problem& problem, const BuildConfig& config) {
  using Clock = std::chrono::steady_clock;
  PlanScene scene;
  std::vector<std::string> warnings;
  const auto t0 = Clock::now();
  auto gather = [&](const std::vector<MeshRef>& refs, TriangleSoup& out) -> std::optional<Error> {
    for (const MeshRef& ref : refs) {
      ImportOptions io;
      io.unit = problem.unit;
      io.file_unit = ref.file_unit;
      io.linear_deflection = ref.deflection > 0 ? ref.deflection : problem.deflection;
      io.max_triangles = problem.max_triangles;
      auto model = import_mesh(ref.file, io);
      if (!model) return model.error();
      for (std::string& w : model->warnings) warnings.push_back(std::move(w));
      TriangleSoup soup;
      if (ref.part.empty() && ref.except.empty()) {
        soup = model->merged();
      } else {
        auto chosen = chosen_parts(*model, ref);
        if (!chosen) return chosen.error();
        soup = chosen->merged();
      }
      if (!cylinders_usable(soup)) soup.cylinder_of.clear(), soup.cylinders.clear();
      if (soup.triangles.empty()) return Error{ref.file.string() + ": the mesh has no triangles"};
      // The CAD's cylinders come along, placed, for the contact model's mates (TriangleSoup).
      append_placed(out, soup, ref.pose);
      if (!out.name.empty()) out.name += "+";
      out.name += soup.name;
    }
    return std::nullopt;
  };
  if (auto e = gather(problem.obstacles, scene.obstacles)) return *e;
  if (auto e = gather(problem.body, scene.body)) return *e;
  if (auto e = part_in_both(problem)) return *e;
  const auto t1 = Clock::now();
  auto made = make_scene(std::move(scene.obstacles), std::move(scene.body), config, problem.reference_point);
  if (!made) return made.error();
  made->warnings = std::move(warnings);
  made->load_ms = std::chrono::duration<double, std::milli>(t1 - t0).count();
  return made;
}

Result<PlanScene> make_scene(TriangleSoup obstacles, TriangleSoup body, const BuildConfig& config,
                             std::optional<Vec3> reference_point) {
  using Clock = std::chrono::steady_clock;
  PlanScene scene;
  scene.obstacles = std::move(obstacles);
  scene.body = std::move(body);
  const auto t1 = Clock::now();
  auto ob = build_bvh(scene.obstacles.triangles, config);
  if (!ob) return Error{"obstacles: " + ob.error().message};
  auto bb = build_bvh(scene.body.triangles, config);
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
  scene.obstacle_parts = surface_parts(scene.obstacles.triangles);
  scene.body_parts = surface_parts(scene.body.triangles);
  scene.build_ms = std::chrono::duration<double, std::milli>(t2 - t1).count();
  return scene;
}

std::optional<std::string> enclosure_at(const PlanScene& scene, const Pose& pose) {
  const auto& body = scene.body.triangles;
  const auto& obstacles = scene.obstacles.triangles;
  auto inside_box = [](const Aabb& b, const Vec3& p) {
    return (p.array() >= b.min.array()).all() && (p.array() <= b.max.array()).all();
  };
  // Surfaces apart, so one vertex of a part tells whether the whole part is inside.
  for (std::size_t o = 0; o < scene.obstacle_parts.size(); ++o) {
    const SurfacePart& op = scene.obstacle_parts[o];
    if (!op.closed) continue;
    for (std::size_t b = 0; b < scene.body_parts.size(); ++b) {
      const Vec3 p = pose.apply(body[scene.body_parts[b].triangles.front()].p);
      if (inside_box(op.box, p) && inside_closed(obstacles, op.triangles, p)) {
        std::ostringstream os;
        os << "the body is inside a closed obstacle surface (the part of " << op.triangles.size()
           << " triangles starting at obstacle triangle " << op.triangles.front() << ")";
        return os.str();
      }
    }
  }
  for (std::size_t b = 0; b < scene.body_parts.size(); ++b) {
    const SurfacePart& bp = scene.body_parts[b];
    if (!bp.closed) continue;
    for (std::size_t o = 0; o < scene.obstacle_parts.size(); ++o) {
      const Vec3 p = pose.apply_inverse(obstacles[scene.obstacle_parts[o].triangles.front()].p);
      if (inside_box(bp.box, p) && inside_closed(body, bp.triangles, p)) {
        std::ostringstream os;
        os << "an obstacle is inside the body's closed surface (the obstacle part starting at triangle "
           << scene.obstacle_parts[o].triangles.front() << ")";
        return os.str();
      }
    }
  }
  return std::nullopt;
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
