#!/usr/bin/env bash
# Hopper (LIGGGHTS): about 2000 glass beads settle in a conical hopper read from an STL file
# (fix mesh/surface) and drain through its 20 mm outlet, with fix hardcontact in LIGGGHTS 3.8
# (OUTDIR/hard, in.hopper: `wall mesh cad`) and with LIGGGHTS's own Hertz contacts and fix
# wall/gran mesh (OUTDIR/soft, in.hopper.soft), then prints the measures of both and draws
# OUTDIR/hopper.png (hopper.py). About 2.5 minutes on one core.
#   examples/liggghts_hopper/run.sh [OUTDIR] [hard|soft|both] [extra LIGGGHTS arguments]
# default OUTDIR out/liggghts_hopper, both. HARDCONTACT_LIGGGHTS overrides the LIGGGHTS with the
# fix (default build/liggghts_hardcontact); LMP_SOFT the one of the twin (default: the same).
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
export HARDCONTACT_LMP="${HARDCONTACT_LIGGGHTS:-$repo/build/liggghts_hardcontact}"
# shellcheck shell=bash source=../common/run_common.sh
source "$(dirname "${BASH_SOURCE[0]}")/../common/run_common.sh"
hc_twin_args liggghts_hopper "$@"
runs="$WHICH"
[ "$WHICH" != both ] || runs="hard soft"
for d in $runs; do
  if [ "$d" = hard ]; then launcher="$LMP" deck=in.hopper
  else launcher="$LMP_SOFT" deck=in.hopper.soft; fi
  mkdir -p "$OUT/$d"
  "$PY" "$HERE/make_hopper.py" "$OUT/$d/hopper.stl" > /dev/null
  hc_lmp "$OUT/$d" "" "liggghts_hopper: $deck" "$launcher" "$deck" "${LMP_ARGS[@]}"
  hc_loop_time "$OUT/$d/log.lammps" "liggghts_hopper %-4s: %d steps, loop time %.2f s\n" "$d"
done
if [ "$WHICH" = both ]; then
  "$PY" "$HERE/hopper.py" "$OUT/hopper.png" "hard=$OUT/hard" "soft=$OUT/soft"
fi
echo "liggghts_hopper: output in $OUT"
