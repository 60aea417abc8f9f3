#!/usr/bin/env bash
# cg's default start without friction, `subspace 10` against `subspace 0` (the default before
# 2026-12-01), timed: bench/studies/subspace_default/README.md. The same build runs both, one process,
# one run at a time, alternated ROUNDS times (this host's times scatter by up to 40 % between
# identical runs; iterations are deterministic), tol 1e-4:
#   settle  bench/compare/in.pile3d at 20 layers (2420 spheres) falling from its lattice,
#           SETTLE steps;
#   rest    the same pile after REST steps (a state written once by the default), then a
#           window of WINDOW steps;
#   tray    the tray of the perf report's section 2 (196 small spheres under one of 1000 x
#           their mass), settled 200 steps by the default, then a window of TRAY_WINDOW steps.
# Writes bench/studies/subspace_default/results/subspace_default.csv (one row per scene, start and round: mean
# iterations per step, loop time, 1-minute load before the run).
#   bench/studies/subspace_default/run.sh [--quick]
set -euo pipefail
# shellcheck source=../../common.sh
source "$(dirname "${BASH_SOURCE[0]}")/../../common.sh" subspace_default_ "$@"
ROUNDS=5; SETTLE=300; REST=2000; WINDOW=200; TRAY_WINDOW=500; NZ=20
[ "$MODE" = quick ] && { ROUNDS=1; SETTLE=60; REST=200; WINDOW=20; TRAY_WINDOW=40; NZ=5; }
CSV="$RESULTS/subspace_default.csv"
[ "$MODE" = quick ] && CSV="$WORK/subspace_default.csv"
echo "scene,start,round,steps,it_mean,loop_s,load1" > "$CSV"
# row LOG SCENE START ROUND LOAD: the mean iterations of the last thermo block of LOG, its first
# line (the state before the run) skipped, and its loop time
row() {
  bench_thermo "$1" rows mean:f_hc[1] loop | sed "s/^/$2,$3,$4,/; s/\$/,$5/" >> "$CSV"
}
TRAY_WALLS=$(bench_tray_1000 "$WORK/tray_m1000.data")
bench_pile_deck "$WORK/in.pile" 's/^thermo_style .*/thermo_style    custom step ke f_hc[1] f_hc[3] f_hc[4]/'
bench_tray_settle_deck "$WORK/in.tray_settle" ""
bench_restart_deck "$WORK/in.window" 'thermo_style    custom step ke f_hc[1] f_hc[3] f_hc[4]
thermo_modify   norm no
thermo          1
run             ${n}'
echo "subspace_default: the pile to rest ($REST steps) and the tray (200 steps), default start"
(cd "$WORK" && "$LMP" -in in.pile -var solver cg -var extra "" -var nz "$NZ" -var n "$REST" \
   -var W rest.restart -log log.rest_state -echo none > /dev/null)
(cd "$WORK" && "$LMP" -in in.tray_settle -var walls "$TRAY_WALLS" -log log.tray_state \
   -echo none > /dev/null)
for r in $(seq 1 "$ROUNDS"); do
  for start in "subspace 0" "default"; do
    extra=""; [ "$start" = default ] || extra="$start"
    tag=${start// /}_$r
    echo "subspace_default: round $r, $start"
    l=$(bench_load1)
    (cd "$WORK" && "$LMP" -in in.pile -var solver cg -var extra "$extra" -var nz "$NZ" \
       -var n "$SETTLE" -var W settle_$tag.restart -log "log.settle_$tag" -echo none > /dev/null)
    row "$WORK/log.settle_$tag" settle "$start" "$r" "$l"
    l=$(bench_load1)
    (cd "$WORK" && "$LMP" -in in.window -var R rest.restart -var extra "$extra" \
       -var walls "$PILE_WALLS" -var n "$WINDOW" -log "log.rest_$tag" -echo none > /dev/null)
    row "$WORK/log.rest_$tag" rest "$start" "$r" "$l"
    l=$(bench_load1)
    (cd "$WORK" && "$LMP" -in in.window -var R tray.restart -var extra "$extra" \
       -var walls "$TRAY_WALLS" -var n "$TRAY_WINDOW" -log "log.tray_$tag" -echo none > /dev/null)
    row "$WORK/log.tray_$tag" tray "$start" "$r" "$l"
  done
done
{
  echo "bench/studies/subspace_default/run.sh ($MODE), $(date -u '+%Y-%m-%d %H:%M UTC'), $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)"
  echo "hardcontact $(git -C "$ROOT" rev-parse --short HEAD 2>/dev/null || echo '?'), load after $(cut -d' ' -f1-3 /proc/loadavg)"
  "$PY" - "$CSV" <<'PYEOF'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
for scene in ("settle", "rest", "tray"):
    by = {}
    for r in rows:
        if r["scene"] == scene:
            by.setdefault(r["start"], []).append(r)
    if len(by) < 2:
        continue
    off, on = by["subspace 0"], by["default"]
    it_off, it_on = float(off[0]["it_mean"]), float(on[0]["it_mean"])
    t_off = sorted(float(r["loop_s"]) for r in off)
    t_on = sorted(float(r["loop_s"]) for r in on)
    med = lambda t: t[len(t) // 2]
    print("%-6s it/step %.1f -> %.1f; loop s best of %d %.3f -> %.3f (%.2f x), median %.3f -> "
          "%.3f (%.2f x); all: %s -> %s"
          % (scene, it_off, it_on, len(t_off), t_off[0], t_on[0], t_on[0] / t_off[0],
             med(t_off), med(t_on), med(t_on) / med(t_off),
             " ".join("%.3f" % t for t in t_off), " ".join("%.3f" % t for t in t_on)))
PYEOF
} | tee "$WORK/summary.txt"
[ "$MODE" = quick ] || cp "$WORK/summary.txt" "$RESULTS/subspace_default_run.txt"
