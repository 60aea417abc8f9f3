#!/usr/bin/env bash
# Column collapse: a quasi-2D column of spheres (mu 0.5, aspect ratio about 2.1) released from
# behind a gate onto a rough floor, with fix hardcontact (in.collapse, the fix's defaults with
# friction) and its soft-sphere twin (in.collapse.soft: pair_style granular, fix wall/gran,
# fix nve/sphere); then the runout of each (collapse_runout.py) and a side view of the
# columns and deposits (collapse_plot.py).
#   examples/column_collapse/run.sh [OUTDIR] [hard|soft|both] [extra LAMMPS arguments, e.g. -var seed 1234567]
# default OUTDIR out/column_collapse, both. Run dirs OUTDIR/hard, OUTDIR/soft: log.lammps,
# collapse0.dump (the column at release), collapse1.dump (the deposit); OUTDIR: runout.txt (one
# line per run), collapse.png.
set -euo pipefail
# shellcheck source=../common/run_common.sh
source "$(dirname "${BASH_SOURCE[0]}")/../common/run_common.sh"
hc_twin_args column_collapse "$@"

runs=()
run_one() {    # run_one hard|soft
  local kind="$1" launcher="$LMP" deck=in.collapse
  [ "$kind" = hard ] || { launcher="$LMP_SOFT"; deck=in.collapse.soft; }
  hc_lmp "$OUT/$kind" "" "column_collapse: $deck" "$launcher" "$deck" "${LMP_ARGS[@]}"
  hc_loop_time "$OUT/$kind/log.lammps" "column_collapse %-4s: %d steps, loop time %.1f s\n" "$kind"
  runs+=("$kind=$OUT/$kind")
}
if [ "$WHICH" != soft ]; then run_one hard; fi
if [ "$WHICH" != hard ]; then run_one soft; fi

: > "$OUT/runout.txt"
for r in "${runs[@]}"; do
  printf "%-5s " "${r%%=*}" >> "$OUT/runout.txt"
  "$PY" "$HERE/collapse_runout.py" "${r#*=}/collapse0.dump" "${r#*=}/collapse1.dump" >> "$OUT/runout.txt"
done
cat "$OUT/runout.txt"
"$PY" "$HERE/collapse_plot.py" "$OUT/collapse.png" "${runs[@]}"
echo "column_collapse: output in $OUT"
