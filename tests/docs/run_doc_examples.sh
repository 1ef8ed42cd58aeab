#!/usr/bin/env bash
# Runs every marked example of the user docs, as a reader would paste it.
#
#   bash tests/docs/run_doc_examples.sh BUILD_DIR      (ctest: doc_examples, label docs)
#
# An example is a ```sh or ```python fence right after a line `<!-- example: NAME -->` (blank lines
# between them allowed) in README.md or docs/*.md (docs/lab is not read). Each one runs in a fresh
# empty folder (its working directory, and TMPDIR, so that nothing it writes lands elsewhere), with
# BUILD_DIR/apps/swept first on PATH and BUILD_DIR/python first on PYTHONPATH: sh blocks under
# `bash -euo pipefail`, python blocks under Debian's /usr/bin/python3 (the interpreter the module is
# built for; a `python3` found first on PATH, such as pyenv's, does not see Debian's NumPy). When
# the module is not built, python blocks and sh blocks that call python3 are skipped, and say so.
# Fails, naming the doc, the line and the example, when one fails, takes over TIMEOUT seconds
# (SWEPT_DOC_EXAMPLE_TIMEOUT, default 120), or when a marker has no fence after it.
set -euo pipefail

if [[ $# -ne 1 ]]; then
  echo "usage: $0 BUILD_DIR" >&2
  exit 1
fi
build=$(cd "$1" && pwd)
source_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
cli_dir="$build/apps/swept"
python_dir="$build/python"
python=/usr/bin/python3
timeout_s=${SWEPT_DOC_EXAMPLE_TIMEOUT:-120}

if [[ ! -x "$cli_dir/swept" ]]; then
  echo "run_doc_examples: no swept binary at $cli_dir/swept (build the CLI first)" >&2
  exit 1
fi
have_python=1
if [[ ! -d "$python_dir/swept" || ! -x "$python" ]]; then
  have_python=0
fi

work=$(mktemp -d "${TMPDIR:-/tmp}/swept-doc-examples.XXXXXX")
trap 'rm -rf "$work"' EXIT

# Extract the blocks: one file per block, and one line per block in $work/index
# (number, language, doc, line of the marker, name).
: > "$work/index"
count=0
malformed=0
for doc in "$source_dir/README.md" "$source_dir"/docs/*.md; do
  rel=${doc#"$source_dir"/}
  lineno=0
  pending=""      # name of a marker waiting for its fence
  pending_line=0
  lang=""         # inside a block: sh or python
  out=""
  while IFS= read -r line || [[ -n "$line" ]]; do
    lineno=$((lineno + 1))
    if [[ -n "$lang" ]]; then
      if [[ "$line" =~ ^\`\`\`[[:space:]]*$ ]]; then
        lang=""
      else
        printf '%s\n' "$line" >> "$out"
      fi
      continue
    fi
    if [[ "$line" =~ ^\<\!--[[:space:]]*example:[[:space:]]*([A-Za-z0-9_.-]+)[[:space:]]*--\>[[:space:]]*$ ]]; then
      if [[ -n "$pending" ]]; then
        echo "FAIL  $rel:$pending_line: example '$pending' is not followed by a \`\`\`sh or \`\`\`python fence" >&2
        malformed=$((malformed + 1))
      fi
      pending=${BASH_REMATCH[1]}
      pending_line=$lineno
      continue
    fi
    if [[ -n "$pending" ]]; then
      if [[ -z "${line//[[:space:]]/}" ]]; then
        continue
      fi
      if [[ "$line" =~ ^\`\`\`(sh|bash|python)[[:space:]]*$ ]]; then
        count=$((count + 1))
        lang=${BASH_REMATCH[1]}
        [[ "$lang" == bash ]] && lang=sh
        out="$work/block-$count.$lang"
        : > "$out"
        printf '%s\t%s\t%s\t%s\t%s\n' "$count" "$lang" "$rel" "$pending_line" "$pending" >> "$work/index"
      else
        echo "FAIL  $rel:$pending_line: example '$pending' is not followed by a \`\`\`sh or \`\`\`python fence" >&2
        malformed=$((malformed + 1))
      fi
      pending=""
    fi
  done < "$doc"
  if [[ -n "$pending" ]]; then
    echo "FAIL  $rel:$pending_line: example '$pending' is not followed by a \`\`\`sh or \`\`\`python fence" >&2
    malformed=$((malformed + 1))
  fi
  if [[ -n "$lang" ]]; then
    echo "FAIL  $rel: the fence of example '$(tail -n 1 "$work/index" | cut -f5)' is never closed" >&2
    malformed=$((malformed + 1))
    sed -i '$d' "$work/index"  # not run: it holds the rest of the doc
    count=$((count - 1))
  fi
done

if [[ $count -eq 0 ]]; then
  echo "run_doc_examples: no marked examples found in README.md and docs/*.md" >&2
  exit 1
fi

passed=0
failed=0
skipped=0
while IFS=$'\t' read -r n lang rel line name; do
  block="$work/block-$n.$lang"
  label="$rel:$line: $name"
  if [[ $have_python -eq 0 ]] && { [[ "$lang" == python ]] || grep -q 'python3' "$block"; }; then
    echo "skip  $label (the Python module is not built in $build)"
    skipped=$((skipped + 1))
    continue
  fi
  dir="$work/run-$n"
  mkdir -p "$dir/tmp"
  if [[ "$lang" == python ]]; then
    cmd=("$python" "$block")
  else
    cmd=(bash -euo pipefail "$block")
  fi
  start=$(date +%s.%N)
  status=0
  (
    cd "$dir"
    export PATH="$cli_dir:$PATH"
    export PYTHONPATH="$python_dir${PYTHONPATH:+:$PYTHONPATH}"
    export TMPDIR="$dir/tmp"
    exec timeout "$timeout_s" "${cmd[@]}"
  ) > "$work/out-$n.txt" 2>&1 < /dev/null || status=$?
  seconds=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }')
  if [[ $status -eq 0 ]]; then
    echo "ok    $label ($lang, $seconds s)"
    passed=$((passed + 1))
  else
    if [[ $status -eq 124 ]]; then
      why="took more than $timeout_s s"
    else
      why="exit $status"
    fi
    echo "FAIL  $label ($lang): $why after $seconds s; the last lines of its output:"
    tail -n 25 "$work/out-$n.txt" | sed 's/^/      /'
    failed=$((failed + 1))
  fi
done < "$work/index"

echo "$count examples: $passed passed, $failed failed, $skipped skipped"
if [[ $failed -gt 0 || $malformed -gt 0 ]]; then
  [[ $malformed -gt 0 ]] && echo "$malformed example markers without a fence" >&2
  exit 1
fi
