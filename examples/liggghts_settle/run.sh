#!/usr/bin/env bash
# Settle (LIGGGHTS): 468 beads settle in a box with fix hardcontact in LIGGGHTS 3.8
# (OUTDIR/hard, in.settle) and with LIGGGHTS's own Hertz contacts (OUTDIR/soft, in.settle.soft),
# then prints the measures of both and draws OUTDIR/settle.png (settle.py).
#   examples/liggghts_settle/run.sh [OUTDIR] [hard|soft|both] [extra LIGGGHTS arguments]
# default OUTDIR out/liggghts_settle, both. HARDCONTACT_LIGGGHTS overrides the LIGGGHTS with the
# fix (default build/liggghts_hardcontact); LMP_SOFT the one of the twin (default: the same).
set -euo pipefail
# run_common.sh runs HARDCONTACT_LMP: here the LIGGGHTS with the fix
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
export HARDCONTACT_LMP="${HARDCONTACT_LIGGGHTS:-$repo/build/liggghts_hardcontact}"
# shellcheck shell=bash source=../common/run_common.sh
source "$(dirname "${BASH_SOURCE[0]}")/../common/run_common.sh"
hc_twin_args liggghts_settle "$@"
runs="$WHICH"
[ "$WHICH" != both ] || runs="hard soft"
for d in $runs; do
  if [ "$d" = hard ]; then launcher="$LMP" deck=in.settle
  else launcher="$LMP_SOFT" deck=in.settle.soft; fi
  hc_lmp "$OUT/$d" "" "liggghts_settle: $deck" "$launcher" "$deck" "${LMP_ARGS[@]}"
  hc_loop_time "$OUT/$d/log.lammps" "liggghts_settle %-4s: %d steps, loop time %.2f s\n" "$d"
done
if [ "$WHICH" = both ]; then
  "$PY" "$HERE/settle.py" "$OUT/hard" "$OUT/soft" "$OUT/settle.png"
fi
echo "liggghts_settle: output in $OUT"
