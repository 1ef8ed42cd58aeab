#!/usr/bin/env bash
# Sets everything up and runs the main job on a built-in example: the tunnel-console scene at
# test scale is generated, a certified path is planned, and written with a viewer beside it.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
swept=build/release/apps/swept/swept
out=build/demo
rm -rf "$out"
"$swept" scene tunnel-console --scale test -o "$out" >/dev/null
"$swept" plan "$out/problem.toml" -o "$out/path.json" --view "$out/view.html"
echo
echo "path: $out/path.json   viewer (open in a browser): $out/view.html"
