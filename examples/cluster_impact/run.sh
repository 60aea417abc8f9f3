#!/usr/bin/env bash
# Runs the paper's 6.3 cluster impact into OUTDIR (default out/cluster_impact):
#   examples/cluster_impact/run.sh [OUTDIR] [NP]
# writes log.lammps, cluster.dump (atoms), contacts.dump (contact forces), cluster.<step>.png
# (pictures of steps 0, 3, 6, 9, 12) and energy.png (kinetic energy and contacts per step).
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
OUT="${1:-$ROOT/out/cluster_impact}"
NP="${2:-1}"
LMP="${HARDCONTACT_LMP:-$ROOT/build/lmp_hardcontact}"
[ -x "$LMP" ] || { echo "no $LMP: build first (bash .ci/build.sh)" >&2; exit 1; }

mkdir -p "$OUT"
OUT="$(cd "$OUT" && pwd)"
cd "$OUT"
rm -f cluster.*.png
if [ "$NP" -gt 1 ]; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
  mpirun --oversubscribe -np "$NP" "$LMP" -in "$HERE/in.cluster_impact" -log log.lammps > screen.txt
else
  "$LMP" -in "$HERE/in.cluster_impact" -log log.lammps > screen.txt
fi
/usr/bin/python3 "$HERE/plot_energy.py" log.lammps energy.png
echo "cluster_impact: output in $OUT"
ls "$OUT"
