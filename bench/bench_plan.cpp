// Side-by-side planner benchmark: swept's certified, deterministic planner against OMPL's
// RRTConnect with FCL collision checking (Debian libompl-dev, libfcl-dev), on the same problems
// in one run. The benchmark is the swept_bench library (swept/bench/plan_compare.h for both
// sides, ompl_peer.h for OMPL's set-up); this program picks the problems and prints.
//
//   bench_plan [--quick] [--time-limit S] [--seeds N] [--threads N] [--only a,b,...] [--no-cad]
//              [--suite classic|ompl|all] [--swept-time-limit S] [--thread-check] [--swept-seeds]
//              [--ompl-collide-only] [--problem FILE]... [--json FILE]
//
// Problems (--suite classic, the default): the box problems of the scenes library (peg_in_hole,
// t_slot, l_tunnel, bar_through_slot, enclosed) and the CAD scenes of `swept scene` at test
// scale (generated into a temporary directory; skipped with a message when generation fails).
// --suite ompl: the planner benchmark suite of issue 13 (swept/scenes/planning_suite.h, the
// counterparts of OMPL.app's problems), written by `swept scene`'s writer and read back from
// their problem.toml; swept gets --swept-time-limit (default 300 s) on the hard ones (trap,
// hooks), and on --problem files when the flag is given; OMPL keeps --time-limit. --suite all:
// both. --problem FILE (repeatable): a problem file of the user's, our problem.toml or an
// OMPL.app .cfg (e.g. OMPL.app's own resources/3D/*.cfg), read by load_problem as `swept plan`
// reads it; given alone, only those files run.
#include "swept/bench/plan_compare.h"
#include "swept/bench/timing.h"
#include "swept/io/file_write.h"
#include "swept/scenes/box_problems.h"
#include "swept/scenes/planning_suite.h"
#include "swept/scenes/scenes.h"

#include <ompl/util/Console.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace swept;
using namespace swept::bench;

[[noreturn]] void usage(const std::string& why) {
  std::cerr << "bench_plan: " << why << "\n"
            << "usage: bench_plan [--quick] [--time-limit S] [--seeds N] [--threads N] [--only a,b] [--no-cad] "
               "[--suite classic|ompl|all] [--swept-time-limit S] [--thread-check] [--swept-seeds] [--ompl-collide-only] "
               "[--problem FILE]... [--json FILE]\n"
            << "  --quick        10 s limit, 5 seeds (defaults: 60 s, 5 seeds)\n"
            << "  --suite S      classic: box problems and CAD scenes (default); ompl: the OMPL.app counterparts "
               "(twisty-slot, bug-trap, hooks-1.5, hooks-1.2, hooks-1.1, house, cubicles, spiral-tube); all: both\n"
            << "  --swept-time-limit S  swept's limit on the suite's hard problems (bug-trap, hooks-*; default 300 s; "
               "OMPL keeps --time-limit),\n"
               "                 and, when given, on the --problem files\n"
            << "  --thread-check one more swept run at 1 thread per solved problem: the path hash must not change\n"
            << "                 (its time is printed, and how many times swept's median it is: what the other cores gave)\n"
            << "  --swept-seeds  swept over seeds too, as OMPL is: one more run for each seed 1..N-1 (another draw of\n"
               "                 the trees' samples), each path re-checked; their median with seed 0's beside OMPL's\n"
            << "  --threads N    swept's threads (0: all cores; default 0)\n"
            << "  --only a,b     only these problems (peg_in_hole, t_slot, l_tunnel, bar_through_slot, enclosed, "
               "air-cleaner, cylinder-head, tunnel-console, or the --suite ompl names)\n"
            << "  --no-cad       skip the CAD scenes\n"
            << "  --ompl-collide-only  OMPL's validity check without the clearance (fcl::collide only)\n"
            << "  --problem FILE a problem file (problem.toml or an OMPL.app .cfg), run as `swept plan` reads it;\n"
               "                 repeatable; given without --suite, only these files run\n"
            << "  --json FILE    also write the results as JSON\n";
  std::exit(2);
}

}  // namespace

int main(int argc, char** argv) {
  CompareOptions o;
  double& limit = o.time_limit;
  int& seeds = o.seeds;
  int& threads = o.threads;
  bool& collide_only = o.collide_only;
  bool cad = true;
  std::string suite = "classic";
  bool suite_given = false;
  std::vector<std::string> problem_files;
  double swept_hard_limit = 300.0;
  bool swept_limit_given = false;
  std::vector<std::string> only;
  std::string json_file;
  auto number = [&](int& i, const std::string& flag) -> double {
    if (i + 1 >= argc) usage(flag + " needs a value");
    char* end = nullptr;
    const double v = std::strtod(argv[++i], &end);
    if (end == argv[i] || *end != '\0' || !std::isfinite(v)) usage(flag + ": not a number: " + argv[i]);
    return v;
  };
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--quick") {
      limit = 10.0;
      seeds = 5;
    } else if (a == "--time-limit") {
      limit = number(i, a);
      if (limit <= 0) usage("--time-limit must be > 0");
    } else if (a == "--seeds") {
      seeds = static_cast<int>(number(i, a));
      if (seeds < 1) usage("--seeds must be >= 1");
    } else if (a == "--threads") {
      threads = static_cast<int>(number(i, a));
      if (threads < 0) usage("--threads must be >= 0");
    } else if (a == "--only") {
      if (i + 1 >= argc) usage("--only needs a value");
      std::stringstream ss(argv[++i]);
      for (std::string n; std::getline(ss, n, ',');)
        if (!n.empty()) only.push_back(n);
    } else if (a == "--suite") {
      if (i + 1 >= argc) usage("--suite needs a value");
      suite = argv[++i];
      suite_given = true;
      if (suite != "classic" && suite != "ompl" && suite != "all")
        usage("--suite: unknown suite '" + suite + "' (classic, ompl or all)");
    } else if (a == "--swept-time-limit") {
      swept_hard_limit = number(i, a);
      if (swept_hard_limit <= 0) usage("--swept-time-limit must be > 0");
      swept_limit_given = true;
    } else if (a == "--thread-check") {
      o.thread_check = true;
    } else if (a == "--swept-seeds") {
      o.swept_seeds = true;
    } else if (a == "--no-cad") {
      cad = false;
    } else if (a == "--ompl-collide-only") {
      collide_only = true;
    } else if (a == "--problem") {
      if (i + 1 >= argc) usage("--problem needs a file");
      problem_files.emplace_back(argv[++i]);
    } else if (a == "--json") {
      if (i + 1 >= argc) usage("--json needs a file");
      json_file = argv[++i];
    } else if (a == "-h" || a == "--help") {
      usage("side-by-side planner benchmark against OMPL RRTConnect + FCL");
    } else {
      usage("unknown argument " + a);
    }
  }
  auto wanted = [&](const std::string& n) { return only.empty() || std::find(only.begin(), only.end(), n) != only.end(); };
  ompl::msg::setLogLevel(ompl::msg::LOG_WARN);

  // Problem files alone replace the built-in problems; with --suite they run first, then the suite.
  if (!problem_files.empty() && !suite_given) {
    suite = "none";
    cad = false;
  }
  const bool classic = suite == "classic" || suite == "all";
  std::vector<PlanCase> cases;
  for (const std::string& file : problem_files) {
    auto loaded = load_problem(file);
    if (!loaded) {
      std::fprintf(stderr, "bench_plan: %s\n", loaded.error().message.c_str());
      return 1;
    }
    // Named by the file's stem, or by its folder for `swept scene`'s problem.toml.
    const std::filesystem::path path(file);
    std::string name = path.stem().string();
    if (name == "problem" && !std::filesystem::absolute(path).parent_path().filename().empty())
      name = std::filesystem::absolute(path).parent_path().filename().string();
    // A file's hardness is the user's to say: --swept-time-limit, when given, is swept's limit on it.
    cases.push_back(PlanCase{name, *loaded, std::nullopt, std::nullopt, "file", swept_limit_given ? swept_hard_limit : 0.0});
  }
  for (auto& g : scenes::box_problems()) {
    if (!classic || !wanted(g.name)) continue;
    cases.push_back(PlanCase{g.name, g.problem, std::move(g.obstacles), std::move(g.body), "box", 0.0});
  }
  std::filesystem::path tmp;
  auto make_tmp = [&] {
    if (tmp.empty()) {
      tmp = std::filesystem::temp_directory_path() /
            ("swept-bench-plan-" + std::to_string(static_cast<long long>(std::time(nullptr))));
    }
  };
  if (suite == "ompl" || suite == "all") {
    for (const scenes::SuiteInfo& info : scenes::suite_catalog()) {
      if (!wanted(info.name)) continue;
      make_tmp();
      auto problem = scenes::suite_problem(info.name);
      auto files = problem ? scenes::write_suite_problem(*problem, tmp / info.name) : Result<scenes::SuiteFiles>(problem.error());
      auto loaded = files ? load_problem(files->problem_toml) : Result<Problem>(files.error());
      if (!loaded) {
        std::fprintf(stderr, "bench_plan: skipping %s: %s\n", info.name.c_str(), loaded.error().message.c_str());
        continue;
      }
      cases.push_back(PlanCase{info.name, *loaded, std::nullopt, std::nullopt, "suite", info.hard ? swept_hard_limit : 0.0});
    }
  }
  if (cad && classic) {
    for (const auto& info : scenes::catalog()) {
      if (!wanted(info.name)) continue;
      make_tmp();
      const auto t0 = Clock::now();
      auto report = scenes::generate_scene({.name = info.name, .scale = scenes::Scale::test, .output_dir = tmp / info.name});
      if (!report) {
        std::fprintf(stderr, "bench_plan: skipping the CAD scene %s: %s\n", info.name.c_str(), report.error().message.c_str());
        continue;
      }
      auto problem = load_problem(report->problem_file);
      if (!problem) {
        std::fprintf(stderr, "bench_plan: skipping the CAD scene %s: %s\n", info.name.c_str(), problem.error().message.c_str());
        continue;
      }
      std::fprintf(stderr, "bench_plan: generated %s (%zu + %zu triangles) in %.1f s\n", info.name.c_str(),
                   report->body_triangles, report->obstacle_triangles, ms_since(t0) / 1e3);
      cases.push_back(PlanCase{info.name, *problem, std::nullopt, std::nullopt, "cad", 0.0});
    }
  }
  if (cases.empty()) usage("no problem selected");

  std::vector<CompareRow> rows;
  for (const PlanCase& c : cases) {
    std::fprintf(stderr, "bench_plan: %s\n", c.name.c_str());
    rows.push_back(run_case(c, o));
    if (!rows.back().error.empty()) std::fprintf(stderr, "  not run: %s\n", rows.back().error.c_str());
    if (!json_file.empty()) {  // rewritten after every problem, so a long run leaves partial results
      // Whole or not at all (a temporary file renamed into place); invalid UTF-8 in names becomes U+FFFD.
      const std::string text =
          to_json(rows, o).dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
      if (auto written = write_file_atomically(json_file, text); !written)
        std::fprintf(stderr, "bench_plan: %s\n", written.error().message.c_str());
    }
  }
  print_tables(rows, o);
  if (!tmp.empty()) {
    std::error_code ec;
    std::filesystem::remove_all(tmp, ec);
  }
  return 0;
}

