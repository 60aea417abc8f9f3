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
  "$PY" - "$LMP" "$ROOT/bench/scale/in.scale3d" "$WORK" "$n" "$nz" "$steps" >> "$CSV" <<'PYEOF'
import resource, subprocess, sys, time
lmp, deck, work, n, nz, steps = sys.argv[1:]
load_before = open("/proc/loadavg").read().split()[0]
log = "%s/log.%sx%sx%s" % (work, n, n, nz)
t0 = time.time()
subprocess.run([lmp, "-in", deck, "-var", "n", n, "-var", "nz", nz, "-var", "steps", steps,
                "-log", log, "-echo", "none"], check=True, stdout=subprocess.DEVNULL, cwd=work)
wall = time.time() - t0
rss_mb = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024.0
rows, loop, mem, atoms, on = [], 0.0, 0.0, 0, False
for line in open(log):
    w = line.split()
    if line.startswith("Per MPI rank memory"):
        mem = float(line.split("=")[1].split("|")[2].split()[0])
    if w[:1] == ["Step"]:
        on = True
        continue
    if w[:1] == ["Loop"]:
        loop, atoms, on = float(w[3]), int(w[-2]), False
        continue
    if on and len(w) == 7:
        rows.append([float(v) for v in w])
its = [r[2] for r in rows[1:]]    # iterations at the thermo steps (every 10)
print("%d,%s,%.1f,%.1f,%.4f,%.1f,%d,%.0f,%.2f,%.0f,%s,%s" % (
    atoms, steps, wall - loop, loop, loop / float(steps), sum(its) / max(len(its), 1),
    rows[-1][3], rss_mb, rss_mb * 1024.0 / atoms, mem, load_before,
    open("/proc/loadavg").read().split()[0]))
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
