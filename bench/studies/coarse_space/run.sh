#!/usr/bin/env bash
# Is there a small coarse space for cg on a frictionless pile at rest? (issue 15, target 1;
# bench/studies/coarse_space/README.md, section 10.13): settles the piles of 10 and 20 layers of section 1 with
# the default solver, dumps a window at rest (bench/studies/spectrum/scenes_run.py, as bench/studies/spectrum/run.sh
# does), and asks of two steps of each (bench/studies/coarse_space/coarse_space.py): how many iterations
# Jacobi-PCG needs with coarse spaces of uniform stresses or constants on aggregates of growing
# size (additive, balancing, A-DEF2), and what the slowest modes look like. Writes
# bench/studies/coarse_space/results/coarse_space.csv and coarse_space.md. About 4 minutes (scipy, one core).
#   bench/studies/coarse_space/run.sh [--quick]      (--quick: the 10-layer pile only)
set -euo pipefail
# shellcheck source=../../common.sh
source "$(dirname "${BASH_SOURCE[0]}")/../../common.sh" coarse_space_ "$@"
NAMES=(pile10:400 pile20:600)    # scene:settle steps (bench/studies/spectrum/scenes_run.py)
[ "$MODE" = quick ] && NAMES=(pile10:400)
T0=$SECONDS
GIT="$(cd "$ROOT" && git rev-parse --short HEAD 2>/dev/null || echo unknown)"
LOAD_BEFORE="$(cut -d' ' -f1-3 /proc/loadavg)"
bench_rest_problems "${NAMES[@]}"
BODY="$("$PY" "$ROOT/bench/studies/coarse_space/coarse_space.py" --csv "$RESULTS/coarse_space.csv" "${PROBLEMS[@]}")"
{
  echo "coarse space study ($MODE), $(date -u '+%Y-%m-%d %H:%M UTC'), launcher $LMP,"
  echo "hardcontact $GIT, load before $LOAD_BEFORE, after $(cut -d' ' -f1-3 /proc/loadavg)," \
       "$(( SECONDS - T0 )) s; tol 1e-4, iterations from the fix's warm start on the exact pushing rows"
  echo
  echo "$BODY"
} > "$RESULTS/coarse_space.md"
cat "$RESULTS/coarse_space.md"
