#!/usr/bin/env python3
"""Packing measures of examples/disc_packing from the last dump frame of each run:

    packing.py [--png OUT.png] DIR[:LABEL] ...

prints, per run: discs, bed height, area fraction in the bulk (from 3 large diameters above
the floor to 3 below the top of the bed), active contacts N_c (pairs + floor: force > 0 in
contacts.dump for fix hardcontact, overlapping pairs for the soft twin) against 2 N (the
isostatic count of frictionless discs: 2 degrees of freedom each), discs without contact,
and the mean contact number z = 2 N_c / N; draws the area fraction in slabs 2 large diameters
thick against height (all runs, one plot).
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
import granular as g  # noqa: E402

WIDTH = 0.08
D_LARGE = 0.0028


def last_local(path):
    frames = []
    lines = open(path).read().splitlines()
    i = 0
    while i < len(lines):
        if lines[i].startswith("ITEM: TIMESTEP"):
            n = int(lines[i + 3])
            ncol = len(lines[i + 8].split()) - 2
            frames.append(np.array([l.split() for l in lines[i + 9:i + 9 + n]], dtype=float).reshape(n, ncol))
            i += 9 + n
        else:
            i += 1
    return frames[-1]


def measure(run_dir):
    step, cols, box = g.read_dump(os.path.join(run_dir, "packing.dump"))[-1]
    n = len(cols["id"])
    top = g.bed_height(cols, 0.99)
    phi = g.area_fraction(cols, 0.0, WIDTH, 3 * D_LARGE, top - 3 * D_LARGE)
    rows = last_local(os.path.join(run_dir, "contacts.dump"))
    if "f_hc[1]" in cols:        # hard: ids i, j (0 = wall), force
        active = rows[rows[:, 2] > 0.0]
        ids = np.concatenate([active[:, 0], active[:, 1][active[:, 1] > 0]])
        nc = len(active)
    else:                        # soft: pair rows (ids, force, distance) + floor overlaps
        pos = np.column_stack([cols["x"], cols["y"]])
        index = {int(i): k for k, i in enumerate(cols["id"])}
        a = np.array([index[int(i)] for i in rows[:, 0]])
        b = np.array([index[int(j)] for j in rows[:, 1]])
        touching = rows[:, 3] < cols["radius"][a] + cols["radius"][b]
        floor = cols["y"] < cols["radius"]
        nc = int(touching.sum() + floor.sum())
        ids = np.concatenate([rows[touching, 0], rows[touching, 1], cols["id"][floor]])
    loaded = len(np.unique(ids))
    return dict(n=n, top=top, phi=phi, nc=nc, loose=n - loaded, z=2.0 * nc / n, cols=cols)


def profile(cols, top, dy=2 * D_LARGE):
    edges = np.arange(0.0, top, dy)
    mids = 0.5 * (edges[:-1] + edges[1:])
    return mids, [g.area_fraction(cols, 0.0, WIDTH, a, b) for a, b in zip(edges[:-1], edges[1:])]


def main():
    args = sys.argv[1:]
    png = None
    if args[:1] == ["--png"]:
        png, args = args[1], args[2:]
    runs = []
    print("%-22s %6s %12s %12s %8s %8s %7s %6s" % ("run", "discs", "height (m)", "phi (bulk)", "N_c", "2 N", "no cont", "z"))
    for a in args:
        d, _, label = a.partition(":")
        m = measure(d)
        label = label or os.path.basename(os.path.normpath(d))
        runs.append((label, m))
        print("%-22s %6d %12.5g %12.4f %8d %8d %7d %6.3f" % (label, m["n"], m["top"], m["phi"], m["nc"],
                                                            2 * m["n"], m["loose"], m["z"]))
    if png:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(4.2, 4.2))
        for label, m in runs:
            y, p = profile(m["cols"], m["top"])
            ax.plot(p, np.array(y) * 1e3, "o-", ms=3, label="%s: bulk %.3f" % (label, m["phi"]))
        ax.axvline(0.84, color="0.5", ls=":", label="random close packing 0.84")
        ax.set_xlabel("area fraction (slabs 5.6 mm)")
        ax.set_ylabel("height (mm)")
        ax.set_xlim(0.5, 0.95)
        ax.legend(fontsize=8, loc="lower left")
        fig.tight_layout()
        fig.savefig(png, dpi=90)
        print("wrote", png)


if __name__ == "__main__":
    main()
