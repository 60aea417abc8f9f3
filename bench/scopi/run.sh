#!/usr/bin/env bash
# SCoPI's box_spheres_3d scene (issue 15, target 3: "at least 2.6x faster than today, measured
# in the same run"): bench/scopi/in.box_spheres_3d (1000 spheres into an open box, h = 0.045,
# tol 1e-3, 1000 steps), one process, run one after the other in this order: the build the
# issue was filed against (OLD_LMP, its default solver apgd), this build's default (cg) and
# this build's apgd. Per run: loop time, ms per step, iterations per step (mean, max), rows,
# largest overlap, solves at maxiter, the load before and after. Writes bench/results/scopi/<host>/scopi.csv
# and prints a markdown table with the time of each run over the old build's (over this
# build's default without OLD_LMP).
#   [OLD_LMP=/path/to/old/lmp_hardcontact] bench/run.sh scopi [--quick]     (--quick: 200 steps)
# Build the old launcher from commit 4977451 (the last commit before the issue was filed):
#   git worktree add /tmp/old15 4977451 && cd /tmp/old15 && ln -s <repo>/.cache .cache &&
#   cmake -S . -B build -DHARDCONTACT_BUILD_TESTS=OFF -DHARDCONTACT_MODERN_LAMMPS_DIR= \
#     -DHARDCONTACT_LIGGGHTS=OFF && make -C build lmp_hardcontact
set -euo pipefail
# shellcheck source=../common.sh
source "$(dirname "${BASH_SOURCE[0]}")/../common.sh" scopi_ "$@"
# without OLD_LMP the issue's build is left out and times are over this build's default
OLD_LMP="${OLD_LMP:-}"
STEPS=1000
[ "$MODE" = quick ] && STEPS=200
"$PY" "$ROOT/bench/scopi/make_data.py" "$WORK/data.scopi"
"$PY" - "$ROOT" "$OLD_LMP" "$LMP" "$ROOT/bench/scopi/in.box_spheres_3d" "$WORK" "$STEPS" \
  "$RESULTS/scopi.csv" <<'PYEOF'
import os, sys
root, old, new, deck, work, steps, csv = sys.argv[1:]
sys.path.insert(0, os.path.join(root, "python"))
import hctools as hc
runs = [("issue's build (4977451), default apgd", old, "default"),
        ("this build, default cg", new, "default"),
        ("this build, apgd", new, "apgd")]
runs = [r for r in runs if r[1]]    # no OLD_LMP: this build only
rows = []
for label, lmp, solver in runs:
    load0 = "%.2f" % os.getloadavg()[0]
    r = hc.run_deck(lmp, deck, workdir=work, variables=dict(data="%s/data.scopi" % work,
                    solver=solver, steps=steps), args=["-echo", "none"], timeout=7200,
                    log_name="log.%s.%s" % ("old" if lmp == old else "new", solver))
    load1 = "%.2f" % os.getloadavg()[0]
    th, loop = r.thermo[-1], hc.loop_times(r.log)[-1]["loop"]
    after = th["Step"] > 0    # step 0: no solve
    its, cand, ov = list(th["f_hc[1]"][after]), list(th["f_hc[3]"][after]), list(th["f_hc[7]"][after])
    stops = int(th["f_hc[6]"][-1])
    rows.append(dict(run=label, steps=len(its), loop_s=loop, ms_per_step=1e3 * loop / len(its),
                     it_mean=float(sum(its)) / len(its), it_max=int(max(its)), rows_end=int(cand[-1]),
                     overlap_max=float(max(ov)), maxiter_stops=stops, load_before=load0, load_after=load1))
with open(csv, "w") as f:
    keys = list(rows[0])
    f.write(",".join(keys) + "\n")
    for r in rows:
        f.write(",".join('"%s"' % r[k] if k == "run" else ("%.6g" % r[k] if isinstance(r[k], float) else str(r[k]))
                         for k in keys) + "\n")
ref = rows[0]["loop_s"]
over = "issue's build" if old else "this build's default"
print("| run | steps | loop (s) | ms/step | time / %s | it/step (mean) | (max) | rows at the end "
      "| largest overlap | maxiter stops | load before / after |" % over)
print("|---|---|---|---|---|---|---|---|---|---|---|")
for r in rows:
    print("| %s | %d | %.2f | %.2f | %.2f | %.1f | %d | %d | %.1e | %d | %s / %s |" % (
        r["run"], r["steps"], r["loop_s"], r["ms_per_step"], r["loop_s"] / ref, r["it_mean"], r["it_max"],
        r["rows_end"], r["overlap_max"], r["maxiter_stops"], r["load_before"], r["load_after"]))
PYEOF
