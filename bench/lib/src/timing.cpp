#include "swept/bench/timing.h"

#include <ctime>

namespace swept::bench {

double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

double cpu_ms() {
  timespec ts{};
  ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) * 1e-6;
}

std::string_view status_name(PlanStatus s) {
  switch (s) {
    case PlanStatus::solved: return "solved";
    case PlanStatus::no_path_time: return "no path (time limit)";
    case PlanStatus::no_path_budget: return "no path (query budget)";
    case PlanStatus::no_path_bounds: return "no path (bounds)";
    case PlanStatus::no_path_resolution: return "no path (resolution)";
    case PlanStatus::invalid_start: return "invalid start";
    case PlanStatus::invalid_goal: return "invalid goal";
    case PlanStatus::invalid_bounds: return "invalid bounds";
  }
  return "unknown";
}

std::optional<PlanStatus> status_named(std::string_view name) {
  if (name == "no path (time)") return PlanStatus::no_path_time;
  for (const PlanStatus s : {PlanStatus::solved, PlanStatus::no_path_time, PlanStatus::no_path_budget, PlanStatus::no_path_bounds,
                             PlanStatus::no_path_resolution, PlanStatus::invalid_start, PlanStatus::invalid_goal,
                             PlanStatus::invalid_bounds})
    if (status_name(s) == name) return s;
  return std::nullopt;
}

}  // namespace swept::bench
