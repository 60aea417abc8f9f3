#!/usr/bin/env python3
"""Measures and picture of the LIGGGHTS hopper example (in.hopper, hard contacts, and its
twin(s) in.hopper.soft): for each run folder (log.lammps, hopper.dump) the steps and loop time of
the settling and the discharge, the discharge rate (beads per second: the slope of the beads
above the outlet, `inside`, from 0.1 s after opening while more than 30 % of the beads are left),
the settled bed's height and its largest bead-bead overlap (dump at the end of settling), as a
table; with an output name, a picture: the beads left against time for every run, and a
cut-away view (|y| < 2 mm) of each of the first two runs 0.3 s after opening.

    hopper.py OUT.png LABEL=FOLDER [LABEL=FOLDER ...]

Used by run.sh and by tests/integration/test_example_liggghts_hopper.py (measure())."""

import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
import granular as gr    # noqa: E402

SKIP = 0.1       # s after opening before the rate is fitted
LEFT = 0.30      # the fit stops when fewer than this fraction of the beads are left


def measure(folder):
    log = os.path.join(folder, "log.lammps")
    blocks = gr.read_thermo(log)
    loops = gr.read_loop_times(log)
    settle, drain = blocks[0], blocks[-1]
    t_open = float(settle["Time"][-1])
    t, inside = drain["Time"], drain["c_inside"]
    n0 = float(inside[0])
    fit = (t >= t_open + SKIP) & (inside >= LEFT * n0)
    rate = -np.polyfit(t[fit], inside[fit], 1)[0] if fit.sum() >= 3 else float("nan")
    frames = gr.read_dump(os.path.join(folder, "hopper.dump"))
    # the dump frame at the end of settling: the last one at or before the opening
    steps_settle = loops[0]["steps"]
    settled = [f for f in frames if f.timestep <= steps_settle][-1].columns
    ov, _ = gr.overlaps(settled)
    return {
        "loops": loops, "t": t, "inside": inside, "t_open": t_open, "rate": rate,
        "n0": n0, "top": float(np.quantile(settled["z"] + settled["radius"], 0.98)),
        "overlap": ov, "frames": frames, "steps_settle": steps_settle,
    }


def table(runs):
    lines = ["%-12s %9s %9s %9s %9s %11s %9s %12s" % (
        "run", "steps", "settle s", "drain s", "total s", "rate (1/s)", "bed mm", "overlap/d")]
    for label, m in runs:
        (ts, ns), (td, nd) = [(m["loops"][k]["loop"], m["loops"][k]["steps"]) for k in (0, -1)]
        lines.append("%-12s %9d %9.1f %9.1f %9.1f %11.0f %9.1f %12.2e" % (
            label, ns + nd, ts, td, ts + td, m["rate"], 1000 * m["top"], m["overlap"] / 0.004))
    return "\n".join(lines)


def picture(out, runs):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    views = runs[:2]
    fig, axes = plt.subplots(1, 1 + len(views), figsize=(4.2 * (1 + len(views)), 4.2),
                             gridspec_kw={"width_ratios": [1.3] + [1] * len(views)})
    ax = axes[0]
    for label, m in runs:
        ax.plot(m["t"] - m["t_open"], m["inside"], label="%s: %.0f beads/s" % (label, m["rate"]))
    ax.set_xlabel("time after opening (s)")
    ax.set_ylabel("beads above the outlet")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    for ax, (label, m) in zip(axes[1:], views):
        h = (m["t"][-1] - m["t"][0]) / max(1, m["loops"][-1]["steps"])    # the discharge's step
        target = m["steps_settle"] + round(0.3 / h)
        step, c, _ = min(m["frames"], key=lambda f: abs(f.timestep - target))
        cut = np.abs(c["y"]) < 0.002
        speed = np.sqrt(c["vx"] ** 2 + c["vy"] ** 2 + c["vz"] ** 2)
        ax.scatter(1000 * c["x"][cut], 1000 * c["z"][cut], s=14, c=speed[cut], cmap="viridis",
                   vmin=0, vmax=0.5)
        r = [10 + 25 * k / 6 for k in range(7)]
        z = [43.30127 * k / 6 for k in range(7)]
        for sgn in (-1, 1):
            ax.plot([sgn * v for v in r] + [sgn * 35], z + [120], "k-", lw=1)
        ax.set_aspect("equal")
        ax.set_xlim(-40, 40)
        ax.set_ylim(-30, 125)
        ax.set_title("%s, %.2f s after opening" % (label, (step - m["steps_settle"]) * h),
                     fontsize=9)
        ax.set_xlabel("x (mm)")
    axes[1].set_ylabel("z (mm)")
    fig.tight_layout()
    fig.savefig(out, dpi=110)


def main():
    out = sys.argv[1]
    runs = [(a.split("=", 1)[0], measure(a.split("=", 1)[1])) for a in sys.argv[2:]]
    print(table(runs))
    picture(out, runs)
    print("hopper: picture in %s" % out)


if __name__ == "__main__":
    main()
