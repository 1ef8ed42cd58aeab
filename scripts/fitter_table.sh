#!/usr/bin/env bash
# Regenerates docs/fitter-table.md: total RSS surface area and volume per fitter and split rule
# on the real CAD of ../shared/data (the paper's Table II question: are INERTIA_FIT's trees
# tighter than PQP_FIT's?).   bash scripts/fitter_table.sh [SWEPT_BINARY]
set -euo pipefail
cd "$(dirname "$0")/.."
swept=${1:-build/release/apps/swept/swept}
data=../shared/data
[ -d "$data" ] || { echo "fitter_table: $data is absent" >&2; exit 1; }
out=docs/fitter-table.md
files=(
  "$data"/occt/motor.stl "$data"/occt/TR12J_OCC64K.stl
  "$data"/ros_industrial/kuka_kr10r1420_visual_base_link.stl "$data"/ros_industrial/kuka_kr10r1420_visual_link_2.stl
  "$data"/tessellated/engine_d0.05/engine_p01_CylinderHead_rle_brep.stl
  "$data"/tessellated/motor_cutaway_d0.1/motor_p0[0-3]_*.stl
  "$data"/nist/nist_ctc_01_asme1_rd.stp "$data"/nist/nist_ctc_04_asme1_rd.stp "$data"/nist/nist_ftc_07_asme1_rd.stp
  "$data"/as1/as1-oc-214.stp "$data"/occt/Propeller_rle.brep "$data"/occt/hammer.brep
)
{
  echo "# Total RSS surface area and volume per fitter (real CAD)"
  echo
  echo "Made by \`bash scripts/fitter_table.sh\` on $(date -u +%Y-%m-%d) ($(nproc) cores); CAD files"
  echo "(STEP/BREP) tessellated at 0.05 mm linear deflection; a file with several parts is one soup."
  echo "Ratios are against pqp with the same split rule: below 1 means a tighter tree than PQP_FIT's."
  echo
  "$swept" bvh "${files[@]}" --fitter all --split all --deflection 0.05 --markdown
} > "$out.tmp"
mv "$out.tmp" "$out"
echo "wrote $out"
