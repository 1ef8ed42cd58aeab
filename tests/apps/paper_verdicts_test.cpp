// The sentences `swept bench paper` draws from its rows (bench/lib: swept/bench/paper_verdicts.h), on
// hand-made rows: ranges cover every row, one verdict per claim, and the verdict rules.
#include "swept/bench/paper_verdicts.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

namespace swept::bench {
namespace {

Spread runs(std::vector<double> v) { return spread_of(std::move(v)); }

/// A mesh with the given total SA / volume per fitter (same under both split rules) and build
/// times (ms, one run each).
MeshRow mesh(const std::string& name, double sa_pqp, double sa_inertia, double build_pqp, double build_inertia) {
  MeshRow m;
  m.name = name;
  for (const SplitRule s : split_rules())
    for (const Fitter f : fitters()) {
      TreeFigures t;
      t.fitter = f;
      t.split = s;
      t.stats.total_surface_area = f == Fitter::inertia ? sa_inertia : sa_pqp;
      t.stats.total_volume = t.stats.total_surface_area;  // lower SA, lower volume
      t.build_ms = runs({f == Fitter::inertia ? build_inertia : build_pqp});
      m.trees.push_back(t);
    }
  m.fcl_obbrss_build_ms = runs({build_pqp * 1.1});
  m.fcl_rss_build_ms = runs({build_pqp * 0.9});
  return m;
}

PlanRow plan(const std::string& scene, Fitter f, std::vector<double> cpu) {
  PlanRow p;
  p.scene = scene;
  p.fitter = f;
  p.split = SplitRule::min_sa;
  p.cpu_ms = runs(std::move(cpu));
  p.statuses.assign(p.cpu_ms.samples.size(), "solved");
  p.solved = static_cast<int>(p.statuses.size());
  return p;
}

QueryRow query(const std::string& scene, const std::string& set, const std::string& engine, double distance_us,
               double collide_us) {
  QueryRow q(scene, set, engine, 10);
  q.distance_us = runs({distance_us});
  q.collide_us = runs({collide_us});
  return q;
}

const std::vector<std::string> kVerdictWords{"confirmed", "consistent", "reproduced", "not measured"};

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

/// One claim, one verdict: the text starts with the verdict's word, and neither the qualifier
/// nor the evidence carries a verdict word of its own.
void expect_one_verdict(const ClaimVerdict& c) {
  const std::string text = c.text();
  EXPECT_EQ(text.rfind(std::string(to_string(c.verdict)), 0), 0u) << text;
  for (const std::string& w : kVerdictWords) {
    EXPECT_EQ(lower(c.evidence).find(w), std::string::npos) << "evidence says '" << w << "': " << c.evidence;
    EXPECT_EQ(lower(c.qualifier).find(w), std::string::npos) << "qualifier says '" << w << "': " << c.qualifier;
  }
}

TEST(PaperVerdicts, RangeCoversEveryRowAndNamesTheUnmeasured) {
  const std::vector<Labelled> v{{"a", 1.07}, {"b", 0.59}, {"c", 4.3}, {"d", std::nan("")}, {"e", 1.0}};
  const RangeOf r = range_of(v);
  EXPECT_EQ(r.rows, 4u);
  EXPECT_DOUBLE_EQ(r.low, 0.59);
  EXPECT_DOUBLE_EQ(r.high, 4.3);
  ASSERT_EQ(r.unmeasured.size(), 1u);
  EXPECT_EQ(r.unmeasured[0], "d");
  ASSERT_EQ(r.below_one.size(), 1u);
  EXPECT_EQ(r.below_one[0].label, "b");
  EXPECT_EQ(r.above_one.size(), 2u);  // 1.0 is neither
  EXPECT_EQ(fmt_range(r, 2), "0.59–4.30×");
  // Each end at the printed precision: 1.074 and 4.346 print as 1.07–4.35.
  EXPECT_EQ(fmt_range(range_of(std::vector<Labelled>{{"x", 1.074}, {"y", 4.346}}), 2), "1.07–4.35×");
  EXPECT_EQ(fmt_range(range_of(std::vector<Labelled>{{"x", 0.5751}, {"y", 1.4209}}), 3), "0.575–1.421×");
  EXPECT_EQ(fmt_range(range_of(std::vector<Labelled>{}), 2), "n/a");
  EXPECT_EQ(fmt_range(range_of(std::vector<Labelled>{{"x", 2.0}}), 2), "2.00×");
}

TEST(PaperVerdicts, SlowerRowsAreNeverSummarisedAsFasterForEveryFitter) {
  // Distances of the docs' table: with the largest split, PQP_FIT is slower than FCL OBBRSS on
  // one scene (0.59× near, 0.76× far); with min-sa every row is faster.
  std::vector<QueryRow> q;
  const double fcl_near = 7278.7, fcl_far = 17996.1;
  q.push_back(query("tunnel", "near", "fcl-obbrss", fcl_near, 282.5));
  q.push_back(query("tunnel", "far", "fcl-obbrss", fcl_far, 0.1));
  q.push_back(query("tunnel", "near", "fcl-rss", 7227.0, 182159.5));
  q.push_back(query("tunnel", "far", "fcl-rss", 18224.7, 179583.2));
  q.push_back(query("tunnel", "near", "swept-pqp/largest", fcl_near / 0.59, 295.8));
  q.push_back(query("tunnel", "far", "swept-pqp/largest", fcl_far / 0.76, 0.1));
  q.push_back(query("tunnel", "near", "swept-inertia/largest", fcl_near / 4.3, 261.9));
  q.push_back(query("tunnel", "far", "swept-inertia/largest", fcl_far / 1.1, 0.1));
  q.push_back(query("tunnel", "near", "swept-pqp/min-sa", fcl_near / 1.1, 308.0));
  q.push_back(query("tunnel", "far", "swept-pqp/min-sa", fcl_far / 4.3, 0.1));
  const std::vector<std::string> sets{"near", "far"};

  const RangeOf largest = query_ratio_range(q, "fcl-obbrss", SplitRule::largest, sets, true);
  EXPECT_EQ(largest.rows, 4u);
  EXPECT_NEAR(largest.low, 0.59, 1e-12);
  EXPECT_NEAR(largest.high, 4.3, 1e-12);
  EXPECT_EQ(largest.below_one.size(), 2u);
  const RangeOf min_sa = query_ratio_range(q, "fcl-obbrss", SplitRule::min_sa, sets, true);
  EXPECT_EQ(min_sa.rows, 2u);
  EXPECT_TRUE(min_sa.below_one.empty());

  PaperRows rows;
  rows.queries = q;
  const std::vector<std::string> findings = peer_findings(rows);
  bool saw_largest = false, saw_min_sa = false;
  for (const std::string& f : findings) {
    if (f.find("distance, near and far poses, largest trees, against FCL OBBRSS") == 0) {
      saw_largest = true;
      EXPECT_NE(f.find("0.59–4.30×"), std::string::npos) << f;
      EXPECT_NE(f.find("swept is slower on 2 of 4"), std::string::npos) << f;
      EXPECT_NE(f.find("tunnel near PQP_FIT 0.59×"), std::string::npos) << f;
      EXPECT_EQ(f.find("every"), std::string::npos) << f;
    }
    if (f.find("distance, near and far poses, min-sa trees, against FCL OBBRSS") == 0) {
      saw_min_sa = true;
      EXPECT_NE(f.find("1.10–4.30×"), std::string::npos) << f;
      EXPECT_NE(f.find("faster on every row"), std::string::npos) << f;
    }
    // The collide rows: PQP_FIT with min-sa takes 308.0 µs against FCL's 282.5 µs.
    if (f.find("collide, near poses, min-sa trees") == 0) {
      EXPECT_NE(f.find("slower on 1 of 1: tunnel near PQP_FIT 0.92×"), std::string::npos) << f;
    }
  }
  EXPECT_TRUE(saw_largest);
  EXPECT_TRUE(saw_min_sa);
}

TEST(PaperVerdicts, BuildTimeClaimGetsOneVerdict) {
  // Per-mesh inertia/pqp ratios 0.88–1.06, geometric mean about 1.00: the paper's 1.14× is not
  // what was measured, whatever else the sentence says.
  std::vector<MeshRow> meshes{mesh("a", 10, 8, 100, 88), mesh("b", 10, 8, 100, 106), mesh("c", 10, 8, 100, 100),
                              mesh("d", 10, 8, 100, 106)};
  PaperRows rows;
  rows.meshes = meshes;
  const auto claims = assess_claims(rows, 1);
  ASSERT_EQ(claims.size(), 4u);
  const ClaimVerdict& build = claims[2];
  EXPECT_NE(build.claim.find("1.14"), std::string::npos);
  EXPECT_EQ(build.verdict, Verdict::not_confirmed) << build.text();
  EXPECT_NE(build.qualifier.find("about what PQP_FIT costs"), std::string::npos) << build.qualifier;
  EXPECT_NE(build.evidence.find("0.88–1.06× per mesh"), std::string::npos) << build.evidence;
  for (const ClaimVerdict& c : claims) expect_one_verdict(c);

  // The band: closer to 1.14 than to 1.00 (log scale), and not beyond 1.14 by more.
  EXPECT_EQ(build_ratio_verdict(1.00, 1.14), Verdict::not_confirmed);
  EXPECT_EQ(build_ratio_verdict(1.05, 1.14), Verdict::not_confirmed);
  EXPECT_EQ(build_ratio_verdict(1.09, 1.14), Verdict::confirmed);
  EXPECT_EQ(build_ratio_verdict(1.14, 1.14), Verdict::confirmed);
  EXPECT_EQ(build_ratio_verdict(1.20, 1.14), Verdict::confirmed);
  EXPECT_EQ(build_ratio_verdict(1.30, 1.14), Verdict::not_confirmed);
  EXPECT_EQ(build_ratio_verdict(0.80, 1.14), Verdict::not_confirmed);
  EXPECT_EQ(build_ratio_verdict(std::nan(""), 1.14), Verdict::not_measured);

  // Measured at 1.14× in geometric mean: confirmed.
  std::vector<MeshRow> costly{mesh("a", 10, 8, 100, 110), mesh("b", 10, 8, 100, 118)};
  rows.meshes = costly;
  EXPECT_EQ(assess_claims(rows, 1)[2].verdict, Verdict::confirmed) << assess_claims(rows, 1)[2].text();
}

TEST(PaperVerdicts, PlanningSpeedUpFasterOnOneSceneSlowerOnTwoIsNotConfirmed) {
  // Table III's pattern: INERTIA_FIT 1.60× faster on one scene, 0.94× and 0.65× on the others,
  // each beyond the run-to-run spread.
  std::vector<PlanRow> plans{plan("air", Fitter::pqp, {1461, 1496, 1497}), plan("air", Fitter::inertia, {1565, 1597, 1610}),
                             plan("cyl", Fitter::pqp, {10540, 10637, 10695}), plan("cyl", Fitter::inertia, {6344, 6660, 6756}),
                             plan("tun", Fitter::pqp, {17800, 17918, 17950}), plan("tun", Fitter::inertia, {27500, 27578, 27600})};
  for (const char* sc : {"air", "cyl", "tun"}) {
    const PlanRow* p = find_plan(plans, sc, Fitter::pqp, SplitRule::min_sa);
    PlanRow r = *p;
    r.fitter = Fitter::rapid2;
    plans.push_back(r);  // RAPID2_FIT as fast as PQP_FIT
  }
  PaperRows rows;
  rows.plans = plans;
  rows.scenes = {"air", "cyl", "tun"};
  const auto claims = assess_claims(rows, 3);
  const ClaimVerdict& speed = claims[1];
  EXPECT_EQ(speed.verdict, Verdict::not_confirmed) << speed.text();
  EXPECT_NE(speed.evidence.find("faster beyond the run-to-run spread on 1 of 3 scenes, slower beyond it on 2"),
            std::string::npos)
      << speed.evidence;
  EXPECT_NE(speed.evidence.find("medians 0.65–1.60× over the 3 scenes"), std::string::npos) << speed.evidence;
  EXPECT_EQ(claims[3].verdict, Verdict::not_confirmed) << claims[3].text();  // RAPID2_FIT not 1.4× slower
  for (const ClaimVerdict& c : claims) expect_one_verdict(c);
  // The tables II/IV claims have no mesh here: not measured, and said so.
  EXPECT_EQ(claims[0].verdict, Verdict::not_measured);
  EXPECT_EQ(claims[2].verdict, Verdict::not_measured);

  // A scene without its rows is named, not dropped from the count silently.
  rows.scenes.push_back("missing");
  const ClaimVerdict again = assess_claims(rows, 3)[1];
  EXPECT_NE(again.evidence.find("without a value: missing"), std::string::npos) << again.evidence;
  EXPECT_NE(again.evidence.find("of 3 scenes"), std::string::npos) << again.evidence;

  EXPECT_EQ(faster_planning_verdict(3, 0, 3), Verdict::confirmed);
  EXPECT_EQ(faster_planning_verdict(1, 0, 3), Verdict::partly_confirmed);
  EXPECT_EQ(faster_planning_verdict(1, 2, 3), Verdict::not_confirmed);
  EXPECT_EQ(faster_planning_verdict(0, 0, 3), Verdict::not_confirmed);
  EXPECT_EQ(faster_planning_verdict(0, 0, 0), Verdict::not_measured);
}

TEST(PaperVerdicts, TighterTreesThresholdsAndTheRangeOfEveryMesh) {
  // 10 of 11 meshes tighter with INERTIA_FIT, one looser (1.42×).
  std::vector<MeshRow> meshes;
  for (int i = 0; i < 10; ++i) meshes.push_back(mesh("m" + std::to_string(i), 100, 58 + 4 * i, 10, 10));
  meshes.push_back(mesh("looser", 100, 142, 10, 10));
  PaperRows rows;
  rows.meshes = meshes;
  const ClaimVerdict c = assess_claims(rows, 3)[0];
  EXPECT_EQ(c.verdict, Verdict::confirmed) << c.text();
  EXPECT_NE(c.evidence.find("on 10 of 11 meshes"), std::string::npos) << c.evidence;
  EXPECT_NE(c.evidence.find("SA 0.580–1.420×"), std::string::npos) << c.evidence;  // the looser mesh is in the range
  expect_one_verdict(c);

  EXPECT_EQ(tighter_trees_verdict(9, 12), Verdict::confirmed);
  EXPECT_EQ(tighter_trees_verdict(8, 12), Verdict::partly_confirmed);
  EXPECT_EQ(tighter_trees_verdict(5, 11), Verdict::not_confirmed);
  EXPECT_EQ(tighter_trees_verdict(0, 0), Verdict::not_measured);

  EXPECT_EQ(slower_planning_verdict(3, 3, 3, true), Verdict::confirmed);
  EXPECT_EQ(slower_planning_verdict(3, 2, 3, true), Verdict::partly_confirmed);
  EXPECT_EQ(slower_planning_verdict(1, 1, 3, true), Verdict::partly_confirmed);
  EXPECT_EQ(slower_planning_verdict(0, 1, 3, true), Verdict::not_confirmed);
}

TEST(PaperVerdicts, BuildPeersCoverEveryMesh) {
  std::vector<MeshRow> meshes{mesh("a", 1, 1, 100, 100), mesh("b", 1, 1, 50, 50)};
  meshes[1].fcl_rss_build_ms = runs({34});  // 0.68× of 50
  PaperRows rows;
  rows.meshes = meshes;
  bool saw = false;
  for (const std::string& f : peer_findings(rows))
    if (f.find("build: FCL RSS") == 0) {
      saw = true;
      EXPECT_NE(f.find("0.68–0.90×"), std::string::npos) << f;
      EXPECT_NE(f.find("over 2 meshes"), std::string::npos) << f;
    }
  EXPECT_TRUE(saw);
}

}  // namespace
}  // namespace swept::bench
