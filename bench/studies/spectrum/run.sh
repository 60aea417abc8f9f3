#!/usr/bin/env bash
# What limits the iterations of a frictionless solve (issue 15; bench/studies/spectrum/README.md, section
# 10): settles piles of 5, 10 and 20 layers and the tray at mass ratio 1000 (bench/perf's
# scenes) with the default solver, dumps every step of a window at rest
# (HARDCONTACT_DUMP_PROBLEMS, src/core/problem_dump.h), and studies two steps of each offline
# (bench/studies/spectrum/analyze.py: the exact solution, the spectrum on the pushing rows, linear PCG
# with five preconditioners). Writes bench/studies/spectrum/results/spectrum.csv, bench/studies/spectrum/results/spectrum.md and
# bench/studies/spectrum/results/spectrum.png. About 5 minutes (scipy, one core).
#   bench/studies/spectrum/run.sh [--quick]      (--quick: the 5-layer pile and the tray only)
set -euo pipefail
# shellcheck source=../../common.sh
source "$(dirname "${BASH_SOURCE[0]}")/../../common.sh" spectrum_ "$@"
NAMES=(pile5:300 pile10:400 pile20:600 tray1000:200)    # scene:settle steps (scenes_run.py)
[ "$MODE" = quick ] && NAMES=(pile5:300 tray1000:200)
T0=$SECONDS
GIT="$(cd "$ROOT" && git rev-parse --short HEAD 2>/dev/null || echo unknown)"
if [ -n "$(cd "$ROOT" && git status --porcelain --untracked-files=no -- src 2>/dev/null)" ]; then
  GIT="$GIT + uncommitted changes in src/"
fi
LOAD_BEFORE="$(cut -d' ' -f1-3 /proc/loadavg)"
"$PY" "$ROOT/bench/studies/spectrum/scenes_run.py" --lmp "$LMP" --work "$WORK" "${NAMES[@]%%:*}"
CSV="$RESULTS/spectrum.csv"
rm -f "$CSV"
for entry in "${NAMES[@]}"; do
  name=${entry%%:*}
  settle=${entry##*:}
  # base: the second step at rest (its factor is reused); studied: the next one and 10 later
  "$PY" "$ROOT/bench/studies/spectrum/analyze.py" --out "$CSV" --log "$WORK/$name/log.rest" \
    --label "$name" --base "$WORK/$name/problem.$((settle + 2))" \
    "$WORK/$name/problem.$((settle + 3))" "$WORK/$name/problem.$((settle + 12))"
done
{
  echo "spectrum study ($MODE), $(date -u '+%Y-%m-%d %H:%M UTC'), launcher $LMP"
  echo "hardcontact $GIT (the tree when the run started)," \
       "load before $LOAD_BEFORE, after $(cut -d' ' -f1-3 /proc/loadavg), $(( SECONDS - T0 )) s"
  echo
  "$PY" "$ROOT/bench/studies/spectrum/report.py" --csv "$CSV" --figure "$RESULTS/spectrum.png"
} > "$RESULTS/spectrum.md"
cat "$RESULTS/spectrum.md"
