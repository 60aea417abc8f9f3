#!/usr/bin/env python3
"""Extreme polydispersity: radius ratio 10, mass ratio 1000. A bed of 600 light spheres
(r = 0.1, density 1: three loose layers of 20 x 10, about 0.02 apart, jittered) in a closed box
of walls (4.4 x 2.2, floor, lid at 7), and 2 heavy spheres (r = 1, same density: 1000 times
the mass) released 1.5 above the bed with a downward speed of 2, under gravity g = 1; h = 0.01,
default tol 1e-4, 600 steps (the heavies sink through the frictionless bed to the floor and
push it up around them).

Why hard: the dual operator h^2 G M^-1 G^T mixes inverse masses 1000 apart (its condition
number carries the mass ratio), a heavy sphere touches dozens of light ones at once and speeds
them up far beyond their free speed (the fix's missed-row pass, f_hc[9] > 1), and light spheres
are squeezed between heavy spheres and walls.

Run 1 (skin 1.0, generous). Asserted: feasibility at every step (f_hc[7] <= tol) and from dumps
every 50 steps over all pairs and the six walls (brute force); no solve stopped at maxiter; no
lost atom, everything finite; energy bounded by its initial value plus the work of gravity:
KE(n) + PE(n) <= KE(0) + PE(0), PE = sum m g z, to 1e-9 of the energy scale KE(0) + sum m g r
(round-off). Measured and reported, not asserted here (the step sweep asserts it): the largest
step-to-step rise of KE + PE, which Prop. 3 with a constant force makes <= 0 for an exact
projection (|u^{n+1}|^2/2 - |u^n|^2/2 - h g.u^{n+1} <= -|u^{n+1} - u^n|^2/2, mass norm, any h).
Run 2: the same deck with the skin the documentation asks for (skin >= 4 x timestep x largest
speed), using the largest speed run 1 reached (struck light spheres) and a margin of 1.5: must
run to the end without ERROR, with the same feasibility checks.
Serial and 2 ranks.
With `--friction MU` (ours, taken out before the common arguments): the same scene with
Coulomb friction MU on every contact at the fix's default tolerance with friction (1e-2: no
`tol` in the deck, so the default is what is tested): every check above holds with tol 1e-2 (the energy check counts the
translational kinetic energy, which the spins' energy only adds to)."""

import sys
from pathlib import Path

import numpy as np

import lammps_run as lr
import stability_common as sc

R_LIGHT, R_HEAVY = 0.1, 1.0
LX, LY = 4.4, 2.2
G = 1.0
H = 0.01
TOL = 1e-4
NSTEPS = 600
TOP = 7.0
SKIN_LARGE = 1.0
SKIN_RULE_MARGIN = 1.5
E_TOL = 1e-9


def scene():
    rng = np.random.default_rng(7)
    a = 0.218
    pts = []
    for k in range(3):
        for i in range(20):
            for j in range(10):
                pts.append((0.12 + i * a, 0.12 + j * a, 0.1 + 1e-3 + k * a))
    light = np.array(pts)
    light[:, :2] += rng.uniform(-0.005, 0.005, (len(light), 2))
    zh = light[:, 2].max() + R_LIGHT + 1.5 + R_HEAVY
    heavy = np.array([(1.1, 1.1, zh), (3.3, 1.1, zh + 0.4)])
    x = np.vstack([light, heavy])
    radius = np.concatenate([np.full(len(light), R_LIGHT), np.full(len(heavy), R_HEAVY)])
    v = np.zeros_like(x)
    v[len(light):, 2] = -2.0
    return x, v, radius, len(light)


def friction_arg(argv):
    """(MU or None, the other arguments)."""
    if "--friction" not in argv:
        return None, argv
    k = argv.index("--friction")
    return float(argv[k + 1]), argv[:k] + argv[k + 2:]


def test():
    global TOL
    mu, argv = friction_arg(sys.argv[1:])
    args = lr.test_args(__doc__, argv)
    # with friction the deck gives no tol: the fix's default with friction applies
    tol_kw = "tol %g" % TOL
    if mu is not None:
        TOL = 1e-2
        tol_kw = "friction %g" % mu
    x, v, radius, nlight = scene()
    n = len(x)
    box = ((0.0, LX), (0.0, LY), (0.0, TOP))
    data = Path(args.workdir) / "data.poly"
    sc.write_data(data, box, radius, 1.0, x, v)
    walls = "wall xplane 0.0 %r wall yplane 0.0 %r wall zplane 0.0 %r" % (LX, LY, TOP)
    wall_list = [(0, 0.0, 1), (0, LX, -1), (1, 0.0, 1), (1, LY, -1), (2, 0.0, 1), (2, TOP, -1)]
    chk = sc.Checks()
    text = sc.deck("data.poly", NSTEPS, H, SKIN_LARGE, "%s %s" % (tol_kw, walls),
                   boundary="f f f", gravity=G, dump_every=50)
    res, th = sc.run(args, text, args.workdir + "/run", data)
    label = "polydisperse (ratio 10 in radius, 1000 in mass, %d bodies%s)" % (
        n, "" if mu is None else ", friction %g, default tol" % mu)
    ov = sc.check_common(th, n, TOL, label, check=chk)

    ke, pe = th["c_ke"], th["c_P[5]"]
    e = ke + pe
    frames = lr.read_dump(res.path("dump.atoms"))
    m = frames[0].columns["mass"]
    chk(abs(m.max() / m.min() - 1000.0) < 1e-9, "%s: mass ratio %.6g" % (label, m.max() / m.min()))
    scale = float(ke[0] + G * (m * frames[0].columns["radius"]).sum())
    excess = float((e - e[0]).max()) / scale
    chk(excess <= E_TOL, "%s: KE + PE never above its initial value (KE(t) <= KE(0) + work of "
        "gravity): largest excess %.3g of the energy scale %.4g <= %g" % (label, excess, scale, E_TOL))
    rise = sc.energy_rises(e, scale)    # measured, reported (asserted by the step sweep)
    worst_pair, worst_wall = sc.dump_overlaps(frames, n, wall_list, chk, label)
    chk(worst_pair <= TOL * (1 + 1e-9), "%s: all-pairs overlap from %d dumps %.3g <= tol"
        % (label, len(frames), worst_pair))
    chk(worst_wall <= TOL * (1 + 1e-9), "%s: wall overlap from dumps %.3g <= tol" % (label, worst_wall))
    zheavy = sc.positions(frames[-1])[nlight:, 2]
    sc.report("polydisperse%s_np%d" % ("" if mu is None else "_friction", args.np), bodies=n, steps=NSTEPS, overlap=ov,
              overlap_dumps=worst_pair, wall_overlap=worst_wall, e_excess=excess, e_rise=rise,
              e_end_over_scale=float((e[-1] - e[0]) / scale),
              heavy_z_end="%.3g-%.3g" % (zheavy.min(), zheavy.max()),
              max_iter=int(th["f_hc[1]"].max()), mean_iter=float(th["f_hc[1]"].mean()),
              max_solves=int(th["f_hc[9]"].max()), vmax=float(th["c_vmax"].max()),
              seconds=round(res.seconds, 1))

    # The documented skin rule (doc/fix_hardcontact.md: skin >= 4 x timestep x largest speed),
    # with the largest speed this very scene reaches (measured above) and a margin of 1.5.
    vmax = float(th["c_vmax"].max())
    skin = SKIN_RULE_MARGIN * 4.0 * H * vmax
    text = sc.deck("data.poly", NSTEPS, H, skin, "%s %s" % (tol_kw, walls),
                   boundary="f f f", gravity=G)
    label = "polydisperse, skin %.4g = %.1f x 4 h v_max (v_max %.4g)" % (skin, SKIN_RULE_MARGIN, vmax)
    try:
        res2, th2 = sc.run(args, text, args.workdir + "/skin_rule", data)
    except lr.LammpsRunError as e:
        chk(False, "%s: the run follows the documented skin rule and must not stop: %s" % (
            label, " | ".join(l for l in str(e).splitlines() if l.strip().startswith("ERROR"))[:600]))
    else:
        chk(True, "%s: ran %d steps without ERROR" % (label, NSTEPS))
        ov2 = sc.check_common(th2, n, TOL, label, check=chk)
        sc.report("polydisperse%s_skin_rule_np%d" % ("" if mu is None else "_friction", args.np), skin=skin, overlap=ov2,
                  seconds=round(res2.seconds, 1))
    chk.finish()


if __name__ == "__main__":
    lr.main(test)
