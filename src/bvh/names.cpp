// The fitter and split-rule tables: the one place a fitter is named.
#include "swept/bvh/bvh.h"

#include <array>

namespace swept {
namespace {

constexpr std::array kFitters{
    FitterInfo{Fitter::pqp, "pqp", "PQP_FIT",
               "vertex mean and covariance (Gottschalk, Lin, Manocha 1996; PQP)",
               {.area_weighted = false, .k_center = 3.0, .k_scatter = 1.0, .per_vertex = true, .by_min_area = false}},
    FitterInfo{Fitter::rapid2, "rapid2", "RAPID2_FIT",
               "area-weighted covariance of the triangles (RAPID, convex hull skipped)",
               {.area_weighted = true, .k_center = 1.0, .k_scatter = 1.0 / 12.0, .per_vertex = false, .by_min_area = false}},
    FitterInfo{Fitter::inertia, "inertia", "INERTIA_FIT",
               "shell centroid and area-weighted tensor of inertia (the paper)",
               {.area_weighted = true, .k_center = 3.0, .k_scatter = 1.0, .per_vertex = true, .by_min_area = true}},
};

constexpr std::array kSplitRules{
    SplitRuleInfo{SplitRule::min_sa, "min-sa",
                  "try e1, e2, e3; keep the smallest SA(left) + SA(right), each side fitted as its own child (IPS CDC, the paper)"},
    SplitRuleInfo{SplitRule::largest, "largest", "split across e1 only (PQP)"},
    SplitRuleInfo{SplitRule::min_sa_box, "min-sa-box",
                  "min-sa with each side costed by its bounding box in the node's frame: cheaper, not the paper's rule"},
};

template <class Table>
std::string joined(const Table& table, std::string_view separator) {
  std::string out;
  for (const auto& row : table) {
    if (!out.empty()) out += separator;
    out += row.name;
  }
  return out;
}

}  // namespace

std::span<const FitterInfo> all_fitters() { return kFitters; }
std::span<const SplitRuleInfo> all_split_rules() { return kSplitRules; }

const FitterInfo& info(Fitter f) {
  for (const FitterInfo& row : kFitters)
    if (row.fitter == f) return row;
  return kFitters.back();  // unreachable for a valid enum value
}

const SplitRuleInfo& info(SplitRule s) {
  for (const SplitRuleInfo& row : kSplitRules)
    if (row.rule == s) return row;
  return kSplitRules.front();
}

std::string_view to_string(Fitter f) { return info(f).name; }
std::string_view to_string(SplitRule s) { return info(s).name; }
std::string fitter_names(std::string_view separator) { return joined(kFitters, separator); }
std::string split_rule_names(std::string_view separator) { return joined(kSplitRules, separator); }

bool parse_fitter(std::string_view text, Fitter& out) {
  for (const FitterInfo& row : kFitters)
    if (row.name == text) return out = row.fitter, true;
  return false;
}

bool parse_split_rule(std::string_view text, SplitRule& out) {
  for (const SplitRuleInfo& row : kSplitRules)
    if (row.name == text) return out = row.rule, true;
  return false;
}

}  // namespace swept
