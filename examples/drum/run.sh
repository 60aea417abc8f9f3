#!/usr/bin/env bash
# Drum: a horizontal drum half full of spheres (friction 0.5) rotating at Froude number 0.01,
# with fix hardcontact (in.drum, the drum a rotating region wall) and its soft-sphere twin
# (in.drum.soft: pair_style granular, fix wall/gran/region, fix nve/sphere); then the dynamic
# angle of repose of each (drum_angle.py) and a picture (drum_plot.py).
#   examples/drum/run.sh [OUTDIR] [hard|soft|both] [extra LAMMPS arguments, e.g. -var nrev 0.5]
# default OUTDIR out/drum, both. Run dirs OUTDIR/hard, OUTDIR/soft: log.lammps, drum.dump;
# OUTDIR: angles.txt (one line per run), drum.png (views along the axis, angle vs time).
# HARD_DT="0.1 0.05" runs the hard deck at each step (OUTDIR/hard_dt<h>): the step's accuracy.
set -euo pipefail
# shellcheck source=../common/run_common.sh
source "$(dirname "${BASH_SOURCE[0]}")/../common/run_common.sh"
hc_twin_args drum "$@"

runs=()
run_one() {    # run_one DIR LAUNCHER DECK LABEL [LAMMPS arguments...]
  local dir="$1" launcher="$2" deck="$3" label="$4"
  shift 4
  hc_lmp "$OUT/$dir" "" "drum: $deck ($dir)" "$launcher" "$deck" "$@" "${LMP_ARGS[@]}"
  # the second run of each deck is the rotation: its loop time over its revolutions
  awk -v d="$dir" '/^drum: R/{dt = $11; period = $13} /^Loop time/{n++; if (n == 2) {t = $4; s = $9}}
       END{rev = s * dt / period; printf "drum %-12s: rotation %d steps (%.2f revolutions), loop time %.1f s, %.1f s per revolution\n", d, s, rev, t, t / rev}' \
    "$OUT/$dir/log.lammps"
  runs+=("$label=$OUT/$dir/drum.dump:$OUT/$dir/log.lammps")
}
if [ "$WHICH" != soft ]; then
  if [ -n "${HARD_DT:-}" ]; then
    for h in $HARD_DT; do run_one "hard_dt$h" "$LMP" in.drum "hard (h $h)" -var dt "$h"; done
  else
    run_one hard "$LMP" in.drum "hard"
  fi
fi
if [ "$WHICH" != hard ]; then run_one soft "$LMP_SOFT" in.drum.soft "soft"; fi

: > "$OUT/angles.txt"
for r in "${runs[@]}"; do
  files="${r#*=}"
  printf "%-12s " "${r%%=*}" >> "$OUT/angles.txt"
  "$PY" "$HERE/drum_angle.py" "${files%%:*}" "${files#*:}" >> "$OUT/angles.txt"
done
cat "$OUT/angles.txt"
(cd "$HERE" && "$PY" drum_plot.py "$OUT/drum.png" "${runs[@]}")
echo "drum: output in $OUT"
