#!/usr/bin/env python3
"""examples/sticky_particles (paper section 6.2), run as the example runs it: in.sticky with
data.sticky (20 point-like particles of radius 1e-4 a on a line, random velocities in [-1, 1],
no force), steps h = 0.01, 0.5 and 1.5 up to t = 4.5 (450, 9 and 3 steps; < 1 s each).

Checked for every h against the exact event-driven sticky solution (sticky_exact.py, next to
the deck):
  * the final state (t = 4.5, after the last collision at t = 2.27) is the exact one: the same
    four clusters 1-2, 3-14, 15-16, 17-20, every position and velocity within 1e-7 (the solver
    tolerance is 1e-6 of the contact size 2r ~ 1e-5);
  * the centre of mass is exact at every step (Remark 10/11): x_cm(t) = 0.5 + t v_cm, 1e-12;
  * the kinetic energy never increases (Prop. 3) and ends at the exact final value;
  * the particles never pass each other: order kept and every gap >= -1e-6 x 2r at every step,
    no solve stopped at maxiter (f_hc[6] = 0);
  * h = 0.01 is on the exact pathlines at every step (1e-7; measured 1e-8): in 1d a cluster
    that closes within a step moves with its exact momentum for the whole step, so its position
    at the end of the step is exact (the large steps merge clusters late, and are exact once
    every collision is taken into account)."""

import os
import sys

import numpy as np

import lammps_run as lr

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
EX = os.path.join(ROOT, "examples", "sticky_particles")
sys.path.insert(0, EX)
import make_data            # noqa: E402
import sticky_exact as se   # noqa: E402

T_END = 4.5


def test():
    args = lr.test_args(__doc__)
    q0, u0, r = make_data.particles()
    n = len(q0)
    final, t_last = se.solve(q0, u0, r)
    x_end, v_end = se.state(q0, u0, r, None, T_END)
    ke_end = 0.5 * sum(v * v for v in v_end)
    vcm = sum(u0) / n
    lr.check([(c[0], c[1]) for c in final] == [(0, 1), (2, 13), (14, 15), (16, 19)] and t_last < 3.0,
             "exact solution: 4 final clusters, last collision at t = %.4f" % t_last)
    for h in ("0.01", "0.5", "1.5"):
        wd = os.path.join(args.workdir, "h" + h)
        res = lr.run_deck(args.lmp, os.path.join(EX, "in.sticky"), args.np, wd,
                          variables={"h": h, "tend": T_END, "data": os.path.join(EX, "data.sticky")},
                          timeout=args.timeout)
        th = res.thermo[-1]
        steps = int(round(T_END / float(h)))
        lr.check(int(th["Step"][-1]) == steps, "h = %s: %d steps in %.2f s" % (h, steps, res.seconds))
        t = th["Time"]
        err_cm = float(np.abs(th["v_xcm"] - (0.5 + t * vcm)).max())
        lr.check(err_cm <= 1e-12, "h = %s: centre of mass exact at every step (%.2g)" % (h, err_cm))
        ke = th["c_ke"]
        lr.check(float(np.diff(ke).max()) <= 1e-14 * ke[0], "h = %s: kinetic energy never increases" % h)
        lr.check(abs(ke[-1] - ke_end) <= 1e-9 * ke[0], "h = %s: final kinetic energy %.12g (exact %.12g)"
                 % (h, ke[-1], ke_end))
        lr.check(int(th["f_hc[6]"][-1]) == 0, "h = %s: no solve stopped at maxiter" % h)
        frames = lr.read_dump(res.path("sticky.dump"))
        lr.check(len(frames) == steps + 1, "h = %s: %d frames" % (h, len(frames)))
        worst_gap, worst_path, off_axis = 0.0, 0.0, 0.0
        for f in frames:
            x = f.columns["x"]
            gap = (np.diff(x) - 2 * r) / (2 * r)
            worst_gap = min(worst_gap, float(gap.min()))
            off_axis = max(off_axis, float(np.abs(f.columns["y"]).max()), float(np.abs(f.columns["z"]).max()))
            if h == "0.01":
                xe, _ = se.state(q0, u0, r, None, f.timestep * float(h))
                worst_path = max(worst_path, float(np.abs(x - np.array(xe)).max()))
        lr.check(off_axis == 0.0, "h = %s: particles stay on the x axis (y = z = 0)" % h)
        lr.check(worst_gap >= -1e-6, "h = %s: order kept, smallest gap %.3g of 2r" % (h, worst_gap))
        if h == "0.01":
            lr.check(worst_path <= 1e-7, "h = 0.01: on the exact pathlines at every step (%.3g)" % worst_path)
        last = frames[-1].columns
        ex = float(np.abs(last["x"] - np.array(x_end)).max())
        ev = float(np.abs(last["vx"] - np.array(v_end)).max())
        lr.check(ex <= 1e-7 and ev <= 1e-7, "h = %s: final state exact (|dx| %.2g, |dv| %.2g)" % (h, ex, ev))


if __name__ == "__main__":
    lr.main(test)
