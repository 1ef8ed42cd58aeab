// swept.Problem (load_problem), swept.Scene (load_scene) and swept.plan (plan): as `swept plan`.
#include "convert.h"

#include "swept/plan/planner.h"
#include "swept/plan/problem.h"

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <iomanip>
#include <sstream>

namespace swept::py {

namespace {

struct PyProblem {
  Problem problem;
};

struct PyScene {
  std::shared_ptr<const PlanScene> scene;
  std::filesystem::path source;  ///< the problem file it was loaded for
  Fitter fitter = Fitter::inertia;
};

pyb::array_t<double> pose7(const Pose& p) {
  auto a = new_array<double>({7});
  write_pose7(p, a.mutable_data());
  return a;
}

std::string hex(std::uint64_t h) {
  std::ostringstream os;
  os << std::hex << std::setw(16) << std::setfill('0') << h;
  return os.str();
}

const char* status_name(PlanStatus s) {
  switch (s) {
    case PlanStatus::solved: return "solved";
    case PlanStatus::no_path_time: return "no_path_time";
    case PlanStatus::no_path_budget: return "no_path_budget";
    case PlanStatus::no_path_bounds: return "no_path_bounds";
    case PlanStatus::no_path_resolution: return "no_path_resolution";
    case PlanStatus::invalid_start: return "invalid_start";
    case PlanStatus::invalid_goal: return "invalid_goal";
    case PlanStatus::invalid_bounds: return "invalid_bounds";
  }
  return "unknown";
}

PyProblem problem_load(const std::filesystem::path& path) {
  Result<Problem> p = Error{};
  {
    pyb::gil_scoped_release release;
    p = load_problem(path);
  }
  return PyProblem{value_or_raise(std::move(p))};
}

Fitter fitter_from(const std::string& text) {
  Fitter f;
  if (!parse_fitter(text, f)) throw InputError("unknown fitter '" + text + "' (" + fitter_names() + ")");
  return f;
}

PyScene scene_load(const PyProblem& p, std::optional<std::string> fitter) {
  BuildConfig config = p.problem.build;  // the problem's split rule and leaf size
  if (fitter) config.fitter = fitter_from(*fitter);
  Result<PlanScene> s = Error{};
  {
    pyb::gil_scoped_release release;
    s = load_scene(p.problem, config);
  }
  return PyScene{std::make_shared<const PlanScene>(value_or_raise(std::move(s))), p.problem.source, config.fitter};
}

PyBvh scene_tree(const PyScene& s, const Bvh& t) {
  PyBvh b;
  b.bvh = std::shared_ptr<const Bvh>(s.scene, &t);  // shares the scene's ownership
  return b;
}

void set_seed(Problem& problem, std::int64_t seed) {
  if (seed < 0) throw InputError("seed must be >= 0, not " + std::to_string(seed));
  problem.seed = static_cast<std::uint64_t>(seed);
}

pyb::dict plan_py(const PyProblem& p_in, std::optional<double> time_limit, std::optional<int> threads,
                  std::optional<PyScene> scene_in, std::optional<std::int64_t> max_queries, std::optional<std::int64_t> seed) {
  Problem problem = p_in.problem;
  if (seed) set_seed(problem, *seed);
  if (time_limit) {
    if (!(*time_limit > 0) || !std::isfinite(*time_limit))
      throw InputError("time_limit must be a positive number of seconds, not " + std::to_string(*time_limit));
    problem.time_limit = *time_limit;
  }
  if (max_queries && *max_queries <= 0)
    throw InputError("max_queries must be a positive number of distance queries, not " + std::to_string(*max_queries));
  if (threads) {
    if (*threads < 0) throw InputError("threads must be >= 0 (0: all cores), not " + std::to_string(*threads));
    problem.threads = *threads;
  }
  PyScene scene;
  if (scene_in) {
    scene = *scene_in;
    if (scene.source != problem.source)
      throw InputError("the scene was loaded for " + scene.source.string() + ", not for " + problem.source.string());
  } else {
    scene = scene_load(p_in, std::nullopt);
  }
  PlanResult r;
  {
    pyb::gil_scoped_release release;
    PlanOptions options;
    if (max_queries) options.max_queries = static_cast<std::uint64_t>(*max_queries);
    r = plan(problem, *scene.scene, options);
  }
  // Bad input ends `swept plan` with exit code 1 and this message; here it is swept.Error.
  if (r.status == PlanStatus::invalid_start || r.status == PlanStatus::invalid_goal ||
      r.status == PlanStatus::invalid_bounds)
    throw InputError(problem.source.string() + ": " + r.message);

  const auto path = poses_array(r.path.poses);
  pyb::dict d;
  d["status"] = status_name(r.status);
  d["solved"] = r.solved();
  d["message"] = r.message;
  d["path"] = path;
  d["path_length"] = r.path_length;
  d["translation_length"] = r.translation_length;
  d["rotation_length_rad"] = r.rotation_length;
  d["min_clearance"] = r.solved() ? pyb::object(pyb::float_(r.min_clearance)) : pyb::object(pyb::none());
  auto segments = [&](std::size_t n) -> pyb::object {
    if (!r.solved() || n == 0) return pyb::none();
    pyb::dict e;
    e["segments"] = n;
    return std::move(e);
  };
  d["escape"] = segments(r.escape_segments);
  d["approach"] = segments(r.approach_segments);
  pyb::dict t;
  t["build"] = r.time_ms.build, t["search"] = r.time_ms.search, t["smooth"] = r.time_ms.smooth, t["total"] = r.time_ms.total;
  d["time_ms"] = t;
  pyb::dict q;
  q["distance"] = r.queries.distance, q["proximity"] = r.queries.proximity, q["sweep"] = r.queries.sweep;
  d["queries"] = q;
  d["path_hash"] = hex(r.path_hash);
  d["seed"] = problem.seed;
  d["unit"] = problem.unit;
  d["fitter"] = std::string(to_string(scene.fitter));
  d["level"] = r.level;
  d["nodes_checked"] = r.nodes_checked;
  d["edges_checked"] = r.edges_checked;
  d["reference_point"] = vec3_array(scene.scene->reference);
  return d;
}

}  // namespace

void bind_plan(pyb::module_& m) {
  using pyb::arg;
  pyb::class_<PyProblem>(m, "Problem", R"doc(
A planning problem (docs/problem-format.md, or an OMPL.app .cfg). Problem.load(path) reads one;
clearance, contact_tolerance, fitter, time_limit, threads and seed may be changed before planning
(copy() first to keep the original).)doc")
      .def_static("load", &problem_load, arg("path"), R"doc(
Reads a problem file (.toml or OMPL.app .cfg). Raises swept.Error with the message `swept plan`
prints (naming the file, the line and the key) on bad input.)doc")
      .def("copy", [](const PyProblem& p) { return p; })
      .def("__copy__", [](const PyProblem& p) { return p; })
      .def("__deepcopy__", [](const PyProblem& p, pyb::handle) { return p; }, arg("memo"))
      .def_property_readonly("source", [](const PyProblem& p) { return p.problem.source.string(); })
      .def_property_readonly("unit", [](const PyProblem& p) { return p.problem.unit; })
      .def_property_readonly("start", [](const PyProblem& p) { return pose7(p.problem.start); },
                             "(7,) start pose: x, y, z, qx, qy, qz, qw")
      .def_property_readonly("goal", [](const PyProblem& p) -> pyb::object {
            return p.problem.goal ? pyb::object(pose7(*p.problem.goal)) : pyb::object(pyb::none());
          }, "(7,) goal pose, or None for a goal region (goal_outside)")
      .def_property_readonly("goal_outside", [](const PyProblem& p) { return p.problem.goal_outside; })
      .def_property_readonly("goal_margin", [](const PyProblem& p) { return p.problem.goal_margin; })
      .def_property_readonly("obstacle_files", [](const PyProblem& p) {
            std::vector<std::string> v;
            for (const auto& r : p.problem.obstacles) v.push_back(r.file.string());
            return v;
          })
      .def_property_readonly("notes", [](const PyProblem& p) { return p.problem.notes; },
                             "What the file asks for that swept does not do (an OMPL.app .cfg's settings for "
                             "OMPL's planners), one line each naming the file and line, as `swept plan` prints them")
      .def_property_readonly("body_files", [](const PyProblem& p) {
            std::vector<std::string> v;
            for (const auto& r : p.problem.body) v.push_back(r.file.string());
            return v;
          })
      .def_property("clearance", [](const PyProblem& p) { return p.problem.clearance; },
                    [](PyProblem& p, double v) {
                      if (!(v >= 0) || !std::isfinite(v)) throw InputError("clearance must be a finite number >= 0, not " + std::to_string(v));
                      p.problem.clearance = v;
                    })
      .def_property("contact_tolerance", [](const PyProblem& p) { return p.problem.contact_tolerance; },
                    [](PyProblem& p, double v) {
                      if (!(v >= 0) || !std::isfinite(v)) throw InputError("contact_tolerance must be a finite number >= 0, not " + std::to_string(v));
                      p.problem.contact_tolerance = v;
                    })
      .def_property("fitter", [](const PyProblem& p) { return std::string(to_string(p.problem.build.fitter)); },
                    [](PyProblem& p, const std::string& v) { p.problem.build.fitter = fitter_from(v); })
      .def_property("time_limit", [](const PyProblem& p) { return p.problem.time_limit; },
                    [](PyProblem& p, double v) {
                      if (!(v > 0) || !std::isfinite(v)) throw InputError("time_limit must be a positive number of seconds, not " + std::to_string(v));
                      p.problem.time_limit = v;
                    })
      .def_property("threads", [](const PyProblem& p) { return p.problem.threads; },
                    [](PyProblem& p, int v) {
                      if (v < 0) throw InputError("threads must be >= 0 (0: all cores), not " + std::to_string(v));
                      p.problem.threads = v;
                    })
      .def_property("seed", [](const PyProblem& p) { return p.problem.seed; },
                    [](PyProblem& p, std::int64_t v) { set_seed(p.problem, v); })
      .def("__repr__", [](const PyProblem& p) {
        return "swept.Problem('" + p.problem.source.string() + "', clearance=" + std::to_string(p.problem.clearance) +
               ", fitter='" + std::string(to_string(p.problem.build.fitter)) + "')";
      });

  pyb::class_<PyScene>(m, "Scene", R"doc(
A problem's meshes loaded (units, deflection and placements applied) with their RSS trees, built
with `fitter` (default: the problem's). Reuse one for many plans of the same problem file with
different clearances or time limits: swept.plan(problem, scene=scene).)doc")
      .def(pyb::init(&scene_load), arg("problem"), arg("fitter") = pyb::none())
      .def_property_readonly("fitter", [](const PyScene& s) { return std::string(to_string(s.fitter)); })
      .def_property_readonly("source", [](const PyScene& s) { return s.source.string(); })
      .def_property_readonly("obstacle_tree", [](const PyScene& s) { return scene_tree(s, s.scene->obstacle_tree); },
                             "BVH of the obstacles (world frame)")
      .def_property_readonly("body_tree", [](const PyScene& s) { return scene_tree(s, s.scene->body_tree); },
                             "BVH of the body (body frame)")
      .def_property_readonly("reference", [](const PyScene& s) { return vec3_array(s.scene->reference); })
      .def_property_readonly("radius", [](const PyScene& s) { return s.scene->radius; })
      .def_property_readonly("obstacle_triangles", [](const PyScene& s) { return s.scene->obstacles.triangles.size(); })
      .def_property_readonly("body_triangles", [](const PyScene& s) { return s.scene->body.triangles.size(); })
      .def_property_readonly("warnings", [](const PyScene& s) { return s.scene->warnings; },
                             "What reading the meshes left out or noticed, each naming its file (as `swept plan` prints them)")
      .def_property_readonly("load_ms", [](const PyScene& s) { return s.scene->load_ms; })
      .def_property_readonly("build_ms", [](const PyScene& s) { return s.scene->build_ms; });

  m.def("_plan", &plan_py, arg("problem"), arg("time_limit") = pyb::none(), arg("threads") = pyb::none(),
        arg("scene") = pyb::none(), arg("max_queries") = pyb::none(), arg("seed") = pyb::none());
}

}  // namespace swept::py
