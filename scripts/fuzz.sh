#!/usr/bin/env bash
# Builds the libFuzzer targets of fuzz/ (preset `fuzz`: clang-14, ASan + UBSan) and fuzzes each on
# its seed corpus (docs/reliability.md).
#   bash scripts/fuzz.sh                  # every target 5 s
#   bash scripts/fuzz.sh 60               # every target 60 s
#   bash scripts/fuzz.sh --long           # every target until 10^6 executions (-runs=1000000)
#   bash scripts/fuzz.sh 1800 --long      # ... or 1800 s, whichever comes first
#   bash scripts/fuzz.sh 30 fuzz_stl fuzz_obj   # only these targets
# A short run stops a target at its first finding. A long run fuzzes in libFuzzer's fork mode
# (one child process at a time) and carries on past crashes, leaks and timeouts, so that it
# reaches its count and collects every finding on the way.
# New inputs go to build/fuzz/scratch/corpus/<target>/ (never into the repository's corpus);
# an input that crashed, leaked or timed out to build/fuzz/scratch/artifacts/<target>/ (emptied
# when the target starts), the
# log to build/fuzz/scratch/logs/<target>.log, the table printed to build/fuzz/scratch/summary.txt.
# Prints per target the executions and the outcome; exits 1 if any target found something.
# SWEPT_FUZZ_NICE (default 10) sets the runs' niceness, SWEPT_FUZZ_JOBS (default: all cores)
# the build's parallelism, SWEPT_FUZZ_SCRATCH another folder than build/fuzz/scratch (for two
# runs at once).
set -euo pipefail
cd "$(dirname "$0")/.."

seconds=""
long=0
only=()
for arg in "$@"; do
  case "$arg" in
    --long) long=1 ;;
    ''|*[!0-9]*) only+=("$arg") ;;
    *) seconds="$arg" ;;
  esac
done
if [ "$long" = 0 ] && [ -z "$seconds" ]; then seconds=5; fi

# clang-14 and its compiler-rt (libFuzzer's runtime, libclang_rt.fuzzer-x86_64.a, is in
# libclang-rt-14-dev on Debian 12), besides the library's own packages.
SWEPT_SKIP_BUILD=1 bash scripts/setup.sh
missing=()
for p in clang-14 libclang-rt-14-dev; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  if [ "$(id -u)" = 0 ]; then
    echo "fuzz: installing ${missing[*]}"
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq
    apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
  else
    echo "fuzz: please run as root:  apt-get install -y ${missing[*]}" >&2
    exit 1
  fi
fi

cmake --preset fuzz >/dev/null
cmake --build --preset fuzz -j"${SWEPT_FUZZ_JOBS:-$(nproc)}"

build=build/fuzz
scratch=${SWEPT_FUZZ_SCRATCH:-$build/scratch}
mapfile -t targets < "$build/fuzz/targets.txt"
if [ ${#only[@]} -gt 0 ]; then targets=("${only[@]}"); fi

export ASAN_OPTIONS="detect_leaks=1"
export LSAN_OPTIONS="suppressions=$PWD/fuzz/lsan.supp"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"

limits=(-rss_limit_mb=4096 -timeout=10)
if [ "$long" = 1 ]; then
  limits+=(-runs=1000000 -fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1)
  [ -n "$seconds" ] && limits+=(-max_total_time="$seconds")
  echo "== fuzzing each target until 10^6 executions${seconds:+ or $seconds s} =="
else
  limits+=(-max_total_time="$seconds")
  echo "== fuzzing each target for $seconds s =="
fi

failed=0
summary=$scratch/summary.txt
mkdir -p "$scratch"
printf '%-18s %12s %8s  %s\n' target executions seconds outcome | tee "$summary"
for t in "${targets[@]}"; do
  exe=$build/fuzz/$t
  [ -x "$exe" ] || { echo "fuzz: no target $t (see $build/fuzz/targets.txt)" >&2; exit 1; }
  rm -rf "$scratch/artifacts/$t"  # this run's findings only
  mkdir -p "$scratch/corpus/$t" "$scratch/artifacts/$t" "$scratch/logs"
  dirs=("$scratch/corpus/$t" "fuzz/corpus/$t")
  [ -d "fuzz/regressions/$t" ] && dirs+=("fuzz/regressions/$t")
  log=$scratch/logs/$t.log
  start=$(date +%s)
  rc=0
  # -close_fd_mask=1: the readers' own chatter on stdout (OpenCASCADE's) is dropped; reports
  # and libFuzzer's status go to stderr, into the log.
  nice -n "${SWEPT_FUZZ_NICE:-10}" "$exe" "${limits[@]}" -print_final_stats=1 -close_fd_mask=1 \
    -artifact_prefix="$scratch/artifacts/$t/" "${dirs[@]}" >"$log" 2>&1 || rc=$?
  elapsed=$(( $(date +%s) - start ))
  if [ "$long" = 1 ]; then  # fork mode's status lines: "#N: cov: ... oom/timeout/crash: a/b/c ..."
    execs=$(sed -n 's/^#\([0-9]*\): cov:.*/\1/p' "$log" | tail -1)
    counts=$(grep -oE 'oom/timeout/crash: [0-9/]+' "$log" | tail -1 || true)
  else
    execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
    counts=""
  fi
  found=$(find "$scratch/artifacts/$t" -type f | wc -l)
  outcome="ok"
  if [ "$rc" != 0 ] || [ "$found" != 0 ]; then
    failed=1
    what=$(grep -oE 'ERROR: (libFuzzer|AddressSanitizer|LeakSanitizer): [a-zA-Z -]+|runtime error: .*' "$log" |
           sed 's/ *$//' | sort | uniq -c | sort -rn | awk '{c=$1; $1=""; printf "%s%s x%s", (NR>1?";":""), $0, c}' || true)
    outcome="FOUND (exit $rc, $found inputs${counts:+, $counts}):${what:- see log} -> $scratch/artifacts/$t/, $log"
  fi
  printf '%-18s %12s %8s  %s\n' "$t" "${execs:-?}" "$elapsed" "$outcome" | tee -a "$summary"
done
if [ "$failed" != 0 ]; then
  echo "fuzz: some target found a crash, leak or timeout (above); a fixed one's input belongs in fuzz/regressions/<target>/" >&2
  exit 1
fi
