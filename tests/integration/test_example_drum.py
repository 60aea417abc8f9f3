#!/usr/bin/env python3
"""examples/drum, shortened: a drum of radius 5 (periodic length 2 fcc cells, 120 spheres) settles
for 3 time units with the drum still, then turns for 16 (0.11 revolution, enough for the bed to
tilt and start flowing) at the example's Froude number 0.01, with fix hardcontact (h = 0.05)
and with the soft-sphere twin. Checks, hard: every sphere stays in the drum (no centre farther
from the axis than R - r + tol r at any output of the rotation, none lost; while the lattice
collapses at the start, spheres falling along the wall may overshoot it by the documented
(v h)^2 / (2 R_c) < 1e-3), the largest overlap relative to the contact size (f_hc[7]) stays
<= tol at every output of the rotation, no solve stopped at maxiter (f_hc[6]; while the bed
rests in the drum's frame between avalanches, 30-47 of the 320 did before the two changes of
doc/performance.md 10.6), the bed is dragged up the rising side (the drum turns about +y, its bottom
moves towards -x: the centre of mass moves towards -x by more than 0.4, where the settled
bed sits within 0.15 of x = 0), and the free surface tilts the right way (drum_angle.py on the
last frames: between 10 and 50 degrees, rising towards -x). Soft twin: runs, loses no sphere,
its bed is dragged the same way. And the two decks differ only in their CONTACT blocks."""

import os
import re
import sys

import numpy as np

import lammps_run as lr

EX = os.path.join(os.environ.get("HARDCONTACT_SOURCE_DIR", "."), "examples", "drum")
sys.path.insert(0, EX)
import drum_angle  # noqa: E402

R, TOL, TSET, TROT, FROUDE = 5.0, 1e-4, 3.0, 16.0, 0.01
SHORT = ["-var", "R", str(R), "-var", "cells", "2", "-var", "zfill", "0.8", "-var", "tset",
         str(TSET), "-var", "froude", str(FROUDE), "-var", "thermo_dt", "0.5",
         "-var", "dump_dt", "1.0", "-var", "tol", str(TOL)]


def nrev():
    omega = (FROUDE / R) ** 0.5
    return "%.6f" % (TROT * omega / (2.0 * np.pi))


def commands(path):
    """The deck's commands outside its CONTACT block: comments dropped, '&' lines joined."""
    text = re.sub(r"&\s*\n", " ", open(path).read())
    out, inside = [], False
    for line in text.splitlines():
        if line.startswith("# CONTACT"):
            inside = not line.startswith("# CONTACT end")
            continue
        cmd = " ".join(line.split("#", 1)[0].split())
        if cmd and not inside:
            out.append(cmd)
    return out


def deck_diff():
    hard = commands(os.path.join(EX, "in.drum"))
    soft = commands(os.path.join(EX, "in.drum.soft"))
    lr.check(hard == soft and len(hard) > 30,
             "in.drum and in.drum.soft differ only in their CONTACT blocks (%d common commands)"
             % len(hard))


def run(args, name, deck, extra):
    wd = lr.fresh_workdir("%s/%s" % (args.workdir, name))
    res = lr.run_deck(args.lmp, os.path.join(EX, deck), args.np, wd, timeout=args.timeout,
                      args=SHORT + ["-var", "nrev", nrev()] + extra)
    settle, rot = res.thermo[-2], res.thermo[-1]
    atoms = np.concatenate([settle["Atoms"], rot["Atoms"]])
    lr.check(atoms.min() == atoms.max() > 100, "%s: all %d spheres stay" % (name, atoms[0]))
    xc0, xc = float(settle["v_xc"][-1]), float(rot["v_xc"][-1])
    lr.check(abs(xc0) <= 0.15 and xc <= xc0 - 0.4,
             "%s: the bed is dragged up the rising side: centre of mass x %.3f settled, %.3f after "
             "turning" % (name, xc0, xc))
    return res, wd, settle, rot


def test():
    args = lr.test_args(__doc__)
    deck_diff()
    res, wd, settle, rot = run(args, "hard", "in.drum", [])
    rmax = float(np.max(rot["c_rmax"]))
    lr.check(rmax <= R + TOL * 0.55 + 1e-9,
             "hard: no sphere leaves the drum while it turns: outermost point %.9f <= R + tol r_max"
             % rmax)
    # the settling collapse: spheres falling along the concave wall at up to ~1.5 overshoot its
    # tangent plane by up to (v h)^2 / (2 (R - r)) = 6e-4 in a step (doc: Region walls, limit 1)
    rset = float(np.max(settle["c_rmax"]))
    lr.check(rset <= R + 1e-3, "hard: settling, outermost point %.6f <= R + (v h)^2 / (2 (R - r)) "
             "(the concave wall linearised at the contact point)" % rset)
    ov = float(np.max(rot["f_hc[7]"]))
    lr.check(ov <= TOL, "hard: largest overlap %.3g of the contact size <= tol while turning" % ov)
    # While the bed turns with the drum, at rest in its frame between avalanches, frictional
    # solves stopped at maxiter (30-47 of 320, at chaotic times) until apgd's backtracking took
    # its test from gradients and frictional contacts kept the overlaps within a tenth of tol
    # (doc/performance.md 10.6): none since, on both hosts.
    f6 = np.asarray(rot["f_hc[6]"])
    stops = float(f6[-1] - f6[0])
    steps = float(rot["Step"][-1] - rot["Step"][0])
    lr.check(stops == 0.0, "hard: no solve of the rotation's %d stopped at maxiter (%d did)"
             % (steps, stops))
    ang = drum_angle.drum_angle(res.path("drum.dump"), res.path("log.lammps"),
                                t_from=TSET + TROT - 3.0)
    lr.check(ang["angle"] is not None and 10.0 <= ang["angle"] <= 50.0,
             "hard: the free surface rises towards -x at %.1f deg (last 3 time units, %d frames; "
             "%.0f iterations per step)" % (ang["angle"] or 0.0, ang["frames"],
                                           float(np.mean(rot["f_hc[1]"]))))
    soft = run(args, "soft", "in.drum.soft", [])[0]
    print("hard: %.1f s, soft: %.1f s" % (res.seconds, soft.seconds))


if __name__ == "__main__":
    lr.main(test)
