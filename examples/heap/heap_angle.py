#!/usr/bin/env python3
"""Angle of repose of a conical heap from a LAMMPS dump (columns id x y z radius, heap axis
the z axis through x = y = 0, floor at z = 0):

    heap_angle.py DUMP [--floor Z] [--json]

The surface height h(rho) is the second-highest sphere top z + r (one sphere in flight does
not make a peak) in rings of width 1 (in units of the largest diameter) around the axis, above the floor Z (default 0; in.heap's rough floor of fixed
spheres has its top at 1); the angle is the slope of a straight-line fit of h(rho) over
the rings whose height lies between 20 % (and at least 1.5 diameters: spheres that rolled away
form a monolayer around the foot) and 80 % of the peak - the flank of the cone, away from the
rounded top and the foot (none if fewer than three rings qualify). Also the cone angle: the
angle of the cone of the heap's peak height H holding the heap's volume V (the spheres'
volume over a packing fraction of 0.6): tan = sqrt(pi H^3 / (3 V)), robust for small heaps. Prints the angles (degrees), the peak height, the radius of the
foot and the fit's rms residual; --json prints the same as one JSON object."""

import argparse
import json
import math
import sys

import numpy as np


def last_frame(path):
    frame, cols, rows, n = None, None, [], None
    with open(path) as f:
        lines = f.readlines()
    k = 0
    while k < len(lines):
        if lines[k].startswith("ITEM: NUMBER OF ATOMS"):
            n = int(lines[k + 1])
        if lines[k].startswith("ITEM: ATOMS"):
            cols = lines[k].split()[2:]
            rows = [ln.split() for ln in lines[k + 1:k + 1 + n]]
            frame = (cols, rows)
            k += n
        k += 1
    if frame is None:
        sys.exit("no frame in %s" % path)
    cols, rows = frame
    data = np.array(rows, dtype=float)
    return {c: data[:, i] for i, c in enumerate(cols)}


def ring_heights(rho, top, d):
    """Surface height per ring of width d: the second-highest sphere top in the ring (one
    sphere still in flight, or perched on the heap, does not make a peak)."""
    nbin = int(rho.max() / d) + 1
    best = np.zeros((nbin, 2))
    for b, t in zip((rho / d).astype(int), top):
        if t > best[b, 0]:
            best[b] = (t, best[b, 0])
        elif t > best[b, 1]:
            best[b, 1] = t
    return np.where(best[:, 1] > 0.0, best[:, 1], best[:, 0])


def heap_angle(path, floor=0.0):
    a = last_frame(path)
    x, y, z, r = a["x"], a["y"], a["z"] - floor, a["radius"]
    d = 2.0 * float(r.max())
    rho = np.hypot(x, y)
    top = z + r
    h = ring_heights(rho, top, d)
    nbin = len(h)
    centres = (np.arange(nbin) + 0.5) * d
    peak = float(h.max())
    ipeak = int(np.argmax(h))
    flank = [b for b in range(ipeak, nbin) if max(0.2 * peak, 1.5 * d) <= h[b] <= 0.8 * peak]
    foot_rings = [b for b in range(ipeak, nbin) if h[b] < 1.5 * d]
    foot = float(centres[foot_rings[0]]) if foot_rings else float(centres[-1])
    volume = float(np.sum(4.0 / 3.0 * math.pi * r ** 3)) / 0.6
    cone = math.degrees(math.atan(math.sqrt(math.pi * peak ** 3 / (3.0 * volume))))
    out = {"angle": None, "cone_angle": cone, "peak": peak, "foot": foot, "rms": 0.0,
           "rings": len(flank), "atoms": len(x)}
    if len(flank) >= 3:
        slope, icpt = np.polyfit(centres[flank], h[flank], 1)
        out["rms"] = float(np.sqrt(np.mean((slope * centres[flank] + icpt - h[flank]) ** 2)))
        out["angle"] = math.degrees(math.atan(max(0.0, -slope)))
    return out


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("dump")
    p.add_argument("--floor", type=float, default=0.0)
    p.add_argument("--json", action="store_true")
    a = p.parse_args()
    res = heap_angle(a.dump, a.floor)
    if a.json:
        print(json.dumps(res))
    else:
        flank = "%.2f deg" % res["angle"] if res["angle"] is not None else "-"
        print("flank %s (fit rms %.3f, %d rings)  cone %.2f deg  peak %.3f  foot %.2f  %d atoms"
              % (flank, res["rms"], res["rings"], res["cone_angle"], res["peak"], res["foot"],
                 res["atoms"]))


if __name__ == "__main__":
    main()
