#pragma once
/// Clocks of the benchmarks, and the planner status words their tables print.
#include "swept/plan/planner.h"

#include <chrono>
#include <optional>
#include <string_view>

namespace swept::bench {

using Clock = std::chrono::steady_clock;

/// Wall milliseconds since t0.
double ms_since(Clock::time_point t0);

/// CPU time of the whole process, ms. The paper benchmark times with it: on a shared machine the
/// wall clock also counts the time other processes hold the cores, the CPU time does not.
double cpu_ms();

/// The status of a plan() as the benchmarks' tables and JSON spell it: "solved",
/// "no path (time limit)", "invalid start", ...
std::string_view status_name(PlanStatus s);
/// The status a status_name() spells (also "no path (time)", bench_plan's word before
/// 2026-11-24); nullopt for anything else.
std::optional<PlanStatus> status_named(std::string_view name);

}  // namespace swept::bench
