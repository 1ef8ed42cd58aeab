// `swept bench paper`, img/: the SVG plots of the report.
#include "swept/bench/fcl_peer.h"
#include "swept/bench/paper.h"
#include "swept/bench/svg_plot.h"

#include <cmath>

namespace swept::bench {

namespace fs = std::filesystem;

void write_plots(const Results& r, const fs::path& img, std::vector<std::string>& files) {
  fs::create_directories(img);
  const Fitter base = baseline_fitter();
  const std::string base_paper = paper_name(base);
  const std::vector<std::string> sc = planned_scenes(r);
  if (!sc.empty()) {
    BarChart c;
    c.title = "Planning speed-up against " + base_paper + " (median over runs, whiskers: min–max)";
    c.y_label = "speed-up (" + std::string(to_string(base)) + " time / time)";
    c.reference_line = 1.0;
    c.reference_label = base_paper;
    for (const SplitRule s : split_rules())
      for (const std::string& name : sc) c.groups.push_back(name + " (" + std::string(to_string(s)) + ")");
    for (const Fitter f : fitters()) {
      BarSeries ser{paper_name(f), {}, {}, {}};
      for (const SplitRule s : split_rules())
        for (const std::string& name : sc) {
          const PlanRow* p = find_plan(r, name, base, s);
          const PlanRow* x = find_plan(r, name, f, s);
          const Ratio ra = p && x ? ratio_of(p->cpu_ms, x->cpu_ms) : Ratio{};
          ser.values.push_back(ra.value);
          ser.low.push_back(ra.low);
          ser.high.push_back(ra.high);
        }
      c.series.push_back(std::move(ser));
    }
    write_svg(c, (img / "paper-speedup.svg").string());
    files.push_back("paper-speedup.svg");

    for (const bool dist : {true, false}) {
      BarChart q;
      q.title = std::string(dist ? "Distance" : "Collide") +
                " query time per pose set: swept (min-sa split) vs FCL (median over runs, whiskers: min–max)";
      q.y_label = "µs per query";
      q.log_scale = true;
      std::vector<std::string> engines;
      for (const Fitter f : fitters()) engines.push_back("swept-" + config_name(f, SplitRule::min_sa));
      engines.push_back(std::string(fcl_engine_name(FclVolume::obbrss)));
      engines.push_back(std::string(fcl_engine_name(FclVolume::rss)));
      const char* set_names[] = {"overlapping", "near", "far"};
      for (const std::string& name : sc)
        for (const char* set : set_names) q.groups.push_back(name + " / " + set);
      for (const std::string& e : engines) {
        BarSeries ser{e, {}, {}, {}};
        for (const std::string& name : sc)
          for (const char* set : set_names) {
            const QueryRow* row = find_query(r, name, set, e);
            const Spread none;
            const Spread& sp = row ? (dist ? row->distance_us : row->collide_us) : none;
            ser.values.push_back(sp.median);
            ser.low.push_back(sp.min);
            ser.high.push_back(sp.max);
          }
        q.series.push_back(std::move(ser));
      }
      const std::string file = dist ? "paper-query-distance.svg" : "paper-query-collide.svg";
      bool any = false;
      for (const BarSeries& s : q.series)
        for (double v : s.values) any = any || (std::isfinite(v) && v > 0);
      if (!any) continue;
      write_svg(q, (img / file).string());
      files.push_back(file);
    }
  }
  if (!r.meshes.empty()) {
    BarChart t;
    t.title = "Total RSS surface area and build time relative to " + base_paper + " (min-sa split)";
    t.y_label = "ratio to " + base_paper;
    t.reference_line = 1.0;
    t.reference_label = base_paper;
    for (const MeshRow& m : r.meshes) t.groups.push_back(m.name);
    for (const Fitter f : fitters()) {
      if (f == base) continue;
      BarSeries sa{paper_name(f) + " surface area", {}, {}, {}};
      BarSeries bt{paper_name(f) + " build time", {}, {}, {}};
      for (const MeshRow& m : r.meshes) {
        sa.values.push_back(m.tree(f, SplitRule::min_sa).stats.total_surface_area /
                            m.tree(base, SplitRule::min_sa).stats.total_surface_area);
        const Ratio b = ratio_of(m.tree(f, SplitRule::min_sa).build_ms, m.tree(base, SplitRule::min_sa).build_ms);
        bt.values.push_back(b.value);
        bt.low.push_back(b.low);
        bt.high.push_back(b.high);
      }
      t.series.push_back(std::move(sa));
      t.series.push_back(std::move(bt));
    }
    write_svg(t, (img / "paper-trees.svg").string());
    files.push_back("paper-trees.svg");
  }
}


}  // namespace swept::bench
