#!/usr/bin/env python3
"""examples/column_collapse, shortened: a column of 5 x 5 x 14 lattice sites (L0 = 6, 350
spheres, a = 1.7) settles behind the gate (t = 15) and collapses (t = 30), with the fix at its defaults
with friction (tol 1e-2) and mu 0.5, and a column of half the height (7 layers), and the soft
twin (in.collapse.soft, kn 6000) of the first.
Checks, hard runs: every solve converged (f_hc[6] = 0), the largest overlap <= tol of the
contact size at every thermo output (f_hc[7]), no sphere lost, the column at rest at release
and the flow over at the end (kinetic energy per sphere below 1e-3 m g d at release, below
1e-3 of the collapse's peak at the end: a sphere may still roll on the floor ahead), the
deposit lower than the column and spread beyond the gate. Physics: the taller column runs out
farther (by at least 0.5 L0: the runout grows with a), each runout lies in the band of the
quasi-2D experiments' laws (between 0.5 x Lube et al. 2005 and 1.5 x Lajeunesse
et al. 2005, collapse_runout.py) and within 35 % of the soft twin's from the same column
(single runs: the runout of a column of this size scatters by about 10-20 % over seeds,
bench/friction/collapse.sh)."""

import math
import os
import sys

import numpy as np

import lammps_run as lr

EX = os.path.join(os.environ.get("HARDCONTACT_SOURCE_DIR", "."), "examples", "column_collapse")
sys.path.insert(0, EX)
import collapse_runout  # noqa: E402

TOL = 1e-2    # the fix's default with friction
SIZE = ["-var", "L0", "6", "-var", "tsettle", "15", "-var", "tend", "30"]
MGD = math.pi / 6.0    # m g d of a unit sphere (density 1, g = 1)


def run(args, name, deck, extra):
    wd = lr.fresh_workdir("%s/%s" % (args.workdir, name))
    res = lr.run_deck(args.lmp, os.path.join(EX, deck), args.np, wd, timeout=args.timeout,
                      args=SIZE + extra)
    out = collapse_runout.runout(os.path.join(str(wd), "collapse0.dump"),
                                 os.path.join(str(wd), "collapse1.dump"))
    settle, collapse = res.thermo[0], res.thermo[-1]
    n = len(collapse_runout.frame(os.path.join(str(wd), "collapse1.dump"))["x"])    # grains
    ke0 = float(settle["c_ke"][-1]) / n
    ke1 = float(collapse["c_ke"][-1]) / n
    print("%s: %d spheres, a %.2f, runout %.3f, H_inf / L0 %.3f, %d strays, kinetic energy per "
          "sphere %.3g at release, %.3g at the end, %.1f s" % (name, n, out["a"], out["runout"],
                                                              out["H_inf_over_L0"], out["strays"],
                                                              ke0, ke1, res.seconds))
    if deck == "in.collapse":
        for block, phase in ((settle, "settle"), (collapse, "collapse")):
            lr.check(float(np.max(block["f_hc[6]"])) == 0.0,
                     "%s, %s: every solve converged" % (name, phase))
            ov = float(np.max(block["f_hc[7]"]))
            lr.check(ov <= TOL, "%s, %s: largest overlap %.3g of the contact size <= tol %g"
                     % (name, phase, ov, TOL))
            lr.check(int(block["Atoms"][-1]) == int(settle["Atoms"][0]),
                     "%s, %s: no sphere lost" % (name, phase))
        peak = float(np.max(collapse["c_ke"])) / n
        lr.check(ke0 <= 1e-3 * MGD and ke1 <= 1e-3 * peak,
                 "%s: the column at rest at release (kinetic energy per sphere %.3g, below "
                 "1e-3 m g d) and the flow over at the end (%.3g, below 1e-3 of the collapse's "
                 "peak %.3g)" % (name, ke0, ke1, peak))
        lr.check(out["runout"] > 0.5 and out["H_inf_over_L0"] < out["a"],
                 "%s: the deposit spread beyond the gate (runout %.2f L0) and is lower than the "
                 "column (H_inf %.2f L0 < H0 %.2f L0)" % (name, out["runout"],
                                                          out["H_inf_over_L0"], out["a"]))
    return out


def test():
    args = lr.test_args(__doc__)
    high = run(args, "hard_nz14", "in.collapse", ["-var", "nz", "14"])
    low = run(args, "hard_nz7", "in.collapse", ["-var", "nz", "7"])
    soft = run(args, "soft_nz14", "in.collapse.soft", ["-var", "nz", "14", "-var", "kn", "6000",
                                                       "-var", "thermo_every", "20000"])
    lr.check(high["a"] >= 1.6 * low["a"] and high["runout"] >= low["runout"] + 0.5,
             "a taller column runs out farther: a %.2f vs %.2f, runout %.2f vs %.2f L0"
             % (high["a"], low["a"], high["runout"], low["runout"]))
    for res, name in ((high, "14 layers"), (low, "7 layers")):
        lo, hi = 0.5 * res["lube2005"], 1.5 * res["lajeunesse2005"]
        lr.check(lo <= res["runout"] <= hi,
                 "%s: runout %.2f L0 at a = %.2f within the experiments' band [%.2f, %.2f]"
                 % (name, res["runout"], res["a"], lo, hi))
    lr.check(abs(high["runout"] - soft["runout"]) <= 0.35 * soft["runout"],
             "14 layers: runout %.2f L0 within 35 %% of the soft twin's %.2f L0"
             % (high["runout"], soft["runout"]))


if __name__ == "__main__":
    lr.main(test)
