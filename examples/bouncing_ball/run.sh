#!/usr/bin/env bash
# Two balls dropped on a floor with restitution (in.bounce): one still floor, one vibrated.
# Writes OUTDIR/log.lammps and OUTDIR/bounce.png (heights against time, with the e^(2k) H the
# law predicts) and prints the measured apexes.
#   examples/bouncing_ball/run.sh [OUTDIR] [extra LAMMPS arguments, e.g. -var e 0.6]
set -euo pipefail
# shellcheck source=../common/run_common.sh
source "$(dirname "${BASH_SOURCE[0]}")/../common/run_common.sh"
hc_outdir "${1:-$ROOT/out/bouncing_ball}"
shift $(( $# >= 1 ? 1 : 0 ))
hc_lmp "$OUT" "" "bouncing_ball: LAMMPS" "$LMP" in.bounce "$@"
e=$(sed -n 's/^variable *e index *//p' "$HERE/in.bounce")
for ((a = 1; a <= $#; a++)); do [ "${!a}" = "-var" ] && b=$((a + 1)) && [ "${!b}" = "e" ] && c=$((a + 2)) && e="${!c}"; done
"$PY" "$HERE/plot_bounce.py" "$OUT/log.lammps" "$OUT/bounce.png" "$e"
echo "bouncing_ball: output in $OUT"
