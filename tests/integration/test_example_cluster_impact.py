#!/usr/bin/env python3
"""examples/cluster_impact (paper section 6.3, the flagship), run as the example runs it but
for 5 steps (-var nsteps 5): ~2000 polydisperse discs fall at 1 m/s onto a floor, h = 0.1 s
(three diameters per step). Checked: every atom kept; the largest overlap after every step
<= tol (1e-4 of the contact size, f_step[7]), and recomputed from the last dump frame over all
pairs; no disc closer to the floor than its radius (within tol); kinetic energy never increases
(gravity-free, Prop. 3, up to the tolerance's own scale); the bottom rows of the cluster have
stopped falling (mean |vy| from 1 to < 0.1); the pictures of steps 0 and 3 are written."""

import os

import numpy as np

import lammps_run as lr

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DECK = os.path.join(ROOT, "examples", "cluster_impact", "in.cluster_impact")
TOL = 1e-4


def test():
    args = lr.test_args(__doc__)
    res = lr.run_deck(args.lmp, DECK, args.np, args.workdir, variables={"nsteps": 6},
                      timeout=args.timeout)
    lr.check(res.returncode == 0 and not res.errors, "deck ran without ERROR")
    th = res.thermo[-1]
    atoms = th["Atoms"]
    lr.check(int(th["Step"][-1]) == 6 and bool(np.all(atoms == atoms[0])) and atoms[0] > 1900,
             "6 steps, %d discs kept" % atoms[0])
    ov = th["f_step[7]"]
    lr.check(float(ov.max()) <= TOL, "largest overlap after every step <= tol (%.3g)" % ov.max())
    ke = th["c_ke"]
    lr.check(float(np.diff(ke).max()) <= 1e-6 * ke[0], "kinetic energy never increases (%s)"
             % " ".join("%.4g" % k for k in ke))
    lr.check(ke[-1] < 0.7 * ke[0], "the impact dissipates energy (%.3g -> %.3g)" % (ke[0], ke[-1]))
    frame = lr.read_dump(res.path("cluster.dump"))[-1]
    c = frame.columns
    x = np.column_stack([c["x"], c["y"]])
    r = c["radius"]
    d = np.sqrt(((x[:, None, :] - x[None, :, :]) ** 2).sum(-1))
    gap = (d - (r[:, None] + r[None, :])) / (r[:, None] + r[None, :])
    np.fill_diagonal(gap, 1.0)
    lr.check(float(-gap.min()) <= TOL * 1.001, "all pairs of the last frame: overlap <= tol (%.3g)"
             % max(0.0, float(-gap.min())))
    wall = (x[:, 1] - r) / r
    lr.check(float(wall.min()) >= -TOL * 1.001, "no disc crosses the floor (%.3g)" % wall.min())
    low = x[:, 1] < 3 * r.max()
    lr.check(low.sum() > 10 and float(np.abs(c["vy"][low]).mean()) < 0.1,
             "the bottom rows have stopped falling (mean |vy| %.3g over %d discs, from 1)"
             % (float(np.abs(c["vy"][low]).mean()), low.sum()))
    for step in (0, 3):
        png = res.path("cluster.%d.png" % step)
        lr.check(os.path.getsize(png) > 1000, "picture of step %d written" % step)
    print("PASS")


if __name__ == "__main__":
    test()
