#!/usr/bin/env python3
"""The frictional beds of tests/integration/test_stab_friction.py (144 spheres in four periodic
FCC layers on a floor, friction 0.8 / floor 0.3, h 0.02, t = 20) run with one solver and tol:
prints one CSV line - case, solver, tol, loop time, iterations per step (all, and over the last
10 time units, at rest in the floor's frame), solves at maxiter, and the kinetic energy relative
to the floor over the last 10 time units (the largest, per sphere, in m g d).

    beds.py CASE SOLVER TOL WORKDIR      (CASE = conveyor or slide)
"""
import math
import os
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]
sys.path.insert(0, str(ROOT / "tests" / "integration"))
import lammps_run as lr           # noqa: E402
import stability_common as sc     # noqa: E402
import test_stab_friction as bedtest    # noqa: E402  the scene (bed(), its constants)

import numpy as np                # noqa: E402


def main():
    case, solver, tol, work = sys.argv[1], sys.argv[2], float(sys.argv[3]), Path(sys.argv[4])
    x, side = bedtest.bed()
    n = len(x)
    v = np.zeros_like(x)
    if case == "slide":
        v[:, 0] = bedtest.V
    floor_speed = bedtest.V if case == "conveyor" else 0.0
    work.mkdir(parents=True, exist_ok=True)
    data = work / "bed.data"
    sc.write_data(str(data), ((0.0, side), (0.0, side), (-1.0, 12.0)), np.full(n, bedtest.R), 1.0,
                  x, v)
    T0 = bedtest.T_START
    xf = ("%r*(time-%r)*(time>%r)" % (bedtest.V, T0, T0)) if case == "conveyor" else "0.0"
    forces = ("variable        xf equal %s\n"
              "region          floor plane 0 0 0 0 0 1 side in move v_xf NULL NULL" % xf)
    nsteps = int(round(bedtest.T_END / bedtest.H))
    text = sc.deck(data.name, nsteps, bedtest.H, 0.3,
                   keywords="solver %s tol %g friction %r wall region floor friction %r"
                   % (solver, tol, bedtest.MU_PAIR, bedtest.MU_FLOOR),
                   boundary="p p f", gravity=bedtest.G, extra_forces=forces)
    res = lr.run_deck(str(os.environ.get("HARDCONTACT_LMP", ROOT / "build" / "lmp_hardcontact")),
                      text, 1, work / "run", files=[data], timeout=3600)
    th = res.thermo[0]
    loop = float(next(l for l in res.log.splitlines() if l.startswith("Loop time")).split()[3])
    M = n * 4.0 / 3.0 * math.pi * bedtest.R ** 3
    t = th["Step"] * bedtest.H
    rest = t >= bedtest.T_END - bedtest.T_REST
    ke_rel = th["c_ke"] - th["c_P[1]"] * floor_speed + 0.5 * M * floor_speed ** 2
    per = float(ke_rel[rest].max()) / (M * bedtest.G * 2 * bedtest.R)    # per sphere: M = n m
    it = th["f_hc[1]"]
    print("%s,%s,%g,%.2f,%.1f,%.1f,%d,%d,%.3g" % (case, solver, tol, loop, float(it.mean()),
          float(it[rest].mean()), int(it[rest].max()), int(th["f_hc[6]"][-1]), per))


if __name__ == "__main__":
    main()
