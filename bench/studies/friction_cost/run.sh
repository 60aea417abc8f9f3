#!/usr/bin/env bash
# What friction and rolling resistance cost (issue 12): the settling 3D pile of
# bench/compare/in.pile3d (nz layers of polydisperse spheres, h = 0.02, walled box) with
# apgd at the default tol, frictionless / friction 0.5 / friction 0.5 + rolling 0.1, and the
# frictionless run of the build before friction landed (OLD_LMP, optional) for "costs nothing
# when absent". Writes bench/studies/friction_cost/results/friction_cost.csv and prints a markdown table (pasted
# into doc/performance.md).
#   bench/studies/friction_cost/run.sh [--quick]        OLD_LMP=<lmp_hardcontact before friction> to compare
set -euo pipefail
# shellcheck source=../../common.sh
source "$(dirname "${BASH_SOURCE[0]}")/../../common.sh" friction_ "$@"
NZ=10; STEPS=150
[ "$MODE" = quick ] && { NZ=4; STEPS=60; }
DECK="$WORK/in.pile3d"
sed 's/hardcontact solver ${solver} wall/hardcontact solver ${solver} ${extra} wall/' "$ROOT/bench/compare/in.pile3d" > "$DECK"
CSV="$RESULTS/friction_cost.csv"
echo "case,build,spheres,steps,loop_s,iterations_per_step,max_iterations,active_end,max_overlap,load1" > "$CSV"
run() {    # run NAME BUILD LMP EXTRA
  local name="$1" build="$2" lmp="$3" extra="$4" log="$WORK/log.$1.$2"
  "$lmp" -in "$DECK" -var solver apgd -var nz "$NZ" -var n "$STEPS" -var extra "$extra" \
    -log "$log" -echo none > /dev/null
  # every thermo row, the first (step 0: no solve) too; spheres, steps, loop, iterations (mean,
  # largest), active contacts at the end, largest overlap
  bench_thermo --keep-first "$log" last:Atoms steps loop mean:f_hc[1] max:f_hc[1] last:f_hc[4] \
    max:f_hc[2] load | sed "s/^/$name,$build,/" >> "$CSV"
}
if [ -n "${OLD_LMP:-}" ]; then run frictionless before "$OLD_LMP" ""; fi
run frictionless now "$LMP" ""
run friction_0.5 now "$LMP" "friction 0.5"
run friction_0.5_rolling_0.1 now "$LMP" "friction 0.5 rolling 0.1"
"$PY" - "$CSV" <<'PYEOF'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
base = next(r for r in rows if r["case"] == "frictionless" and r["build"] == "now")
print("| case | build | spheres | steps | loop (s) | time / frictionless | iterations/step (max) | active contacts at the end | load |")
print("|---|---|---|---|---|---|---|---|---|")
for r in rows:
    print("| %s | %s | %s | %s | %s | %.2f | %s (%s) | %s | %s |" % (
        r["case"], r["build"], r["spheres"], r["steps"], r["loop_s"],
        float(r["loop_s"]) / float(base["loop_s"]), r["iterations_per_step"], r["max_iterations"],
        r["active_end"], r["load1"]))
PYEOF
