#!/usr/bin/env bash
# Silo discharge (2d) for several outlet widths, and the Beverloo fit:
#   examples/hopper/run.sh [OUTDIR] [WIDTHS_MM] [extra LAMMPS arguments]
# default OUTDIR out/hopper, WIDTHS_MM "6 8 10 12 16". One run per width in OUTDIR/D<w>/
# (log.lammps, silo.dump, contacts.dump, silo.<step>.png during the discharge); then
# beverloo.py prints the rates and the fit and writes OUTDIR/beverloo.png.
set -euo pipefail
# shellcheck source=../common/run_common.sh
source "$(dirname "${BASH_SOURCE[0]}")/../common/run_common.sh"
hc_outdir "${1:-$ROOT/out/hopper}"
WIDTHS="${2:-6 8 10 12 16}"
shift $(( $# >= 2 ? 2 : $# ))
"$PY" "$HERE/make_data.py" "$OUT/data.silo" > /dev/null
for w in $WIDTHS; do
  outlet=$(awk -v w="$w" 'BEGIN{printf "%.6g", w/1000}')
  hc_lmp "$OUT/D$w" "silo.*.png" "hopper: D = $w mm" "$LMP" in.silo \
    -var outlet "$outlet" -var data "$OUT/data.silo" "$@"
  hc_loop_time "$OUT/D$w/log.lammps" "hopper D = %s mm: %d steps, loop time %.2f s\n" "$w"
done
# shellcheck disable=SC2086   # one argument per width
"$PY" "$HERE/beverloo.py" "$OUT" $WIDTHS
echo "hopper: output in $OUT"
