#!/usr/bin/env bash
# Kept overlaps (src/core/kept_overlaps.h): frictionless rows that pushed in the last step keep
# a shallow overlap instead of clearing it, within a budget of iterations per solve. The fix has
# no switch for it, so this script runs this build against a reference build from before the
# change (HARDCONTACT_REF_LMP, required: e.g. a build of 9ccc96c), from the same states, one
# process, one run at a time, alternated ROUNDS times (this host's times scatter by up to 40 %
# between identical runs; iterations are deterministic), cg (the default), tol 1e-4:
#   rest<NZ>  bench/compare/in.pile3d at NZ = 5, 10, 20 layers (10 x 10 columns), settled
#             200 + 20 NZ steps and then run on until it is at rest for real (kinetic energy
#             per sphere below 1e-10 m g d, checked every 10 steps, at most CALM steps and
#             CALM_CAP seconds; as the
#             part still of bench/run.sh perf, the perf report (bench/results/perf/amd-epyc+intel-xeon/report.md), section 1.1) by the
#             reference build, then a window of WINDOW steps;
#   tray      the tray of the perf report's section 2 (196 small spheres under one of 1000 x
#             their mass), settled 200 steps by the reference, then TRAY_WINDOW steps;
#   settle    the 20-layer pile (2420 spheres) falling from its lattice, SETTLE steps.
# Each row: mean iterations per step over the window and over its second half, the largest
# iterations of a step, the solves whose kept overlaps were cleared again (f_hc[12], new
# build only), the largest overlap / size over the window (f_hc[7]), the loop time and the
# 1-minute load before the run. Writes bench/studies/kept_overlaps/results/kept_overlaps.csv and
# kept_overlaps_run.txt (bench/studies/kept_overlaps/README.md, section 10.8).
# KEPT_OVERLAPS_NAME (default kept_overlaps) names the two result files, so that a later change
# to the kept overlaps (the budget that follows cleared steps, 10.10) is recorded beside them.
#   HARDCONTACT_REF_LMP=/path/lmp_hardcontact bench/studies/kept_overlaps/run.sh [--quick]
set -euo pipefail
# shellcheck source=../../common.sh
source "$(dirname "${BASH_SOURCE[0]}")/../../common.sh" kept_overlaps_ "$@"
REF="${HARDCONTACT_REF_LMP:?set HARDCONTACT_REF_LMP to a reference build (before the change)}"
ROUNDS=3; SETTLE=300; WINDOW=200; TRAY_WINDOW=500; LAYERS="5 10 20"
[ "$MODE" = quick ] && { ROUNDS=1; SETTLE=60; WINDOW=20; TRAY_WINDOW=40; LAYERS="5"; }
CALM=7000; CALM_CAP=240
[ "$MODE" = quick ] && { CALM=200; CALM_CAP=30; }
NAME="${KEPT_OVERLAPS_NAME:-kept_overlaps}"
CSV="$RESULTS/$NAME.csv"
[ "$MODE" = quick ] && CSV="$WORK/$NAME.csv"
echo "scene,build,round,steps,it_mean,it_second_half,it_max,undone,overlap_rel_max,loop_s,load1" > "$CSV"
# row LOG SCENE BUILD ROUND LOAD UNDONE: thermo columns step ke f_hc[1] f_hc[7] UNDONE of the
# last block of LOG, its first line (the state before the run) skipped
row() {
  bench_thermo "$1" rows mean:f_hc[1] half:f_hc[1] max:f_hc[1] "last:$6" max:f_hc[7] loop \
    | sed "s/^/$2,$3,$4,/; s/\$/,$5/" >> "$CSV"
}
THERMO='s/^thermo_style .*/thermo_style    custom step ke f_hc[1] f_hc[7] ${undone}/'
TRAY_WALLS=$(bench_tray_1000 "$WORK/tray_m1000.data")
bench_pile_deck "$WORK/in.pile" "$THERMO"
bench_tray_settle_deck "$WORK/in.tray_settle" ""
# the reference has 11 values (f_hc[12] is new): the decks ask for column 12 of the new build
# only (the reference's runs repeat f_hc[1] there)
bench_restart_deck "$WORK/in.window" 'thermo_style    custom step ke f_hc[1] f_hc[7] ${undone}
thermo_modify   norm no
thermo          1
run             ${n}'
# at rest for real: m g d of a sphere of the mean diameter 0.9 and density 1 is 0.3435
bench_restart_deck "$WORK/in.calm" 'compute         kin all ke
variable        calm equal c_kin/atoms/0.3435
fix             calm all halt 10 v_calm < 1e-10 error soft message no
variable        elapsed equal cpu
fix             cap all halt 10 v_elapsed > ${cap} error soft message no
thermo_style    custom step ke f_hc[1] v_calm
thermo          100
run             ${n}
write_restart   ${W}'
: > "$WORK/states.txt"
for nz in $LAYERS; do
  echo "kept_overlaps: the $nz-layer pile settled and run on to rest (at most $CALM steps, reference build)"
  (cd "$WORK" && "$REF" -in in.pile -var solver cg -var extra "" -var nz "$nz" -var undone "f_hc[1]" \
     -var n $((200 + 20 * nz)) -var W "settled$nz.restart" -log "log.settle_state$nz" -echo none > /dev/null)
  (cd "$WORK" && "$REF" -in in.calm -var R "settled$nz.restart" -var extra "" -var walls "$PILE_WALLS" \
     -var n "$CALM" -var cap "$CALM_CAP" -var W "rest$nz.restart" -log "log.calm_state$nz" -echo none > /dev/null)
  IFS=, read -r step calm < <(bench_thermo "$WORK/log.calm_state$nz" last:Step last:v_calm)
  echo "state: $nz layers at step $step, kinetic energy per sphere $calm m g d" | tee -a "$WORK/states.txt"
done
(cd "$WORK" && "$REF" -in in.tray_settle -var walls "$TRAY_WALLS" -log log.tray_state \
   -echo none > /dev/null)
run_window() {    # LMP BUILD ROUND SCENE RESTART WALLS STEPS
  local undone="f_hc[1]"; [ "$2" = new ] && undone="f_hc[12]"
  local l; l=$(bench_load1)
  (cd "$WORK" && "$1" -in in.window -var R "$5" -var extra "" -var walls "$6" -var n "$7" -var undone "$undone" \
     -log "log.$4_$2_$3" -echo none > /dev/null)
  row "$WORK/log.$4_$2_$3" "$4" "$2" "$3" "$l" "$undone"
}
for r in $(seq 1 "$ROUNDS"); do
  for build in ref new; do
    lmp="$LMP"; [ "$build" = ref ] && lmp="$REF"
    echo "kept_overlaps: round $r, $build"
    for nz in $LAYERS; do
      run_window "$lmp" "$build" "$r" "rest$nz" "rest$nz.restart" "$PILE_WALLS" "$WINDOW"
    done
    run_window "$lmp" "$build" "$r" tray tray.restart "$TRAY_WALLS" "$TRAY_WINDOW"
    undone="f_hc[1]"; [ "$build" = new ] && undone="f_hc[12]"
    l=$(bench_load1)
    (cd "$WORK" && "$lmp" -in in.pile -var solver cg -var extra "" -var nz 20 -var n "$SETTLE" -var undone "$undone" \
       -var W "settle_${build}_$r.restart" -log "log.settle_${build}_$r" -echo none > /dev/null)
    row "$WORK/log.settle_${build}_$r" settle "$build" "$r" "$l" "$undone"
  done
done
{
  echo "bench/studies/kept_overlaps/run.sh ($MODE), $(date -u '+%Y-%m-%d %H:%M UTC'), $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)"
  echo "hardcontact $(git -C "$ROOT" rev-parse --short HEAD 2>/dev/null || echo '?') against $REF, load after $(cut -d' ' -f1-3 /proc/loadavg)"
  cat "$WORK/states.txt"
  "$PY" - "$CSV" <<'PYEOF'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
scenes = []
for r in rows:
    if r["scene"] not in scenes:
        scenes.append(r["scene"])
med = lambda t: sorted(t)[len(t) // 2]
for scene in scenes:
    by = {}
    for r in rows:
        if r["scene"] == scene:
            by.setdefault(r["build"], []).append(r)
    if len(by) < 2:
        continue
    ref, new = by["ref"][0], by["new"][0]
    t_ref = [float(r["loop_s"]) for r in by["ref"]]
    t_new = [float(r["loop_s"]) for r in by["new"]]
    print("%-7s it/step %s (%s) -> %s (%s), max %s -> %s; undone %s; overlap/size %s -> %s; "
          "loop s median %.3f -> %.3f (%.2f x), all: %s -> %s"
          % (scene, ref["it_mean"], ref["it_second_half"], new["it_mean"], new["it_second_half"],
             ref["it_max"], new["it_max"], new["undone"], ref["overlap_rel_max"],
             new["overlap_rel_max"], med(t_ref), med(t_new), med(t_new) / med(t_ref),
             " ".join("%.3f" % t for t in t_ref), " ".join("%.3f" % t for t in t_new)))
PYEOF
} | tee "$WORK/summary.txt"
[ "$MODE" = quick ] || cp "$WORK/summary.txt" "$RESULTS/${NAME}_run.txt"
