#!/usr/bin/env python3
"""Side views (x, z) of collapsed columns: per run the column at release (grey) and the
deposit (coloured by the distance each sphere travelled), from in.collapse's dumps.

    collapse_plot.py OUT.png LABEL=RUNDIR [LABEL=RUNDIR ...]
"""

import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import PatchCollection  # noqa: E402
from matplotlib.patches import Circle  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import collapse_runout  # noqa: E402


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    out, runs = sys.argv[1], [a.split("=", 1) for a in sys.argv[2:]]
    fig, axes = plt.subplots(len(runs), 1, figsize=(9, 3.2 * len(runs)), squeeze=False,
                             layout="constrained")
    for ax, (label, d) in zip(axes[:, 0], runs):
        c0 = collapse_runout.grains(os.path.join(d, "collapse0.dump"))
        c1 = collapse_runout.grains(os.path.join(d, "collapse1.dump"))
        moved = np.hypot(c1["x"] - c0["x"], c1["z"] - c0["z"])
        ax.add_collection(PatchCollection([Circle((x, z), r) for x, z, r in
                                           zip(c0["x"], c0["z"], c0["radius"])],
                                          facecolor="0.85", edgecolor="none"))
        deposit = PatchCollection([Circle((x, z), r) for x, z, r in
                                   zip(c1["x"], c1["z"], c1["radius"])],
                                  cmap="viridis", edgecolor="none")
        deposit.set_array(moved)
        ax.add_collection(deposit)
        res = collapse_runout.runout(os.path.join(d, "collapse0.dump"),
                                     os.path.join(d, "collapse1.dump"))
        ax.axvline(res["L_inf"], color="r", lw=0.8)
        ax.set_title("%s: a = %.2f, runout (L_inf - L0) / L0 = %.2f, H_inf / L0 = %.2f"
                     % (label, res["a"], res["runout"], res["H_inf_over_L0"]), fontsize=9)
        ax.set_xlim(0, max(res["L_inf"] + 3, 20))
        ax.set_ylim(0, res["H0"] + 3)
        ax.set_xlabel("x (d)")
        ax.set_ylabel("z (d)")
        fig.colorbar(deposit, ax=ax, label="distance travelled (d)", shrink=0.8)
    fig.savefig(out, dpi=110)
    print("collapse_plot: %s" % out)


if __name__ == "__main__":
    main()
