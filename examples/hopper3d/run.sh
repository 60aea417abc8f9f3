#!/usr/bin/env bash
# Conical hopper (3d): 1500 glass beads with friction (mu 0.5) settle once with the outlet
# closed, then drain through round outlets of several diameters, with fix hardcontact and with
# the soft-sphere twin (pair_style granular + fix wall/gran/region); then the Beverloo fit.
#   examples/hopper3d/run.sh [OUTDIR] [hard|soft|both] [OUTLETS_MM] [extra LAMMPS arguments]
# default OUTDIR out/hopper3d, both, OUTLETS_MM "7 8 10 12 14". Run dirs OUTDIR/<kind>_settle
# (settled.data) and OUTDIR/<kind>_D<mm> (log.lammps, hopper3d.dump, hopper3d.<step>.png of a
# cut-away side view); OUTDIR: beverloo.txt (rates and fits), beverloo.png.
set -euo pipefail
# shellcheck source=../common/run_common.sh
source "$(dirname "${BASH_SOURCE[0]}")/../common/run_common.sh"
OUTLETS="${3:-7 8 10 12 14}"
hc_twin_args hopper3d "${1:-}" "${2:-both}" "${@:4}"
"$PY" "$HERE/make_data.py" "$OUT/data.hopper3d"

kinds="$WHICH"
[ "$WHICH" != both ] || kinds="hard soft"
for kind in $kinds; do
  if [ "$kind" = hard ]; then launcher="$LMP" deck=in.hopper3d; else launcher="$LMP_SOFT" deck=in.hopper3d.soft; fi
  # the settling does not depend on the outlet: once per model, then every outlet starts from it
  hc_lmp "$OUT/${kind}_settle" "hopper3d.*.png" "hopper3d: $deck settling" "$launcher" "$deck" \
    -var data "$OUT/data.hopper3d" -var tflow 0 -var pictures no "${LMP_ARGS[@]}"
  hc_loop_time "$OUT/${kind}_settle/log.lammps" "hopper3d %-12s: %d steps, loop time %.1f s\n" "${kind}_settle"
  for w in $OUTLETS; do
    outlet=$(awk -v w="$w" 'BEGIN{printf "%.6g", w/1000}')
    hc_lmp "$OUT/${kind}_D$w" "hopper3d.*.png" "hopper3d: $deck D = $w mm" "$launcher" "$deck" \
      -var data "$OUT/${kind}_settle/settled.data" -var settle no -var outlet "$outlet" "${LMP_ARGS[@]}"
    hc_loop_time "$OUT/${kind}_D$w/log.lammps" "hopper3d %-12s: %d steps, loop time %.1f s\n" "${kind}_D$w"
  done
done
# shellcheck disable=SC2086   # one argument per outlet
"$PY" "$HERE/beverloo3d.py" "$OUT" $OUTLETS | tee "$OUT/beverloo.txt"
echo "hopper3d: output in $OUT"
