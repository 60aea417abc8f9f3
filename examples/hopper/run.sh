#!/usr/bin/env bash
# Silo discharge (2d) for several outlet widths, and the Beverloo fit:
#   examples/hopper/run.sh [OUTDIR] [WIDTHS_MM] [extra LAMMPS arguments]
# default OUTDIR out/hopper, WIDTHS_MM "6 8 10 12 16". One run per width in OUTDIR/D<w>/
# (log.lammps, silo.dump, contacts.dump, silo.<step>.png during the discharge); then
# beverloo.py prints the rates and the fit and writes OUTDIR/beverloo.png.
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
OUT="${1:-$ROOT/out/hopper}"
WIDTHS="${2:-6 8 10 12 16}"
shift $(( $# >= 2 ? 2 : $# ))
LMP="${HARDCONTACT_LMP:-$ROOT/build/lmp_hardcontact}"
[ -x "$LMP" ] || { echo "no $LMP: build first (bash .ci/build.sh)" >&2; exit 1; }
PY=/usr/bin/python3; [ -x "$PY" ] || PY=python3
mkdir -p "$OUT"
OUT="$(cd "$OUT" && pwd)"
"$PY" "$HERE/make_data.py" "$OUT/data.silo" > /dev/null
for w in $WIDTHS; do
  mkdir -p "$OUT/D$w"
  rm -f "$OUT/D$w"/silo.*.png
  outlet=$(awk -v w="$w" 'BEGIN{printf "%.6g", w/1000}')
  (cd "$OUT/D$w" && "$LMP" -in "$HERE/in.silo" -var outlet "$outlet" -var data "$OUT/data.silo" \
      -log log.lammps "$@" > screen.txt) \
    || { tail -5 "$OUT/D$w/screen.txt" >&2; echo "hopper: D = $w mm failed (see $OUT/D$w)" >&2; exit 1; }
  awk -v w="$w" '/^Loop time/{t+=$4; n+=$9} END{printf "hopper D = %s mm: %d steps, loop time %.2f s\n", w, n, t}' \
      "$OUT/D$w/log.lammps"
done
"$PY" "$HERE/beverloo.py" "$OUT" $WIDTHS
echo "hopper: output in $OUT"
