#!/bin/bash
# Frictional scenes at rest with apgd (the default with friction), issue 15 / doc/performance.md
# section 10.4: what a stalled solve's Gauss-Seidel polish changes.
# - the 20-layer pile of bench/perf (2000 spheres) brought to rest without friction (part
#   `still` of bench/run_perf.sh: its calm.restart), then `friction 0.5` for SETTLE steps
#   (written as a restart), then a window of WINDOW steps from that restart;
# - the heavy sphere (mass ratio 1000) on the tray of part `tray` (its settled.restart) with
#   `friction 0.5`, a window of WINDOW steps;
# - the settling 10-layer pile of bench/compare/in.pile3d with friction and with friction and
#   rolling, 150 steps (as bench/run_friction.sh).
# Each case with this build (LMP) and, if OLD_LMP is set, with an older build from the same
# start (the window's restart is always made by LMP). Writes bench/results/friction_rest.csv and
# prints a markdown table.
#   bench/run_friction_rest.sh [--quick]      OLD_LMP=<lmp_hardcontact before the polish>
# Needs the parts still and tray of the full benchmark (PERF_ONLY=heights,still,tray
# bench/run_perf.sh), or PILE_REST=<restart> TRAY_REST=<restart>.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh" friction_rest_ "$@"
SETTLE=1000; WINDOW=300
[ "$MODE" = quick ] && { SETTLE=200; WINDOW=100; }
PERF="${BENCH_WORKDIR:-$ROOT/bench/work}/perf-full"
PILE_REST="${PILE_REST:-$PERF/still_pile10x10x20_cg/calm.restart}"
TRAY_REST="${TRAY_REST:-$PERF/tray_tray_m1000_cg/settled.restart}"
for f in "$PILE_REST" "$TRAY_REST"; do
  [ -f "$f" ] || { echo "no $f: run PERF_ONLY=heights,still,tray bench/run_perf.sh first" >&2; exit 1; }
done

# one deck for every case at rest: walls at 0 and L in x and y, a floor; ${X}: more keywords
cat > "$WORK/in.rest" <<'EOF'
units           lj
dimension       3
atom_style      sphere
boundary        f f f
atom_modify     map array
read_restart    ${R}
pair_style      none
neighbor        0.3 bin
neigh_modify    delay 0 every 1 check yes
fix             grav all gravity 1.0 vector 0 0 -1
fix             hc all hardcontact tol 0.0001 friction 0.5 ${X} wall xplane 0.0 ${L} wall yplane 0.0 ${L} wall zplane 0.0 NULL
timestep        0.02
thermo_style    custom step ke f_hc[1] f_hc[4] f_hc[6] f_hc[7]
thermo_modify   norm no
thermo          1
run             ${N}
write_restart   ${W}
EOF
DECK3D="$WORK/in.pile3d"
sed 's/hardcontact solver ${solver} wall/hardcontact solver ${solver} ${extra} wall/' \
  "$ROOT/bench/compare/in.pile3d" > "$DECK3D"

CSV="$RESULTS/friction_rest.csv"
echo "case,build,steps,loop_s,iterations_per_step,max_iterations,maxiter_solves,active_start,active_end,max_ke,max_overlap,load1" > "$CSV"
summarise() {    # summarise CASE BUILD LOG: the thermo of a run with step ke it act maxiter overlap
  awk -v c="$1" -v b="$2" -v load="$(cut -d' ' -f1 /proc/loadavg)" '
    /^ *Step/{f=1; first=1; next} /^Loop/{f=0; t=$4; n=$9}
    f && NF >= 6 && $1 ~ /^[0-9]+$/ {
      if (first) {a0 = $4; m0 = $5; first = 0; next}
      it += $3; k++; if ($3 > mx) mx = $3; a1 = $4; m1 = $5; if ($2 > ke) ke = $2; if ($6 > ov) ov = $6}
    END{printf "%s,%s,%d,%.3f,%.1f,%d,%d,%d,%d,%.3g,%.3g,%s\n", c, b, n, t, it / k, mx, m1 - m0, a0, a1, ke, ov, load}' \
    "$3" >> "$CSV"
}
rest() {    # rest CASE BUILD LMP RESTART L STEPS OUT
  local log="$WORK/log.$1.$2"
  "$3" -in "$WORK/in.rest" -var R "$4" -var L "$5" -var N "$6" -var X "" -var W "$7" \
    -log "$log" -echo none > /dev/null
  summarise "$1" "$2" "$log"
}
settle() {    # settle CASE BUILD LMP EXTRA: the 10-layer pile from its lattice, 150 steps
  local log="$WORK/log.$1.$2"
  "$3" -in "$DECK3D" -var solver apgd -var nz 10 -var n 150 -var extra "$4" -log "$log" \
    -echo none > /dev/null
  awk -v c="$1" -v b="$2" -v load="$(cut -d' ' -f1 /proc/loadavg)" '
    /^ *Step/{f=1; next} /^Loop/{f=0; t=$4; n=$9}
    f && NF >= 9 {it += $4; k++; if ($4 > mx) mx = $4; act = $6; if ($8 > ov) ov = $8}
    END{printf "%s,%s,%d,%.3f,%.1f,%d,-,-,%d,-,%.3g,%s\n", c, b, n, t, it / k, mx, act, ov, load}' \
    "$log" >> "$CSV"
}

# the frictional pile at rest: this build makes the start of both windows
rest pile20_friction_to_rest now "$LMP" "$PILE_REST" 11.0 "$SETTLE" "$WORK/pile20_friction.restart"
builds=(now)
[ -n "${OLD_LMP:-}" ] && builds+=(before)
for b in "${builds[@]}"; do
  lmp="$LMP"; [ "$b" = before ] && lmp="$OLD_LMP"
  rest pile20_friction_window "$b" "$lmp" "$WORK/pile20_friction.restart" 11.0 "$WINDOW" "$WORK/x.$b.restart"
  rest tray_m1000_friction_window "$b" "$lmp" "$TRAY_REST" 14.0 "$WINDOW" "$WORK/y.$b.restart"
  settle pile10_settle_friction "$b" "$lmp" "friction 0.5"
  settle pile10_settle_friction_rolling "$b" "$lmp" "friction 0.5 rolling 0.1"
done
"$PY" - "$CSV" <<'PYEOF'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
print("| case | build | steps | loop (s) | iterations/step (max) | solves at maxiter | active contacts (start -> end) | largest KE | largest overlap / size | load |")
print("|---|---|---|---|---|---|---|---|---|---|")
for r in rows:
    print("| %s | %s | %s | %s | %s (%s) | %s | %s -> %s | %s | %s | %s |" % (
        r["case"], r["build"], r["steps"], r["loop_s"], r["iterations_per_step"],
        r["max_iterations"], r["maxiter_solves"], r["active_start"], r["active_end"], r["max_ke"],
        r["max_overlap"], r["load1"]))
PYEOF
