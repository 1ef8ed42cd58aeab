#pragma once
/// The rows `swept bench paper` measures and the sentences it draws from them: one verdict per
/// claim of the paper, and the ranges of its peer comparisons. Kept apart from the measuring so
/// that the logic that turns rows into sentences is unit-tested with hand-made rows
/// (tests/apps/paper_verdicts_test.cpp).
///
/// Two rules every sentence here follows:
/// - a range ("0.59–4.34×") is the minimum and maximum over *every* row it summarises, and the
///   sentence says how many rows that is; rows that could not be measured are counted and named,
///   never dropped silently;
/// - a claim gets exactly one Verdict; its text starts with that verdict's word and the evidence
///   after it never contains another verdict word.
#include "swept/bvh/bvh.h"

#include <cstdint>
#include <limits>
#include <ranges>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace swept::bench {

// ---- statistics --------------------------------------------------------------------------------

/// Median and range over runs.
struct Spread {
  double median = std::numeric_limits<double>::quiet_NaN();
  double min = std::numeric_limits<double>::quiet_NaN();
  double max = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> samples;
};

/// Median, min and max of the samples (NaN for none).
Spread spread_of(std::vector<double> samples);

/// Ratio a/b with its range from the runs' extremes: [a.min/b.max, a.max/b.min].
struct Ratio {
  double value = std::numeric_limits<double>::quiet_NaN(), low = value, high = value;
  bool ranged = false;  ///< both sides have more than one run
};

/// a/b; NaN unless b's median, min and max are positive.
Ratio ratio_of(const Spread& a, const Spread& b);

/// "1.23×", or with `range` and more than one run on both sides "1.23× (1.20–1.25)".
std::string fmt_ratio(const Ratio& r, bool range);

// ---- the rows ----------------------------------------------------------------------------------

/// The fitters measured: the library's table, all_fitters(), in its order (PQP_FIT first: the
/// baseline of every ratio). Adding a row there adds a column to every table here.
inline auto fitters() { return all_fitters() | std::views::transform(&FitterInfo::fitter); }
/// The fitter every ratio is taken against: the table's first row (PQP_FIT).
inline Fitter baseline_fitter() { return all_fitters().front().fitter; }
/// A fitter as the paper names it, as a string: "INERTIA_FIT".
inline std::string paper_name(Fitter f) { return std::string(info(f).paper_name); }
/// The split rules measured: the library's table, all_split_rules(), in its order.
inline auto split_rules() { return all_split_rules() | std::views::transform(&SplitRuleInfo::rule); }

/// "pqp/min-sa".
std::string config_name(Fitter f, SplitRule s);

/// One tree of Tables II and IV.
struct TreeFigures {
  Fitter fitter = Fitter::pqp;
  SplitRule split = SplitRule::min_sa;
  BvhStats stats;
  Spread build_ms;  ///< CPU time of a serial build
};

/// One mesh of Tables II and IV.
struct MeshRow {
  std::string name;    ///< e.g. "air-cleaner †"
  std::string source;  ///< file or scene part
  std::string kind;    ///< "scene-body", "scene-obstacles", "cad"
  std::size_t triangles = 0;
  std::size_t paper_triangles = 0;  ///< Table I, for the scenes
  std::vector<TreeFigures> trees;
  Spread fcl_obbrss_build_ms, fcl_rss_build_ms;

  /// The tree of one configuration; throws std::logic_error when it is missing.
  const TreeFigures& tree(Fitter f, SplitRule s) const;
};

/// One planner configuration of Table III.
struct PlanRow {
  std::string scene;
  Fitter fitter = Fitter::pqp;
  SplitRule split = SplitRule::min_sa;
  Spread cpu_ms;   ///< CPU time of plan(): the timing used for speed-ups
  Spread wall_ms;  ///< wall time of plan() (inflated by other processes on a shared machine)
  std::vector<std::string> statuses;
  int solved = 0;
  std::uint64_t distance_queries = 0;
  std::size_t waypoints = 0;
  bool same_path = true;  ///< the same path hash on every run
};

/// Query times of one engine on one pose set of one scene.
struct QueryRow {
  QueryRow(std::string scene_name, std::string set_name, std::string engine_name, std::size_t pose_count)
      : scene(std::move(scene_name)), set(std::move(set_name)), engine(std::move(engine_name)), poses(pose_count) {}
  std::string scene, set, engine;  ///< engine: "swept-<fitter>/<split>", "fcl-obbrss", "fcl-rss"
  std::size_t poses = 0;
  Spread collide_us, distance_us;
};

/// What the sentences are drawn from.
struct PaperRows {
  std::span<const MeshRow> meshes;
  std::span<const PlanRow> plans;
  std::span<const QueryRow> queries;
  std::vector<std::string> scenes;  ///< the planned scenes, in report order
};

const PlanRow* find_plan(std::span<const PlanRow> plans, const std::string& scene, Fitter f, SplitRule s);
const QueryRow* find_query(std::span<const QueryRow> queries, const std::string& scene, const std::string& set,
                           const std::string& engine);

// ---- ranges ------------------------------------------------------------------------------------

/// A named value of a summary (a row's ratio).
struct Labelled {
  std::string label;
  double value = std::numeric_limits<double>::quiet_NaN();
};

/// The range of a set of rows' values: min and max over every finite value, how many rows had
/// one, and the labels of the rows without one.
struct RangeOf {
  double low = std::numeric_limits<double>::quiet_NaN();
  double high = std::numeric_limits<double>::quiet_NaN();
  std::size_t rows = 0;                 ///< rows with a finite value
  std::vector<std::string> unmeasured;  ///< rows without one
  std::vector<Labelled> below_one, above_one;  ///< rows < 1 and > 1
};
RangeOf range_of(std::span<const Labelled> values);

/// "0.59–4.34×" at `digits` decimals ("1.20×" when both ends print alike; "n/a" without rows).
/// Every row's value printed at the same precision lies inside the printed range.
std::string fmt_range(const RangeOf& r, int digits);

// ---- the paper's claims ------------------------------------------------------------------------

enum class Verdict : std::uint8_t { confirmed, partly_confirmed, not_confirmed, not_measured };

/// "Confirmed", "Partly confirmed", "Not confirmed", "Not measured".
std::string_view to_string(Verdict v);

/// One claim of the paper and what the rows say about it.
struct ClaimVerdict {
  std::string claim;     ///< the paper's claim, with its table
  Verdict verdict = Verdict::not_measured;
  std::string qualifier; ///< optional, after the verdict word: "(paper's split rule, min-sa)"
  std::string evidence;  ///< the figures the verdict rests on

  /// "<Verdict>[ <qualifier>]: <evidence>".
  std::string text() const;
};

/// The paper's four claims (Table II tighter trees, Table III INERTIA_FIT's and RAPID2_FIT's
/// planning speed, Table IV build time), judged on the rows. `runs`: runs per figure.
std::vector<ClaimVerdict> assess_claims(const PaperRows& rows, int runs);

/// The verdict rules, one per claim, exposed for the tests. Inputs are the per-mesh or
/// per-scene ratios the claims are about.

/// Table II. `both_lower`: meshes where INERTIA_FIT's tree has a lower total SA and volume than
/// PQP_FIT's (paper's split rule); confirmed on at least ¾ of the meshes ("almost all cases"),
/// partly on at least half.
Verdict tighter_trees_verdict(int both_lower, int meshes);

/// Table III, INERTIA_FIT "up to 20 % faster" (speed-ups 1.07–1.18): confirmed when faster
/// beyond the run-to-run spread on every scene; partly when faster on some and slower on none;
/// otherwise not confirmed.
Verdict faster_planning_verdict(int faster, int slower, int scenes);

/// Table IV, "~1.14×": confirmed when the geometric mean of the per-mesh ratios is closer to
/// the claimed factor than to 1 (no difference), i.e. within half the claimed difference of it.
Verdict build_ratio_verdict(double geometric_mean, double claimed);

/// Table III, RAPID2_FIT "1.4–3.7× slower": confirmed when at least `claimed_low` slower (median)
/// and slower beyond the spread on every scene; partly when at least `claimed_low` on some.
Verdict slower_planning_verdict(int at_least_claimed, int slower_beyond_spread, int scenes, bool spread);

// ---- peers -------------------------------------------------------------------------------------

/// Sentences on the peer rows: swept's distance and collide queries against FCL's (per split
/// rule and pose-set kind, ratio = FCL time / swept time, so > 1 means swept is faster), and
/// FCL's build times against swept's serial PQP_FIT build. Each names its rows and its range
/// over all of them, and names every row where swept is slower.
std::vector<std::string> peer_findings(const PaperRows& rows);

/// One peer summary: FCL `peer` engine against every swept engine with split `split` on the
/// pose sets `sets` (e.g. {"near", "far"}); `distance` picks the distance (else collide) times.
RangeOf query_ratio_range(std::span<const QueryRow> queries, const std::string& peer, SplitRule split,
                          std::span<const std::string> sets, bool distance);

}  // namespace swept::bench
