#!/usr/bin/env python3
"""examples/pour, shortened: fix pour drops 150 glass discs (instead of 600; d = 1.6-2.4 mm)
from a slab 120-190 mm high into a box 100 mm wide, 0.4 s of physical time (800 steps of
h = 5e-4 s with fix hardcontact; about 44 000 steps of 9e-6 s for the soft-sphere twin).

Hard contacts (in.pour), checked:
  * fix pour works with the fix (pair_style none): 151 atoms at the end (150 poured + the
    disc of the largest diameter that starts on the floor); atoms created during the run
    enter the contact problem (no overlap, below);
  * no solve stopped at maxiter; f_hc[7] <= 1e-4 at every thermo step; every dumped frame
    without overlap beyond 1e-4 of the contact size (pairs and walls);
  * every disc ends at rest on the bed: kinetic energy below 1e-4 of its peak, bed height
    5-7.5 mm (150 discs of mean area 3.2 mm^2 over 100 mm at packing 0.8: 6 mm);
Soft twin (in.pour.soft): 151 atoms, bed height within 1 mean diameter of the hard one."""

import os
import sys

import numpy as np

import lammps_run as lr

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
EX = os.path.join(ROOT, "examples", "pour")
sys.path.insert(0, os.path.join(ROOT, "examples", "common"))
import granular as g  # noqa: E402

WALLS = [(0, 0.0, 1), (0, 0.1, -1), (1, 0.0, 1)]
VARS = {"npour": 150, "tend": 0.4, "dump_dt": 0.1, "potentials": os.path.join(ROOT, "potentials")}


def test():
    args = lr.test_args(__doc__)
    hard = lr.run_deck(args.lmp, os.path.join(EX, "in.pour"), args.np, os.path.join(args.workdir, "hard"),
                       variables=VARS, timeout=args.timeout)
    th = hard.thermo[-1]
    print("hard: %d steps in %.1f s" % (th["Step"][-1], hard.seconds))
    lr.check(int(th["Step"][-1]) == 800 and int(th["Atoms"][-1]) == 151, "hard: 800 steps, 151 atoms at the end")
    lr.check(int(th["f_hc[6]"][-1]) == 0, "hard: no solve stopped at maxiter")
    lr.check(float(th["f_hc[7]"].max()) <= 1e-4, "hard: f_hc[7] <= tol (max %.3g)" % float(th["f_hc[7]"].max()))
    frames = g.read_dump(hard.path("pour.dump"))
    worst = max(g.overlaps(c, WALLS)[1] for _, c, _ in frames)
    lr.check(worst <= 1e-4 + 1e-6, "hard: dumped frames, largest overlap %.3g of the contact size" % worst)
    ke = th["c_ke"]
    lr.check(ke[-1] <= 1e-4 * ke.max(), "hard: at rest, KE %.3g J at the end (peak %.3g J)" % (ke[-1], ke.max()))
    last = frames[-1].columns
    top = g.bed_height(last, 0.95)
    lr.check(0.005 <= top <= 0.0075, "hard: bed height %.4g m" % top)

    soft = lr.run_deck(args.lmp, os.path.join(EX, "in.pour.soft"), args.np, os.path.join(args.workdir, "soft"),
                       variables=VARS, timeout=args.timeout)
    ths = soft.thermo[-1]
    print("soft: %d steps in %.1f s" % (ths["Step"][-1], soft.seconds))
    lr.check(int(ths["Atoms"][-1]) == 151, "soft: 151 atoms at the end")
    top_soft = g.bed_height(g.read_dump(soft.path("pour.dump"))[-1].columns, 0.95)
    lr.check(abs(top_soft - top) <= 0.002, "soft: bed height %.4g m (hard %.4g m)" % (top_soft, top))


if __name__ == "__main__":
    lr.main(test)
