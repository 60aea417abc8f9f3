#!/usr/bin/env bash
# The frictional suite (README.md here): the 10-layer settle at every (tol, h) with its twins,
# the heap over three seeds, the cones on the drum, heap and hopper (cones.sh) and their twins
# at 10 x kn (cones.sh --stiff), the column collapse (collapse.sh), then the tables and the
# plots (report.py, summary.py), into bench/results/friction/<host>/;
# --quick checks the scripts (a small settle, one heap seed, about 5 minutes).
#   bench/run.sh friction [--quick]        (or bench/friction/run.sh [--quick])
# The 8000-sphere settle is separate: python3 front.py --scene settle20 --results DIR (about 4
# minutes). FRONT_JOBS: runs of front.py at a time (default 2).
set -euo pipefail
# shellcheck source=../common.sh
source "$(dirname "${BASH_SOURCE[0]}")/../common.sh" friction_front_ "$@"
HERE="$ROOT/bench/friction"
"$PY" "$HERE/front.py" --jobs "${FRONT_JOBS:-2}" --lmp "$LMP" --soft-lmp "$SOFT_LMP" \
  --results "$RESULTS" "${QUICK[@]}"
bash "$HERE/heap_front.sh" "${QUICK[@]}"
bash "$HERE/cones.sh" "${QUICK[@]}"
bash "$HERE/cones.sh" "${QUICK[@]}" --stiff
bash "$HERE/collapse.sh" "${QUICK[@]}"
"$PY" "$HERE/report.py" "$RESULTS/friction_front${QUICK:+_quick}.csv"
# the performance page's frictional rows: every scene's hard runs and twins, soft / hard as run
# and at largest overlaps of 1e-2 and 1e-3 (friction_summary.md, .png)
if [ "$MODE" = quick ]; then
  "$PY" "$HERE/summary.py" --settle10 "$RESULTS/friction_front_quick.csv" --settle20 none \
    --cones "$RESULTS/friction_cones_quick.csv" --collapse "$RESULTS/friction_collapse_quick.csv"
else
  "$PY" "$HERE/summary.py" --results "$RESULTS"
fi
echo "friction suite ($MODE): $RESULTS"
