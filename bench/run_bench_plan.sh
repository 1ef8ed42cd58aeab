#!/usr/bin/env bash
# Builds and runs the side-by-side planner benchmark (swept vs OMPL RRTConnect + FCL) in the
# background-friendly way used for docs/bench-plan.md: table on stdout, progress on stderr,
# JSON next to the log.
#   bench/run_bench_plan.sh [BUILD_DIR] [bench_plan arguments...]
# e.g. bench/run_bench_plan.sh build/release --quick
set -euo pipefail
src="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$src/build/bench-plan}"
shift || true
cmake -S "$src" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" --target bench_plan -j2
out="$build/bench-plan-$(date +%Y%m%d-%H%M%S)"
echo "bench_plan: log $out.log, JSON $out.json" >&2
"$build/bench/bench_plan" --json "$out.json" "$@" 2> >(tee "$out.log" >&2) | tee "$out.txt"
