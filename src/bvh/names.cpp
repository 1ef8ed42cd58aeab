#include "swept/bvh/bvh.h"

namespace swept {

std::string_view to_string(Fitter f) {
  switch (f) {
    case Fitter::pqp: return "pqp";
    case Fitter::rapid2: return "rapid2";
    case Fitter::inertia: return "inertia";
  }
  return "?";
}

std::string_view to_string(SplitRule s) {
  switch (s) {
    case SplitRule::min_sa: return "min-sa";
    case SplitRule::largest: return "largest";
  }
  return "?";
}

bool parse_fitter(std::string_view text, Fitter& out) {
  if (text == "pqp") out = Fitter::pqp;
  else if (text == "rapid2") out = Fitter::rapid2;
  else if (text == "inertia") out = Fitter::inertia;
  else return false;
  return true;
}

bool parse_split_rule(std::string_view text, SplitRule& out) {
  if (text == "min-sa") out = SplitRule::min_sa;
  else if (text == "largest") out = SplitRule::largest;
  else return false;
  return true;
}

}  // namespace swept
