#!/usr/bin/env bash
# Scale (issue 15, target 5): bench/scale/in.scale3d with 1e4, 1e5 and 1e6 spheres (a simple
# cubic block of polydisperse spheres falling into a walled box and starting to settle), one
# process, the default solver (cg without friction) at the default tolerance. Per size: setup
# and loop time, time per step, the solver iterations per step and rows at the end, the peak
# resident memory of the process and per sphere, and LAMMPS's own per-rank memory figure (which
# includes the fix's memory_usage()). Writes bench/results/scale/unrecorded/scale.csv and prints a markdown
# table.
#   bench/run.sh scale [--quick]      (--quick: 1e4 and 1e5 only)
set -euo pipefail
# shellcheck source=../common.sh
source "$(dirname "${BASH_SOURCE[0]}")/../common.sh" scale_ "$@"
SIZES=("22 21 200" "46 47 200" "100 100 100")    # n nz steps: n x n x nz spheres
[ "$MODE" = quick ] && SIZES=("22 21 100" "46 47 50")
CSV="$RESULTS/scale.csv"
echo "spheres,steps,setup_s,loop_s,s_per_step,iterations_per_step,rows_end,peak_rss_mb,kb_per_sphere,lammps_mb,load_before,load_after" > "$CSV"
for size in "${SIZES[@]}"; do
  read -r n nz steps <<< "$size"
  echo "scale: $n x $n x $nz spheres, $steps steps"
  "$PY" - "$ROOT" "$LMP" "$ROOT/bench/scale/in.scale3d" "$WORK" "$n" "$nz" "$steps" >> "$CSV" <<'PYEOF'
import os, resource, sys
root, lmp, deck, work, n, nz, steps = sys.argv[1:]
sys.path.insert(0, os.path.join(root, "python"))
import hctools as hc
load_before = os.getloadavg()[0]
r = hc.run_deck(lmp, deck, workdir=work, variables=dict(n=n, nz=nz, steps=steps),
                args=["-echo", "none"], log_name="log.%sx%sx%s" % (n, n, nz), timeout=7200)
rss_mb = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024.0
mem = float(r.log.split("Per MPI rank memory")[1].split("=")[1].split("|")[2].split()[0])
th, run = r.thermo[-1], hc.loop_times(r.log)[-1]
its = th["f_hc[1]"][1:]    # iterations at the thermo steps (every 10; step 0 has no solve)
atoms = run["atoms"]
print("%d,%s,%.1f,%.1f,%.4f,%.1f,%d,%.0f,%.2f,%.0f,%.2f,%.2f" % (
    atoms, steps, r.seconds - run["loop"], run["loop"], run["loop"] / float(steps),
    its.mean() if len(its) else 0.0, th["f_hc[3]"][-1], rss_mb, rss_mb * 1024.0 / atoms, mem,
    load_before, os.getloadavg()[0]))
PYEOF
done
"$PY" - "$CSV" <<'PYEOF'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
print("| spheres | steps | setup (s) | loop (s) | s/step | iterations/step (thermo steps) | rows at the end | peak RSS (MB) | kB/sphere | LAMMPS per-rank MB | load before/after |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
for r in rows:
    print("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s/%s |" % (
        r["spheres"], r["steps"], r["setup_s"], r["loop_s"], r["s_per_step"],
        r["iterations_per_step"], r["rows_end"], r["peak_rss_mb"], r["kb_per_sphere"],
        r["lammps_mb"], r["load_before"], r["load_after"]))
PYEOF
