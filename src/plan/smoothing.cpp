// Phase 3: shortcut smoothing (smoothing.h).
#include "smoothing.h"

#include <tbb/parallel_for.h>

#include <limits>

namespace swept::detail {
namespace {

// A shortcut whose certificate needs more bisection queries than this grazes the margin for
// most of its length: it is not taken, and the path keeps its waypoints there (measured on the
// suite: the cubicles' smoothing 44 -> 18 ms at 256, its path no longer and no closer to the
// obstacles; no other problem's path changed but the spiral tube's). 192 against 256: the
// cubicles' whole plan 4 % fewer instructions, the same paths but the spiral tube's (0.07 %
// shorter); at 128 the cubicles' path changes. docs/lab/planner-history.md.
constexpr int kShortcutQueries = 192;

}  // namespace

void smooth(PlanContext& context, std::vector<Pose>& path, std::size_t fixed) {
  // The distance at every waypoint a shortcut can start or end at, measured once, in parallel:
  // each serves as a known end bound of every shortcut through it.
  std::vector<double> distance(path.size(), -1.0);
  tbb::parallel_for(fixed, path.size(), [&](std::size_t k) {
    distance[k] = context.check.clearance(path[k], std::numeric_limits<double>::infinity());
  });
  for (int round = 0; round < 2 && path.size() > fixed + 2; ++round) {
    std::vector<Pose> out(path.begin(), path.begin() + static_cast<std::ptrdiff_t>(fixed + 1));
    std::vector<double> out_distance(distance.begin(), distance.begin() + static_cast<std::ptrdiff_t>(fixed + 1));
    std::size_t i = fixed;
    while (i + 1 < path.size()) {
      if (context.out_of_time() || context.over_budget()) return;
      std::size_t lo = i + 1, hi = path.size() - 1;  // lo: known reachable (an edge of the path)
      while (lo < hi) {
        const std::size_t mid = (lo + hi + 1) / 2;
        if (context.over_budget()) return;  // the path as it was: every segment certified
        if (context.certify(path[i], distance[i], path[mid], distance[mid], kShortcutQueries)) lo = mid;
        else hi = mid - 1;
      }
      out.push_back(path[lo]);
      out_distance.push_back(distance[lo]);
      i = lo;
    }
    path = std::move(out);
    distance = std::move(out_distance);
  }
}

}  // namespace swept::detail
