#!/usr/bin/env python3
"""Long run: a closed box of walls (10 x 10 x 10, six walls) holding 200 spheres (radii uniform
in [0.4, 0.5], density 1, placed at random without overlap) with random velocities N(0, 1) per
component, no force, h = 0.01 (0.04 diameters per step at the largest initial speed), default
tol 1e-4. The inelastic gas cools by collisions, clusters, and clusters stick to the walls.
--steps 10000 in CI, 10^5 in the soak variant.

Asserted at every step (thermo, %.16g): no lost atom; every value finite; no overlap beyond
tol (f_hc[7]); no solve at maxiter; the kinetic energy monotone non-increasing (Prop. 3: walls
are fixed obstacles, 0 stays admissible), step to step, to round-off, beyond the work of
clearing overlaps present at the start of a step (f_hc[10]: the overlaps a solve stopped at tol
leaves are pushed apart at the next step, and Prop. 3 holds for D >= 0 only):
KE(n+1) - KE(n) - f_hc[10](n+1) <= 1e-12 KE(0). The raw rises and the total clearing work are
reported (ke_rise_raw, clearing_work_total, in units of KE(0)). From dumps every 1/20 of the run: all-pairs and wall overlap <= tol, all atoms
inside the walls, everything finite."""

import sys
from pathlib import Path

import numpy as np

import lammps_run as lr
import stability_common as sc

N = 200
L = 10.0
H = 0.01
TOL = 1e-4
KE_ROUNDOFF = 1e-12


def scene():
    rng = np.random.default_rng(314)
    radius = rng.uniform(0.4, 0.5, N)
    x = []
    while len(x) < N:
        k = len(x)
        p = rng.uniform(radius[k] + 0.01, L - radius[k] - 0.01, 3)
        if x and np.min(np.linalg.norm(np.array(x) - p, axis=1) - radius[:k] - radius[k]) <= 0.02:
            continue
        x.append(p)
    return np.array(x), rng.normal(0.0, 1.0, (N, 3)), radius


def test():
    argv = list(sys.argv[1:])
    nsteps = 10000
    if "--steps" in argv:
        k = argv.index("--steps")
        nsteps = int(argv[k + 1])
        del argv[k:k + 2]
    args = lr.test_args(__doc__, argv)
    x, v, radius = scene()
    data = Path(args.workdir) / "data.gas"
    sc.write_data(data, ((0.0, L),) * 3, radius, 1.0, x, v)
    vmax0 = float(np.linalg.norm(v, axis=1).max())
    walls = " ".join("wall %s 0.0 %r" % (p, L) for p in ("xplane", "yplane", "zplane"))
    wl = [(d, 0.0, 1) for d in range(3)] + [(d, L, -1) for d in range(3)]
    text = sc.deck("data.gas", nsteps, H, 4 * H * vmax0 * 1.5, "tol %g %s" % (TOL, walls),
                   boundary="f f f", dump_every=max(nsteps // 20, 1))
    chk = sc.Checks()
    res, th = sc.run(args, text, args.workdir + "/run", data)
    label = "closed box, %d spheres, %d steps" % (N, nsteps)
    ov = sc.check_common(th, N, TOL, label, check=chk)
    ke = th["c_ke"]
    work = th["f_hc[10]"]
    d = np.diff(ke) - work[1:]    # rise beyond the work of clearing overlaps (f_hc[10])
    rise = float(max(d.max(), 0.0) / ke[0])
    raw = sc.energy_rises(ke)
    nrise = int((d > KE_ROUNDOFF * ke[0]).sum())
    k = int(np.argmax(d)) + 1
    chk(rise <= KE_ROUNDOFF, "%s: kinetic energy monotone non-increasing beyond the work of "
        "clearing overlaps: largest step-to-step excess %.3g KE(0) at step %d (KE %.6g -> %.6g, "
        "work %.3g), %d steps with an excess above %g KE(0)"
        % (label, rise, int(th["Step"][k]), ke[k - 1], ke[k], work[k], nrise, KE_ROUNDOFF))
    frames = lr.read_dump(res.path("dump.atoms"))
    worst_pair, worst_wall = sc.dump_overlaps(frames, N, wl, chk, label)
    chk(worst_pair <= TOL * (1 + 1e-9) and worst_wall <= TOL * (1 + 1e-9),
        "%s: dumps: all-pairs overlap %.3g, wall overlap %.3g <= tol" % (label, worst_pair, worst_wall))
    sc.report("long_run_np%d_%d" % (args.np, nsteps), steps=nsteps, overlap=ov, ke_excess=rise,
              ke_rise_raw=raw, clearing_work_total=float(work.sum() / ke[0]),
              steps_with_rise=nrise, ke_end_over_ke0=float(ke[-1] / ke[0]),
              overlap_dumps=worst_pair, wall_overlap=worst_wall, max_iter=int(th["f_hc[1]"].max()),
              seconds=round(res.seconds, 1))
    chk.finish()


if __name__ == "__main__":
    lr.main(test)
