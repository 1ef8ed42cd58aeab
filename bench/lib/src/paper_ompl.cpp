// `swept bench paper`, the OMPL peer: RRTConnect + FCL on the same scenes, run by the bench_plan
// program (OMPL is linked into bench_plan, not into the CLI) and read back from its JSON.
#include "swept/bench/paper.h"
#include "swept/bench/plan_compare.h"
#include "swept/bench/timing.h"

#include "swept/scenes/scenes.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <limits>

namespace swept::bench {

namespace fs = std::filesystem;

namespace {

fs::path default_bench_plan() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  // <build>/apps/swept/swept-tools (what `swept bench paper` runs) → <build>/bench/bench_plan
  return exe.parent_path().parent_path().parent_path() / "bench" / "bench_plan";
}

std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

}  // namespace

void run_ompl(const PaperOptions& o, bool paper, const fs::path& out, Results& res) {
  res.ompl_time_limit = o.ompl_time_limit > 0 ? o.ompl_time_limit : (paper ? 60.0 : 10.0);
  if (o.no_ompl) {
    res.ompl_status = "not run (--no-ompl)";
    return;
  }
  const fs::path prog = o.bench_plan.empty() ? default_bench_plan() : fs::path(o.bench_plan);
  if (prog.empty() || !fs::exists(prog)) {
    res.ompl_status = "not run: the bench_plan program (" + (prog.empty() ? std::string("?") : prog.string()) +
                      ") is not built; build it with `cmake --build <build> --target bench_plan` or name it with "
                      "--bench-plan";
    log_line(o, std::string("bench paper: OMPL ") + res.ompl_status);
    return;
  }
  // The scenes of this benchmark (bench_plan generates them itself, at test scale).
  std::string names;
  for (const scenes::SceneInfo& s : scenes::catalog()) {
    if (!o.only.empty() && std::find(o.only.begin(), o.only.end(), s.name) == o.only.end()) continue;
    names += (names.empty() ? "" : ",") + s.name;
  }
  if (names.empty()) {
    res.ompl_status = "not run: no scene";
    return;
  }
  const fs::path json = out / "bench_plan.json";
  const std::string cmd = shell_quote(prog.string()) + " --only " + names + " --seeds " + std::to_string(o.runs) +
                          " --time-limit " + fmt_g(res.ompl_time_limit, 6) + " --threads " + std::to_string(o.threads) +
                          " --json " + shell_quote(json.string()) + " > " + shell_quote((out / "bench_plan.txt").string()) +
                          " 2> " + shell_quote((out / "bench_plan.log").string());
  log_line(o, std::string("bench paper: OMPL RRTConnect + FCL via ") + prog.string() + " (test-scale scenes)");
  const int rc = std::system(cmd.c_str());
  std::ifstream in(json);
  if (rc != 0 || !in) {
    res.ompl_status = "bench_plan failed (exit " + std::to_string(rc) + "); see bench_plan.log";
    return;
  }
  nlohmann::json j;
  try {
    in >> j;
  } catch (const std::exception& e) {
    res.ompl_status = std::string("bench_plan wrote unreadable JSON: ") + e.what();
    return;
  }
  std::vector<CompareRow> rows;
  try {
    rows = rows_from_json(j);
  } catch (const std::exception& e) {
    res.ompl_status = std::string("bench_plan wrote JSON this benchmark cannot read: ") + e.what();
    return;
  }
  for (const CompareRow& p : rows) {
    OmplRow row;
    row.problem = p.name;
    if (!p.error.empty()) {
      res.notes.push_back("bench_plan: " + row.problem + " not run: " + p.error);
      continue;
    }
    std::vector<double> times;
    for (const OmplRun& r : p.ompl) times.push_back(r.ms);
    row.runs = static_cast<int>(p.ompl.size());
    row.successes = p.ompl_successes();
    const Spread sp = spread_of(times);
    row.median_ms = sp.median;
    row.min_ms = sp.min;
    row.max_ms = sp.max;
    row.fcl_build_ms = p.ompl_fcl_build_ms;
    // The paper's method (the scenes' fitter): its first run in bench_plan.
    for (const SweptRun& s : p.swept) {
      if (s.fitter != Fitter::inertia) continue;
      row.swept_ms = s.plan_ms;
      row.swept_status = status_name(s.result.status);
      break;
    }
    res.ompl.push_back(row);
  }
  res.ompl_status = "bench_plan (" + prog.string() + "): OMPL RRTConnect + FCL OBBRSS, " + std::to_string(o.runs) +
                    " seeds, " + fmt_g(res.ompl_time_limit) +
                    " s limit per run (failed runs count as the limit in the median), on the scenes at test scale";
}

}  // namespace swept::bench
