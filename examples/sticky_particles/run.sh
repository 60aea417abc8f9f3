#!/usr/bin/env bash
# Paper section 6.2, sticky particles: runs in.sticky with h = 0.01, 0.5 and 1.5 over t in [0, 4.5]
# into OUTDIR/h<h>/ (default out/sticky_particles), then plots the pathlines
# (OUTDIR/pathlines.png) and prints the final states against the exact event-driven solution.
#   examples/sticky_particles/run.sh [OUTDIR]
set -euo pipefail
# shellcheck source=../common/run_common.sh
source "$(dirname "${BASH_SOURCE[0]}")/../common/run_common.sh"
hc_outdir "${1:-$ROOT/out/sticky_particles}"
for h in 0.01 0.5 1.5; do
  hc_lmp "$OUT/h$h" "" "sticky_particles: LAMMPS for h = $h" "$LMP" in.sticky -var h "$h" -var data "$HERE/data.sticky"
  hc_loop_time "$OUT/h$h/log.lammps" "h = %-5s %5d steps, loop time %s s\n" "$h"
done
"$PY" "$HERE/plot_pathlines.py" "$OUT" 0.01 0.5 1.5
echo "sticky_particles: output in $OUT"
