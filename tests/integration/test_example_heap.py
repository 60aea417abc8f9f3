#!/usr/bin/env python3
"""examples/heap, shortened: 400 spheres poured through the inlet onto the rough floor
(t = 30: pouring ends near t = 16), once with mu = 0.1 and once with mu = 0.5 and rolling 0.1.
Checks: every solve converged (f_hc[6] = 0), no overlap beyond tol of the contact size at
any thermo output (f_hc[7]; the deck's tol, 1e-2, the fix's default with friction), the heaps settled (kinetic energy per sphere below 1 % of
m g d), and the angle of repose (examples/heap/heap_angle.py, the cone angle from the heap's height
and volume: heaps of 400 are too small for a flank fit) is larger with more friction and
rolling resistance by at least 3 degrees and the heap higher by half a diameter, each angle in
a plausible range."""

import os
import sys

import numpy as np

import lammps_run as lr

EX = os.path.join(os.environ.get("HARDCONTACT_SOURCE_DIR", "."), "examples", "heap")
sys.path.insert(0, EX)
import heap_angle  # noqa: E402


TOL = 1e-2    # in.heap's tol: the fix's default with friction


def run(args, name, mu, mur):
    wd = lr.fresh_workdir("%s/%s" % (args.workdir, name))
    res = lr.run_deck(args.lmp, os.path.join(EX, "in.heap"), args.np, wd, timeout=args.timeout,
                      args=["-var", "npour", "400", "-var", "tend", "30", "-var", "mu", str(mu),
                            "-var", "mur", str(mur), "-var", "thermo_every", "50",
                            "-var", "dump_every", "1100"])
    th = res.thermo[-1]
    lr.check(float(np.max(th["f_hc[6]"])) == 0.0, "%s: every solve converged" % name)
    ov = float(np.max(th["f_hc[7]"]))
    lr.check(ov <= TOL, "%s: largest overlap %.3g of the contact size <= tol %g" % (name, ov, TOL))
    n = int(th["Atoms"][-1]) - 900    # the rough floor's 900 fixed spheres
    ke = float(th["c_ke"][-1]) / n
    lr.check(n == 401 and ke <= 0.01 * 0.52, "%s: %d spheres settled (kinetic energy per sphere "
             "%.3g, below 1 %% of m g d)" % (name, n, ke))
    res_angle = heap_angle.heap_angle(os.path.join(str(wd), "heap.dump"), floor=1.0)
    print("%s: cone angle %.2f deg, flank %s, peak %.2f, foot %.2f, %d iterations per step "
          "(mean)" % (name, res_angle["cone_angle"], res_angle["angle"], res_angle["peak"],
                      res_angle["foot"], float(np.mean(th["f_hc[1]"]))))
    return res_angle


def test():
    args = lr.test_args(__doc__)
    low = run(args, "mu0.1", 0.1, 0.0)
    high = run(args, "mu0.5_mur0.1", 0.5, 0.1)
    lo, hi = low["cone_angle"], high["cone_angle"]
    lr.check(5.0 <= lo < 22.0 and 18.0 < hi < 40.0,
             "cone angles in plausible ranges: mu 0.1: %.1f deg, mu 0.5 + rolling 0.1: %.1f deg"
             % (lo, hi))
    lr.check(hi >= lo + 3.0 and high["peak"] >= low["peak"] + 0.5,
             "more friction and rolling resistance, a steeper and higher heap (%.1f vs %.1f deg, "
             "peak %.2f vs %.2f)" % (hi, lo, high["peak"], low["peak"]))


if __name__ == "__main__":
    lr.main(test)
