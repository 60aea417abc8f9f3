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
import test_stab_friction as bedtest    # noqa: E402  the scene (bed(), its constants)



def main():
    case, solver, tol, work = sys.argv[1], sys.argv[2], float(sys.argv[3]), Path(sys.argv[4])
    work.mkdir(parents=True, exist_ok=True)
    data = work / "bed.data"
    text, n, _, floor_speed = bedtest.scene(case, data, "solver %s tol %g" % (solver, tol),
                                            dumps=False)
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
