#!/usr/bin/env python3
"""Force chains of a 2d bed: the discs of the last dump frame (grey) and one segment per
contact between their centres, width and colour by the normal force.

    plot_bed.py OUT.png DIR:DUMP:CONTACTS:KIND[:TITLE] ...

KIND = hard (contacts.dump of fix hardcontact: f_hc[1] f_hc[2] ids (j = 0 for a wall),
f_hc[3] force) or soft (contacts.dump of compute property/local patom1 patom2 + compute
pair/local force: columns 1, 2 ids, 3 force). One panel per run, same colour scale.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import granular as g  # noqa: E402


def last_local(path):
    """Last frame of a dump local file: (timestep, array of rows)."""
    step, rows, lines = None, [], open(path).read().splitlines()
    i = 0
    while i < len(lines):
        if lines[i].startswith("ITEM: TIMESTEP"):
            step = int(lines[i + 1])
            n = int(lines[i + 3])
            rows = [l.split() for l in lines[i + 9:i + 9 + n]]
            i += 9 + n
        else:
            i += 1
    return step, np.array(rows, dtype=float).reshape(len(rows), -1)


def main():
    out = sys.argv[1]
    panels = [a.split(":") for a in sys.argv[2:]]
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import LineCollection, PatchCollection
    from matplotlib.patches import Circle

    data = []
    fmax = 0.0
    for p in panels:
        d, dump, contacts, kind = p[:4]
        title = p[4] if len(p) > 4 else kind
        step, cols, _ = g.read_dump(os.path.join(d, dump))[-1]
        cstep, rows = last_local(os.path.join(d, contacts))
        index = {int(i): k for k, i in enumerate(cols["id"])}
        seg, force = [], []
        for r in rows:
            i, j, f = int(r[0]), int(r[1]), float(r[2])
            if j == 0 or i not in index or j not in index or f <= 0.0:
                continue
            a, b = index[i], index[j]
            seg.append(((cols["x"][a], cols["y"][a]), (cols["x"][b], cols["y"][b])))
            force.append(f)
        force = np.array(force)
        if len(force):
            fmax = max(fmax, float(np.quantile(force, 0.995)))
        data.append((title, cols, seg, force))

    top = max(float(np.quantile(c["y"] + c["radius"], 0.99)) for _, c, _, _ in data)
    width = max(float((c["x"] + c["radius"]).max()) for _, c, _, _ in data)
    aspect = 1.05 * top / width
    if aspect < 0.5:     # wide beds: panels one above the other
        fig, axes = plt.subplots(len(data), 1, figsize=(8.0, len(data) * (8.0 * aspect + 0.4)), squeeze=False)
        axes = axes[:, 0]
    else:
        fig, axes = plt.subplots(1, len(data), figsize=(4.6 * len(data), 4.6 * aspect + 0.6), squeeze=False)
        axes = axes[0]
    for ax, (title, cols, seg, force) in zip(axes, data):
        discs = [Circle((x, y), r) for x, y, r in zip(cols["x"], cols["y"], cols["radius"])]
        ax.add_collection(PatchCollection(discs, facecolor="0.88", edgecolor="0.6", linewidth=0.3))
        if len(seg):
            lc = LineCollection(seg, linewidths=0.4 + 2.6 * np.minimum(force / fmax, 1.0), cmap="inferno_r")
            lc.set_array(force)
            lc.set_clim(0.0, fmax)
            ax.add_collection(lc)
        ax.set_xlim(0.0, width)
        ax.set_ylim(0.0, 1.05 * top)
        ax.set_aspect("equal")
        ax.set_title(title, fontsize=10)
        ax.set_xticks([])
        ax.set_yticks([])
    fig.tight_layout()
    fig.savefig(out, dpi=80, bbox_inches="tight")
    try:    # a palette PNG: a third of the size
        from PIL import Image
        Image.open(out).convert("RGB").quantize(colors=128).save(out, optimize=True)
    except ImportError:
        pass
    print("wrote", out)


if __name__ == "__main__":
    main()
