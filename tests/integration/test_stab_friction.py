#!/usr/bin/env python3
"""Frictional hard cases (issue 36): a crystal bed whose friction has been mobilised, then at
rest. 144 spheres (d = 1, density 1) in four FCC (100) layers, periodic in x and y, on a floor
region `plane` under g = 1; friction 0.8 between spheres, 0.3 on the floor (the floor's own
`friction`), the fix's default tolerance with friction (1e-2) and default solver, h = 0.02.

--case conveyor (a wall-driven rigid bed): the bed starts at rest and at t = 1 the floor starts
  sliding in its own plane at V = 1 (`region ... move v_xf`). Every floor contact slides, so
  the bed takes the floor's friction mu_w M g and its momentum grows as
  P_x = mu_w M g (t - 1) until it reaches M V at t = 1 + V / (mu_w g) = 4.33; then it moves with
  the floor.
--case slide (a bed sliding to rest): the bed starts at V = 1 on the fixed floor; it stops at
  t = V / (mu_w g) = 3.33 with P_x = M (V - mu_w g t).
  The fix's default with friction is `speed contact` (the slip conditions measured against
  the contact points' fastest motion, the gap conditions against the approach:
  core/residual.h, contact_speed_scale): while the bed slides its floor contacts' direction
  is solved to tol of the slide speed; its inner contacts stick, and their slip stays held by
  the gap's scale through the shift, so the bed keeps its contacts. The option's first form
  (one scale from the slides for every condition) failed the slide's checks: the bed opened
  its inner contacts while sliding (500-555 pushing at rest against 620-630) and crept
  2.2e-3 d at rest.
--case slide_speed_approach: the slide under `speed approach` (every condition against the
  approach, the default before 2026-12-07), held to the same checks.
--case heavy (a mass ratio of 1000 on a frictional bed): the bed at rest on the fixed floor
  and, in a hollow of its top layer, one sphere of the same size and 1000 x the density; it
  must rest there, the bed under it held by friction. At tol 1e-2 the solves leave velocity
  errors up to tol x the row scale / h = tol g h per row (core/residual.h), and under the heavy
  sphere the bed creeps at that order: the rest checks of this case are that bound (every
  sphere's speed and spin r at most 4 tol g h - a contact point's slip sums two spheres'
  motions, and each sphere's sums the errors of its contacts on either side - and its move
  over the last 10 time units at most 2 tol g h T), not the others' 1e-3 V. Measured: speeds
  and spins 1.9-2.2e-4 (2026-12-06) and 3.7-4.0e-4 (2026-12-07, the same code but for the
  round-off of apgd's scaling), moves 1.5-1.7e-3 d: the creep's path is chaotic, its size is
  the tolerance's. Iterations at rest are measured, not bounded (50-55 per step with either
  Coulomb cone, 8 with `cone convex`, 113 with tol 1e-4, measured 2026-12-06).

Asserted at every step: no lost atom, no solve at maxiter, the largest overlap <= tol
(f_hc[7]); the exact momentum balance sum m dv = h (sum of the floor rows' forces, normal and
tangential, from the local dump) - h M g z; while the floor contacts slide, P_x within 1 % of
M V of the analytic line. From the last 10 time units (the bed at rest in the floor's frame):
the kinetic energy of the motion relative to the floor below 1e-6 m g d per sphere, every
sphere within 1e-3 V of the floor's velocity and every spin below 1e-3 V / r, no sphere moving
more than 1e-3 d relative to the floor, all pairs (from the dumps) overlapping by at most tol.
Measured and printed (MEASURED): iterations per step at rest. A bed whose friction holds
tangential forces near the cones' edges is where apgd took 500-2400 iterations per step (and
left the bed agitated at tol 1e-2); the hybrid default takes a handful: asserted at most 20
per step on average at rest."""

import math
import sys

import numpy as np

import lammps_run as lr
import stability_common as sc

N_SIDE, LAYERS, R = 6, 4, 0.5
MU_PAIR, MU_FLOOR, V, G, H = 0.8, 0.3, 1.0, 1.0, 0.02
T_START, T_END, T_REST = 1.0, 20.0, 10.0
HEAVY = 1000.0    # the heavy case's density ratio
TOL = 1e-2    # the fix's default with friction


def bed():
    """Periodic FCC (100) layers: every layer 6 x 6, odd layers in the hollows."""
    d = 2.0 * R
    side = N_SIDE * d
    pts = []
    for k in range(LAYERS):
        off = R if k % 2 == 0 else 2.0 * R
        z = R + k * math.sqrt(2.0) * R
        pts += [((off + i * d) % side, (off + j * d) % side, z)
                for i in range(N_SIDE) for j in range(N_SIDE)]
    return np.array(pts), side


def scene(case, data, keywords="", dumps=True):
    """Writes the bed's data file (at rest, or at V for the slide) and returns (deck text, atoms,
    box side, floor speed at the end). keywords go first on the fix line (solver, tol);
    dumps: the atoms, spins and local rows the checks read. Also used by
    bench/studies/friction_hybrid/beds.py."""
    x, side = bed()
    density = np.ones(len(x))
    if case == "heavy":    # on the top layer (odd: offset 2R), in the hollow at (R, R)
        top = float(x[:, 2].max())
        x = np.vstack([x, [R, R, top + math.sqrt(2.0) * R]])
        density = np.append(density, HEAVY)
    n = len(x)
    v = np.zeros_like(x)
    if case == "slide":
        v[:, 0] = V
    sc.write_data(str(data), ((0.0, side), (0.0, side), (-1.0, 12.0)), np.full(n, R), density,
                  x, v)
    xf = ("%r*(time-%r)*(time>%r)" % (V, T_START, T_START)) if case == "conveyor" else "0.0"
    forces = ("variable        xf equal %s\n"
              "region          floor plane 0 0 0 0 0 1 side in move v_xf NULL NULL" % xf)
    local = ("\ndump            l all local 1 dump.local " +
             " ".join("f_hc[%d]" % k for k in range(1, 12)) +
             "\ndump_modify     l format float %.16g"
             "\ndump            w all custom 250 dump.spin id omegax omegay omegaz"
             "\ndump_modify     w format float %.16g sort id")
    nsteps = int(round(T_END / H))
    text = sc.deck(data.name, nsteps, H, 0.3,
                   keywords="%s friction %r wall region floor friction %r"
                   % (keywords, MU_PAIR, MU_FLOOR),
                   boundary="p p f", gravity=G, dump_every=250 if dumps else 0,
                   extra_forces=forces, extra_dumps=local if dumps else "")
    return text, n, side, (V if case == "conveyor" else 0.0)


def run_case(args, label, checks):
    # slide_speed_approach: the slide under `speed approach`, held to the slide's checks
    case, keywords = ("slide", "speed approach") if label == "slide_speed_approach" else (label, "")
    within_tol = label == "heavy"
    wd = lr.fresh_workdir("%s/%s" % (args.workdir, label))
    data = wd.parent / ("bed_%s.data" % case)
    text, n, side, floor_speed = scene(case, data, keywords)
    res, th = sc.run(args, text, wd, str(data))
    sc.check_common(th, n, TOL, label, check=checks)

    mass = 4.0 / 3.0 * math.pi * R ** 3
    M = (n + (HEAVY - 1.0 if case == "heavy" else 0.0)) * mass
    steps = th["Step"].astype(int)
    t = steps * H
    P = np.column_stack([th["c_P[1]"], th["c_P[2]"], th["c_P[3]"]])

    # the exact momentum balance with the floor rows' forces (on the atoms: -(F_n n + F_t))
    frames = {f.timestep: f for f in lr.read_dump_local(wd / "dump.local")}
    worst, worst_step = 0.0, 0
    for k in range(1, len(steps)):
        fr = frames.get(int(steps[k]))
        F = np.zeros(3)
        if fr is not None and len(fr.columns.get("f_hc[1]", [])):
            c = fr.columns
            wall = c["f_hc[7]"].astype(float) > 0
            nrm = np.column_stack([c["f_hc[4]"], c["f_hc[5]"], c["f_hc[6]"]]).astype(float)
            ft = np.column_stack([c["f_hc[8]"], c["f_hc[9]"], c["f_hc[10]"]]).astype(float)
            F = -(c["f_hc[3]"].astype(float)[wall, None] * nrm[wall] + ft[wall]).sum(axis=0)
        dP = P[k] - P[k - 1]
        expect = H * (F - np.array([0.0, 0.0, M * G]))
        e = float(np.abs(dP - expect).max()) / (M * G * H)
        if e > worst:
            worst, worst_step = e, int(steps[k])
    checks(worst < 1e-9, "%s: every step sum m dv = h (floor forces - weight), normal and "
           "tangential (%.2g of the weight impulse, step %d)" % (label, worst, worst_step))

    # the sliding phase against Coulomb's law on the floor
    a = MU_FLOOR * G
    t_stop = V / a
    if case == "slide":
        line = np.where(t < t_stop, M * (V - a * t), 0.0)
        window = t < t_stop - 0.2
    else:
        line = np.clip(M * a * (t - T_START), 0.0, M * V)
        window = (t > T_START + 0.2) & (t < T_START + t_stop - 0.2)
    dev = float(np.abs(P[window, 0] - line[window]).max()) / (M * V) if case != "heavy" else 0.0
    if case != "heavy":
        checks(dev <= 1e-2, "%s: while the floor contacts slide, P_x follows the floor's "
               "friction mu_w M g to %.2g of M V" % (label, dev))

    # at rest in the floor's frame over the last T_REST
    rest = t >= T_END - T_REST
    # the kinetic energy relative to the floor: sum m |v - V_floor|^2 / 2
    ke_rel = th["c_ke"] - P[:, 0] * floor_speed + 0.5 * M * floor_speed ** 2
    worst_ke = float(ke_rel[rest].max()) / (n * mass * G * 2 * R)
    # the heavy case: speeds and moves within what tol allows (the docstring)
    speed_bound = 4.0 * TOL * G * H if within_tol else 1e-3 * V
    move_bound = 2.0 * TOL * G * H * T_REST if within_tol else 1e-3 * 2 * R
    if case != "heavy":
        checks(worst_ke <= 1e-6, "%s: at rest in the floor's frame over the last %g time units "
               "(kinetic energy relative to the floor %.2g m g d per sphere)"
               % (label, T_REST, worst_ke))
    atoms = {f.timestep: f for f in lr.read_dump(wd / "dump.atoms")}
    spins = {f.timestep: f for f in lr.read_dump(wd / "dump.spin")}
    first = min(s for s in atoms if s * H >= T_END - T_REST)
    last = max(atoms)
    fa, fb = atoms[first], atoms[last]
    dv = float(np.abs(sc.velocities(fb) - np.array([floor_speed, 0.0, 0.0])).max())
    w = spins[last].columns
    spin = float(np.abs(np.column_stack([w["omegax"], w["omegay"], w["omegaz"]])).max()) * R
    checks(dv <= speed_bound and spin <= speed_bound, "%s: every sphere moves with the floor "
           "(|v - V_floor| <= %.2g, |omega| r <= %.2g; bound %.2g)" % (label, dv, spin, speed_bound))
    shift = floor_speed * (last - first) * H
    disp = sc.positions(fb) - sc.positions(fa)
    disp[:, 0] -= shift
    disp[:, :2] -= side * np.round(disp[:, :2] / side)    # periodic images
    creep = float(np.abs(disp).max())
    checks(creep <= move_bound, "%s: no creep relative to the floor over the last %g time "
           "units beyond %.2g d (largest move %.2g d)" % (label, T_REST, move_bound, creep))
    worst_pair = 0.0
    for fr in (fa, fb):
        pos = sc.positions(fr)
        # periodic in x, y: the box and its 8 neighbouring images, pairs with the box's spheres
        pos[:, :2] = np.mod(pos[:, :2], side)
        images = np.vstack([pos + np.array([sx, sy, 0.0]) for sx in (-side, 0.0, side)
                            for sy in (-side, 0.0, side)])
        d = np.sqrt(((pos[:, None, :] - images[None, :, :]) ** 2).sum(axis=2))
        d[d == 0.0] = np.inf    # a sphere with itself
        worst_pair = max(worst_pair, float(((2 * R - d) / (2 * R)).max()))
    checks(worst_pair <= TOL, "%s: no pair overlaps by more than tol in the dumps at rest "
           "(%.2g)" % (label, worst_pair))
    it = th["f_hc[1]"][rest]
    checks(case == "heavy" or float(it.mean()) <= 20.0, "%s: a handful of iterations per step at rest (mean %.1f, "
           "largest %d)" % (label, float(it.mean()), int(it.max())))
    sc.report(label, iterations_rest_mean=float(it.mean()), iterations_rest_max=int(it.max()),
              iterations_max=int(th["f_hc[1]"].max()), momentum_balance=worst,
              slide_line=dev, ke_rel_rest=worst_ke, dv_rest=dv, spin_rest=spin, creep=creep,
              overlap=float(th["f_hc[7]"].max()), overlap_dumps=worst_pair)


def test():
    argv = sys.argv[1:]
    case = "conveyor"
    if "--case" in argv:
        at = argv.index("--case")
        case = argv[at + 1]
        del argv[at:at + 2]
    args = lr.test_args(__doc__, argv)
    checks = sc.Checks()
    run_case(args, case, checks)
    checks.finish()


if __name__ == "__main__":
    lr.main(test)
