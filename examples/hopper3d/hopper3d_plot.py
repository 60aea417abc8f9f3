#!/usr/bin/env python3
"""Cut-away side views of examples/hopper3d runs: the beads within 2 mm of the plane y = 0
(and the frozen floor, black), coloured by their speed, with the cone's outline.

    hopper3d_plot.py OUT.png TIME LABEL=DUMP [LABEL=DUMP ...]   (TIME: s after the outlet opens,
                                                                 a multiple of 0.05 s)
"""
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import PatchCollection  # noqa: E402
from matplotlib.patches import Circle  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
import granular as g  # noqa: E402
import make_data  # noqa: E402

DUMP_DT = 0.05


def frame_at(path, t):
    """The dump frame `t` seconds after the first one (run.sh's discharge runs: the first frame
    is the opening, frames every DUMP_DT, the decks' default dump_dt)."""
    frames = g.read_dump(path)
    return frames[min(len(frames) - 1, int(round(t / DUMP_DT)))].columns


def main():
    out, t, runs = sys.argv[1], float(sys.argv[2]), [a.split("=", 1) for a in sys.argv[3:]]
    fig, axes = plt.subplots(1, len(runs), figsize=(3.3 * len(runs), 3.3))
    axes = np.atleast_1d(axes)
    for ax, (label, path) in zip(axes, runs):
        c = frame_at(path, t)
        s = np.abs(c["y"]) < 0.002
        beads = s & (c["type"] == 1)
        speed = np.sqrt(c["vx"] ** 2 + c["vy"] ** 2 + c["vz"] ** 2)
        pc = PatchCollection([Circle((x * 1e3, z * 1e3), r * 1e3) for x, z, r in
                              zip(c["x"][beads], c["z"][beads], c["radius"][beads])],
                             cmap="viridis", linewidths=0)
        pc.set_array(speed[beads])
        pc.set_clim(0, 0.3)
        ax.add_collection(pc)
        fl = s & (c["type"] == 2)
        ax.add_collection(PatchCollection([Circle((x * 1e3, z * 1e3), r * 1e3) for x, z, r in
                                           zip(c["x"][fl], c["z"][fl], c["radius"][fl])],
                                          color="black", linewidths=0))
        z = np.linspace(-4e-3, 30e-3, 2)
        for sgn in (-1, 1):
            ax.plot(sgn * make_data.cone_radius(z) * 1e3, z * 1e3, "k-", lw=1)
        ax.set_aspect("equal")
        ax.set_xlim(-30, 30)
        ax.set_ylim(-4, 28)
        ax.set_title("%s, t = %.2f s" % (label, t), fontsize=9)
        ax.set_xlabel("x (mm)")
    axes[0].set_ylabel("z (mm)")
    fig.colorbar(pc, ax=axes.tolist(), shrink=0.8, label="speed (m/s)")
    fig.savefig(out, dpi=80, bbox_inches="tight")


if __name__ == "__main__":
    main()
