// Phase 3: shortcut smoothing (smoothing.h).
#include "smoothing.h"

namespace swept::detail {
namespace {

// A shortcut whose certificate needs more bisection queries than this grazes the margin for
// most of its length: it is not taken, and the path keeps its waypoints there (measured on the
// suite: the cubicles' smoothing 44 -> 18 ms, its path no longer and no closer to the
// obstacles; no other problem's path changed but the spiral tube's).
constexpr int kShortcutQueries = 256;

}  // namespace

void smooth(PlanContext& context, std::vector<Pose>& path, std::size_t fixed) {
  for (int round = 0; round < 2 && path.size() > fixed + 2; ++round) {
    std::vector<Pose> out(path.begin(), path.begin() + static_cast<std::ptrdiff_t>(fixed + 1));
    std::size_t i = fixed;
    while (i + 1 < path.size()) {
      if (context.out_of_time() || context.over_budget()) return;
      std::size_t lo = i + 1, hi = path.size() - 1;  // lo: known reachable (an edge of the path)
      while (lo < hi) {
        const std::size_t mid = (lo + hi + 1) / 2;
        if (context.over_budget()) return;  // the path as it was: every segment certified
        if (context.certify(path[i], -1, path[mid], -1, kShortcutQueries)) lo = mid;
        else hi = mid - 1;
      }
      out.push_back(path[lo]);
      i = lo;
    }
    path = std::move(out);
  }
}

}  // namespace swept::detail
