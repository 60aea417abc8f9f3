#!/usr/bin/env python3
"""Frictional hard cases (issue 36): a heap at rest. examples/heap/in.heap pours 400 spheres
(d 0.9-1.1, density 1) through its inlet onto its rough floor (900 fixed spheres of d = 1, top
at z = 1) under g = 1 with friction 0.5 (spheres, floor and walls), no rolling resistance, at
the fix's default tolerance with friction (tol 1e-2, passed as in.heap does), its default solver
and cone, h = 0.02. Pouring ends near t = 16 and the heap comes to rest by t = 45-50 (the 2-rank
run pours the same spheres and builds another heap by round-off, the later to settle: at t = 60
one of its spheres still spun at omega r = 2.8e-4, 0.7 of the bound below); the rest stretch is
t = 80 to 100 (T = 20), with thermo at every step and dumps at both ends.

What tol allows at rest: a solve stops with velocity errors up to tol x the row scale / h, and
at rest the row scale is min(size, h V) with V = g h (core/residual.h, doc/stability.md (A)):
tol g h = 2e-4 per contact. As in test_stab_friction.py's heavy case, every sphere's speed and
spin r stay at most 2 tol g h (a contact's slip sums the two), so the kinetic energy
(translation 1/2 m v^2, rotation 1/5 m (omega r)^2) at most 0.7 (2 tol g h)^2 sum m, and a
sphere creeps over T by at most tol g h T = 4e-3 d. The heap's height H (heap_angle.py's peak,
a sphere's top) moves by at most as much, and its cone angle a (tan a = sqrt(pi H^3 / (3 V)),
the volume V fixed) by at most da = 3/2 sin a cos a dH / H <= 3/4 tol g h T / H radians.

Asserted over the whole run (pour, settling, rest) at every step: no solve at maxiter
(f_hc[6] = 0), the largest overlap <= tol (f_hc[7]). Over the rest stretch, at every step: no
lost atom, every thermo value finite, the kinetic energy (c_ke + c_rot) within the bound above,
and not growing (its mean over the second half at most twice that over the first). From the
dumps at t = 80 and t = 100: every speed and spin r <= 2 tol g h; every sphere's move <= tol g h T;
the heap's height and cone angle (examples/heap/heap_angle.py) changed by at most the bounds
above; no pair, floor sphere or wall overlapping by more than tol (brute force); and the heap is
one (all 401 grains, peak >= 2.5 d, cone angle 10-30 degrees), not a spread monolayer.
Measured and printed (MEASURED): iterations per step at rest, kinetic energy, creep, speeds,
height, cone and flank angles (flank: reported only, its fit rings move with the peak)."""

import math
import os
import sys

import numpy as np

import lammps_run as lr
import stability_common as sc

EX = os.path.join(os.environ.get("HARDCONTACT_SOURCE_DIR", "."), "examples", "heap")
sys.path.insert(0, EX)
import heap_angle  # noqa: E402

NPOUR, MU, G, H = 400, 0.5, 1.0, 0.02
TOL = 1e-2    # the fix's default with friction
T_SETTLE, T_REST = 80.0, 20.0    # the rest stretch: T_SETTLE to T_SETTLE + T_REST
FLOOR_TOP, N_FLOOR = 1.0, 900    # in.heap's rough floor: 30 x 30 spheres of d = 1 at z = 0.5
BOX = 15.0    # in.heap's side walls at +-15


def frame_file(dump, step, out):
    """Write the frame of `step` of a text dump to its own file (heap_angle reads a file's last
    frame)."""
    frames = open(dump).read().split("ITEM: TIMESTEP\n")
    text = [f for f in frames if f.split("\n", 1)[0].strip() == str(step)]
    lr.check(len(text) == 1, "heap.dump holds step %d" % step)
    with open(out, "w") as f:
        f.write("ITEM: TIMESTEP\n" + text[0])
    return out


def floor_overlap(x, radius):
    """Largest overlap with in.heap's floor spheres (centres (i + 1/2, j + 1/2, 1/2), r 1/2)
    relative to r_i + 1/2: the 3 x 3 floor spheres around each grain."""
    worst = 0.0
    for di in (-1.0, 0.0, 1.0):
        for dj in (-1.0, 0.0, 1.0):
            cx = np.clip(np.floor(x[:, 0]) + 0.5 + di, -BOX + 0.5, BOX - 0.5)
            cy = np.clip(np.floor(x[:, 1]) + 0.5 + dj, -BOX + 0.5, BOX - 0.5)
            d = np.sqrt((x[:, 0] - cx) ** 2 + (x[:, 1] - cy) ** 2 + (x[:, 2] - 0.5) ** 2)
            size = radius + 0.5
            worst = max(worst, float(((size - d) / size).max()))
    return worst


def test():
    args = lr.test_args(__doc__)
    checks = sc.Checks()
    label = "heap"
    wd = lr.fresh_workdir("%s/%s" % (args.workdir, label))
    rest_steps = int(round(T_REST / H))
    first, last = int(round(T_SETTLE / H)), int(round((T_SETTLE + T_REST) / H))
    res = lr.run_deck(args.lmp, os.path.join(EX, "in.heap"), args.np, wd, timeout=args.timeout,
                      variables={"npour": NPOUR, "mu": MU, "mur": 0.0, "tol": TOL, "h": H,
                                 "tend": T_SETTLE + T_REST, "thermo_every": 1,
                                 "dump_every": rest_steps})
    lr.check(not res.errors, "%s: no ERROR (%s)" % (label, "; ".join(res.errors)))
    th = res.thermo[-1]
    lr.check(int(th["Step"][-1]) == last, "%s: the run reached step %d" % (label, last))
    n = NPOUR + 1    # and in.heap's one sphere in a corner
    steps = th["Step"].astype(int)

    # the whole run, every step: feasibility and convergence (f_hc[6] counts since the start)
    ov_all = float(th["f_hc[7]"].max())
    checks(ov_all <= TOL, "%s: largest overlap over the whole run %.3g (step %d) <= tol %g"
           % (label, ov_all, int(steps[int(np.argmax(th["f_hc[7]"]))]), TOL))
    rest = steps >= first
    th_rest = {k: v[rest] for k, v in th.items()}
    sc.check_common(th_rest, N_FLOOR + n, TOL, label + " at rest", check=checks)

    # the rest stretch's kinetic energy: within what tol allows, not growing
    atoms = {f.timestep: f for f in lr.read_dump(wd / "heap.dump")}
    lr.check(first in atoms and last in atoms,
             "%s: dumps at steps %d and %d" % (label, first, last))
    fa, fb = atoms[first], atoms[last]
    radius = fa.columns["radius"].astype(float)
    mass = 4.0 / 3.0 * math.pi * radius ** 3
    checks(len(radius) == n and len(fb.columns["id"]) == n and
           np.array_equal(fa.columns["id"], fb.columns["id"]),
           "%s: all %d grains in both dumps" % (label, n))
    slip = TOL * G * H    # what a solve's stopping test allows per contact at rest
    ke = th_rest["c_ke"] + th_rest["c_rot"]
    ke_bound = 0.7 * (2.0 * slip) ** 2 * float(mass.sum())
    checks(float(ke.max()) <= ke_bound, "%s: kinetic energy per sphere at rest %.3g (largest, "
           "step %d) <= %.3g, speeds and spins r of 2 tol g h" % (label, float(ke.max()) / n,
           int(th_rest["Step"][int(np.argmax(ke))]), ke_bound / n))
    half = len(ke) // 2
    growth = float(ke[half:].mean()) / max(float(ke[:half].mean()), 1e-300)
    checks(growth <= 2.0, "%s: kinetic energy not growing at rest (mean over the second half "
           "%.3g x that over the first, <= 2)" % (label, growth))

    # the dumps: speeds, spins, creep, overlaps
    speed = max(float(np.abs(sc.velocities(fr)).max()) for fr in (fa, fb))
    spin = max(float((np.abs(np.column_stack([fr.columns["omegax"], fr.columns["omegay"],
                                               fr.columns["omegaz"]])).max(axis=1) *
                      fr.columns["radius"]).max()) for fr in (fa, fb))
    checks(speed <= 2.0 * slip and spin <= 2.0 * slip, "%s: every sphere at rest at both ends "
           "(|v| %.2g, |omega| r %.2g; bound 2 tol g h = %.2g)" % (label, speed, spin, 2.0 * slip))
    move = np.abs(sc.positions(fb) - sc.positions(fa)).max(axis=1)
    creep_bound = slip * T_REST
    worst = int(np.argmax(move))
    checks(float(move.max()) <= creep_bound, "%s: no sphere moves more than tol g h T = %.2g d "
           "over the %g time units at rest (largest %.2g d, id %d at z %.2f)"
           % (label, creep_bound, T_REST, float(move.max()), int(fa.columns["id"][worst]),
              float(sc.positions(fa)[worst, 2])))
    walls = [(0, -BOX, 1), (0, BOX, -1), (1, -BOX, 1), (1, BOX, -1)]
    pair = max(sc.pair_overlap(sc.positions(fr), radius)[0] for fr in (fa, fb))
    floor = max(floor_overlap(sc.positions(fr), radius) for fr in (fa, fb))
    wall = max(sc.wall_overlap(sc.positions(fr), radius, walls) for fr in (fa, fb))
    checks(max(pair, floor, wall) <= TOL, "%s: no pair, floor sphere or wall overlapping by more "
           "than tol in the dumps at rest (pairs %.2g, floor %.2g, walls %.2g)"
           % (label, pair, floor, wall))

    # the heap's shape: height and cone angle
    ha = heap_angle.heap_angle(frame_file(wd / "heap.dump", first, wd / "heap_start.dump"),
                               floor=FLOOR_TOP)
    hb = heap_angle.heap_angle(frame_file(wd / "heap.dump", last, wd / "heap_end.dump"),
                               floor=FLOOR_TOP)
    checks(ha["atoms"] == n and ha["peak"] >= 2.5 and 10.0 <= ha["cone_angle"] <= 30.0,
           "%s: a heap (%d grains, peak %.2f d >= 2.5 d, cone angle %.1f deg in 10-30)"
           % (label, ha["atoms"], ha["peak"], ha["cone_angle"]))
    dpeak = abs(hb["peak"] - ha["peak"])
    checks(dpeak <= creep_bound, "%s: the heap's height unchanged at rest (%.4f -> %.4f d, "
           "change %.2g <= tol g h T = %.2g)" % (label, ha["peak"], hb["peak"], dpeak, creep_bound))
    dcone = abs(hb["cone_angle"] - ha["cone_angle"])
    cone_bound = math.degrees(0.75 * creep_bound / ha["peak"])
    checks(dcone <= cone_bound, "%s: the cone angle unchanged at rest (%.4f -> %.4f deg, change "
           "%.2g <= 3/4 tol g h T / H = %.2g deg)" % (label, ha["cone_angle"], hb["cone_angle"],
                                                      dcone, cone_bound))

    it = th_rest["f_hc[1]"]
    flank = [fr["angle"] if fr["angle"] is not None else float("nan") for fr in (ha, hb)]
    print("%s: %d ranks, %.1f s wall time (not asserted)" % (label, args.np, res.seconds))
    sc.report(label, iterations_rest_mean=float(it.mean()), iterations_rest_max=int(it.max()),
              iterations_max=int(th["f_hc[1]"].max()), ke_rest_max=float(ke.max()) / n,
              ke_growth=growth, speed_rest=speed, spin_rest=spin, creep=float(move.max()),
              overlap=ov_all, overlap_dumps=max(pair, floor, wall), peak=ha["peak"],
              peak_change=dpeak, cone_angle=ha["cone_angle"], cone_change=dcone,
              flank_start=flank[0], flank_end=flank[1])
    checks.finish()


if __name__ == "__main__":
    lr.main(test)
