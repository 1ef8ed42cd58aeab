#!/usr/bin/env bash
# Regenerates the pictures of the built-in scenes in docs/img/: each scene at test scale is
# generated, planned, written as a viewer page, and photographed by headless Chromium at the
# start and at the end of its path.   bash scripts/scene_pictures.sh [SWEPT_BINARY]
set -euo pipefail
cd "$(dirname "$0")/.."
swept=${1:-build/release/apps/swept/swept}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for scene in air-cleaner cylinder-head tunnel-console; do
  "$swept" scene "$scene" --scale test -o "$work/$scene" >/dev/null
  "$swept" plan "$work/$scene/problem.toml" -q -o "$work/$scene/path.json" --view "$work/$scene/$scene.html" >/dev/null
  node tests/viewer/view_screenshots.mjs "$work/$scene/$scene.html" "$work/shots" --size 1200x800 >/dev/null || true
  for end in start end; do
    cp "$work/shots/$scene-$end.png" "docs/img/scene-$scene-$end.png"
  done
done
echo "wrote docs/img/scene-*.png"
