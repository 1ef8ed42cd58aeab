// `swept bench paper`, report.md: the tables, the verdicts on the paper's claims, the notes.
#include "swept/bench/fcl_peer.h"
#include "swept/bench/output.h"
#include "swept/bench/paper.h"

#include <sys/utsname.h>

#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <sstream>
#include <thread>

namespace swept::bench {

namespace fs = std::filesystem;

std::string fmt_spread(const Spread& s, int digits) {
  if (!std::isfinite(s.median)) return "n/a";
  if (s.samples.size() <= 1) return fmt_fixed(s.median, digits);
  return fmt_fixed(s.median, digits) + " (" + fmt_fixed(s.min, digits) + "–" + fmt_fixed(s.max, digits) + ")";
}

std::string fmt_g(double v, int digits) {
  if (!std::isfinite(v)) return "n/a";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

std::string machine_description() {
  std::string cpu;
  std::ifstream info("/proc/cpuinfo");
  for (std::string line; std::getline(info, line);)
    if (line.rfind("model name", 0) == 0) {
      cpu = line.substr(line.find(':') + 2);
      break;
    }
  std::string mem;
  std::ifstream meminfo("/proc/meminfo");
  for (std::string line; std::getline(meminfo, line);)
    if (line.rfind("MemTotal:", 0) == 0) {
      std::istringstream ss(line.substr(9));
      double kb = 0;
      ss >> kb;
      mem = fmt_fixed(kb / (1024.0 * 1024.0), 1) + " GiB RAM";
      break;
    }
  utsname u{};
  std::string os;
  if (::uname(&u) == 0) os = std::string(u.sysname) + " " + u.release + " " + u.machine;
  std::string s = (cpu.empty() ? std::string("unknown CPU") : cpu) + ", " +
                  std::to_string(std::thread::hardware_concurrency()) + " hardware threads";
  if (!mem.empty()) s += ", " + mem;
  if (!os.empty()) s += ", " + os;
#ifdef __VERSION__
  s += ", compiler " + std::string(__VERSION__);
#endif
  return s;
}

std::string utc_now() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[64];
  std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M UTC", &tm);
  return buf;
}

std::string command_line(const PaperOptions& o) {
  std::string c = "swept bench paper --scale " + o.scale + " --runs " + std::to_string(o.runs) + " --out " + o.out;
  if (!o.scenes_dir.empty()) c += " --scenes " + o.scenes_dir;
  if (o.data_dir != "../shared/data") c += " --data " + o.data_dir;
  if (!o.only.empty()) {
    c += " --only ";
    for (std::size_t i = 0; i < o.only.size(); ++i) c += (i ? "," : "") + o.only[i];
  }
  if (o.no_scenes) c += " --no-scenes";
  if (o.no_cad) c += " --no-cad";
  if (!o.merge.empty()) {
    c += " --merge ";
    for (std::size_t i = 0; i < o.merge.size(); ++i) c += (i ? "," : "") + o.merge[i];
  }
  if (o.poses > 0) c += " --poses " + std::to_string(o.poses);
  if (o.threads != 1) c += " --threads " + std::to_string(o.threads);
  if (o.time_limit > 0) c += " --time-limit " + fmt_g(o.time_limit);
  if (o.no_ompl) c += " --no-ompl";
  if (!o.bench_plan.empty()) c += " --bench-plan " + o.bench_plan;
  if (o.ompl_time_limit > 0) c += " --ompl-time-limit " + fmt_g(o.ompl_time_limit);
  return c;
}

constexpr double kMm2ToM2 = 1e-6, kMm3ToM3 = 1e-9;

std::string markdown_report(const Results& r, const PaperOptions& o, const std::string& date,
                            const std::string& machine, const std::vector<std::string>& plots) {
  std::ostringstream md;
  const bool spread = o.runs > 1;
  md << "# The paper's experiments, reproduced: Tables II–IV with FCL and OMPL beside them\n\n";
  md << "- Command: `" << command_line(o) << "`\n";
  md << "- Date: " << date << "\n";
  md << "- Machine: " << machine
     << ". The machine is shared: other processes (compilers, other benchmarks) may run at the same time, which "
        "widens the min–max ranges.\n";
  md << "- Scale: `" << o.scale << "`; " << o.runs << " run(s) per figure (median, min–max); planner on " << o.threads
     << " thread(s), trees built serially (`parallel = false`) so that build times compare fitters, not thread "
        "scheduling.\n";
  md << "- Times are CPU time of the process (`CLOCK_PROCESS_CPUTIME_ID`): on a shared machine the wall clock "
        "also counts the time other processes hold the cores. Table III gives the planner's wall time beside it. "
        "The planner's time limit is wall time.\n";
  md << "- Planner time is `plan()` — what `swept plan` runs — on trees built beforehand: mesh loading and "
        "the tree build are not in Table III (the build is Table IV).\n";
  md << "- Units: scenes and CAD are in millimetres; Table II gives m² and m³ as the paper's figures read.\n\n";

  md << "## Table I — the meshes\n\n| mesh | source | triangles | paper's Table I |\n|---|---|---:|---:|\n";
  for (const MeshRow& m : r.meshes)
    md << "| " << m.name << " | " << m.source << " | " << m.triangles << " | "
       << (m.paper_triangles ? std::to_string(m.paper_triangles) : std::string("—")) << " |\n";
  md << "\n† rigid body, ‡ obstacles (as in the paper).\n\n";

  const Fitter base = baseline_fitter();
  const std::string base_name(to_string(base)), paper_ratio = std::string(to_string(Fitter::inertia)) + "/" + base_name;
  for (const SplitRule s : split_rules()) {
    md << "## Table II — total RSS surface area (m²) and volume (m³), split rule `" << to_string(s) << "`\n\n";
    md << "| mesh |";
    for (const Fitter f : fitters()) md << " " << info(f).paper_name << " SA | " << info(f).paper_name << " V |";
    md << " " << paper_ratio << " SA | " << paper_ratio << " V |\n|---|";
    for (std::size_t i = 0; i < 2 * all_fitters().size() + 2; ++i) md << "---:|";
    md << "\n";
    for (const MeshRow& m : r.meshes) {
      md << "| " << m.name;
      for (const Fitter f : fitters()) {
        const BvhStats& st = m.tree(f, s).stats;
        md << " | " << fmt_g(st.total_surface_area * kMm2ToM2) << " | " << fmt_g(st.total_volume * kMm3ToM3);
      }
      const BvhStats& i = m.tree(Fitter::inertia, s).stats;
      const BvhStats& p = m.tree(base, s).stats;
      md << " | " << fmt_fixed(i.total_surface_area / p.total_surface_area, 3) << " | "
         << fmt_fixed(i.total_volume / p.total_volume, 3) << " |\n";
    }
    md << "\n";
  }

  const std::vector<std::string> sc = planned_scenes(r);
  for (const SplitRule s : split_rules()) {
    md << "## Table III — planner time, split rule `" << to_string(s) << "`: CPU ms, median (min–max) over runs "
       << "[speed-up against " << info(base).paper_name << "]; wall ms; distance queries\n\n";
    md << "| scene |";
    for (const Fitter f : fitters()) md << " " << info(f).paper_name << " |";
    md << " wall ms " << fitter_names(" / ") << " (median) | distance queries " << fitter_names(" / ")
       << " | status |\n|---|";
    for (std::size_t i = 0; i < all_fitters().size() + 2; ++i) md << "---:|";
    md << "---|\n";
    for (const std::string& name : sc) {
      const PlanRow* p = find_plan(r, name, base, s);
      md << "| " << name;
      std::string queries, status, wall;
      for (const Fitter f : fitters()) {
        const PlanRow* x = find_plan(r, name, f, s);
        if (!x || !p) {
          md << " | n/a";
          continue;
        }
        md << " | " << fmt_spread(x->cpu_ms, 0) << " [" << fmt_ratio(ratio_of(p->cpu_ms, x->cpu_ms), spread) << "]";
        wall += (wall.empty() ? "" : " / ") + fmt_fixed(x->wall_ms.median, 0);
        queries += (queries.empty() ? "" : " / ") + std::to_string(x->distance_queries);
        status += (status.empty() ? "" : "; ") + std::string(to_string(f)) + " " + std::to_string(x->solved) + "/" +
                  std::to_string(x->statuses.size()) + " solved" + (x->same_path ? "" : ", paths differ");
      }
      md << " | " << wall << " | " << queries << " | " << status << " |\n";
    }
    md << "\nIn brackets: speed-up = " << info(base).paper_name << " time / this fitter's time (range from the runs' extremes).\n\n";
  }

  // Build-time ratios against the baseline: the paper's method first (its "~1.14×" claim), then
  // every other fitter of the table.
  std::vector<Fitter> ratio_fitters{Fitter::inertia};
  for (const Fitter f : fitters())
    if (f != base && f != Fitter::inertia) ratio_fitters.push_back(f);
  for (const SplitRule s : split_rules()) {
    md << "## Table IV — tree build time (CPU ms, serial build), split rule `" << to_string(s)
       << "`; FCL's builds beside them\n\n";
    md << "| mesh | triangles |";
    for (const Fitter f : fitters()) md << " " << info(f).paper_name << " |";
    for (const Fitter f : ratio_fitters) md << " " << to_string(f) << "/" << base_name << " |";
    md << " FCL OBBRSS | FCL RSS |\n|---|";
    for (std::size_t i = 0; i < all_fitters().size() + ratio_fitters.size() + 3; ++i) md << "---:|";
    md << "\n";
    for (const MeshRow& m : r.meshes) {
      md << "| " << m.name << " | " << m.triangles;
      for (const Fitter f : fitters()) md << " | " << fmt_spread(m.tree(f, s).build_ms, 1);
      for (const Fitter f : ratio_fitters)
        md << " | " << fmt_ratio(ratio_of(m.tree(f, s).build_ms, m.tree(base, s).build_ms), false);
      md << " | " << fmt_spread(m.fcl_obbrss_build_ms, 1) << " | " << fmt_spread(m.fcl_rss_build_ms, 1) << " |\n";
    }
    md << "\n";
  }

  md << "## Peers: query times per pose set (CPU µs per query, median (min–max) over runs)\n\n"
        "Obstacles fixed, body posed: `overlapping` (colliding), `near` (0 < distance ≤ 1 % of the body's size), "
        "`far` (bounding spheres apart); seeded, the same poses for every engine. FCL: `fcl::collide` (first "
        "contact) and `fcl::distance` (nearest points) on OBBRSS and RSS trees.\n\n";
  md << "| scene | set | poses | engine | collide µs | distance µs | distance vs fcl-obbrss |\n"
        "|---|---|---:|---|---:|---:|---:|\n";
  for (const QueryRow& q : r.queries) {
    const QueryRow* f = find_query(r, q.scene, q.set, std::string(fcl_engine_name(FclVolume::obbrss)));
    md << "| " << q.scene << " | " << q.set << " | " << q.poses << " | " << q.engine << " | "
       << fmt_spread(q.collide_us, 1) << " | " << fmt_spread(q.distance_us, 1) << " | "
       << (f ? fmt_ratio(ratio_of(f->distance_us, q.distance_us), false) : std::string("n/a")) << " |\n";
  }
  md << "\n(ratio > 1: swept faster than FCL OBBRSS.)\n\n";

  md << "## Peers: OMPL RRTConnect + FCL on the same problems\n\n" << r.ompl_status << ".\n\n";
  if (!r.ompl.empty()) {
    md << "| problem | OMPL solved | OMPL median ms | OMPL min–max ms | FCL build ms | swept (inertia) ms in the "
          "same run | swept status |\n|---|---:|---:|---:|---:|---:|---|\n";
    for (const OmplRow& w : r.ompl)
      md << "| " << w.problem << " | " << w.successes << "/" << w.runs << " | " << fmt_fixed(w.median_ms, 1) << " | "
         << fmt_fixed(w.min_ms, 1) << "–" << fmt_fixed(w.max_ms, 1) << " | " << fmt_fixed(w.fcl_build_ms, 1) << " | "
         << fmt_fixed(w.swept_ms, 1) << " | " << w.swept_status << " |\n";
    md << "\n";
  }

  const PaperRows rows = rows_of(r);
  md << "## The paper's claims\n\n";
  for (const ClaimVerdict& c : assess_claims(rows, o.runs)) md << "- **" << c.claim << "** — " << c.text() << "\n";
  md << "\n";
  md << "## The peers in numbers\n\nRatios are FCL's time / swept's time (> 1: swept is faster), each range over every "
        "row it names.\n\n";
  for (const std::string& f : peer_findings(rows)) md << "- " << f << "\n";
  md << "\n";

  if (!plots.empty()) {
    md << "## Plots\n\n";
    for (const std::string& p : plots) md << "![" << p << "](img/" << p << ")\n\n";
  }
  if (!r.notes.empty()) {
    md << "## Notes\n\n";
    for (const std::string& n : r.notes) md << "- " << n << "\n";
    md << "\n";
  }
  return md.str();
}

}  // namespace swept::bench
