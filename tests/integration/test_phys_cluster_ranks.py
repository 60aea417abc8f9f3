#!/usr/bin/env python3
"""Agreement between rank counts on the paper's 6.3 cluster impact (the deck and data of
test_phys_cluster.py --case wall: 2029 discs, h = 0.1, tol 1e-6, wall yplane 0.0 NULL).

Every rank count must project onto the same set: the solution of one step is unique
(Lemma 1), and each run stops within the same tolerance, so ONE STEP from the same state must
agree within the tolerance whatever the number of ranks. The test runs the impact serially
(12 steps, dump at %.17g), takes the exact states of steps 2, 4, 6 and 9 (first contact,
compression, piling up), writes each as a data file, and runs ONE step from it with 1, 2 and
4 ranks. Asserted for every state and rank count, atom by atom (by ID):
  |x_np - x_1| <= 10 tol r0 and |v_np - v_1| <= 10 tol r0 / h
(the one-step runs all start cold, from the same data: the iterations must follow the same
path whatever the decomposition, up to the order of sums). The serial one-step run must
reproduce step k + 1 of the serial 12-step run, which started that solve warm (from the
forces of step k), within 20 x those bounds: both stop at tol, but tol bounds each contact's
complementarity violation, not the distance to the exact velocities, which was measured at
38-89 tol r0 in positions on these states (`solver exact` as reference). Each one-step
result has no overlap beyond tol (all pairs, numpy) and no disc behind the wall.

With --full (label soak): also the whole 12-step impact with 2 and 4 ranks from the same data
file, and a serial reference run with the other fast solver (`solver apgd`; the default is
cg), an equally valid answer at the same tol. Full trajectories do NOT stay within 10 tol r0
of each other: the impact is chaotic, a difference of the size of the tolerance in one step
grows 3-10x per step (measured with cg: apgd vs cg 2.8 r0 at step 12; 2 and 4 ranks vs serial
0.16 r0. With apgd the default: tol x 1.01 moved discs by 0.42 r0, 2 and 4 ranks 0.074 r0; a
1% change of tol is no reference for cg, which stops well below tol and then takes the same
iterates: 0 difference for 10 steps). Asserted there: the physics checks of
test_phys_cluster.py on each run; at every step the largest position difference from the
serial run at most 10 x that of the apgd reference (or 10 tol r0); kinetic energy and p_y
within 2% (of their initial values) of the serial run at every step."""

import argparse

import numpy as np

import lammps_run as lr
import physics_common as pc
import test_phys_cluster as tc

STATES = (2, 4, 6, 9)
# tol bounds each contact's complementarity violation, not the distance to the exact velocities:
# on these states a tol-converged apgd step is 38-89 tol r0 (positions) from the exact solver's
# answer (measured once with `solver exact`, 155-390 s per step, too slow to run here). Two
# tol-converged answers from different starts (warm vs cold) may thus differ by ~2 x that.
WARM_FACTOR = 20.0
RANKS = (1, 2, 4)


def state_file(frame, path, box, host):
    c = frame.columns
    # radius as LAMMPS holds it, density as the deck wrote it: the masses come out identical
    pc.write_sphere_data(path, box, c["radius"], 1000.0, pc.positions(frame), pc.velocities(frame),
                         host=host, dimension=2)


def compare(label, fa, fb, pos_tol, vel_tol):
    lr.check(list(fa.columns["id"]) == list(fb.columns["id"]), "%s: same atom IDs" % label)
    dx = float(np.abs(pc.positions(fa) - pc.positions(fb)).max())
    dv = float(np.abs(pc.velocities(fa) - pc.velocities(fb)).max())
    lr.check(dx <= pos_tol and dv <= vel_tol, "%s: positions within %.3g (%.3g), velocities within %.3g (%.3g)"
             % (label, pos_tol, dx, vel_tol, dv))


def test():
    pre = argparse.ArgumentParser(add_help=False)
    pre.add_argument("--full", action="store_true")
    opts, rest = pre.parse_known_args()
    args = lr.test_args(__doc__, rest)
    x0, r, v0, box = tc.wall_setup()
    pos_tol = 10.0 * tc.TOL * tc.R0
    vel_tol = pos_tol / tc.H

    full = {}
    for np_ in ((1,) + ((2, 4) if opts.full else ())):
        wd = "%s/full_np%d" % (args.workdir, np_)
        lr.fresh_workdir(wd)
        pc.write_sphere_data(wd + "/data.cluster", box, r, 1000.0, x0, v0, host=args.lmp,
                             dimension=2)
        res = lr.run_deck(args.lmp, tc.deck("wall"), np_, wd, timeout=args.timeout)
        print("full run, %d rank(s): %.1f s" % (np_, res.seconds))
        if np_ > 1:
            tc.check_wall(args, res, x0, r, v0)
        full[np_] = lr.read_dump(res.path("dump.atoms"))

    for k in STATES:
        one = {}
        for np_ in RANKS:
            wd = "%s/step%d_np%d" % (args.workdir, k, np_)
            lr.fresh_workdir(wd)
            state_file(full[1][k], wd + "/data.cluster", box, args.lmp)
            res = lr.run_deck(args.lmp, tc.deck("wall", n=1), np_, wd, timeout=args.timeout)
            print("one step from step %d, %d rank(s): %.1f s (%s iterations)"
                  % (k, np_, res.seconds, int(res.thermo[0]["f_hc[1]"][-1])))
            f = lr.read_dump(res.path("dump.atoms"))[-1]
            ov, _ = pc.pair_overlaps(pc.positions(f), f.columns["radius"])
            behind = float(((f.columns["radius"] - f.columns["y"]) / f.columns["radius"]).max())
            lr.check(ov <= tc.TOL + 1e-12 and behind <= tc.TOL + 1e-12,
                     "step %d -> %d, %d rank(s): no overlap (%.3g), none behind the wall (%.3g)"
                     % (k, k + 1, np_, ov, behind))
            one[np_] = f
        compare("step %d -> %d: serial one-step run (cold start) vs step %d of the serial run (warm "
                "start)" % (k, k + 1, k + 1), one[1], full[1][k + 1], WARM_FACTOR * pos_tol, WARM_FACTOR * vel_tol)
        for np_ in RANKS[1:]:
            compare("step %d -> %d: %d ranks vs serial" % (k, k + 1, np_), one[np_], one[1], pos_tol, vel_tol)

    if opts.full:
        # the chaos reference: the same serial run solved by apgd, an equally valid answer at the
        # same tol (a run with tol 1% larger was the reference while apgd was the default: cg
        # stops well below tol and takes the same iterates then, 0 difference for 10 steps)
        wd = "%s/full_np1_apgd" % args.workdir
        lr.fresh_workdir(wd)
        pc.write_sphere_data(wd + "/data.cluster", box, r, 1000.0, x0, v0, host=args.lmp,
                             dimension=2)
        res = lr.run_deck(args.lmp, tc.deck("wall").replace("hardcontact tol", "hardcontact solver apgd tol"),
                          1, wd, timeout=args.timeout)
        lr.check("hardcontact solver apgd tol" in res.log, "reference run with solver apgd")
        ref = lr.read_dump(res.path("dump.atoms"))
        chaos = [float(np.abs(pc.positions(a) - pc.positions(b)).max()) for a, b in zip(ref, full[1])]
        print("serial, apgd vs the default solver, largest position difference per step / r0: %s"
              % " ".join("%.2g" % (d / tc.R0) for d in chaos))
        ke0 = pc.kinetic_energy(full[1][0])
        p0 = abs(float(pc.momentum(full[1][0])[1]))
        for np_ in (2, 4):
            diffs = [float(np.abs(pc.positions(a) - pc.positions(b)).max()) for a, b in zip(full[np_], full[1])]
            print("full run, %d ranks vs serial, largest position difference per step / r0: %s"
                  % (np_, " ".join("%.2g" % (d / tc.R0) for d in diffs)))
            worst = max(d / max(c, pos_tol) for d, c in zip(diffs, chaos))
            lr.check(worst <= 10.0, "full run, %d ranks: at every step the positions differ from the serial "
                     "run by at most 10 x what another solver at the same tol causes (or 10 tol r0); worst ratio %.3g"
                     % (np_, worst))
            dke = max(abs(pc.kinetic_energy(a) - pc.kinetic_energy(b)) / ke0 for a, b in zip(full[np_], full[1]))
            dp = max(abs(float(pc.momentum(a)[1] - pc.momentum(b)[1])) / p0 for a, b in zip(full[np_], full[1]))
            lr.check(dke <= 0.02 and dp <= 0.02, "full run, %d ranks: kinetic energy and p_y within 2%% of "
                     "the serial run's at every step (%.3g, %.3g of the initial values)" % (np_, dke, dp))


if __name__ == "__main__":
    lr.main(test)
