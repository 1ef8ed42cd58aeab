// `swept check`: certifies a path (ours or OMPL's `.path`, from swept or any other planner)
// against a problem with the certificate the planner uses (swept::check_path).
#include "commands.h"
#include "part_source.h"
#include "output.h"
#include "progress_line.h"

#include "swept/plan/check.h"
#include "swept/plan/planner.h"

#include <nlohmann/json.hpp>

#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

namespace swept::cli {
namespace {

struct CheckCliOptions {
  ProblemSource source;  ///< the problem file, or an assembly's part (--part)
  std::string path;
  double clearance = -1.0;
  std::string reference;
  bool json = false;
  bool quiet = false;
};

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// The body-frame point the path's motions interpolate about: --reference, else the path file's
// own (our JSON records it), else OMPL's convention for `.path` (the body frame's origin).
Vec3 reference_of(const CheckCliOptions& o, const Problem& problem, const PlanScene& scene) {
  if (o.reference == "origin") return Vec3::Zero();
  if (o.reference == "problem") return scene.reference;
  if (!o.reference.empty()) {
    std::istringstream in(o.reference);
    Vec3 p;
    char c1 = 0, c2 = 0;
    if (!(in >> p.x() >> c1 >> p.y() >> c2 >> p.z()) || c1 != ',' || c2 != ',' || !(in >> std::ws).eof() ||
        !p.allFinite())
      throw std::runtime_error("--reference must be origin, problem or x,y,z (got '" + o.reference + "')");
    return p;
  }
  if (ends_with(o.path, ".path")) return Vec3::Zero();
  std::ifstream in(o.path);
  nlohmann::json doc = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  if (doc.is_object() && doc.contains("unit") && doc["unit"].is_string() && doc["unit"].get<std::string>() != problem.unit)
    throw std::runtime_error(o.path + ": the path is in " + doc["unit"].get<std::string>() + ", the problem in " +
                             problem.unit);
  if (doc.is_object() && doc.contains("reference_point")) {
    const auto& r = doc["reference_point"];
    if (!r.is_array() || r.size() != 3 || !r[0].is_number() || !r[1].is_number() || !r[2].is_number())
      throw std::runtime_error(o.path + ": reference_point must be an array of three numbers");
    const Vec3 p(r[0].get<double>(), r[1].get<double>(), r[2].get<double>());
    if (!p.allFinite()) throw std::runtime_error(o.path + ": reference_point is not finite");
    return p;
  }
  return scene.reference;
}

nlohmann::json pose_json(const Pose& p) {
  const Quat q = p.quaternion();
  return {{"translation", {p.translation.x(), p.translation.y(), p.translation.z()}},
          {"quaternion", {q.x(), q.y(), q.z(), q.w()}}};
}

std::string pose_text(const Pose& p) {
  const Quat q = p.quaternion();
  std::ostringstream os;
  os << std::setprecision(9) << "translation (" << p.translation.x() << ", " << p.translation.y() << ", "
     << p.translation.z() << "), quaternion (" << q.x() << ", " << q.y() << ", " << q.z() << ", " << q.w() << ")";
  return os.str();
}

void run(const CheckCliOptions& o) {
  auto path = read_path(o.path);
  if (!path) throw std::runtime_error(path.error().message);
  if (path->poses.empty()) throw std::runtime_error(o.path + ": the path has no poses");
  ProblemSource source = o.source;
  if (o.clearance >= 0) source.clearance = o.clearance;
  PartProblem loaded = load_problem_source(source);
  const Problem* problem = &loaded.problem;
  const PlanScene* scene = &loaded.scene;
  PathCheckOptions options;
  if (o.clearance >= 0) options.clearance = o.clearance;
  options.reference_point = reference_of(o, *problem, *scene);
  ProgressLine line(!o.quiet);
  if (line.on()) options.progress = [&line](std::size_t done, std::size_t total) { line.count("checking", done, total, "segments"); };
  const PathCheckResult r = check_path(*problem, *scene, *path, options);
  line.clear();

  if (o.json) {
    nlohmann::json segments = nlohmann::json::array();
    for (const SegmentCheck& s : r.segments) {
      nlohmann::json j{{"certified", s.certified}, {"min_distance", s.min_distance}, {"t_min", s.t_min}};
      if (s.in_contact) j["in_contact"] = true;
      if (!s.certified) j["blocked"] = {{"t", s.t_blocked}, {"distance", s.distance_at_block}};
      segments.push_back(std::move(j));
    }
    nlohmann::json doc{{"valid", r.valid},
                       {"message", r.message},
                       {"clearance", r.clearance},
                       {"unit", problem->unit},
                       {"waypoints", path->poses.size()},
                       {"reference_point", {options.reference_point->x(), options.reference_point->y(), options.reference_point->z()}},
                       {"min_clearance", r.min_clearance},
                       {"min_at", {{"segment", r.min_segment}, {"t", r.min_t}, {"pose", pose_json(r.min_pose)}}},
                       {"first_invalid", nullptr},
                       {"contact_segments", r.contact_segments},
                       {"segments", segments},
                       {"warnings", scene->warnings},
                       {"distance_queries", r.distance_queries},
                       {"sweeps", r.sweeps}};
    if (r.first_bad_segment) {
      const SegmentCheck& s = r.segments[*r.first_bad_segment];
      doc["first_invalid"] = {{"segment", *r.first_bad_segment},
                              {"t", s.t_blocked},
                              {"distance", r.first_bad_distance},
                              {"colliding", r.first_bad_distance <= 0.0},
                              {"pose", pose_json(r.first_bad_pose)}};
    }
    std::cout << json_text(doc, 2) << "\n";
  } else {
    std::cout << std::setprecision(6) << "problem      " << o.source.file << "\n"
              << "path         " << o.path << ": " << path->poses.size() << " waypoints\n";
    for (const std::string& w : scene->warnings) std::cout << "warning      " << w << "\n";
    std::cout
              << "result       " << r.message << "\n"
              << "clearance    min " << r.min_clearance << " " << problem->unit << " (required " << r.clearance
              << ") in segment " << r.min_segment << " at t = " << r.min_t << "\n";
    if (r.contact_segments > 0)
      std::cout << "contact      " << r.contact_segments << (r.contact_segments == 1 ? " segment" : " segments")
                << " with an end in contact, each certified as a pull by the mate rule (tolerance " << problem->contact_tolerance
                << " " << problem->unit << ")\n";
    if (r.first_bad_segment)
      std::cout << "first bad    segment " << *r.first_bad_segment << ": distance " << r.first_bad_distance
                << (r.first_bad_distance <= 0.0 ? " (in collision)" : "") << " at " << pose_text(r.first_bad_pose)
                << "\n";
  }
  if (!r.valid) throw ExitCode{2};
}

}  // namespace

void add_check_command(CLI::App& app) {
  auto o = std::make_shared<CheckCliOptions>();
  CLI::App* cmd = app.add_subcommand(
      "check",
      "Certify a path against a problem with the planner's own certificate: every segment must keep\n"
      "the clearance along the whole continuous motion (position linear, rotation slerp about the\n"
      "reference point). Prints the minimum clearance and where, and the first pose where the path\n"
      "comes too close or collides. Exit 0: valid; 2: not valid; 1: bad input.");
  cmd->add_option("problem", o->source.file,
                  "Problem file (.toml or OMPL.app .cfg), or with --part an assembly (as swept disassemble reads it)")
      ->required();
  add_part_options(*cmd, o->source);
  cmd->add_option("path", o->path, "Path file: our JSON, or OMPL .path (x y z qx qy qz qw per line, or OMPL's printed SE(3) states as OMPL.app ships its paths)")->required();
  cmd->add_option("--clearance", o->clearance, "Required clearance (default: the problem's)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--reference", o->reference,
                  "Point the motions interpolate about: origin | problem | x,y,z (body frame). Default: the\n"
                  "path file's own (JSON), the body frame's origin for .path (OMPL's interpolation)");
  cmd->add_flag("--json", o->json, "Print one JSON document");
  cmd->add_flag("-q,--quiet", o->quiet, "No progress line (there is none either when stderr is not a terminal)");
  cmd->callback([o] { run(*o); });
}

}  // namespace swept::cli
