#!/usr/bin/env bash
# Regenerates docs/mesh-stats.md: triangle-size and shape spread (`swept mesh-stats`) of the
# built-in scenes at test scale and of the real CAD meshes in ../shared/data, so the spread of
# the generated scenes can be compared with real CAD exports.
#   bash scripts/mesh_stats_table.sh [SWEPT_BINARY]
set -euo pipefail
cd "$(dirname "$0")/.."
repo=$(pwd)
swept=$(realpath "${1:-build/release/apps/swept/swept}")
data=../shared/data
[ -x "$swept" ] || { echo "mesh_stats_table: no swept binary at $swept" >&2; exit 1; }
[ -d "$data" ] || { echo "mesh_stats_table: $data is absent" >&2; exit 1; }
out=$repo/docs/mesh-stats.md
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

scenes=(air-cleaner cylinder-head tunnel-console)
for s in "${scenes[@]}"; do
  "$swept" scene "$s" --scale test -o "$work/scenes/$s" > /dev/null
done
{
  echo "# Triangle-size spread: generated scenes vs. real CAD"
  echo
  echo "Made by \`bash scripts/mesh_stats_table.sh\` on $(date -u +%Y-%m-%d). Columns (\`swept mesh-stats\`):"
  echo "triangles; degenerate triangles (2·area / longest edge² ≤ 1e-12); largest over smallest"
  echo "triangle area; median aspect ratio (longest edge / smallest height); share of triangles with"
  echo "aspect ratio > 10. Area and aspect figures are over the non-degenerate triangles."
  echo
  echo "## Built-in scenes, \`--scale test\`"
  echo
  echo "Generated with \`swept scene NAME --scale test\` (paths relative to the output directory)."
  echo
  (cd "$work/scenes" && "$swept" mesh-stats --markdown */*.stl)
  echo
  echo "## Real CAD meshes (../shared/data)"
  echo
  echo "\`tessellated/\`: OpenCASCADE BRepMesh at the deflection in the folder name; \`occt/*.stl\`:"
  echo "CAD-exported meshes shipped with OCCT; \`ros_industrial/\`: vendor-exported robot links (metres,"
  echo "read as mm here, so areas are scaled by 1e6 but ratios are unaffected)."
  echo
  (cd "$data" && "$swept" mesh-stats --markdown tessellated/*/*.stl occt/*.stl ros_industrial/*.stl)
} > "$out.tmp"
mv "$out.tmp" "$out"
echo "wrote $out"
