#!/usr/bin/env python3
"""examples/mixer, shortened (one revolution): a drum with 6 lifters read from an STL file and
rotated by `wall stl mixer.stl rotate v_theta ...` turns 144 spheres whose halves start side by
side; the same drum without lifters is the reference. Checked, for both: every sphere stays,
no sphere's outer point gets farther from the axis than R + tol r (the facets' corners are at R),
the largest overlap stays within tol, no solve stops at maxiter, the two halves mix (Lacey
index above 0.3 after one revolution); and what the lifters do: they carry spheres up out of the
bed (the highest sphere after the drum starts turning is more than 1.5 above the bare drum's),
so that they shower back down."""

import os
import subprocess
import sys

import numpy as np

import lammps_run as lr

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
EX = os.path.join(ROOT, "examples", "mixer")
sys.path.insert(0, EX)
import mixer    # noqa: E402


def test():
    args = lr.test_args(__doc__)
    runs = {}
    L = 3 * 1.12 * 2 ** 0.5
    for lifters in (6, 0):
        wd = os.path.join(args.workdir, "lifters%d" % lifters)
        lr.fresh_workdir(wd)
        subprocess.run([sys.executable, os.path.join(EX, "make_mixer.py"),
                        os.path.join(wd, "mixer.stl"), "7", repr(L), str(lifters), "2.0"],
                       check=True, stdout=subprocess.DEVNULL)
        res = lr.run_deck(args.lmp, os.path.join(EX, "in.mixer"), args.np, wd,
                          timeout=args.timeout, variables={"lifters": lifters, "nrev": 1,
                                                           "dump_dt": 2.5})
        lr.check(not res.errors, "in.mixer with %d lifters: no ERROR" % lifters)
        runs[lifters] = mixer.measure(wd)
    print(mixer.table([("6 lifters", runs[6]), ("no lifters", runs[0])]))
    tol = 1e-2
    highest = {}
    for lifters, m in runs.items():
        atoms = m["atoms"]
        lr.check(atoms.min() == atoms.max() == 144, "%d lifters: all 144 spheres stay" % lifters)
        lr.check(m["rmax"] <= 7.0 + tol * 0.55, "%d lifters: no sphere reaches beyond the drum "
                 "(largest outer radius %.6f <= R + tol r_max)" % (lifters, m["rmax"]))
        lr.check(m["overlap"] <= tol and m["maxiter"] == 0, "%d lifters: overlaps %.3g <= tol, "
                 "solves at maxiter %g" % (lifters, m["overlap"], m["maxiter"]))
        lr.check(m["mix"][-1] > 0.3, "%d lifters: the halves mix (Lacey index %.2f after one "
                 "revolution)" % (lifters, m["mix"][-1]))
        nset = m["loops"][0]["steps"]
        frames = mixer.gr.read_dump(os.path.join(args.workdir, "lifters%d" % lifters, "mixer.dump"))
        highest[lifters] = max(float(c["z"].max()) for step, c, _ in frames if step > nset)
    lr.check(highest[6] > highest[0] + 1.5, "the lifters carry spheres up out of the bed (highest "
             "sphere %.2f against %.2f without lifters)" % (highest[6], highest[0]))


if __name__ == "__main__":
    lr.main(test)
