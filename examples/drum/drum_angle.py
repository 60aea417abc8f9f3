#!/usr/bin/env python3
"""Dynamic angle of repose of the bed in a rotating drum (examples/drum/in.drum, in.drum.soft),
from its dump (columns id x y z radius; drum axis the y axis through x = z = 0, periodic along
y, gravity -z, rotation about +y, so the bottom moves towards -x and the bed climbs the -x
side) and its log (the deck's "drum: R .. L .. omega .. tset .. dt .." line):

    drum_angle.py DUMP LOG [--from T] [--json] [--series]

For each frame the spheres are seen along the axis (the xz plane) and cut into columns of width
1 (the mean diameter) across the middle of the drum, |x| <= R/2; the surface height of a column
is the k-th highest sphere top z + r in it, k = half the spheres a layer of the column holds
(L/2 for a column of width 1: the top layer, not a sphere bouncing on it); a straight line
z = a + b x fitted to these heights gives the angle atan(-b) (positive when the surface rises
towards -x, the side the drum drags the bed up). The dynamic angle is the mean over the frames
at times >= T (default: the last revolution of the run) with its standard deviation. Also the
centre of mass x of the bed (negative: dragged up the -x side). --series prints one line per
frame (time, angle, x_cm)."""

import argparse
import json
import math
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
import hctools as hc  # noqa: E402


def read_frames(path):
    """Every frame of a LAMMPS text dump: a list of (step, {column: array})."""
    frames = [(fr.timestep, fr.columns) for fr in hc.read_dump(path, sort_by_id=False)]
    if not frames:
        sys.exit("no frame in %s" % path)
    return frames


def read_scene(log):
    """R, L, omega, tset, dt from the deck's 'drum: ...' line in its log."""
    with open(log) as f:
        for line in f:
            m = re.match(r"drum: R (\S+) L (\S+) omega (\S+) tset (\S+) dt (\S+)", line)
            if m:
                return dict(zip(("R", "L", "omega", "tset", "dt"), map(float, m.groups())))
    sys.exit("no 'drum: R .. L .. omega .. tset .. dt ..' line in %s" % log)


def surface_angle(atoms, R, L, width=1.0):
    """(angle in degrees, slope, intercept, column centres, heights) of one frame."""
    x, top = atoms["x"], atoms["z"] + atoms["radius"]
    k = max(1, int(round(0.5 * L * width)))
    edges = np.arange(-0.5 * R, 0.5 * R + 1e-9, width)
    centres, heights = [], []
    for lo, hi in zip(edges[:-1], edges[1:]):
        tops = np.sort(top[(x >= lo) & (x < hi)])[::-1]
        if len(tops) >= k:
            centres.append(0.5 * (lo + hi))
            heights.append(tops[k - 1])
    centres, heights = np.array(centres), np.array(heights)
    if len(centres) < 3:
        return None, None, None, centres, heights
    b, a = np.polyfit(centres, heights, 1)
    return math.degrees(math.atan(-b)), b, a, centres, heights


def drum_angle(dump, log, t_from=None):
    sc = read_scene(log)
    frames = read_frames(dump)
    t_end = frames[-1][0] * sc["dt"]
    if t_from is None:
        t_from = max(sc["tset"], t_end - 2.0 * math.pi / sc["omega"])
    series = []
    for step, atoms in frames:
        angle = surface_angle(atoms, sc["R"], sc["L"])[0]
        series.append((step * sc["dt"], angle, float(np.mean(atoms["x"]))))
    steady = [a for t, a, _ in series if t >= t_from - 1e-9 and a is not None]
    xcm = [xc for t, _, xc in series if t >= t_from - 1e-9]
    return {"angle": float(np.mean(steady)) if steady else None,
            "angle_std": float(np.std(steady)) if steady else None,
            "frames": len(steady), "t_from": t_from, "t_end": t_end,
            "revolutions_averaged": (t_end - t_from) * sc["omega"] / (2.0 * math.pi),
            "xcm": float(np.mean(xcm)) if xcm else None, "atoms": len(frames[-1][1]["x"]),
            "series": series}


def main():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("dump")
    p.add_argument("log")
    p.add_argument("--from", dest="t_from", type=float, default=None)
    p.add_argument("--json", action="store_true")
    p.add_argument("--series", action="store_true")
    a = p.parse_args()
    res = drum_angle(a.dump, a.log, a.t_from)
    if a.series:
        for t, angle, xc in res["series"]:
            print("%9.2f %8s %8.3f" % (t, "-" if angle is None else "%.2f" % angle, xc))
    if a.json:
        print(json.dumps({k: v for k, v in res.items() if k != "series"}))
    elif res["angle"] is None:
        print("no angle: fewer than three surface columns")
    else:
        print("dynamic angle %.2f +- %.2f deg (%d frames, t %.1f-%.1f, %.2f revolutions)  "
              "x_cm %.3f  %d atoms" % (res["angle"], res["angle_std"], res["frames"],
                                       res["t_from"], res["t_end"],
                                       res["revolutions_averaged"], res["xcm"], res["atoms"]))


if __name__ == "__main__":
    main()
