#!/usr/bin/env python3
"""Restarts with fix hardcontact, two scenes.

Pile: 100 polydisperse spheres (deterministic data file) thrown
down under gravity into a box closed by walls on five sides, 40 steps (a pile forms: over a
hundred active contacts). Serially or under mpirun (--np):

  straight  read_data, run 40
  split     read_data, run 20, write_restart; then a NEW LAMMPS process: read_restart,
            redefine neighbor, fix gravity and fix hardcontact, run 20
  twice     read_data, run 20, run 20 (same process: what any second run does)

Checks: the first 20 steps of the split run are bit-identical to the straight run (same
history); the restarted run starts at step 20 with no initial-overlap warning (the state at a
converged step is feasible to within tol); at step 40 positions agree within tol * size and
velocities within tol * size / h (the solver tolerance: a new run rebuilds the neighbor list
and re-sorts the atoms, so the rows of the contact problem come in another order); and the
restart does not differ from the straight run more than a plain second run does.
Warm start (default): the restart file carries the last multipliers, so the first solve after
read_restart takes as many iterations as in the straight run; a fix redefined under another
ID starts cold and agrees within 100 x tol x size (20 steps of collisions amplify a
tolerance-sized difference; it scales with tol). With --np > 1 the restart file is also
read on one rank (same tolerances).

The pile runs three times: frictionless, with `friction 0.5` (the history then carries the
tangential forces too, and the warm start after read_restart must bring them back), and with
`restitution 0.5 cohesion 0.2`. With friction the default solver sweeps Gauss-Seidel in the
neighbour list's order, which a new run rebuilds: there the restart is held to the run split in
one process (tol), and to the straight run within 100 x tol as the cold start.

Crystal: 216 touching spheres stacked as an FCC crystal slide sideways on a frictionless floor
(periodic in x and y), so that under mpirun atoms cross processor boundaries with their
warm-start multipliers: run 120 vs run 60 + restart + run 60 within tol * size, the restart
file also read on one rank, and the horizontal momentum exact.

Kept overlaps: the hexagonal crystal of the stability suite (120 discs squeezed by gravity
between two walls, tol 1e-6, cg warm) stops a solve with kept overlaps at its budget every few
hundred steps, after which the next steps clear from the start (src/core/kept_overlaps.h).
The restart file carries that back-off and the budget's measure: run 900 vs run 700 +
write_restart + (new process) read_restart + run 200 must stop as often in steps 701-900 (within
one stop) and its costliest step stay within 2 x + 10 of the straight run's. Without them the
restarted run keeps overlaps at once, with a budget of maxiter / 10: measured 8 stops and 1021
iterations in one step, against 1 stop and 50."""

import numpy as np

import lammps_run as lr
import scene_data as sd
import stability_common as stc
import test_stab_crystal as stab_crystal

TOL = 1.0e-4      # the fix's default tol
DT = 0.02
STEPS = 40
HALF = 20

COMMON = """units           lj
atom_style      sphere
boundary        f f f
{read}
pair_style      none
neighbor        1.0 bin
timestep        {dt}
fix             g all gravity 10.0 vector 0 0 -1
fix             1 all hardcontact tol {tol} {extra} wall xplane 0 {w} wall yplane 0 {w} wall zplane 0 NULL
thermo_style    custom step ke f_1[1] f_1[2] f_1[3] f_1[4] f_1[5] f_1[6] f_1[7]
thermo_modify   norm no
thermo          1
dump            d all custom {every} {dump} id x y z vx vy vz
dump_modify     d format float %.17g
"""


def deck(read, dump, body, width, extra=""):
    return COMMON.format(read=read, dt=DT, tol=TOL, w=repr(width), every=HALF, dump=dump,
                         extra=extra) + body


def final_state(path, step):
    frames = lr.read_dump(path)
    fr = [f for f in frames if f.timestep == step]
    lr.check(len(fr) == 1, "%s has a frame at step %d" % (path.name, step))
    c = fr[0].columns
    return (c["id"], np.column_stack([c["x"], c["y"], c["z"]]),
            np.column_stack([c["vx"], c["vy"], c["vz"]]))


CRYSTAL = """units           lj
atom_style      sphere
boundary        p p f
{read}
pair_style      none
neighbor        0.3 bin
timestep        0.02
fix             g all gravity 1.0 vector 0 0 -1
fix             1 all hardcontact wall zplane 0 NULL
thermo_style    custom step ke f_1[1] f_1[3] f_1[4] f_1[6]
thermo_modify   norm no
thermo          10
dump            d all custom {every} {dump} id x y z vx vy vz
dump_modify     d format float %.17g
{body}
"""


def crystal(args):
    """216 touching unit spheres stacked as an FCC crystal (12 contacts each, about 1100 of them
    pushing) on a frictionless floor in a box periodic in x and y, sliding sideways at
    (0.5, 0.2): under mpirun every atom crosses processor boundaries carrying its warm-start
    multipliers. run 120 vs run 60 + write_restart + (new process) read_restart + run 60, and
    the restart file read on 1 rank: within tol * size; the horizontal momentum is exact."""
    steps, half = 120, 60
    wd = lr.fresh_workdir("%s/crystal" % args.workdir)
    scene = sd.square_stack(n_side=6, layers=6, spacing=1.0, lift=0.001)
    vel = np.zeros_like(scene.pos)
    vel[:, 0], vel[:, 1] = 0.5, 0.2
    scene = scene._replace(vel=vel)
    sd.write_data(wd / "crystal.data", scene, "restart test: sliding FCC crystal")

    def run(name, read, body, np_=args.np):
        return lr.run_deck(args.lmp, CRYSTAL.format(read=read, every=half, dump=name + ".dump",
                                                    body=body),
                           np_, wd, deck_name="in." + name, log_name="log." + name,
                           timeout=args.timeout)

    straight = run("straight", "read_data crystal.data", "run %d" % steps)
    run("split1", "read_data crystal.data", "run %d\nwrite_restart half.restart" % half)
    split2 = run("split2", "read_restart half.restart", "run %d" % half)
    th = straight.thermo[0]
    lr.check(th["f_1[4]"][-1] > 1000, "crystal: %d of its %d contacts push at the end"
             % (th["f_1[4]"][-1], th["f_1[3]"][-1]))
    _, xs, vs = final_state(wd / "straight.dump", steps)
    _, xr, vr = final_state(wd / "split2.dump", steps)
    dx, dv = float(np.abs(xs - xr).max()), float(np.abs(vs - vr).max())
    lr.check(dx <= TOL and dv <= TOL / 0.02, "crystal: restart on %d ranks within tol * size of "
             "the straight run (dx %.3g, dv %.3g)" % (args.np, dx, dv))
    m = sd.mass(scene)
    for name, v in (("straight", vs), ("restarted", vr)):
        px = (m * v[:, 0]).sum()
        lr.check(abs(px - (m * 0.5).sum()) < 1e-11 * (m * 0.5).sum(),
                 "crystal: x momentum of the %s run exact (%.17g)" % (name, px))
    it_s = th["f_1[1]"][list(th["Step"]).index(half + 10)]
    it_r = split2.thermo[0]["f_1[1]"][list(split2.thermo[0]["Step"]).index(half + 10)]
    print("crystal: %d active contacts at the end; iterations at step %d: %d straight, %d after "
          "the restart" % (th["f_1[4]"][-1], half + 10, it_s, it_r))
    if args.np > 1:
        run("split2_np1", "read_restart half.restart", "run %d" % half, np_=1)
        _, x1, v1 = final_state(wd / "split2_np1.dump", steps)
        dx1, dv1 = float(np.abs(xs - x1).max()), float(np.abs(vs - v1).max())
        lr.check(dx1 <= TOL and dv1 <= TOL / 0.02, "crystal: restart file of %d ranks read on 1 "
                 "rank, within tol * size (dx %.3g, dv %.3g)" % (args.np, dx1, dv1))


KEPT = """units           lj
atom_style      sphere
dimension       2
boundary        f f p
atom_modify     map array
comm_modify     vel yes
{read}
pair_style      none
neighbor        0.3 bin
neigh_modify    delay 0 every 1 check yes
fix             grav all gravity 1.0 vector 0 -1 0
fix             1 all hardcontact tol 1e-06 solver cg warmstart yes {walls}
fix             e2d all enforce2d
timestep        0.01
thermo_style    custom step ke f_1[1] f_1[12]
thermo_modify   norm no
thermo          1
{body}
"""


def kept_overlaps(args):
    """The back-off and the budget of kept overlaps come back from the restart file (module
    docstring): the restarted run stops as the unsplit one does, at as little cost."""
    steps, half = 900, 700
    wd = lr.fresh_workdir("%s/kept_overlaps" % args.workdir)
    x, _, box, walls, _, _ = stab_crystal.geometry(2)    # the stability suite's 2d crystal
    stc.write_data(wd / "crystal.data", box, stab_crystal.R, 1.0, x)

    def run(name, read, body):
        return lr.run_deck(args.lmp, KEPT.format(read=read, walls=walls, body=body), args.np, wd,
                           deck_name="in." + name, log_name="log." + name, timeout=args.timeout)

    straight = run("straight", "read_data crystal.data", "run %d" % steps).thermo[0]
    run("split1", "read_data crystal.data", "run %d\nwrite_restart half.restart" % half)
    split2 = run("split2", "read_restart half.restart", "run %d" % (steps - half)).thermo[0]

    def window(th):
        """iterations of the steps after `half`, and the solves stopped at their budget there"""
        at = list(th["Step"]).index(half)
        it = [int(v) for v in th["f_1[1]"][at + 1:]]
        return it, int(th["f_1[12]"][-1] - th["f_1[12]"][at])

    it_s, stops_s = window(straight)
    it_r, stops_r = window(split2)
    before = int(straight["f_1[12]"][list(straight["Step"]).index(half)])
    print("kept overlaps: %d stops before step %d; steps %d-%d: straight %d stops, %d iterations "
          "(largest %d); restarted %d stops, %d iterations (largest %d)"
          % (before, half, half + 1, steps, stops_s, sum(it_s), max(it_s), stops_r, sum(it_r),
             max(it_r)))
    lr.check(len(it_r) == len(it_s) == steps - half, "both runs reach step %d" % steps)
    lr.check(before >= 5 and stops_s >= 1, "the scene stops kept solves at their budget: %d "
             "times before step %d, %d after" % (before, half, stops_s))
    lr.check(abs(stops_r - stops_s) <= 1, "after read_restart the kept solves stop as in the "
             "straight run (%d against %d): the back-off came back" % (stops_r, stops_s))
    lr.check(max(it_r) <= 2 * max(it_s) + 10, "the costliest step after read_restart (%d "
             "iterations) within 2 x + 10 of the straight run's (%d): the budget's measure came "
             "back" % (max(it_r), max(it_s)))


def pile(args, label="pile", extra=""):
    scene = sd.pile(n_side=5, layers=4, seed=1)
    n = len(scene.diameter)
    width = scene.box[0, 1]
    wd = lr.fresh_workdir("%s/%s" % (args.workdir, label))

    def scene_deck(read, dump, body, width):
        return deck(read, dump, body, width, extra)

    sd.write_data(wd / "pile.data", scene, "restart test: 100 spheres thrown into a box")

    def run(name, text):
        return lr.run_deck(args.lmp, text, args.np, wd, deck_name="in." + name,
                           log_name="log." + name, timeout=args.timeout)

    straight = run("straight", scene_deck("read_data pile.data", "straight.dump",
                                    "run %d\n" % STEPS, width))
    run("split1", scene_deck("read_data pile.data", "split1.dump",
                       "run %d\nwrite_restart half.restart\n" % HALF, width))
    split2 = run("split2", scene_deck("read_restart half.restart", "split2.dump",
                                "run %d\n" % HALF, width))
    run("twice", scene_deck("read_data pile.data", "twice.dump",
                      "run %d\nrun %d\n" % (HALF, HALF), width))

    print("--- %s (%s)" % (label, extra or "frictionless"))
    th = straight.thermo[0]
    lr.check(th["f_1[4]"][list(th["Step"]).index(HALF)] > 40 and th["f_1[4]"][-1] > 100,
             "the scene is a pile: %d active contacts at step %d, %d at step %d"
             % (th["f_1[4]"][list(th["Step"]).index(HALF)], HALF, th["f_1[4]"][-1], STEPS))
    lr.check(th["f_1[6]"][-1] == 0, "every solve of the straight run converged")

    # the restart file is read back at step 20, into a feasible state
    th2 = split2.thermo[0]
    lr.check(th2["Step"][0] == HALF and th2["Step"][-1] == STEPS,
             "restarted run goes from step %d to %d" % (HALF, STEPS))
    lr.check(not any("overlapping" in w for w in split2.warnings),
             "no initial-overlap warning after read_restart: %s" % split2.warnings)
    lr.check(not split2.errors and not straight.errors, "no ERROR")

    # same history up to the restart: bit-identical
    ids_a, xa, va = final_state(wd / "straight.dump", HALF)
    ids_b, xb, vb = final_state(wd / "split1.dump", HALF)
    lr.check(len(ids_a) == n and np.array_equal(ids_a, ids_b) and np.array_equal(xa, xb)
             and np.array_equal(va, vb),
             "step %d of the split run is bit-identical to the straight run" % HALF)

    # step 40: within the solver tolerance
    size = float(scene.diameter.max())
    ids_s, xs, vs = final_state(wd / "straight.dump", STEPS)
    ids_r, xr, vr = final_state(wd / "split2.dump", STEPS)
    ids_t, xt, vt = final_state(wd / "twice.dump", STEPS)
    lr.check(np.array_equal(ids_s, ids_r) and len(ids_r) == n,
             "all %d atoms in the restarted run's last frame" % n)
    dx_r, dv_r = float(np.abs(xs - xr).max()), float(np.abs(vs - vr).max())
    dx_t, dv_t = float(np.abs(xs - xt).max()), float(np.abs(vs - vt).max())
    print("straight vs restart: max |dx| = %.3g, max |dv| = %.3g" % (dx_r, dv_r))
    print("straight vs run 20 + run 20: max |dx| = %.3g, max |dv| = %.3g" % (dx_t, dv_t))
    if "friction" in extra:
        # With friction the default solver (hybrid) sweeps Gauss-Seidel in the neighbour list's
        # order, and a new run starts with a list rebuilt in another order: a run split in one
        # process already differs from the straight run by tolerance-sized amounts, which 20
        # steps amplify (as for the cold start below). What the restart must reproduce is that
        # split: to the tolerance (it is checked to the bit-level below too); the straight run
        # within the cold start's 100 x tol.
        dx_ref, dv_ref = float(np.abs(xt - xr).max()), float(np.abs(vt - vr).max())
        lr.check(dx_ref <= TOL * size and dv_ref <= TOL * size / DT,
                 "positions and velocities after the restart within tol * size (/ h) of the run "
                 "split in one process (dx %.3g, dv %.3g)" % (dx_ref, dv_ref))
        lr.check(dx_r <= 100 * TOL * size and dv_r <= 100 * TOL * size / DT,
                 "and within 100 x tol * size (/ h) of the straight run (dx %.3g, dv %.3g)"
                 % (dx_r, dv_r))
    else:
        lr.check(dx_r <= TOL * size, "positions after the restart within tol * size = %.3g of "
                 "the straight run (%.3g)" % (TOL * size, dx_r))
        lr.check(dv_r <= TOL * size / DT, "velocities after the restart within tol * size / h = "
                 "%.3g of the straight run (%.3g)" % (TOL * size / DT, dv_r))
    # warm start: the restart file holds the last multipliers of fix 1 (redefined with the same
    # ID), so the first solve after it starts where the unsplit run's does
    it_s = th["f_1[1]"][list(th["Step"]).index(HALF + 1)]
    it_r = th2["f_1[1]"][list(th2["Step"]).index(HALF + 1)]
    lr.check(abs(int(it_s) - int(it_r)) <= 1, "first solve after read_restart: %d iterations, as in "
             "the straight run (%d): the warm-start multipliers came back" % (it_r, it_s))
    # fix redefined under another ID: its restart data is not used (cold start), same result
    other = run("split2_other_id", scene_deck("read_restart half.restart", "split2_other.dump",
                                        "run %d\n" % HALF, width).replace("fix             1 all",
                                                                          "fix             7 all")
                .replace("f_1[", "f_7["))
    _, xo, vo = final_state(wd / "split2_other.dump", STEPS)
    dx_o, dv_o = float(np.abs(xs - xo).max()), float(np.abs(vs - vo).max())
    th3 = other.thermo[0]
    print("fix redefined as 7: first solve %d iterations; max |dx| = %.3g, max |dv| = %.3g"
          % (th3["f_7[1]"][list(th3["Step"]).index(HALF + 1)], dx_o, dv_o))
    # another starting point of the solves: tolerance-sized differences at step 21, which 20
    # steps of collisions amplify (measured: dx = 24, 15, 16 x tol * size for tol = 1e-4, 1e-6,
    # 1e-8: it scales with tol)
    lr.check(dx_o <= 100 * TOL * size and dv_o <= 100 * TOL * size / DT,
             "fix redefined under another ID after read_restart (cold start): within 100 x tol * "
             "size of the straight run (dx %.3g, dv %.3g)" % (dx_o, dv_o))

    if args.np > 1:
        # the same restart file read on one rank
        lr.run_deck(args.lmp, scene_deck("read_restart half.restart", "split2_np1.dump",
                                   "run %d\n" % HALF, width), 1, wd, deck_name="in.split2_np1",
                    log_name="log.split2_np1", timeout=args.timeout)
        ids_1, x1, v1 = final_state(wd / "split2_np1.dump", STEPS)
        dx_1, dv_1 = float(np.abs(xs - x1).max()), float(np.abs(vs - v1).max())
        f = 100.0 if "friction" in extra else 1.0    # Gauss-Seidel order: see above
        lr.check(np.array_equal(ids_s, ids_1) and dx_1 <= f * TOL * size
                 and dv_1 <= f * TOL * size / DT,
                 "the restart file written on %d ranks, read on 1 rank: within %g x tol * size "
                 "(dx %.3g, dv %.3g)" % (args.np, f, dx_1, dv_1))
    lr.check(dx_r <= max(10.0 * dx_t, 1e-12) and dv_r <= max(10.0 * dv_t, 1e-10),
             "the restart differs from the straight run no more than a second run in the same "
             "process does (dx %.3g vs %.3g, dv %.3g vs %.3g)" % (dx_r, dx_t, dv_r, dv_t))


def test():
    args = lr.test_args(__doc__)
    pile(args)
    # friction: the history holds three values per contact (the force as a box-frame vector),
    # the spins are in the restart file
    pile(args, "pile_friction", "friction 0.5")
    # restitution (targets from the start-of-step velocities) and cohesion (pulls on touching
    # rows): no state of their own beyond the multipliers, so a restart continues the same way
    pile(args, "pile_restitution_cohesion", "restitution 0.5 cohesion 0.2")
    crystal(args)
    kept_overlaps(args)


if __name__ == "__main__":
    lr.main(test)
