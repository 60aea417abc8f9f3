#!/usr/bin/env python3
"""examples/liggghts_settle, as shipped (0.5 s of physical time: 500 steps of h = 1 ms with fix
hardcontact, 50 000 steps of 10 us for the Hertz twin), on the LIGGGHTS host: 468 glass beads
(d = 4 and 5 mm) fall from up to 10 cm into a 40 x 40 mm box and settle.

The decks: in.settle and in.settle.soft hold the same scene lines (between '# --- the scene'
and '# ---') and differ in the contact lines only, as a LIGGGHTS user's deck would.
Hard contacts (in.settle), checked:
  * 468 atoms at every step; no overlap beyond the tolerance: f_hc[7] <= 1e-4 at every thermo
    step, and from the dumped positions (%.10g) every pair and every wall within 1e-4 of the
    contact size (measured 1.3e-6);
  * the bed settles: final kinetic energy below 1e-3 of its peak (measured 3e-5); bed height
    (98% of the tops) 24-28 mm (measured 25.85 mm).
Soft twin (in.settle.soft, pair gran model hertz tangential history, fix wall/gran primitive,
fix nve/sphere), checked: runs, its bed height agrees with the hard one within 3% (measured
0.05%), its largest overlap is well above the hard one's (Hertz at 5 MPa: about 1% of the
contact size), and settle.py prints the table and draws the picture."""

import os
import re
import subprocess
import sys

import numpy as np

import lammps_run as lr

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
EX = os.path.join(ROOT, "examples", "liggghts_settle")
TOL = 1e-4


def section(text, start):
    """The lines of a deck between a '# --- <start>' line and the next '# ---' line."""
    m = re.search(r"^# --- %s.*?\n(.*?)^# ---\s*$" % re.escape(start), text, re.S | re.M)
    lr.check(m is not None, "deck has a '# --- %s' section" % start)
    return m.group(1)


def test():
    args = lr.test_args(__doc__)
    lr.check(args.lmp.name == "liggghts", "this test runs on the LIGGGHTS host (--host liggghts)")
    hard_deck = open(os.path.join(EX, "in.settle")).read()
    soft_deck = open(os.path.join(EX, "in.settle.soft")).read()
    lr.check(section(hard_deck, "the scene") == section(soft_deck, "the scene"),
             "in.settle and in.settle.soft hold the same scene lines")
    lr.check("hardcontact" in section(hard_deck, "contacts") and
             "pair_style      gran model hertz tangential history" in section(soft_deck, "contacts"),
             "the decks differ in their contact lines: fix hardcontact / pair gran + wall/gran")

    runs = {}
    for name, deck in (("hard", "in.settle"), ("soft", "in.settle.soft")):
        wd = os.path.join(args.workdir, name)
        lr.fresh_workdir(wd)
        res = lr.run_deck(args.lmp, os.path.join(EX, deck), args.np, wd, timeout=args.timeout)
        lr.check(not res.errors, "%s: no ERROR" % deck)
        runs[name] = res
        print("%s: %.1f s" % (deck, res.seconds))

    th = runs["hard"].thermo[-1]
    lr.check(bool(np.all(th["Atoms"] == 468)), "hard: 468 atoms at every thermo step")
    lr.check(float(th["f_hc[7]"].max()) <= TOL,
             "hard: f_hc[7] <= tol at every thermo step (largest %.3g)" % th["f_hc[7]"].max())

    # the example's own measures (settle.py), as run.sh prints them
    out = subprocess.run(["/usr/bin/python3", os.path.join(EX, "settle.py"),
                          os.path.join(args.workdir, "hard"), os.path.join(args.workdir, "soft"),
                          os.path.join(args.workdir, "settle.png")],
                         capture_output=True, text=True)
    lr.check(out.returncode == 0, "settle.py runs: %s" % out.stderr[-500:])
    print(out.stdout)
    lr.check(os.path.getsize(os.path.join(args.workdir, "settle.png")) > 10000, "settle.png drawn")
    sys.path.insert(0, EX)
    import settle    # noqa: E402
    hard = settle.measure(os.path.join(args.workdir, "hard"))
    soft = settle.measure(os.path.join(args.workdir, "soft"))
    lr.check(hard["overlap_rel"] <= TOL * (1 + 1e-6) + 1e-9,
             "hard: every pair and wall within tol of the contact size (%.3g)" % hard["overlap_rel"])
    lr.check(hard["ke_final"] < 1e-3 * hard["ke_peak"],
             "hard: settled, kinetic energy %.3g of its peak" % (hard["ke_final"] / hard["ke_peak"]))
    lr.check(0.024 <= hard["bed_height"] <= 0.028,
             "hard: bed height %.2f mm in 24-28 mm" % (1e3 * hard["bed_height"]))
    lr.check(soft["atoms"] == 468 and soft["ke_final"] < 1e-2 * soft["ke_peak"],
             "soft twin: 468 beads, settled (kinetic energy %.3g of its peak)"
             % (soft["ke_final"] / soft["ke_peak"]))
    rel = abs(soft["bed_height"] - hard["bed_height"]) / hard["bed_height"]
    lr.check(rel <= 0.03, "soft twin: bed height within 3%% of the hard one (%.2f vs %.2f mm)"
             % (1e3 * soft["bed_height"], 1e3 * hard["bed_height"]))
    lr.check(soft["overlap_rel"] > 100 * max(hard["overlap_rel"], 1e-9) and soft["overlap_rel"] > 1e-3,
             "soft twin overlaps as Hertz contacts do (%.3g of the contact size vs %.3g hard)"
             % (soft["overlap_rel"], hard["overlap_rel"]))


if __name__ == "__main__":
    lr.main(test)
