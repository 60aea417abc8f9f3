#!/usr/bin/env python3
"""The developers' report of the solver's communication (HARDCONTACT_COMM_TIMES,
src/lammps/fix_hardcontact.cpp, read by bench/perf): 125 spheres fall onto a floor in a walled
box (cg, the default without friction), in two `run` commands, serially and under mpirun.
  * Without the variable the log holds no report; with it, exactly one line per `run` (rank 0
    writes it, whatever the rank count), which names the rank count.
  * The counts are those of the solver's synchronisation points: every cg iteration forwards
    the velocities of its direction once and reduces twice (the product's sums, the move's
    stopping test), so a run's forwards and reductions are at least its iterations and twice
    them (f_hc[1] summed over its steps), and at most a few per iteration (setup, projected
    steps, the step's own checks).
  * Seconds are >= 0 and the largest rank's are >= the mean.
  * The two runs' counts are their own (the second run's are not the sum of both)."""

import re

import numpy as np

import lammps_run as lr
import physics_common as pc

STEPS = (60, 40)
R = 0.5

DECK = lr.preamble() + """
processors      * * 1
read_data       data.spheres
pair_style      none
neighbor        0.3 bin
fix             grav all gravity 1.0 vector 0 0 -1
fix             hc all hardcontact tol 1e-6 wall xplane 0.0 6.0 wall yplane 0.0 6.0 wall zplane 0.0 NULL
timestep        0.02
thermo_style    custom step f_hc[1]
thermo          1
run             {n1}
run             {n2}
"""

LINE = re.compile(r"Fix hardcontact communication in this run, per process: (\d+) forwards "
                  r"(\S+) s \(mean, max (\S+) s\), (\d+) reductions (\S+) s \(mean, max (\S+) s\), "
                  r"(\d+) processes")


def scene():
    g = np.arange(5) * 1.1 + 0.8
    x = np.array([[a, b, c - 0.28] for c in g for b in g for a in g])    # 0.02 above the floor
    rng = np.random.default_rng(3)
    x[:, :2] += rng.uniform(-0.03, 0.03, size=(len(x), 2))
    return x


def run(args):
    x = scene()
    box = ((0.0, 6.0), (0.0, 6.0), (0.0, 8.0))
    deck = DECK.format(n1=STEPS[0], n2=STEPS[1])
    reports = {}
    for switch in (False, True):
        wd = args.workdir + ("/on" if switch else "/off")
        lr.fresh_workdir(wd)
        pc.write_sphere_data(wd + "/data.spheres", box, R, 1.0, x)
        res = lr.run_deck(args.lmp, deck, args.np, wd, timeout=args.timeout,
                          env={"HARDCONTACT_COMM_TIMES": "1"} if switch else None)
        lr.check(len(res.thermo) == 2, "two thermo blocks (two runs)")
        reports[switch] = (res, LINE.findall(res.log))
    lr.check(reports[False][1] == [], "no report without HARDCONTACT_COMM_TIMES")
    res, lines = reports[True]
    lr.check(len(lines) == 2, "one report per run, whatever the rank count (%d lines)" % len(lines))
    for k, line in enumerate(lines):
        fw, fs, fmax, red, rs, rmax, nprocs = line
        fw, red, nprocs = int(fw), int(red), int(nprocs)
        fs, fmax, rs, rmax = (float(v) for v in (fs, fmax, rs, rmax))
        # the first row of a block is the state before the run (no solve)
        it = int(res.thermo[k]["f_hc[1]"][1:].sum())
        steps = STEPS[k]
        lr.check(nprocs == args.np, "run %d: the report names %d processes (%d)" % (k + 1, args.np, nprocs))
        lr.check(it >= steps, "run %d: the solver iterated (%d iterations in %d steps)" % (k + 1, it, steps))
        lr.check(it <= fw <= 3 * it + 10 * steps,
                 "run %d: forwards %d within [iterations, 3 x iterations + 10 per step] (%d iterations)"
                 % (k + 1, fw, it))
        lr.check(2 * it <= red <= 4 * it + 10 * steps,
                 "run %d: reductions %d within [2 x iterations, 4 x iterations + 10 per step] (%d iterations)"
                 % (k + 1, red, it))
        lr.check(0.0 <= fs <= fmax * (1 + 1e-3) + 1e-4 and 0.0 <= rs <= rmax * (1 + 1e-3) + 1e-4,
                 "run %d: seconds >= 0, the mean within the largest rank's (%g %g %g %g)"
                 % (k + 1, fs, fmax, rs, rmax))
    # counted from the start of each run: the second's would otherwise be the first's plus at
    # least one per iteration of its own
    fw1, fw2 = int(lines[0][0]), int(lines[1][0])
    it2 = int(res.thermo[1]["f_hc[1]"][1:].sum())
    lr.check(fw2 < fw1 + it2, "the second run counts its own calls (%d forwards after %d, %d iterations)"
             % (fw2, fw1, it2))


if __name__ == "__main__":
    lr.main(lambda: run(lr.test_args(__doc__)))
