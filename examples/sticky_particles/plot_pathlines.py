#!/usr/bin/env python3
"""Pathlines of the sticky particles (paper figures 5-7) and the final states compared.

    plot_pathlines.py OUT h1 h2 ...      reads OUT/h<h>/sticky.dump and OUT/h<h>/log.lammps
writes OUT/pathlines.png (x against t for every particle, one panel per h, the exact
event-driven pathlines in grey underneath) and prints, for every h, the final state against the
exact one: largest position and velocity error, centre of mass error, clusters found.
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import make_data           # noqa: E402
import sticky_exact as se  # noqa: E402
sys.path.insert(0, os.path.join(HERE, "..", "..", "python"))
import hctools as hc       # noqa: E402


def read_dump(path):
    """{step: (ids, x, vx)} from a dump custom id x vx ..., sorted by id."""
    return {fr.timestep: (list(fr.columns["id"]), list(fr.columns["x"]), list(fr.columns["vx"]))
            for fr in hc.read_dump(path)}


def clusters(x, v, r, tol=1e-3):
    """Groups of consecutive particles in contact (gap below tol x contact size)."""
    out, start = [], 0
    for i in range(1, len(x) + 1):
        if i == len(x) or x[i] - x[i - 1] - 2 * r > tol * 2 * r:
            out.append((start + 1, i, sum(v[start:i]) / (i - start)))
            start = i
    return out


def main():
    out, hs = sys.argv[1], sys.argv[2:]
    q0, u0, r = make_data.particles()
    n = len(q0)
    results = []
    for h in hs:
        frames = read_dump(os.path.join(out, "h" + h, "sticky.dump"))
        steps = sorted(frames)
        t = [s * float(h) for s in steps]
        results.append((h, t, [frames[s][1] for s in steps], frames[steps[-1]]))

    t_end = results[0][1][-1]
    x_ex, v_ex = se.state(q0, u0, r, None, t_end)
    final, t_last = se.solve(q0, u0, r)
    print("exact: last collision at t = %.4f, %d final clusters %s" % (
        t_last, len(final), " ".join("%d-%d" % (c[0] + 1, c[1] + 1) for c in final)))
    print("%-6s %6s %14s %14s %14s %s" % ("h", "steps", "max|x-x_ex|", "max|v-v_ex|", "|xcm-xcm_ex|",
                                           "clusters at t = %g" % t_end))
    xcm_ex = sum(x_ex) / n
    for h, t, xs, (ids, x, v) in results:
        ex = max(abs(a - b) for a, b in zip(x, x_ex))
        ev = max(abs(a - b) for a, b in zip(v, v_ex))
        cl = clusters(x, v, r)
        print("%-6s %6d %14.3g %14.3g %14.3g %s" % (h, len(t) - 1, ex, ev, abs(sum(x) / n - xcm_ex),
                                                    " ".join("%d-%d" % (c[0], c[1]) for c in cl)))

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("no matplotlib: no picture")
        return
    fig, axes = plt.subplots(1, len(results), figsize=(4.2 * len(results), 4.2), sharey=True)
    axes = axes if len(results) > 1 else [axes]
    nfine = 601
    tf = [t_end * k / (nfine - 1) for k in range(nfine)]
    ex_paths = se.pathlines(q0, u0, r, None, tf)
    for ax, (h, t, xs, _) in zip(axes, results):
        for i in range(n):
            ax.plot([p[i] for p in ex_paths], tf, color="0.75", lw=2.5, zorder=1)
            ax.plot([p[i] for p in xs], t, "-", color="C%d" % (i % 10), lw=1.0,
                    marker="o" if len(t) < 40 else None, ms=3, zorder=2)
        ax.axhline(t_last, color="k", ls=":", lw=0.8)
        ax.set_title("h = %s (%d steps)" % (h, len(t) - 1))
        ax.set_xlabel("x")
        ax.set_ylim(0, t_end)
    axes[0].set_ylabel("t")
    fig.suptitle("Sticky particles (Maury 2006, 6.2): computed pathlines (colour), exact (grey), "
                 "last exact collision (dotted)")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "pathlines.png"), dpi=80)
    print("wrote", os.path.join(out, "pathlines.png"))


if __name__ == "__main__":
    main()
