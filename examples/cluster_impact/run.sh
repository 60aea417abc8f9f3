#!/usr/bin/env bash
# Runs the paper's 6.3 cluster impact into OUTDIR (default out/cluster_impact):
#   examples/cluster_impact/run.sh [OUTDIR] [NP]
# writes log.lammps, cluster.dump (atoms), contacts.dump (contact forces), cluster.<step>.png
# (pictures of steps 0, 3, 6, 9, 12) and energy.png (kinetic energy and contacts per step).
set -euo pipefail
# shellcheck source=../common/run_common.sh
source "$(dirname "${BASH_SOURCE[0]}")/../common/run_common.sh"
hc_outdir "${1:-$ROOT/out/cluster_impact}"
HC_NP="${2:-1}"
hc_lmp "$OUT" "cluster.*.png" "cluster_impact: in.cluster_impact" "$LMP" in.cluster_impact
cd "$OUT"
"$PY" "$HERE/plot_energy.py" log.lammps energy.png
echo "cluster_impact: output in $OUT"
ls "$OUT"
