// Phase 3: shortcut smoothing (smoothing.h).
#include "smoothing.h"

namespace swept::detail {

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
        if (context.certify(path[i], -1, path[mid], -1)) lo = mid;
        else hi = mid - 1;
      }
      out.push_back(path[lo]);
      i = lo;
    }
    path = std::move(out);
  }
}

}  // namespace swept::detail
