#!/usr/bin/env bash
# Paper section 6.2, sticky particles: runs in.sticky with h = 0.01, 0.5 and 1.5 over t in [0, 4.5]
# into OUTDIR/h<h>/ (default out/sticky_particles), then plots the pathlines
# (OUTDIR/pathlines.png) and prints the final states against the exact event-driven solution.
#   examples/sticky_particles/run.sh [OUTDIR]
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
OUT="${1:-$ROOT/out/sticky_particles}"
LMP="${HARDCONTACT_LMP:-$ROOT/build/lmp_hardcontact}"
[ -x "$LMP" ] || { echo "no $LMP: build first (bash .ci/build.sh)" >&2; exit 1; }
PY=/usr/bin/python3; [ -x "$PY" ] || PY=python3

mkdir -p "$OUT"
OUT="$(cd "$OUT" && pwd)"
for h in 0.01 0.5 1.5; do
  mkdir -p "$OUT/h$h"
  cd "$OUT/h$h"
  "$LMP" -in "$HERE/in.sticky" -var h "$h" -var data "$HERE/data.sticky" -log log.lammps > screen.txt \
    || { tail -5 screen.txt >&2; echo "sticky_particles: LAMMPS failed for h = $h" >&2; exit 1; }
  awk -v h="$h" '/^Loop time/{printf "h = %-5s %5d steps, loop time %s s\n", h, $9, $4}' log.lammps
done
"$PY" "$HERE/plot_pathlines.py" "$OUT" 0.01 0.5 1.5
echo "sticky_particles: output in $OUT"
