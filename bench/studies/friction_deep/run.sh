#!/usr/bin/env bash
# A deep frictional pile (issue 15, bench/studies/friction_deep/README.md, section 10.4): the pile of
# bench/compare/in.pile3d with NZ layers (11 x 11 columns: 2420 spheres at 20 layers) and
# `friction 0.5`, apgd (the default with friction) at tol 1e-4, settled from its lattice for
# SETTLE steps (iterations per step every 10 steps, written as a restart), then a window of
# WINDOW steps from that restart at tol 1e-4 and 1e-3, and the same settle without friction
# (cg, the default) for comparison. Writes bench/studies/friction_deep/results/friction_deep.csv (one row per sampled
# step of the settles, one per window) and prints a summary.
#   bench/studies/friction_deep/run.sh [--quick]
set -euo pipefail
# shellcheck source=../../common.sh
source "$(dirname "${BASH_SOURCE[0]}")/../../common.sh" friction_deep_ "$@"
NZ=20; SETTLE=190; WINDOW=20
[ "$MODE" = quick ] && { NZ=8; SETTLE=120; WINDOW=10; }
SETTLE_DECK="$WORK/in.settle"
sed -e 's/hardcontact solver ${solver} wall/hardcontact solver ${solver} ${extra} wall/' \
    -e 's/^thermo .*/thermo          10\nthermo_modify   flush yes/' \
    -e 's/^run .*/run             ${n}\nwrite_restart   ${W}/' \
    "$ROOT/bench/compare/in.pile3d" > "$SETTLE_DECK"
WINDOW_DECK="$WORK/in.window"
cat > "$WINDOW_DECK" <<'EOF'
units           lj
dimension       3
atom_style      sphere
boundary        f f f
atom_modify     map array
comm_modify     vel yes
read_restart    ${R}
pair_style      none
neighbor        0.3 bin
fix             hc all hardcontact tol ${tol} friction 0.5 wall xplane 0 11 wall yplane 0 11 wall zplane 0 NULL
fix             g all gravity 1.0 vector 0 0 -1
timestep        0.02
thermo_style    custom step ke f_hc[1] f_hc[4] f_hc[6] f_hc[7]
thermo          1
run             ${n}
EOF
CSV="$RESULTS/friction_deep.csv"
echo "case,step,iterations,active,loop_s,load1" > "$CSV"
settle() {    # settle CASE SOLVER EXTRA
  local log="$WORK/log.$1"
  (cd "$WORK" && "$LMP" -in "$SETTLE_DECK" -var solver "$2" -var extra "$3" -var nz "$NZ" \
     -var n "$SETTLE" -var W "$1.restart" -log "$log" -echo none > /dev/null)
  bench_thermo --each "$log" Step f_hc[1] f_hc[4] loop load | sed "s/^/$1,/" >> "$CSV"
}
window() {    # window CASE TOL
  local log="$WORK/log.$1"
  (cd "$WORK" && "$LMP" -in "$WINDOW_DECK" -var R settle_friction.restart -var tol "$2" \
     -var n "$WINDOW" -log "$log" -echo none > /dev/null)
  bench_thermo "$log" last:Step mean:f_hc[1] last:f_hc[4] loop load | sed "s/^/$1,/" >> "$CSV"
}
echo "friction_deep: settle, friction 0.5 ($NZ layers, $SETTLE steps)"
settle settle_friction apgd "friction 0.5"
echo "friction_deep: settle, frictionless"
settle settle_frictionless cg ""
for tol in 1e-4 1e-3; do
  echo "friction_deep: window at tol $tol"
  window "window_tol$tol" "$tol"
done
"$PY" - "$CSV" <<'PYEOF'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
for case in ("settle_friction", "settle_frictionless"):
    r = [x for x in rows if x["case"] == case]
    print("%s: loop %s s (load %s); iterations per step every 10 steps:" % (case, r[-1]["loop_s"], r[-1]["load1"]))
    print("  " + " ".join("%s:%s" % (x["step"], x["iterations"]) for x in r))
for x in rows:
    if x["case"].startswith("window"):
        print("%s: %s it/step over the window, loop %s s, %s active contacts (load %s)" % (
            x["case"], x["iterations"], x["loop_s"], x["active"], x["load1"]))
PYEOF
