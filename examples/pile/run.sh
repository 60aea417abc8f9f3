#!/usr/bin/env bash
# Pile: 750 glass discs settle in a box, with fix hardcontact (OUTDIR/hard) and with the
# soft-sphere twin (OUTDIR/soft; pair_style gran/hertz/history), then compares them.
#   examples/pile/run.sh [OUTDIR] [hard|soft|both] [extra LAMMPS arguments, e.g. -var tend 0.2]
# default OUTDIR out/pile, both. Each run dir: log.lammps, pile.dump (atoms), contacts.dump
# (contact forces), pile.<step>.png; OUTDIR: compare.png (kinetic energy), chains.png.
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
OUT="${1:-$ROOT/out/pile}"
WHICH="${2:-both}"
shift $(( $# >= 2 ? 2 : $# ))
LMP="${HARDCONTACT_LMP:-$ROOT/build/lmp_hardcontact}"
LMP_SOFT="${LMP_SOFT:-$LMP}"
[ -x "$LMP" ] || { echo "no $LMP: build first (bash .ci/build.sh)" >&2; exit 1; }
PY=/usr/bin/python3; [ -x "$PY" ] || PY=python3
mkdir -p "$OUT"
OUT="$(cd "$OUT" && pwd)"
"$PY" "$HERE/make_data.py" "$OUT/data.pile" > /dev/null

run() {    # run <dir> <launcher> <deck>
  mkdir -p "$OUT/$1"
  rm -f "$OUT/$1"/pile.*.png
  (cd "$OUT/$1" && "$2" -in "$HERE/$3" -var data "$OUT/data.pile" -var potentials "$ROOT/potentials" \
      -log log.lammps "${@:4}" > screen.txt) \
    || { tail -5 "$OUT/$1/screen.txt" >&2; echo "pile: $3 failed (see $OUT/$1)" >&2; exit 1; }
  awk -v d="$1" '/^Loop time/{printf "pile %-4s: %d steps, loop time %.2f s\n", d, $9, $4}' "$OUT/$1/log.lammps"
}
case "$WHICH" in
  hard) run hard "$LMP" in.pile "$@" ;;
  soft) run soft "$LMP_SOFT" in.pile.soft "$@" ;;
  both) run hard "$LMP" in.pile "$@"; run soft "$LMP_SOFT" in.pile.soft "$@"
        "$PY" "$ROOT/examples/compare.py" pile "$OUT/hard" "$OUT/soft" "$OUT/compare.png"
        "$PY" "$ROOT/examples/common/plot_bed.py" "$OUT/chains.png" \
          "$OUT/hard:pile.dump:contacts.dump:hard:fix hardcontact" \
          "$OUT/soft:pile.dump:contacts.dump:soft:soft spheres (gran/hertz/history)" ;;
  *) echo "pile: second argument is hard, soft or both" >&2; exit 1 ;;
esac
echo "pile: output in $OUT"
