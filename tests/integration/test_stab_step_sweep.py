#!/usr/bin/env python3
"""Step-size sweep: the same scene of 300 spheres (radii uniform in [0.4, 0.6], density 1),
placed at random without overlap in a ball of radius 6 and collapsing onto its centre
(v = -0.3 x + N(0, 0.3) per component: the cloud is compressed around t = 3 and bounces off
itself inelastically), integrated with steps from tiny (h = 0.002, a step moves 0.006 of a
diameter) to huge (h = 5 D / v_max: the fastest sphere moves five diameters per step, every
collision of several steps handled in one solve).

Properties (SCHEME.md section 4), asserted at EVERY step from the thermo (%.16g) and every
20th step from dumps:
  feasibility (Prop. 2): f_hc[7] (largest overlap / (r_i + r_j) after the step) <= tol = 1e-4,
     and the same recomputed over ALL pairs (brute force, no neighbour list) from the dumps;
  stability (Prop. 3): no force, so the kinetic energy never increases beyond the work of
     clearing overlaps present at the start of a step (f_hc[10], the overlaps a solve stopped
     at tol leaves; the fix's own bound, as in test_stab_long_run.py): KE(n+1) - KE(n) -
     f_hc[10](n+1) <= 1e-12 KE(0) (round-off);
  momentum (Prop. 4): |sum m v (n) - sum m v (0)| <= 1e-12 max_n sum m |v| (round-off);
  no solve stopped at maxiter (f_hc[6] = 0), no lost atom, nothing non-finite.
Case 'free': no wall, no force (boundary s s s). Case 'wall': the same cloud drifting down
(v_z - 0.5) onto `wall zplane -7 NULL` (boundary s s m): feasibility also against the wall,
energy as above, momentum in x and y (the wall pushes along z only).
Options: --case free|wall, --steps tiny,small,medium,large,huge (which steps), --tol (default
1e-4, the fix's default), --solver (default apgd). The registered variants (stability.cmake):
default tol serial and 2 ranks; tol 1e-10 (the exact-projection properties, at round-off);
solver exact (Lawson-Hanson, machine precision) at the default tol; solver cg (projected CG, the
default without friction) serially, on 2 ranks and at tol 1e-10."""

import math
import sys
from pathlib import Path

import numpy as np

import lammps_run as lr
import stability_common as sc

N = 300
R_CLOUD = 6.0
TOL = 1e-4    # the default; --tol changes it
T_END = 8.0
MIN_STEPS = 30
KE_ROUNDOFF = 1e-12
P_ROUNDOFF = 1e-12


def scene(case):
    rng = np.random.default_rng(20240611)
    radius = rng.uniform(0.4, 0.6, N)
    x = []
    while len(x) < N:
        p = rng.uniform(-R_CLOUD, R_CLOUD, 3)
        k = len(x)
        if np.linalg.norm(p) > R_CLOUD - radius[k]:
            continue
        if x and np.min(np.linalg.norm(np.array(x) - p, axis=1) - radius[:k] - radius[k]) <= 0.05:
            continue
        x.append(p)
    x = np.array(x)
    v = -0.3 * x + rng.normal(0.0, 0.3, (N, 3))
    if case == "wall":
        v[:, 2] -= 0.5
    return x, v, radius


def step_list(vmax, which):
    d = 2.0 * 0.5
    steps = {"tiny": 0.002, "small": 0.02, "medium": 0.2, "large": 1.0, "huge": 5.0 * d / vmax}
    return [(name, steps[name]) for name in which]


def test():
    argv = list(sys.argv[1:])
    case, which = "free", ["tiny", "small", "medium", "large", "huge"]
    if "--case" in argv:
        k = argv.index("--case")
        case = argv[k + 1]
        del argv[k:k + 2]
    solver = "apgd"
    if "--solver" in argv:
        k = argv.index("--solver")
        solver = argv[k + 1]
        del argv[k:k + 2]
    tol = TOL
    if "--tol" in argv:
        k = argv.index("--tol")
        tol = float(argv[k + 1])
        del argv[k:k + 2]
    if "--steps" in argv:
        k = argv.index("--steps")
        which = argv[k + 1].split(",")
        del argv[k:k + 2]
    args = lr.test_args(__doc__, argv)
    x, v, radius = scene(case)
    vmax = float(np.linalg.norm(v, axis=1).max())
    lo = -R_CLOUD - 2.0
    box = ((lo, -lo), (lo, -lo), (lo, -lo))
    data = Path(args.workdir) / "data.cloud"
    sc.write_data(data, box, radius, 1.0, x, v)
    walls = []
    if case == "wall":
        boundary, keywords = "s s m", "solver %s tol %g wall zplane -7.0 NULL" % (solver, tol)
        walls = [(2, -7.0, +1)]
    else:
        boundary, keywords = "s s s", "solver %s tol %g" % (solver, tol)
    chk = sc.Checks()
    for name, h in step_list(vmax, which):
        nsteps = max(int(math.ceil(T_END / h)), MIN_STEPS)
        skin = max(4.0 * h * vmax * 1.25, 0.2)
        every = max(nsteps // 20, 1)
        label = "%s %s tol=%g h=%.4g (%s: %.3g diameters per step at v_max, %d steps)" % (
            case, solver, tol, h, name, h * vmax, nsteps)
        text = sc.deck("data.cloud", nsteps, h, skin, keywords, boundary=boundary,
                       dump_every=every)
        res, th = sc.run(args, text, "%s/%s" % (args.workdir, name), data)
        ov = sc.check_common(th, N, tol, label, check=chk)

        ke = th["c_ke"]
        beyond = np.diff(ke) - th["f_hc[10]"][1:]    # rise beyond the clearing work
        rise = max(0.0, float(beyond.max())) / max(abs(float(ke[0])), 1e-300)
        k_rise = int(np.argmax(beyond)) + 1
        chk(rise <= KE_ROUNDOFF,
                 "%s: kinetic energy never increases beyond the clearing work: largest "
            "step-to-step rise less f_hc[10] %.3g KE(0) (step %d, KE %.6g -> %.6g, clearing work "
            "%.3g, %d solver iterations; largest raw rise %.3g KE(0)) <= %g"
            % (label, rise, int(th["Step"][k_rise]), ke[k_rise - 1], ke[k_rise],
               th["f_hc[10]"][k_rise], int(th["f_hc[1]"][k_rise]), sc.energy_rises(ke),
               KE_ROUNDOFF))
        P = np.column_stack([th["c_P[1]"], th["c_P[2]"], th["c_P[3]"]])
        scale = float(th["c_P[4]"].max())
        dims = [0, 1, 2] if case == "free" else [0, 1]
        drift = float(np.abs(P[:, dims] - P[0, dims]).max()) / scale
        chk(drift <= P_ROUNDOFF,
                 "%s: momentum (components %s) exact: drift %.3g of sum m|v| <= %g"
                 % (label, dims, drift, P_ROUNDOFF))

        frames = lr.read_dump(res.path("dump.atoms"))
        worst_pair, worst_wall = sc.dump_overlaps(frames, N, walls, chk, label)
        chk(worst_pair <= tol * (1 + 1e-9),
                 "%s: all-pairs overlap from %d dumps %.3g <= tol" % (label, len(frames), worst_pair))
        if walls:
            chk(worst_wall <= tol * (1 + 1e-9),
                     "%s: wall overlap from dumps %.3g <= tol" % (label, worst_wall))
        sc.report("step_sweep_%s_%s_tol%g_np%d_%s" % (case, solver, tol, args.np, name), h=h, steps=nsteps,
                  overlap=ov, overlap_dumps=worst_pair, wall_overlap=worst_wall,
                  ke_rise=rise, ke_final_over_initial=float(ke[-1] / ke[0]), p_drift=drift,
                  max_iter=int(th["f_hc[1]"].max()), max_rows=int(th["f_hc[3]"].max()),
                  max_solves=int(th["f_hc[9]"].max()), seconds=round(res.seconds, 1))
    chk.finish()


if __name__ == "__main__":
    lr.main(test)
