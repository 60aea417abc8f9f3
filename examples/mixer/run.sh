#!/usr/bin/env bash
# Mixer: a drum with 6 lifters read from an STL file (make_mixer.py) turns a bed of spheres whose
# two halves start side by side (OUTDIR/lifters, in.mixer with `wall stl mixer.stl rotate ...`),
# and the same drum without lifters (OUTDIR/bare); prints the mixing of both and draws
# OUTDIR/mixer.png (mixer.py). About 10 s on 2 cores.
#   examples/mixer/run.sh [OUTDIR] [extra LAMMPS arguments]
# default OUTDIR out/mixer; HARDCONTACT_LMP overrides the LAMMPS with the fix.
set -euo pipefail
# shellcheck shell=bash source=../common/run_common.sh
source "$(dirname "${BASH_SOURCE[0]}")/../common/run_common.sh"
hc_outdir "${1:-$ROOT/out/mixer}"
shift $(( $# >= 1 ? 1 : 0 ))
for lifters in 6 0; do
  name=lifters; [ "$lifters" = 0 ] && name=bare
  mkdir -p "$OUT/$name"
  L=$("$PY" -c "import math; print(3 * 1.12 * math.sqrt(2.0))")    # in.mixer's periodic length
  "$PY" "$HERE/make_mixer.py" "$OUT/$name/mixer.stl" 7 "$L" "$lifters" 2.0 > /dev/null
  hc_lmp "$OUT/$name" "" "mixer: in.mixer ($lifters lifters)" "$LMP" in.mixer -var lifters "$lifters" "$@" &
done
wait
for name in lifters bare; do
  hc_loop_time "$OUT/$name/log.lammps" "mixer %-7s: %d steps, loop time %.2f s\n" "$name"
done
"$PY" "$HERE/mixer.py" "$OUT/mixer.png" "6 lifters=$OUT/lifters" "no lifters=$OUT/bare"
echo "mixer: output in $OUT"
