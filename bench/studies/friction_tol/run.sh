#!/usr/bin/env bash
# What accuracy costs with friction (issues 12 and 15, with doc/accuracy-vs-time.md): the
# settling 3D pile of bench/compare/in.pile3d (nz layers of polydisperse spheres, h = 0.02,
# walled box), tolerances 1e-2 .. 1e-6: frictionless with apgd and with cg (the default without
# friction), friction 0.5 and friction 0.5 + rolling 0.1 with apgd (the default with friction),
# each against its own reference (same case and solver) at tol 1e-8: loop time, iterations per step,
# overlap at the end of the run (f_hc[7]; the deck's lattice starts with overlaps up to 3 % of
# a diameter, which the overlap policy clears within about 80 steps) and the error of the final positions (RMS and largest
# distance to the reference's, in sphere diameters). Writes bench/studies/friction_tol/results/friction_tol.csv
# and prints a markdown table (pasted into doc/accuracy-vs-time.md).
#   bench/studies/friction_tol/run.sh [--quick]
set -euo pipefail
# shellcheck source=../../common.sh
source "$(dirname "${BASH_SOURCE[0]}")/../../common.sh" friction_tol_ "$@"
NZ=6; STEPS=150; TOLS="1e-2 1e-3 1e-4 1e-5 1e-6"; REF=1e-8
[ "$MODE" = quick ] && { NZ=3; STEPS=50; TOLS="1e-2 1e-4"; REF=1e-6; }
DECK="$WORK/in.pile3d"
sed -e 's/hardcontact solver ${solver} wall/hardcontact solver ${solver} tol ${tol} maxiter 100000 ${extra} wall/' \
    -e 's/^thermo_style .*/thermo_style    custom step atoms ke f_hc[1] f_hc[7] f_hc[6]/' \
    -e 's/^run .*/run             ${n}\nwrite_dump      all custom final.${name} id x y z modify sort id format float %.17g/' \
    "$ROOT/bench/compare/in.pile3d" > "$DECK"
CSV="$RESULTS/friction_tol.csv"
echo "case,tol,spheres,steps,loop_s,iterations_per_step,max_iterations,end_overlap,maxiter_solves,rms_error_d,max_error_d,load1" > "$CSV"
run() {    # run CASE SOLVER TOL EXTRA -> log.CASE.TOL, final.CASE.TOL
  local case="$1" solver="$2" tol="$3" extra="$4"
  (cd "$WORK" && "$LMP" -in "$DECK" -var solver "$solver" -var nz "$NZ" -var n "$STEPS" -var tol "$tol" \
     -var extra "$extra" -var name "$case.$tol" -log "log.$case.$tol" -echo none > /dev/null)
}
for spec in "frictionless:apgd:" "frictionless_cg:cg:" "friction_0.5:apgd:friction 0.5" \
            "friction_0.5_rolling_0.1:apgd:friction 0.5 rolling 0.1"; do
  case="${spec%%:*}"; rest="${spec#*:}"; solver="${rest%%:*}"; extra="${rest#*:}"
  echo "friction_tol: $case ($solver) reference (tol $REF)"
  run "$case" "$solver" "$REF" "$extra"
  for tol in $TOLS; do
    echo "friction_tol: $case ($solver) tol $tol"
    run "$case" "$solver" "$tol" "$extra"
    "$PY" - "$WORK" "$case" "$tol" "$REF" "$(cut -d' ' -f1 /proc/loadavg)" >> "$CSV" <<'PYEOF'
import sys
import numpy as np
work, case, tol, ref, load = sys.argv[1:]
def final(t):
    rows = [l.split() for l in open("%s/final.%s.%s" % (work, case, t)).read().splitlines()[9:]]
    return np.array([[float(v) for v in r[1:4]] for r in rows])
def thermo(t):
    out, loop, on = [], 0.0, False
    for line in open("%s/log.%s.%s" % (work, case, t)):
        w = line.split()
        if w[:1] == ["Step"]:
            on = True
            continue
        if w[:1] == ["Loop"]:
            on, loop = False, float(w[3])
            continue
        if on and len(w) == 6:
            out.append([float(v) for v in w])
    return np.array(out), loop
a, b = final(tol), final(ref)
err = np.linalg.norm(a - b, axis=1) / 0.9    # in mean diameters
th, loop = thermo(tol)
it = th[1:, 3]
print("%s,%s,%d,%d,%.3f,%.1f,%d,%.3g,%d,%.3g,%.3g,%s" % (
    case, tol, len(a), len(th) - 1, loop, it.mean(), it.max(), th[-1, 4], th[-1, 5],
    np.sqrt((err ** 2).mean()), err.max(), load))
PYEOF
  done
done
"$PY" - "$CSV" <<'PYEOF'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
base = {r["tol"]: float(r["loop_s"]) for r in rows if r["case"] == "frictionless"}
print("| case | tol | loop (s) | time / frictionless at that tol | iterations/step (max) | overlap / size at the end | position error RMS (max), diameters | load |")
print("|---|---|---|---|---|---|---|---|")
for r in rows:
    print("| %s | %s | %s | %.1f | %s (%s) | %s | %s (%s) | %s |" % (
        r["case"], r["tol"], r["loop_s"], float(r["loop_s"]) / base[r["tol"]],
        r["iterations_per_step"], r["max_iterations"], r["end_overlap"], r["rms_error_d"],
        r["max_error_d"], r["load1"]))
PYEOF
