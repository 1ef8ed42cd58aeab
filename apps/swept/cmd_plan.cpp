// `swept plan`: a certified, deterministic disassembly path for a problem file.
#include "cli_options.h"
#include "commands.h"
#include "part_source.h"
#include "output.h"

#include "swept/plan/planner.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <ctime>
#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <unistd.h>

namespace swept::cli {
namespace {

struct PlanCliOptions {
  std::string problem;
  std::string fitter;
  double time_limit = 0.0;
  std::uint64_t max_queries = 0;
  int threads = -1;
  std::optional<std::uint64_t> seed;
  std::string output;
  std::string view;
  bool json = false;
  bool quiet = false;
  ProblemSource source;  ///< the problem file, or an assembly's part (--part)
};

std::string hex(std::uint64_t h) {
  std::ostringstream os;
  os << std::hex << std::setw(16) << std::setfill('0') << h;
  return os.str();
}

void run(const PlanCliOptions& o) {
  ProblemSource source = o.source;
  if (!o.fitter.empty()) source.fitter = fitters_from(o.fitter, false).front();
  PartProblem loaded = load_problem_source(source);
  Problem* problem = &loaded.problem;
  const PlanScene* scene = &loaded.scene;
  if (o.time_limit > 0) problem->time_limit = o.time_limit;
  if (o.threads >= 0) problem->threads = o.threads;
  if (o.seed) problem->seed = *o.seed;

  PlanOptions options;
  if (o.max_queries > 0) options.max_queries = o.max_queries;
  const bool tty = isatty(fileno(stderr)) && !o.quiet;
  if (tty) {
    options.progress = [](const PlanProgress& p) {
      if (p.level == kTreeLevel)
        std::fprintf(stderr, "\r  trees  nodes %zu  queries %llu  %.1f s   ", p.nodes_checked,
                     static_cast<unsigned long long>(p.queries), p.elapsed_s);
      else
        std::fprintf(stderr, "\r  level %d  nodes %zu  queries %llu  %.1f s   ", p.level, p.nodes_checked,
                     static_cast<unsigned long long>(p.queries), p.elapsed_s);
      std::fflush(stderr);
    };
  }
  // The process's CPU time over plan() (every thread, TBB's spin-waiting included): next to the
  // wall time it shows whether the planner had its cores (about threads × wall when it did;
  // near the wall time when another process took one, e.g. a program started beside it).
  auto cpu_ms = [] {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
  };
  const double cpu_before = cpu_ms();
  const PlanResult r = plan(*problem, *scene, options);
  const double cpu = cpu_ms() - cpu_before;
  if (tty) std::fprintf(stderr, "\r%60s\r", "");

  if (r.status == PlanStatus::invalid_start || r.status == PlanStatus::invalid_goal ||
      r.status == PlanStatus::invalid_bounds)
    throw std::runtime_error(o.source.file + ": " + r.message);

  if (r.solved() && !o.output.empty()) {
    auto w = write_path(o.output, r.path, problem->unit, scene->reference);
    if (!w) throw std::runtime_error(w.error().message);
  }
  if (!o.view.empty()) {
    if (!r.solved()) std::cerr << "swept: no path, so no view written\n";
    else write_view_file(*problem, *scene, r.path, o.view);
  }
  if (o.json) {
    nlohmann::json doc{
        {"solved", r.solved()},
        {"message", r.message},
        {"waypoints", r.path.poses.size()},
        {"path_length", r.path_length},
        {"translation_length", r.translation_length},
        {"rotation_length_rad", r.rotation_length},
        {"min_clearance", r.solved() ? nlohmann::json(r.min_clearance) : nlohmann::json(nullptr)},
        {"escape", r.solved() && r.escape_segments > 0 ? nlohmann::json{{"segments", r.escape_segments}}
                                                       : nlohmann::json(nullptr)},
        {"approach", r.solved() && r.approach_segments > 0 ? nlohmann::json{{"segments", r.approach_segments}}
                                                           : nlohmann::json(nullptr)},
        {"time_ms", {{"build", r.time_ms.build}, {"search", r.time_ms.search}, {"smooth", r.time_ms.smooth}, {"total", r.time_ms.total},
                     {"cpu", cpu}}},
        {"queries", {{"distance", r.queries.distance}, {"proximity", r.queries.proximity}, {"sweep", r.queries.sweep}}},
        {"path_hash", hex(r.path_hash)},
        {"notes", problem->notes},
        {"warnings", scene->warnings},
        {"seed", problem->seed},
        {"unit", problem->unit},
        {"fitter", std::string(to_string(problem->build.fitter))},
        {"split", std::string(to_string(problem->build.split))},
        {"leaf_size", problem->build.leaf_size},
        {"nodes_checked", r.nodes_checked},
        {"edges_checked", r.edges_checked}};
    std::cout << json_text(doc, 2) << "\n";
  } else {
    std::cout << "problem      " << o.source.file << "\n";
    for (const std::string& note : problem->notes) std::cout << "note         " << note << "\n";
    for (const std::string& w : scene->warnings) std::cout << "warning      " << w << "\n";
    std::cout << "meshes       obstacles " << scene->obstacles.triangles.size() << " triangles, body "
              << scene->body.triangles.size() << " triangles (fitter " << to_string(problem->build.fitter) << ", split "
              << to_string(problem->build.split) << ", leaf size " << problem->build.leaf_size << ")\n"
              << "result       " << r.message << "\n";
    if (r.solved()) {
      std::cout << std::setprecision(6) << "path         " << r.path.poses.size() << " waypoints, length "
                << r.path_length << " " << problem->unit << " (translation " << r.translation_length << " "
                << problem->unit << ", rotation " << r.rotation_length * 180.0 / 3.14159265358979323846 << " deg)\n"
                << "clearance    min " << r.min_clearance << " " << problem->unit << " (required " << problem->clearance
                << (r.escape_segments > 0 ? "; the start is in contact" : "")
                << (r.approach_segments > 0 ? "; the goal is in contact" : "") << ")\n";
      auto pulls = [](std::size_t n) { return n == 1 ? "one straight pull" : "a slide, then a straight pull"; };
      if (r.escape_segments > 0)
        std::cout << "escape       " << pulls(r.escape_segments) << " out of contact, certified by the mate rule (tolerance "
                  << problem->contact_tolerance << " " << problem->unit << ")\n";
      if (r.approach_segments > 0)
        std::cout << "approach     " << pulls(r.approach_segments) << " into contact, played backwards, certified by the mate rule (tolerance "
                  << problem->contact_tolerance << " " << problem->unit << ")\n";
      std::cout << "path hash    " << hex(r.path_hash) << (problem->seed != 0 ? " (seed " + std::to_string(problem->seed) + ")" : "")
                << "\n";
      if (!o.output.empty()) std::cout << "written      " << o.output << "\n";
    }
    std::cout << std::setprecision(4) << "time         build " << r.time_ms.build << " ms, search " << r.time_ms.search
              << " ms, smooth " << r.time_ms.smooth << " ms, total " << r.time_ms.total << " ms (CPU after the build "
              << cpu << " ms)\n"
              << "queries      distance " << r.queries.distance << ", nodes " << r.nodes_checked << ", edges "
              << r.edges_checked << "\n";
  }
  if (!r.solved()) {
    std::cerr << "swept: no path: " << r.message << "\n";
    throw ExitCode{2};
  }
}

}  // namespace

void add_plan_command(CLI::App& app) {
  auto o = std::make_shared<PlanCliOptions>();
  CLI::App* cmd = app.add_subcommand(
      "plan",
      "Plan a certified, deterministic 6-DOF path for the body of a problem file (our TOML, see\n"
      "docs/problem-format.md, or an OMPL.app .cfg). Every segment keeps the clearance margin along\n"
      "the whole continuous motion. Exit 0: solved; 2: no path within the limits (the message says\n"
      "which: time, query budget, bounds or resolution); 1: bad input.");
  cmd->add_option("problem", o->source.file,
                  "Problem file (.toml or OMPL.app .cfg), or with --part an assembly (as swept disassemble reads it)")
      ->required();
  add_part_options(*cmd, o->source);
  cmd->add_option("--clearance", o->source.clearance, "With --part: the clearance every non-mated pair keeps (default 0.01)")
      ->check(CLI::NonNegativeNumber);
  add_fitter_option(*cmd, o->fitter, "Override the fitter", false);
  cmd->add_option("--time-limit", o->time_limit, "Override the time limit, seconds")->check(CLI::PositiveNumber);
  cmd->add_option("--max-queries", o->max_queries,
                  "Stop after this many distance queries: a limit on the work that, unlike the time limit, gives the same "
                  "outcome on every machine and at any thread count")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--threads", o->threads, "Override the thread count (0: all cores); the same path at any count (tested: 1, 2, 4, 8)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--seed", o->seed,
                  "Which draw of the trees' sample sequence (default: the problem's planner.seed, else 0): another "
                  "seed, another path and time where the trees solve it; the same path for the same seed at any "
                  "thread count")
      ->check(CLI::Validator(
          [](std::string& v) -> std::string {
            // As planner.seed in a problem file (a TOML integer): 0 to 2^63 − 1.
            const bool digits = !v.empty() && v.size() <= 19 && v.find_first_not_of("0123456789") == std::string::npos;
            if (!digits || std::stoull(v) > static_cast<unsigned long long>(std::numeric_limits<std::int64_t>::max()))
              return "must be a whole number from 0 to " + std::to_string(std::numeric_limits<std::int64_t>::max()) + ", got " + v;
            return {};
          },
          "SEED"));
  cmd->add_option("-o,--output", o->output, "Write the path: OMPL .path when the name ends in .path, else JSON");
  cmd->add_option("--view", o->view, "Also write a self-contained HTML viewer of the path");
  cmd->add_flag("--json", o->json, "Print one JSON document with the result and statistics");
  cmd->add_flag("-q,--quiet", o->quiet, "No progress line");
  cmd->callback([o] { run(*o); });
}

}  // namespace swept::cli
