#!/usr/bin/env bash
# Frictional scenes at rest (issue 15, bench/studies/friction_rest/README.md, section 10.6): where apgd's solves
# stalled at maxiter. Each scene is brought to its state once with LMP, then a window of steps
# is run from that state by LMP and, when given, by OLD_LMP and MID_LMP (builds before a
# change, or between two), one after the other (same load), tol 1e-4, one process:
#   drum   examples/drum at the size of its test (120 spheres, R 5, settled 3 time units, then
#          0.11 revolution, 320 steps, at Froude 0.01): the bed turns with the drum and rests
#          in its frame between avalanches (the drum deck settles and turns in one run, so it
#          is run whole by each build);
#   rest   bench/compare/in.pile3d at 8 layers (968 spheres), brought to rest without friction
#          (cg, REST steps: kinetic energy about 1e-8 m g d per sphere), then a window of
#          WINDOW steps with friction 0.5;
#   settle the same pile falling from its lattice with friction 0.5 for SETTLE steps (still
#          settling: kinetic energy 0.08 -> 0.005 in the window), then a window of WINDOW steps;
#   tray   the tray of section 2 (196 small spheres under one of 1000 x their mass, friction
#          0.5), settled for 200 steps, then a window of WINDOW steps.
# Writes bench/studies/friction_rest/results/friction_rest.csv (one row per scene and build: mean and largest
# iterations per step, solves stopped at maxiter, largest overlap / size, loop time, load).
#   [OLD_LMP=<lmp_hardcontact>] [MID_LMP=<lmp_hardcontact>] bench/studies/friction_rest/run.sh [--quick]
# (--quick: shorter settles and windows, to check the script; its pile is not yet at rest)
set -euo pipefail
# shellcheck source=../../common.sh
source "$(dirname "${BASH_SOURCE[0]}")/../../common.sh" friction_rest_ "$@"
REST=2000; SETTLE=600; WINDOW=200
[ "$MODE" = quick ] && { REST=600; SETTLE=200; WINDOW=40; }
OLD_LMP="${OLD_LMP:-}"
MID_LMP="${MID_LMP:-}"
CSV="$RESULTS/friction_rest.csv"
echo "scene,build,steps,it_mean,it_max,maxiter_stops,overlap_max,loop_s,load1" > "$CSV"
# summary LOG SCENE BUILD ITCOL STOPCOL OVCOL: the last thermo block of LOG (its first line is
# the state before the window and is skipped): rows, mean and largest iterations, maxiter stops,
# largest overlap, loop time, load
summary() {
  bench_thermo "$1" rows "mean:$4" "max:$4" "delta:$5" "max:$6" loop load | sed "s/^/$2,$3,/" >> "$CSV"
}
builds=("new:$LMP")
[ -n "$MID_LMP" ] && builds+=("mid:$MID_LMP")
[ -n "$OLD_LMP" ] && builds+=("old:$OLD_LMP")

# drum: the test's shortened run (tests/integration/test_example_drum.py)
NREV=$("$PY" -c "import math; print('%.6f' % (16.0 * math.sqrt(0.01 / 5.0) / (2 * math.pi)))")
for b in "${builds[@]}"; do
  name=${b%%:*}; lmp=${b#*:}
  echo "friction_rest: drum ($name)"
  mkdir -p "$WORK/drum_$name"
  (cd "$WORK/drum_$name" && "$lmp" -in "$ROOT/examples/drum/in.drum" -var R 5.0 -var cells 2 \
     -var zfill 0.8 -var tset 3.0 -var froude 0.01 -var thermo_dt 0.5 -var dump_dt 1.0 \
     -var tol 1e-4 -var nrev "$NREV" -log log.lammps -echo none > /dev/null)
  # the drum's thermo samples every 0.5 time units: iterations per step there, stops exact
  summary "$WORK/drum_$name/log.lammps" drum "$name" f_hc[1] f_hc[6] f_hc[7]
done

# pile and tray: a state from LMP, then the windows
TRAY_WALLS=$(bench_tray_1000 "$WORK/tray_m1000.data")
bench_pile_deck "$WORK/in.pile" 's/^thermo .*/thermo          100/'
bench_tray_settle_deck "$WORK/in.tray_settle" "friction 0.5"
cat > "$WORK/in.window" <<'EOF'
read_restart    ${R}
neighbor        0.3 bin
neigh_modify    delay 0 every 1 check yes
fix             grav all gravity 1.0 vector 0 0 -1
fix             hc all hardcontact solver apgd tol 1e-4 friction 0.5 ${walls}
timestep        0.02
thermo_style    custom step ke f_hc[1] f_hc[3] f_hc[4] f_hc[5] f_hc[6] f_hc[7]
thermo_modify   norm no
thermo          1
run             ${n}
EOF
echo "friction_rest: the pile to rest ($REST steps), settling ($SETTLE), the tray (200 steps)"
(cd "$WORK" && "$LMP" -in in.pile -var solver cg -var extra "" -var nz 8 -var n "$REST" \
   -var W rest.restart -log log.rest_settle -echo none > /dev/null)
(cd "$WORK" && "$LMP" -in in.pile -var solver apgd -var extra "friction 0.5" -var nz 8 \
   -var n "$SETTLE" -var W settle.restart -log log.settle_settle -echo none > /dev/null)
(cd "$WORK" && "$LMP" -in in.tray_settle -var walls "$TRAY_WALLS" -log log.tray_settle \
   -echo none > /dev/null)
for b in "${builds[@]}"; do
  name=${b%%:*}; lmp=${b#*:}
  for scene in rest settle tray; do
    echo "friction_rest: $scene window ($name, $WINDOW steps)"
    if [ $scene != tray ]; then w="$PILE_WALLS"; else w="$TRAY_WALLS"; fi
    (cd "$WORK" && "$lmp" -in in.window -var R "$scene.restart" -var walls "$w" -var n "$WINDOW" \
       -log "log.${scene}_$name" -echo none > /dev/null)
    summary "$WORK/log.${scene}_$name" "$scene" "$name" f_hc[1] f_hc[6] f_hc[7]
  done
done
{
  echo "bench/studies/friction_rest/run.sh ($MODE), $(date -u '+%Y-%m-%d %H:%M UTC'), $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)"
  echo "load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)"
  for b in "${builds[@]}"; do echo "${b%%:*}: ${b#*:}"; done
} > "$RESULTS/friction_rest_run.txt"
column -s, -t "$CSV"
