#!/usr/bin/env python3
"""Runout of a collapsed granular column from two LAMMPS dumps (columns id x y z radius; back
wall at x = 0, floor top at z = --floor):

    collapse_runout.py COLUMN_DUMP DEPOSIT_DUMP [--floor Z] [--json]

COLUMN_DUMP is the column at release (in.collapse's collapse0.dump), DEPOSIT_DUMP the deposit
(collapse1.dump). L0 is the column's width (the largest x + r at release: the gate), H0 its
height (the largest z + r at release above the floor), a = H0 / L0 the aspect ratio.
L_inf is the front of the deposit: the spheres sorted by x, the deposit ends at the first gap
of more than 2 largest diameters between consecutive centres (spheres that rolled off alone,
ahead of a gap, are not the deposit: they are counted as strays). H_inf is the deposit's
height at the back wall (the largest z + r of the spheres within one diameter of it).
Prints a, the runout (L_inf - L0) / L0, H_inf / L0, L_inf, H_inf and the strays; --json
prints the same as one JSON object. The literature's runout laws for quasi-2D columns
(Lube et al. 2005: 1.2 a for a < 1.8, 1.9 a^(2/3) above; Lajeunesse et al. 2005: 1.84 a for
a < 3) are printed beside it for reference: they hold within tens of per cent, set by the
grains' friction and the channel."""

import argparse
import json
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
import hctools as hc  # noqa: E402


def frame(path):
    """The last frame of a dump as {column: array}, rows in id order (hctools.read_dump)."""
    frames = hc.read_dump(path)
    if not frames:
        sys.exit("collapse_runout: no frame in %s" % path)
    return frames[-1].columns


def grains(path):
    """The grains (type 1: not the floor's spheres) of a dump's last frame, in id order."""
    f = frame(path)
    return {k: v[f["type"] == 1] for k, v in f.items()} if "type" in f else f


def runout(column_dump, deposit_dump, floor=1.05):
    c0, c1 = grains(column_dump), grains(deposit_dump)
    dmax = 2.0 * float(np.max(c0["radius"]))
    L0 = float(np.max(c0["x"] + c0["radius"]))
    H0 = float(np.max(c0["z"] + c0["radius"])) - floor
    x, r = c1["x"], c1["radius"]
    order = np.argsort(x)
    xs = x[order]
    gaps = np.nonzero(np.diff(xs) > 2.0 * dmax)[0]
    last = gaps[0] if len(gaps) else len(xs) - 1
    L_inf = float(xs[last] + r[order][last])
    near = x < dmax
    H_inf = float(np.max(c1["z"][near] + r[near])) - floor if near.any() else 0.0
    a = H0 / L0
    return {"a": a, "runout": (L_inf - L0) / L0, "H_inf_over_L0": H_inf / L0, "L0": L0, "H0": H0,
            "L_inf": L_inf, "H_inf": H_inf, "strays": int(len(xs) - 1 - last),
            "lube2005": 1.2 * a if a < 1.8 else 1.9 * a ** (2.0 / 3.0),
            "lajeunesse2005": 1.84 * a}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("column_dump")
    ap.add_argument("deposit_dump")
    ap.add_argument("--floor", type=float, default=1.05,
                    help="top of the floor (in.collapse's rough floor: 1.05)")
    ap.add_argument("--json", action="store_true")
    args = ap.parse_args()
    res = runout(args.column_dump, args.deposit_dump, args.floor)
    if args.json:
        print(json.dumps(res))
    else:
        print("a %.3f  runout (L_inf - L0) / L0 %.3f  H_inf / L0 %.3f  (L_inf %.2f, H_inf %.2f, "
              "L0 %.2f, H0 %.2f, %d strays; Lube 2005 %.2f, Lajeunesse 2005 %.2f)"
              % (res["a"], res["runout"], res["H_inf_over_L0"], res["L_inf"], res["H_inf"],
                 res["L0"], res["H0"], res["strays"], res["lube2005"], res["lajeunesse2005"]))


if __name__ == "__main__":
    main()
