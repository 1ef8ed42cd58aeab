#pragma once
/// The library's fitter and split-rule tables as plain lists, for the tests that loop over every
/// fitter or split rule: a row added to all_fitters() is tested everywhere without editing them.
#include "swept/bvh/bvh.h"

#include <vector>

namespace swept::test {

inline std::vector<Fitter> every_fitter() {
  std::vector<Fitter> out;
  for (const FitterInfo& f : all_fitters()) out.push_back(f.fitter);
  return out;
}

inline std::vector<SplitRule> every_split_rule() {
  std::vector<SplitRule> out;
  for (const SplitRuleInfo& s : all_split_rules()) out.push_back(s.rule);
  return out;
}

}  // namespace swept::test
