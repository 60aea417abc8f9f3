#!/usr/bin/env python3
"""Pictures of the heap runs: the surface profiles h(rho) with their fitted flanks, and a side
view (a slice |y| < 1 of each final heap, coloured by height).

    heap_plot.py OUT.png LABEL=DUMP [LABEL=DUMP ...]
"""

import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import heap_angle  # noqa: E402

FLOOR = 1.0    # in.heap's rough floor: fixed spheres of diameter 1 on z = 0


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    out, runs = sys.argv[1], [a.split("=", 1) for a in sys.argv[2:]]
    fig, axes = plt.subplots(len(runs) + 1, 1, figsize=(7, 2.2 * (len(runs) + 1)))
    prof = axes[0]
    for k, (label, path) in enumerate(runs):
        a = heap_angle.last_frame(path)
        res = heap_angle.heap_angle(path, FLOOR)
        x, y, z, r = a["x"], a["y"], a["z"] - FLOOR, a["radius"]
        d = 2.0 * float(r.max())
        rho = np.hypot(x, y)
        h = heap_angle.ring_heights(rho, z + r, d)
        nbin = len(h)
        flank = "%.1f" % res["angle"] if res["angle"] is not None else "-"
        prof.plot((np.arange(nbin) + 0.5) * d, h, "o-", ms=3,
                  label="%s: flank %s deg, cone %.1f deg" % (label, flank, res["cone_angle"]))
        ax = axes[k + 1]
        s = np.abs(y) < 1.0
        ax.scatter(x[s], z[s], s=12, c=z[s], cmap="viridis", vmin=0, vmax=max(1.0, res["peak"]))
        ax.set_aspect("equal")
        ax.set_xlim(-15, 15)
        ax.set_ylim(0, max(4.0, res["peak"] + 1))
        ax.set_title("%s: flank %s deg, cone %.1f deg, %d spheres"
                     % (label, flank, res["cone_angle"], res["atoms"]), fontsize=9)
    prof.set_xlabel("distance from the axis")
    prof.set_ylabel("height above the floor")
    prof.set_xlim(0, 15)
    prof.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    main()
