#!/usr/bin/env python3
"""Measures and picture of examples/mixer: for each run folder (log.lammps, mixer.dump) the
time per revolution, and at each dump the Lacey mixing index of the two halves (types 1 and 2)
over square cells of side 2 in the x-z plane holding at least 6 spheres,
M = (s0 - s) / (s0 - sr), s the spread of the type-2 fraction over the cells, s0 = sqrt(p (1 -
p)) that of the segregated bed, sr = sqrt(p (1 - p) / n) that of a random one (n spheres per
cell); 0 segregated, 1 random. With an output name, a picture: M against revolutions for each
run, and the end state of each (y-averaged x-z view, colour = starting half).

    mixer.py OUT.png LABEL=FOLDER [LABEL=FOLDER ...]

Used by run.sh and by tests/integration/test_example_mixer.py (measure())."""

import math
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
import granular as gr    # noqa: E402

CELL, MIN_COUNT = 2.0, 6
LIFTER_HEIGHT = 2.0    # run.sh's make_mixer.py argument


def lacey(c):
    p = float(np.mean(c["type"] == 2))
    ix = np.floor(c["x"] / CELL).astype(int)
    iz = np.floor(c["z"] / CELL).astype(int)
    keys = ix * 1000 + iz
    fr, counts = [], []
    for k in np.unique(keys):
        sel = keys == k
        if sel.sum() >= MIN_COUNT:
            fr.append(float(np.mean(c["type"][sel] == 2)))
            counts.append(int(sel.sum()))
    fr, counts = np.array(fr), np.array(counts)
    s = math.sqrt(float(np.average((fr - p) ** 2, weights=counts)))
    s0 = math.sqrt(p * (1 - p))
    sr = math.sqrt(p * (1 - p) / float(np.mean(counts)))
    return (s0 - s) / (s0 - sr)


def measure(folder):
    log = os.path.join(folder, "log.lammps")
    text = open(log).read()
    # the print's output (the log also echoes the command with its ${...} unexpanded)
    m = [x for x in re.finditer(r"^mixer: R (\S+) L (\S+) lifters (\S+) omega (\S+) dt (\S+) "
                                r"revolution (\S+)", text, re.M) if "$" not in x.group(0)][-1]
    omega, dt, rev = float(m.group(4)), float(m.group(5)), float(m.group(6))
    loops = gr.read_loop_times(log)
    frames = gr.read_dump(os.path.join(folder, "mixer.dump"))
    nset = loops[0]["steps"]
    revs, mix = [], []
    for step, c, _ in frames:
        if step < nset:
            continue
        revs.append((step - nset) * dt / rev)
        mix.append(lacey(c))
    th = gr.read_thermo(log)[-1]
    R = float(m.group(1))
    theta_end = omega * (frames[-1][0] - nset) * dt
    return {"lifters": int(m.group(3)), "rev_time": rev, "loops": loops, "R": R,
            "theta_end": theta_end, "lifter_height": LIFTER_HEIGHT,
            "seconds_per_rev": loops[-1]["loop"] / ((loops[-1]["steps"] * dt) / rev),
            "revs": np.array(revs), "mix": np.array(mix), "end": frames[-1].columns,
            "atoms": th["Atoms"], "rmax": float(th["c_rmax"].max()),
            "overlap": float(th["f_hc[7]"].max()), "maxiter": float(th["f_hc[6]"].max()),
            "iterations": float(th["f_hc[1]"].mean())}


def table(runs):
    lines = ["%-10s %8s %14s %10s %12s %11s" % ("run", "lifters", "s/revolution", "it/step",
                                                 "M at 0.5 rev", "M at end")]
    for label, m in runs:
        half = m["mix"][np.argmin(np.abs(m["revs"] - 0.5))]
        lines.append("%-10s %8d %14.2f %10.1f %12.2f %11.2f" % (
            label, m["lifters"], m["seconds_per_rev"], m["iterations"], half, m["mix"][-1]))
    return "\n".join(lines)


def picture(out, runs, R=7.0):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 1 + len(runs), figsize=(4.2 * (1 + len(runs)), 4.2))
    ax = axes[0]
    for label, m in runs:
        ax.plot(m["revs"], m["mix"], "o-", ms=3, label=label)
    ax.set_xlabel("revolutions")
    ax.set_ylabel("Lacey mixing index")
    ax.set_ylim(-0.1, 1.05)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    for ax, (label, m) in zip(axes[1:], runs):
        c = m["end"]
        for t, col in ((1, "tab:blue"), (2, "tab:orange")):
            sel = c["type"] == t
            ax.scatter(c["x"][sel], c["z"][sel], s=14, c=col)
        a = np.linspace(0, 2 * math.pi, 200)
        ax.plot(R * np.cos(a), R * np.sin(a), "k-", lw=1)
        # the lifters where the drum has turned them (rotation about +y: angle a - theta)
        for j in range(m["lifters"]):
            b = 2 * math.pi * (j + 0.5) / m["lifters"] + math.pi / 72 - m["theta_end"]
            rr = np.array([R, R - m["lifter_height"]])
            ax.plot(rr * math.cos(b), rr * math.sin(b), "k-", lw=2.5)
        ax.set_aspect("equal")
        ax.set_xlim(-R - 0.5, R + 0.5)
        ax.set_ylim(-R - 0.5, R + 0.5)
        ax.set_title("%s, after %.2f revolutions" % (label, m["revs"][-1]), fontsize=9)
    fig.tight_layout()
    fig.savefig(out, dpi=110)


def main():
    out = sys.argv[1]
    runs = [(a.split("=", 1)[0], measure(a.split("=", 1)[1])) for a in sys.argv[2:]]
    print(table(runs))
    picture(out, runs)
    print("mixer: picture in %s" % out)


if __name__ == "__main__":
    main()
