#!/usr/bin/env bash
# Pour: 600 glass discs poured into a box, with fix hardcontact (OUTDIR/hard) and with the
# soft-sphere twin (OUTDIR/soft; pair_style gran/hertz/history), then compares them.
#   examples/pour/run.sh [OUTDIR] [hard|soft|both] [extra LAMMPS arguments, e.g. -var tend 0.3]
# default OUTDIR out/pour, both. Each run dir: log.lammps, pour.dump (atoms), contacts.dump
# (contact forces), pour.<step>.png; OUTDIR: compare.png (kinetic energy), chains.png.
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
OUT="${1:-$ROOT/out/pour}"
WHICH="${2:-both}"
shift $(( $# >= 2 ? 2 : $# ))
LMP="${HARDCONTACT_LMP:-$ROOT/build/lmp_hardcontact}"
LMP_SOFT="${LMP_SOFT:-$LMP}"
[ -x "$LMP" ] || { echo "no $LMP: build first (bash .ci/build.sh)" >&2; exit 1; }
PY=/usr/bin/python3; [ -x "$PY" ] || PY=python3
mkdir -p "$OUT"
OUT="$(cd "$OUT" && pwd)"

run() {    # run <dir> <launcher> <deck>
  mkdir -p "$OUT/$1"
  rm -f "$OUT/$1"/pour.*.png
  (cd "$OUT/$1" && "$2" -in "$HERE/$3" -var potentials "$ROOT/potentials" \
      -log log.lammps "${@:4}" > screen.txt) \
    || { tail -5 "$OUT/$1/screen.txt" >&2; echo "pour: $3 failed (see $OUT/$1)" >&2; exit 1; }
  awk -v d="$1" '/^Loop time/{printf "pour %-4s: %d steps, loop time %.2f s\n", d, $9, $4}' "$OUT/$1/log.lammps"
}
case "$WHICH" in
  hard) run hard "$LMP" in.pour "$@" ;;
  soft) run soft "$LMP_SOFT" in.pour.soft "$@" ;;
  both) run hard "$LMP" in.pour "$@"; run soft "$LMP_SOFT" in.pour.soft "$@"
        "$PY" "$ROOT/examples/compare.py" pour "$OUT/hard" "$OUT/soft" "$OUT/compare.png"
        "$PY" "$ROOT/examples/common/plot_bed.py" "$OUT/chains.png" \
          "$OUT/hard:pour.dump:contacts.dump:hard:fix hardcontact" \
          "$OUT/soft:pour.dump:contacts.dump:soft:soft spheres (gran/hertz/history)" ;;
  *) echo "pour: second argument is hard, soft or both" >&2; exit 1 ;;
esac
echo "pour: output in $OUT"
