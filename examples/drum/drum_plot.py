#!/usr/bin/env python3
"""Pictures of the drum runs: for each run a view along the axis of its last frame (spheres
coloured by speed, the drum's circle, the surface columns and the fitted surface line), and
below the surface angle of every run against the number of revolutions.

    drum_plot.py OUT.png LABEL=DUMP:LOG [LABEL=DUMP:LOG ...]
"""

import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import PatchCollection  # noqa: E402
from matplotlib.patches import Circle  # noqa: E402
import numpy as np  # noqa: E402

import drum_angle  # noqa: E402


def side_view(ax, label, dump, log):
    sc = drum_angle.read_scene(log)
    step, atoms = drum_angle.read_frames(dump)[-1]
    x, z, r = atoms["x"], atoms["z"], atoms["radius"]
    speed = np.sqrt(atoms["vx"] ** 2 + atoms["vy"] ** 2 + atoms["vz"] ** 2)
    order = np.argsort(atoms["y"])    # the nearest (small y) drawn last, on top
    circles = PatchCollection([Circle((x[i], z[i]), r[i]) for i in order], cmap="viridis",
                              edgecolor="k", linewidth=0.2)
    circles.set_array(speed[order] / (sc["omega"] * sc["R"]))
    circles.set_clim(0.0, 4.0)
    ax.add_collection(circles)
    ax.add_patch(Circle((0, 0), sc["R"], fill=False, linewidth=1.5))
    angle, b, a, cx, hz = drum_angle.surface_angle(atoms, sc["R"], sc["L"])
    if angle is not None:
        xs = np.array([-0.6 * sc["R"], 0.6 * sc["R"]])
        ax.plot(cx, hz, "r.", markersize=4)
        ax.plot(xs, a + b * xs, "r-", linewidth=1.2)
    ax.annotate("", xy=(-0.7 * sc["R"], -0.95 * sc["R"]), xytext=(0.7 * sc["R"], -0.95 * sc["R"]),
                arrowprops=dict(arrowstyle="->", color="0.4"))
    ax.set_xlim(-1.05 * sc["R"], 1.05 * sc["R"])
    ax.set_ylim(-1.05 * sc["R"], 1.05 * sc["R"])
    ax.set_aspect("equal")
    ax.set_xticks([])
    ax.set_yticks([])
    ax.set_title("%s, t = %.0f: %.1f deg" % (label, step * sc["dt"], angle if angle else 0.0),
                 fontsize=9)
    return circles


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    out = sys.argv[1]
    runs = []
    for arg in sys.argv[2:]:
        label, files = arg.split("=", 1)
        dump, log = files.split(":", 1)
        runs.append((label, dump, log))
    fig = plt.figure(figsize=(3.2 * len(runs) + 0.8, 5.6))
    grid = fig.add_gridspec(2, len(runs), height_ratios=[3, 2])
    views = [fig.add_subplot(grid[0, k]) for k in range(len(runs))]
    for ax, (label, dump, log) in zip(views, runs):
        circles = side_view(ax, label, dump, log)
    fig.colorbar(circles, ax=views, shrink=0.8, location="right", label="speed / (omega R)")
    ax = fig.add_subplot(grid[1, :])
    for label, dump, log in runs:
        sc = drum_angle.read_scene(log)
        res = drum_angle.drum_angle(dump, log)
        t = np.array([s[0] for s in res["series"] if s[1] is not None])
        a = np.array([s[1] for s in res["series"] if s[1] is not None])
        rev = (t - sc["tset"]) * sc["omega"] / (2.0 * math.pi)
        ax.plot(rev, a, ".-",
                label="%s: %.1f +- %.1f deg" % (label, res["angle"], res["angle_std"]))
    ax.set_xlabel("revolutions")
    ax.set_ylabel("surface angle (deg)")
    ax.axhline(0.0, color="0.7", linewidth=0.5)
    ax.legend(fontsize=8)
    fig.savefig(out, dpi=80)
    print("drum: wrote %s" % out)


if __name__ == "__main__":
    main()
