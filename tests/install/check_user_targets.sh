#!/usr/bin/env bash
# The first command (scripts/demo.sh: scripts/setup.sh without --all) builds what a user runs and
# nothing else. Reads the build's own plan (ninja -t commands, nothing is built) for the targets
# setup.sh names, and fails if it would compile a test or a benchmark program, or link
# GoogleTest, Google Benchmark or OMPL.
#   tests/install/check_user_targets.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$1 source=$2
targets=$(sed -n 's/^user_targets=(\(.*\))$/\1/p' "$source/scripts/setup.sh")
[ -n "$targets" ] || { echo "no user_targets=(...) line in $source/scripts/setup.sh" >&2; exit 1; }
if ninja -C "$build" -t query swept_python >/dev/null 2>&1; then targets="$targets swept_python"; fi
# shellcheck disable=SC2086
commands=$(ninja -C "$build" -t commands $targets)
compiled=$(grep -oE ' -c [^ ]+\.cpp' <<<"$commands" | sed 's/^ -c //' | sort -u)
status=0
bad=$(grep -E "^$source/(tests|fuzz)/|^$source/bench/[^/]+\.cpp$" <<<"$compiled" || true)
if [ -n "$bad" ]; then
  echo "setup.sh's targets ($targets) compile test or benchmark sources:" >&2
  echo "$bad" >&2
  status=1
fi
if grep -qE 'libgtest|-lgtest|libbenchmark|-lbenchmark|libompl|-lompl' <<<"$commands"; then
  echo "setup.sh's targets ($targets) link GoogleTest, Google Benchmark or OMPL:" >&2
  grep -oE '[^ ]*(libgtest|libbenchmark|libompl)[^ ]*' <<<"$commands" | sort -u >&2
  status=1
fi
for needed in swept swept-tools libswept_cad.so; do
  grep -qE -- "-o [^ ]*/$needed( |$)" <<<"$commands" || { echo "setup.sh's targets do not build $needed" >&2; status=1; }
done
echo "user targets: $targets; $(wc -l <<<"$compiled") sources compiled"
exit "$status"
