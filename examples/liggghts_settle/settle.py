#!/usr/bin/env python3
"""Measures and picture of the LIGGGHTS settle example (in.settle, hard contacts, and its twin
in.settle.soft): for each run folder (log.lammps, settle.dump) the steps and loop time, the final
kinetic energy, the bed height, the solid fraction of the bed's core and the largest overlaps
(bead-bead and bead-wall, from the dump at %.10g), printed as a table; with an output name, a
picture: the final beds side by side (side view) and the kinetic energy of both runs.

    settle.py OUT/hard OUT/soft [OUT/settle.png]

Used by run.sh and by tests/integration/test_example_liggghts_settle.py (measure())."""

import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
import granular as gr    # noqa: E402

WIDTH = 0.04                      # box: 40 x 40 mm, walls at 0 and WIDTH in x and y, floor z = 0
WALLS = [(0, 0.0, +1), (0, WIDTH, -1), (1, 0.0, +1), (1, WIDTH, -1), (2, 0.0, +1)]
CORE = (0.005, 0.015)             # slab of the bed away from floor and surface (m)


def _below(r, h):
    """Volume of the part of a sphere of radius r below a plane at signed height h from its
    centre (h clipped to [-r, r])."""
    h = np.clip(h, -r, r)
    return math.pi * (r + h) ** 2 * (2.0 * r - h) / 3.0


def solid_fraction(cols, z0, z1):
    """Volume of the beads inside the slab z0 < z < z1 over the slab's volume (exact caps)."""
    z, r = cols["z"], cols["radius"]
    v = _below(r, z1 - z) - _below(r, z0 - z)
    return float(v.sum()) / (WIDTH * WIDTH * (z1 - z0))


def measure(folder):
    """The measures of one run folder, as a dict."""
    blocks = gr.read_thermo(os.path.join(folder, "log.lammps"))
    th = blocks[-1]
    loops = gr.read_loop_times(os.path.join(folder, "log.lammps"))
    cols = gr.read_dump(os.path.join(folder, "settle.dump"))[-1].columns
    ov, ov_rel = gr.overlaps(cols, WALLS)
    tops = cols["z"] + cols["radius"]
    return {
        "steps": sum(l["steps"] for l in loops),
        "loop_time": sum(l["loop"] for l in loops),
        "atoms": len(cols["id"]),
        "time": th["Time"], "ke": th["c_ke"], "top": th["c_top"],
        "ke_final": float(th["c_ke"][-1]),
        "ke_peak": float(th["c_ke"].max()),
        "bed_height": float(np.quantile(tops, 0.98)),
        "solid_fraction": solid_fraction(cols, *CORE),
        "overlap": ov, "overlap_rel": ov_rel,
        "cols": cols,
    }


def table(hard, soft):
    rows = [("steps", "%d", "steps"), ("loop time (s)", "%.2f", "loop_time"),
            ("final kinetic energy (J)", "%.2e", "ke_final"),
            ("bed height, 98%% of tops (mm)", "%.2f", "bed_height_mm"),
            ("solid fraction, z = 5-15 mm", "%.3f", "solid_fraction"),
            ("largest overlap (um)", "%.3g", "overlap_um"),
            ("largest overlap / contact size", "%.2g", "overlap_rel")]
    for m in (hard, soft):
        m["bed_height_mm"] = 1e3 * m["bed_height"]
        m["overlap_um"] = 1e6 * m["overlap"]
    out = ["%-32s %14s %14s" % ("", "hard", "soft (Hertz)")]
    for label, fmt, key in rows:
        out.append("%-32s %14s %14s" % (label.replace("%%", "%"), fmt % hard[key], fmt % soft[key]))
    return "\n".join(out)


def picture(hard, soft, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import PatchCollection
    from matplotlib.patches import Circle

    fig, axes = plt.subplots(1, 3, figsize=(12, 4.2), gridspec_kw={"width_ratios": [1, 1, 1.4]})
    for ax, m, title in ((axes[0], hard, "fix hardcontact, h = 1 ms"),
                         (axes[1], soft, "pair gran hertz, dt = 10 us")):
        c = m["cols"]
        order = np.argsort(c["y"])      # far beads first, near ones drawn over them
        patches = [Circle((1e3 * c["x"][i], 1e3 * c["z"][i]), 1e3 * c["radius"][i]) for i in order]
        pc = PatchCollection(patches, cmap="viridis", edgecolor="k", linewidth=0.3)
        pc.set_array(1e3 * c["y"][order])
        pc.set_clim(0, 1e3 * WIDTH)
        ax.add_collection(pc)
        ax.set_xlim(0, 1e3 * WIDTH)
        ax.set_ylim(0, 40)
        ax.set_aspect("equal")
        ax.set_xlabel("x (mm)")
        ax.set_title("%s\nbed %.1f mm, overlap %.2g" % (title, 1e3 * m["bed_height"],
                                                     m["overlap_rel"]), fontsize=9)
    axes[0].set_ylabel("z (mm)")
    fig.colorbar(pc, ax=axes[:2], label="depth y (mm)", shrink=0.8)
    ax = axes[2]
    ax.semilogy(hard["time"], np.maximum(hard["ke"], 1e-12), label="hard contacts")
    ax.semilogy(soft["time"], np.maximum(soft["ke"], 1e-12), "--", label="soft twin (Hertz)")
    ax.set_xlabel("time (s)")
    ax.set_ylabel("kinetic energy (J)")
    ax.set_title("468 beads settling in LIGGGHTS 3.8", fontsize=9)
    ax.legend()
    fig.savefig(path, dpi=110, bbox_inches="tight")


def main(argv):
    if len(argv) < 3:
        print(__doc__, file=sys.stderr)
        return 2
    hard, soft = measure(argv[1]), measure(argv[2])
    print(table(hard, soft))
    if len(argv) > 3:
        picture(hard, soft, argv[3])
        print("picture: %s" % argv[3])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
