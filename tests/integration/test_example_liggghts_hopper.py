#!/usr/bin/env python3
"""examples/liggghts_hopper on the LIGGGHTS host, shortened for the test suite (-var ztop 0.065:
about 750 beads in place of 2030; 0.2 s of settling and 0.25 s of discharge in place of 0.3 and
0.6): beads settle in a
conical hopper read from an STL file by `fix mesh/surface` and drain through its 20 mm outlet.

The decks: in.hopper and in.hopper.soft hold the same scene lines (between '# --- the scene' and
'# ---'); the hard one gives the mesh to fix hardcontact as `wall mesh cad`, the soft one to
`fix wall/gran ... mesh`. Checked:
  * both run without ERROR; hard: no bead leaves the hopper other than through its outlet (every
    bead above the outlet plane is inside the cone and the cylinder, within 1e-3 of its radius)
    and the largest bead-bead overlap of the settled bed is within tol of a diameter;
  * both drain: the beads above the outlet fall steadily, and the hard rate is the soft one's
    within 15 % (one 0.15 s window each: measured 968 and 987 here, 1048 and 1053 beads/s on the full
    example);
  * hopper.py prints the table and draws the picture."""

import math
import os
import re
import subprocess
import sys

import numpy as np

import lammps_run as lr

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
EX = os.path.join(ROOT, "examples", "liggghts_hopper")
sys.path.insert(0, EX)
import hopper    # noqa: E402


def section(text, start):
    m = re.search(r"^# --- %s.*?\n(.*?)^# ---\s*$" % re.escape(start), text, re.S | re.M)
    lr.check(m is not None, "deck has a '# --- %s' section" % start)
    return m.group(1)


def inside_hopper(c, slack):
    """Whether every bead centre more than a radius above the outlet (away from its rim) lies at
    least r (less slack r) inside the round cone / cylinder: its 48 flat facets lie inside the
    round surface, so a bead kept r from them is at least r from it."""
    rho = np.hypot(c["x"], c["y"])
    z = c["z"]
    cone = z < 43.30127e-3
    wall = np.where(cone, 0.010 + z * math.tan(math.radians(30.0)), 0.035)
    tilt = np.where(cone, math.cos(math.radians(30.0)), 1.0)    # radial gap -> normal distance
    dist = (wall - rho) * tilt
    away = z > c["radius"]
    return bool(np.all(dist[away] >= c["radius"][away] * (1.0 - slack)))


def test():
    args = lr.test_args(__doc__)
    lr.check(args.lmp.name == "liggghts", "this test runs on the LIGGGHTS host (--host liggghts)")
    decks = {k: open(os.path.join(EX, k)).read() for k in ("in.hopper", "in.hopper.soft")}
    lr.check(section(decks["in.hopper"], "the scene") == section(decks["in.hopper.soft"], "the scene"),
             "in.hopper and in.hopper.soft hold the same scene lines")
    lr.check("wall mesh cad" in decks["in.hopper"] and "meshes cad" in decks["in.hopper.soft"],
             "the hard deck gives fix mesh/surface cad to the fix, the soft one to fix wall/gran")
    runs = {}
    for name, deck in (("hard", "in.hopper"), ("soft", "in.hopper.soft")):
        wd = os.path.join(args.workdir, name)
        lr.fresh_workdir(wd)
        subprocess.run([sys.executable, os.path.join(EX, "make_hopper.py"),
                        os.path.join(wd, "hopper.stl")], check=True, stdout=subprocess.DEVNULL)
        res = lr.run_deck(args.lmp, os.path.join(EX, deck), args.np, wd, timeout=args.timeout,
                          variables={"ztop": 0.065, "tsettle": 0.2, "tdrain": 0.25,
                                     "dump_dt": 0.05})
        lr.check(not res.errors, "%s: no ERROR" % deck)
        runs[name] = hopper.measure(wd)
        print("%s: %.1f s" % (deck, res.seconds))
    hard, soft = runs["hard"], runs["soft"]
    print(hopper.table([("hard", hard), ("soft", soft)]))
    for step, c, _ in hard["frames"]:
        lr.check(inside_hopper(c, 1e-3), "hard: at step %d every bead above the outlet is inside "
                 "the hopper" % step)
    lr.check(hard["overlap"] <= 1e-2 * 0.004, "hard: the settled bed's largest bead-bead overlap "
             "%.3g m is within tol (the friction default, 1e-2) of a diameter, 4e-5 m (frictional "
             "contacts keep up to tol / 10 at rest)" % hard["overlap"])
    lr.check(hard["rate"] > 300 and soft["rate"] > 300, "both drain (%.0f and %.0f beads/s)"
             % (hard["rate"], soft["rate"]))
    lr.check(abs(hard["rate"] / soft["rate"] - 1.0) <= 0.15, "hard and soft discharge rates "
             "agree within 15 %% (%.0f and %.0f beads/s)" % (hard["rate"], soft["rate"]))
    png = os.path.join(args.workdir, "hopper.png")
    hopper.picture(png, [("hard", hard), ("soft", soft)])
    lr.check(os.path.getsize(png) > 10000, "hopper.py draws the picture")


if __name__ == "__main__":
    lr.main(test)
