#!/usr/bin/env bash
# Disc packing: 1000 bidisperse discs compressed by gravity, with fix hardcontact (OUTDIR/hard)
# and with the soft-sphere twin (OUTDIR/soft; pair_style gran/hertz/history), then compares them.
#   examples/disc_packing/run.sh [OUTDIR] [hard|soft|both] [extra LAMMPS arguments, e.g. -var tend 0.2]
# default OUTDIR out/disc_packing, both. Each run dir: log.lammps, packing.dump (atoms), contacts.dump
# (contact forces), packing.<step>.png; OUTDIR: compare.png (kinetic energy), chains.png,
# profile.png (area fraction against height) and the table of packing.py.
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
OUT="${1:-$ROOT/out/disc_packing}"
WHICH="${2:-both}"
shift $(( $# >= 2 ? 2 : $# ))
LMP="${HARDCONTACT_LMP:-$ROOT/build/lmp_hardcontact}"
LMP_SOFT="${LMP_SOFT:-$LMP}"
[ -x "$LMP" ] || { echo "no $LMP: build first (bash .ci/build.sh)" >&2; exit 1; }
PY=/usr/bin/python3; [ -x "$PY" ] || PY=python3
mkdir -p "$OUT"
OUT="$(cd "$OUT" && pwd)"
"$PY" "$HERE/make_data.py" "$OUT/data.packing" > /dev/null

run() {    # run <dir> <launcher> <deck>
  mkdir -p "$OUT/$1"
  rm -f "$OUT/$1"/packing.*.png
  (cd "$OUT/$1" && "$2" -in "$HERE/$3" -var data "$OUT/data.packing" -var potentials "$ROOT/potentials" \
      -log log.lammps "${@:4}" > screen.txt) \
    || { tail -5 "$OUT/$1/screen.txt" >&2; echo "disc_packing: $3 failed (see $OUT/$1)" >&2; exit 1; }
  awk -v d="$1" '/^Loop time/{printf "disc_packing %-4s: %d steps, loop time %.2f s\n", d, $9, $4}' "$OUT/$1/log.lammps"
}
case "$WHICH" in
  hard) run hard "$LMP" in.packing "$@"; "$PY" "$HERE/packing.py" "$OUT/hard:hardcontact" ;;
  soft) run soft "$LMP_SOFT" in.packing.soft "$@" ;;
  both) run hard "$LMP" in.packing "$@"; run soft "$LMP_SOFT" in.packing.soft "$@"
        "$PY" "$ROOT/examples/compare.py" disc_packing "$OUT/hard" "$OUT/soft" "$OUT/compare.png"
        "$PY" "$ROOT/examples/common/plot_bed.py" "$OUT/chains.png" \
          "$OUT/hard:packing.dump:contacts.dump:hard:fix hardcontact" \
          "$OUT/soft:packing.dump:contacts.dump:soft:soft spheres (gran/hertz/history)"
        "$PY" "$HERE/packing.py" --png "$OUT/profile.png" "$OUT/hard:hardcontact" "$OUT/soft:soft spheres" ;;
  *) echo "disc_packing: second argument is hard, soft or both" >&2; exit 1 ;;
esac
echo "disc_packing: output in $OUT"
