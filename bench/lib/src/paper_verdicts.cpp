// The verdicts and ranges of `swept bench paper` (see paper_verdicts.h for the two rules every
// sentence follows).
#include "swept/bench/paper_verdicts.h"

#include "swept/bench/output.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace swept::bench {

Spread spread_of(std::vector<double> v) {
  Spread s;
  s.samples = v;
  if (v.empty()) return s;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  s.median = n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
  s.min = v.front();
  s.max = v.back();
  return s;
}

Ratio ratio_of(const Spread& a, const Spread& b) {
  Ratio r;
  if (!(b.median > 0) || !(b.min > 0) || !(b.max > 0)) return r;
  r.value = a.median / b.median;
  r.low = a.min / b.max;
  r.high = a.max / b.min;
  r.ranged = a.samples.size() > 1 && b.samples.size() > 1;
  return r;
}

std::string fmt_ratio(const Ratio& r, bool range) {
  if (!std::isfinite(r.value)) return "n/a";
  if (!range || !r.ranged) return fmt_fixed(r.value, 2) + "×";
  return fmt_fixed(r.value, 2) + "× (" + fmt_fixed(r.low, 2) + "–" + fmt_fixed(r.high, 2) + ")";
}

std::string config_name(Fitter f, SplitRule s) { return std::string(to_string(f)) + "/" + std::string(to_string(s)); }


const TreeFigures& MeshRow::tree(Fitter f, SplitRule s) const {
  for (const TreeFigures& t : trees)
    if (t.fitter == f && t.split == s) return t;
  throw std::logic_error(name + ": missing tree figures for " + config_name(f, s));
}

const PlanRow* find_plan(std::span<const PlanRow> plans, const std::string& scene, Fitter f, SplitRule s) {
  for (const PlanRow& p : plans)
    if (p.scene == scene && p.fitter == f && p.split == s) return &p;
  return nullptr;
}

const QueryRow* find_query(std::span<const QueryRow> queries, const std::string& scene, const std::string& set,
                           const std::string& engine) {
  for (const QueryRow& q : queries)
    if (q.scene == scene && q.set == set && q.engine == engine) return &q;
  return nullptr;
}

// ---- ranges ------------------------------------------------------------------------------------

RangeOf range_of(std::span<const Labelled> values) {
  RangeOf r;
  for (const Labelled& v : values) {
    if (!std::isfinite(v.value)) {
      r.unmeasured.push_back(v.label);
      continue;
    }
    if (r.rows == 0) {
      r.low = r.high = v.value;
    } else {
      r.low = std::min(r.low, v.value);
      r.high = std::max(r.high, v.value);
    }
    ++r.rows;
    if (v.value < 1.0) r.below_one.push_back(v);
    if (v.value > 1.0) r.above_one.push_back(v);
  }
  return r;
}

std::string fmt_range(const RangeOf& r, int digits) {
  if (r.rows == 0) return "n/a";
  // Rounding is monotone, so every row printed at the same precision lies inside the range.
  const std::string lo = fmt_fixed(r.low, digits), hi = fmt_fixed(r.high, digits);
  return lo == hi ? lo + "×" : lo + "–" + hi + "×";
}

namespace {

std::string join(const std::vector<std::string>& parts, const std::string& sep) {
  std::string out;
  for (const std::string& p : parts) out += (out.empty() ? "" : sep) + p;
  return out;
}

std::string rows_word(std::size_t n) { return std::to_string(n) + (n == 1 ? " row" : " rows"); }

/// "; without a value: a, b" or "".
std::string unmeasured_note(const RangeOf& r) {
  return r.unmeasured.empty() ? "" : "; without a value: " + join(r.unmeasured, ", ");
}

}  // namespace

// ---- the paper's claims ------------------------------------------------------------------------

std::string_view to_string(Verdict v) {
  switch (v) {
    case Verdict::confirmed: return "Confirmed";
    case Verdict::partly_confirmed: return "Partly confirmed";
    case Verdict::not_confirmed: return "Not confirmed";
    case Verdict::not_measured: return "Not measured";
  }
  return "?";
}

std::string ClaimVerdict::text() const {
  return std::string(to_string(verdict)) + (qualifier.empty() ? "" : " " + qualifier) + ": " + evidence;
}

Verdict tighter_trees_verdict(int both_lower, int meshes) {
  if (meshes <= 0) return Verdict::not_measured;
  if (4 * both_lower >= 3 * meshes) return Verdict::confirmed;
  if (2 * both_lower >= meshes) return Verdict::partly_confirmed;
  return Verdict::not_confirmed;
}

Verdict faster_planning_verdict(int faster, int slower, int scenes) {
  if (scenes <= 0) return Verdict::not_measured;
  if (faster == scenes) return Verdict::confirmed;
  if (faster > 0 && slower == 0) return Verdict::partly_confirmed;
  return Verdict::not_confirmed;
}

Verdict build_ratio_verdict(double gm, double claimed) {
  if (!(gm > 0) || !std::isfinite(gm)) return Verdict::not_measured;
  // Closer to the claimed factor than to "no difference" on its side, and not beyond it by more
  // (log scale, the natural one for ratios): gm in (√c, c·√c).
  return std::abs(std::log(gm / claimed)) < 0.5 * std::abs(std::log(claimed)) ? Verdict::confirmed
                                                                              : Verdict::not_confirmed;
}

Verdict slower_planning_verdict(int at_least_claimed, int slower_beyond_spread, int scenes, bool spread) {
  if (scenes <= 0) return Verdict::not_measured;
  if (at_least_claimed == scenes && (slower_beyond_spread == scenes || !spread)) return Verdict::confirmed;
  if (at_least_claimed > 0) return Verdict::partly_confirmed;
  return Verdict::not_confirmed;
}

std::vector<ClaimVerdict> assess_claims(const PaperRows& r, int runs) {
  std::vector<ClaimVerdict> out;
  const bool spread = runs > 1;
  const std::string spread_note = spread ? "" : " (a single run: no spread to judge noise by)";

  // 1. Tighter trees, judged with the paper's split rule (min-sa); PQP's own (largest) reported beside.
  {
    ClaimVerdict c{"INERTIA_FIT builds tighter RSS trees (Table II: lower total surface area and volume in almost all "
                   "cases)"};
    std::ostringstream s;
    int both_min_sa = 0, meshes = 0;
    for (const SplitRule sp : split_rules()) {
      int sa = 0, vol = 0, both = 0, n = 0, sa_r = 0, vol_r = 0;
      std::vector<Labelled> sa_ratio, vol_ratio;
      for (const MeshRow& m : r.meshes) {
        const BvhStats& i = m.tree(Fitter::inertia, sp).stats;
        const BvhStats& p = m.tree(Fitter::pqp, sp).stats;
        const BvhStats& q = m.tree(Fitter::rapid2, sp).stats;
        ++n;
        sa += i.total_surface_area < p.total_surface_area;
        vol += i.total_volume < p.total_volume;
        both += i.total_surface_area < p.total_surface_area && i.total_volume < p.total_volume;
        sa_r += i.total_surface_area < q.total_surface_area;
        vol_r += i.total_volume < q.total_volume;
        sa_ratio.push_back({m.name, i.total_surface_area / p.total_surface_area});
        vol_ratio.push_back({m.name, i.total_volume / p.total_volume});
      }
      if (sp == SplitRule::min_sa) {
        both_min_sa = both;
        meshes = n;
      }
      const RangeOf sar = range_of(sa_ratio), volr = range_of(vol_ratio);
      s << "split " << to_string(sp) << ": INERTIA_FIT has a smaller total RSS surface area than PQP_FIT on " << sa
        << " of " << n << " meshes and a smaller total volume on " << vol << " (both on " << both
        << "); ratio inertia/pqp over all " << n << " meshes: SA " << fmt_range(sar, 3) << ", volume "
        << fmt_range(volr, 3) << unmeasured_note(sar) << "; against RAPID2_FIT: smaller SA on " << sa_r
        << ", smaller volume on " << vol_r << ". ";
    }
    c.verdict = tighter_trees_verdict(both_min_sa, meshes);
    c.qualifier = "(paper's split rule, min-sa; the threshold is ¾ of the meshes)";
    c.evidence = meshes == 0 ? "no mesh." : s.str() + "Tree sizes are deterministic: no spread.";
    out.push_back(c);
  }

  // 2. INERTIA_FIT up to 20 % faster planning than PQP_FIT.
  {
    ClaimVerdict c{"INERTIA_FIT plans up to 20 % faster than PQP_FIT (Table III: 1.07–1.18×)"};
    std::ostringstream s;
    int faster = 0, slower = 0;
    std::vector<Labelled> medians;
    for (const std::string& sc : r.scenes) {
      const PlanRow* p = find_plan(r.plans, sc, Fitter::pqp, SplitRule::min_sa);
      const PlanRow* i = find_plan(r.plans, sc, Fitter::inertia, SplitRule::min_sa);
      const Ratio sp = p && i ? ratio_of(p->cpu_ms, i->cpu_ms) : Ratio{};
      medians.push_back({sc, sp.value});
      if (!std::isfinite(sp.value)) continue;
      if (sp.low > 1.0) ++faster;
      if (sp.high < 1.0) ++slower;
      s << sc << " " << fmt_ratio(sp, spread);
      if (i->solved < static_cast<int>(i->statuses.size()) || p->solved < static_cast<int>(p->statuses.size()))
        s << " [not every run solved]";
      s << "; ";
    }
    const RangeOf range = range_of(medians);
    const int n = static_cast<int>(range.rows);
    c.verdict = faster_planning_verdict(faster, slower, n);
    c.evidence = n == 0 ? "no planned scene." + unmeasured_note(range)
                        : "speed-up of INERTIA_FIT over PQP_FIT (min-sa split; median and range over runs): " + s.str() +
                              "faster beyond the run-to-run spread on " + std::to_string(faster) + " of " +
                              std::to_string(n) + " scenes, slower beyond it on " + std::to_string(slower) +
                              "; medians " + fmt_range(range, 2) + " over the " + std::to_string(n) + " scenes" +
                              unmeasured_note(range) + spread_note + ".";
    out.push_back(c);
  }

  // 3. ~1.14× build time.
  {
    constexpr double claimed = 1.14;
    ClaimVerdict c{"INERTIA_FIT builds trees in ~1.14× PQP_FIT's time (Table IV)"};
    std::vector<Labelled> ratios;
    for (const MeshRow& m : r.meshes)
      ratios.push_back({m.name, m.tree(Fitter::inertia, SplitRule::min_sa).build_ms.median /
                                    m.tree(Fitter::pqp, SplitRule::min_sa).build_ms.median});
    const RangeOf range = range_of(ratios);
    double log_sum = 0.0;
    for (const Labelled& v : ratios)
      if (std::isfinite(v.value) && v.value > 0) log_sum += std::log(v.value);
    const double gm = range.rows ? std::exp(log_sum / static_cast<double>(range.rows)) : std::nan("");
    c.verdict = build_ratio_verdict(gm, claimed);
    if (c.verdict == Verdict::not_confirmed)
      c.qualifier = gm >= claimed                  ? "(INERTIA_FIT costs more than claimed)"
                    : gm > 1.0 / std::sqrt(claimed) ? "(INERTIA_FIT costs about what PQP_FIT costs)"
                                                    : "(INERTIA_FIT is cheaper than PQP_FIT)";
    const double lo = claimed / std::sqrt(claimed), hi = claimed * std::sqrt(claimed);
    c.evidence = range.rows == 0
                     ? "no build time." + unmeasured_note(range)
                     : "INERTIA_FIT / PQP_FIT build time (min-sa, serial build, medians) is " + fmt_fixed(gm, 2) +
                           "× in geometric mean over " + std::to_string(range.rows) + " meshes, " +
                           fmt_range(range, 2) + " per mesh" + unmeasured_note(range) + "; the claimed " +
                           fmt_fixed(claimed, 2) + "× would need a mean between " + fmt_fixed(lo, 2) + "× and " +
                           fmt_fixed(hi, 2) + "× (closer to it than to 1.00×)" + spread_note + ".";
    out.push_back(c);
  }

  // 4. RAPID2_FIT 1.4–3.7× slower planning.
  {
    constexpr double claimed_low = 1.4;
    ClaimVerdict c{"RAPID2_FIT plans 1.4–3.7× slower than PQP_FIT (Table III: speed-ups 0.27–0.69)"};
    std::ostringstream s;
    int in_range = 0, slower = 0;
    std::vector<Labelled> medians;
    for (const std::string& sc : r.scenes) {
      const PlanRow* p = find_plan(r.plans, sc, Fitter::pqp, SplitRule::min_sa);
      const PlanRow* q = find_plan(r.plans, sc, Fitter::rapid2, SplitRule::min_sa);
      const Ratio sl = p && q ? ratio_of(q->cpu_ms, p->cpu_ms) : Ratio{};
      medians.push_back({sc, sl.value});
      if (!std::isfinite(sl.value)) continue;
      if (sl.low > 1.0) ++slower;
      if (sl.value >= claimed_low) ++in_range;
      s << sc << " " << fmt_ratio(sl, spread) << "; ";
    }
    const RangeOf range = range_of(medians);
    const int n = static_cast<int>(range.rows);
    c.verdict = slower_planning_verdict(in_range, slower, n, spread);
    c.evidence = n == 0 ? "no planned scene." + unmeasured_note(range)
                        : "RAPID2_FIT / PQP_FIT planning time (min-sa; median and range over runs): " + s.str() +
                              "slower beyond the run-to-run spread on " + std::to_string(slower) + " of " +
                              std::to_string(n) + " scenes, at least 1.4× slower on " + std::to_string(in_range) +
                              "; medians " + fmt_range(range, 2) + unmeasured_note(range) + spread_note + ".";
    out.push_back(c);
  }
  return out;
}

// ---- peers -------------------------------------------------------------------------------------

RangeOf query_ratio_range(std::span<const QueryRow> queries, const std::string& peer, SplitRule split,
                          std::span<const std::string> sets, bool distance) {
  std::vector<Labelled> values;
  const std::string suffix = "/" + std::string(to_string(split));
  for (const QueryRow& q : queries) {
    if (q.engine.rfind("swept-", 0) != 0 || q.engine.size() < suffix.size() ||
        q.engine.compare(q.engine.size() - suffix.size(), suffix.size(), suffix) != 0)
      continue;
    if (std::find(sets.begin(), sets.end(), q.set) == sets.end()) continue;
    const QueryRow* f = find_query(queries, q.scene, q.set, peer);
    const std::string fitter = q.engine.substr(6, q.engine.size() - 6 - suffix.size());
    Fitter fit = Fitter::pqp;
    const std::string name = parse_fitter(fitter, fit) ? std::string(info(fit).paper_name) : fitter;
    const Ratio ratio = f ? ratio_of(distance ? f->distance_us : f->collide_us, distance ? q.distance_us : q.collide_us)
                          : Ratio{};
    values.push_back({q.scene + " " + q.set + " " + name, ratio.value});
  }
  return range_of(values);
}

namespace {

/// "FCL OBBRSS takes 1.07–4.35× swept's time over 18 rows; swept is faster on every row" or
/// "...; swept is slower on 2 of 18: tunnel-console near PQP_FIT 0.59×, ...".
std::string ratio_sentence(const RangeOf& r, const std::string& peer_name, const std::string& what) {
  if (r.rows == 0) return what + ": not measured" + unmeasured_note(r) + ".";
  std::string s = what + ": " + peer_name + " takes " + fmt_range(r, 2) + " swept's time over " + rows_word(r.rows);
  if (r.below_one.empty()) {
    s += r.above_one.size() == r.rows ? "; swept is faster on every row" : "; swept is slower on none";
  } else {
    std::vector<std::string> slow;
    for (const Labelled& v : r.below_one) slow.push_back(v.label + " " + fmt_fixed(v.value, 2) + "×");
    s += "; swept is slower on " + std::to_string(r.below_one.size()) + " of " + std::to_string(r.rows) + ": " +
         join(slow, ", ");
  }
  return s + unmeasured_note(r) + ".";
}

}  // namespace

std::vector<std::string> peer_findings(const PaperRows& rows) {
  std::vector<std::string> out;
  const std::vector<std::string> near_far{"near", "far"}, overlapping{"overlapping"}, near{"near"};
  const struct {
    const char* engine;
    const char* name;
  } peers[] = {{"fcl-obbrss", "FCL OBBRSS"}, {"fcl-rss", "FCL RSS"}};
  for (const SplitRule split : split_rules()) {
    const std::string trees = std::string(to_string(split)) + " trees";
    for (const auto& peer : peers)
      out.push_back(ratio_sentence(query_ratio_range(rows.queries, peer.engine, split, near_far, true), peer.name,
                                   "distance, near and far poses, " + trees + ", against " + peer.name));
    out.push_back(ratio_sentence(query_ratio_range(rows.queries, "fcl-obbrss", split, overlapping, true), "FCL OBBRSS",
                                 "distance, overlapping poses, " + trees + ", against FCL OBBRSS"));
    out.push_back(ratio_sentence(query_ratio_range(rows.queries, "fcl-obbrss", split, near, false), "FCL OBBRSS",
                                 "collide, near poses, " + trees + ", against FCL OBBRSS"));
  }
  // FCL's builds against swept's serial build of the baseline fitter (PQP_FIT) with the paper's
  // split rule.
  const Fitter base = baseline_fitter();
  for (const auto& peer : peers) {
    std::vector<Labelled> values;
    for (const MeshRow& m : rows.meshes) {
      const Spread& f = std::string(peer.engine) == "fcl-obbrss" ? m.fcl_obbrss_build_ms : m.fcl_rss_build_ms;
      values.push_back({m.name, ratio_of(f, m.tree(base, SplitRule::min_sa).build_ms).value});
    }
    const RangeOf r = range_of(values);
    out.push_back(r.rows == 0 ? std::string("build, ") + peer.name + ": not measured" + unmeasured_note(r) + "."
                              : std::string("build: ") + peer.name + " takes " + fmt_range(r, 2) +
                                    " the CPU time of swept's serial " + paper_name(base) + " build (min-sa) over " +
                                    std::to_string(r.rows) + " meshes (medians)" + unmeasured_note(r) + ".");
  }
  return out;
}

}  // namespace swept::bench
