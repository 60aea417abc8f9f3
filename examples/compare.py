#!/usr/bin/env python3
"""Side by side: a scene run with fix hardcontact and its soft-sphere twin.

    compare.py SCENE HARD_DIR SOFT_DIR [PNG]

reads HARD_DIR/log.lammps + HARD_DIR/<dump> and SOFT_DIR/log.lammps + SOFT_DIR/<dump> (written
by examples/<SCENE>/run.sh) and prints: wall time (LAMMPS loop time), steps, time step, wall
time per unit of physical time, largest overlap (hard: f_hc[2]/f_hc[7] at every step; soft:
every dump frame), final bed height and packing fraction (2d area fraction in a window inside
the bed), final kinetic energy; draws kinetic energy against time for both (PNG, default
SOFT_DIR/../compare.png). Scenes: pile, pour (the settled bed of both), disc_packing.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "common"))
import granular as g  # noqa: E402

# per scene: dump file name, walls (axis, position, +1 lower / -1 upper), bed window in x
SCENES = {
    "pile": dict(dump="pile.dump", walls=[(0, 0.0, 1), (0, 0.08, -1), (1, 0.0, 1)], x=(0.0, 0.08)),
    "pour": dict(dump="pour.dump", walls=[(0, 0.0, 1), (0, 0.1, -1), (1, 0.0, 1)], x=(0.0, 0.1)),
    "disc_packing": dict(dump="packing.dump", walls=[(1, 0.0, 1)], x=(0.0, 0.08)),    # periodic in x
}


def summary(run_dir, spec, hard):
    th = g.read_thermo(os.path.join(run_dir, "log.lammps"))[-1]
    loops = g.read_loop_times(os.path.join(run_dir, "log.lammps"))
    seconds = sum(l["loop"] for l in loops)
    steps = sum(l["steps"] for l in loops)
    t = th["Time"]
    dt = (t[-1] - t[0]) / max(1.0, th["Step"][-1] - th["Step"][0])
    frames = g.read_dump(os.path.join(run_dir, spec["dump"]))
    ov_abs, ov_rel = 0.0, 0.0
    for _, cols, _ in frames:
        a, r = g.overlaps(cols, spec["walls"])
        ov_abs, ov_rel = max(ov_abs, a), max(ov_rel, r)
    if hard and "f_hc[2]" in th:
        ov_abs = max(ov_abs, float(th["f_hc[2]"].max()))
        ov_rel = max(ov_rel, float(th["f_hc[7]"].max()))
    last = frames[-1].columns
    top = g.bed_height(last)
    d_mean = 2.0 * float(last["radius"].mean())
    x0, x1 = spec["x"]
    phi = g.area_fraction(last, x0, x1, 2.0 * d_mean, top - 3.0 * d_mean) if top > 6 * d_mean else float("nan")
    return dict(seconds=seconds, steps=steps, dt=dt, tphys=float(t[-1]), ov_abs=ov_abs, ov_rel=ov_rel,
                top=top, phi=phi, ke=float(th["c_ke"][-1]), atoms=int(th["Atoms"][-1]),
                t=t, ke_t=th["c_ke"], frames=len(frames))


def main():
    scene, hard_dir, soft_dir = sys.argv[1:4]
    png = sys.argv[4] if len(sys.argv) > 4 else os.path.join(os.path.dirname(os.path.abspath(soft_dir)), "compare.png")
    spec = SCENES[scene]
    h = summary(hard_dir, spec, True)
    s = summary(soft_dir, spec, False)
    rows = [
        ("atoms (end)", "%d", "atoms"),
        ("physical time (s)", "%.4g", "tphys"),
        ("time step (s)", "%.3g", "dt"),
        ("steps", "%d", "steps"),
        ("wall time (s)", "%.2f", "seconds"),
        ("wall time / physical time", "%.1f", None),
        ("largest overlap (m)", "%.3g", "ov_abs"),
        ("largest overlap / contact size", "%.3g", "ov_rel"),
        ("bed height (m)", "%.5g", "top"),
        ("packing fraction (2d)", "%.4f", "phi"),
        ("final kinetic energy (J)", "%.3g", "ke"),
    ]
    print("%-32s %16s %16s" % (scene, "hardcontact", "soft (gran/hertz)"))
    for label, fmt, key in rows:
        if key is None:
            a, b = h["seconds"] / h["tphys"], s["seconds"] / s["tphys"]
        else:
            a, b = h[key], s[key]
        print("%-32s %16s %16s" % (label, fmt % a, fmt % b))
    print("%-32s %16s" % ("wall time ratio soft / hard", "%.2f" % (s["seconds"] / h["seconds"])))
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("no matplotlib: no plot")
        return
    fig, ax = plt.subplots(figsize=(6, 3.6))
    ax.semilogy(s["t"], np.maximum(s["ke_t"], 1e-14), "-", color="tab:orange",
                label="soft spheres, dt = %.2g s" % s["dt"])
    ax.semilogy(h["t"], np.maximum(h["ke_t"], 1e-14), "o-", ms=2.5, color="tab:blue",
                label="hardcontact, h = %.2g s" % h["dt"])
    ax.set_xlabel("time (s)")
    ax.set_ylabel("kinetic energy (J)")
    ax.set_title("%s: kinetic energy" % scene)
    ax.legend()
    fig.tight_layout()
    fig.savefig(png, dpi=90)
    print("wrote", png)


if __name__ == "__main__":
    main()
