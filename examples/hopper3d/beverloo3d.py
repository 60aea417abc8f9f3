#!/usr/bin/env python3
"""Discharge rates of examples/hopper3d and the 3d Beverloo fit.

    beverloo3d.py OUTDIR D1 D2 ...        (outlet diameters in mm; runs in OUTDIR/<kind>_D<D>/,
                                          kind = hard and/or soft, settled beds in
                                          OUTDIR/<kind>_settle/settled.data)

For every run the rate Q (beads per second) is the slope of the number of beads still above
the floor (thermo v_inside of the discharge run) against time, fitted from T_SKIP after the
outlet opens (the flow starts) while at least KEEP of the beads are left (the bed must not run
low); W = Q m (kg/s), m the mean bead mass. The 3d Beverloo law (Beverloo, Leniger and van de
Velde, Chem. Eng. Sci. 15 (1961) 260)
    W = C rho_b sqrt(g) (D - k d)^(5/2),
rho_b = phi rho_p the bulk density of the settled bed (phi its packing fraction, measured in a
cylinder around the axis), d the mean diameter: W^(2/5) is linear in D, the straight-line fit
gives k and C. Runs whose outlet clogged (fewer than MIN_OUT beads left over the window) are
listed and left out of the fit. Writes OUTDIR/beverloo.png.
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
import granular as g  # noqa: E402

G = 9.81
RHO_P = 2500.0
T_SKIP = 0.05
KEEP = 0.35
MIN_OUT = 20
KINDS = (("hard", "fix hardcontact"), ("soft", "soft twin (pair granular)"))


def read_beads(path):
    """(diameter, z, rho = distance from the axis) of the type 1 atoms of a LAMMPS data file."""
    rows, on = [], False
    with open(path) as f:
        for line in f:
            w = line.split()
            if w[:1] == ["Atoms"]:
                on = True
                continue
            if on and w and not w[0].lstrip("-").isdigit():
                break
            if on and len(w) >= 7 and w[1] == "1":
                rows.append([float(x) for x in w[2:7]])
    a = np.array(rows)
    return a[:, 0], a[:, 4], np.hypot(a[:, 2], a[:, 3])


def packing_fraction(data):
    """Volume fraction of the beads whose centres lie within 8 mm of the axis, between 3 d above
    the floor and 3 d below the bed's top (centres in the cylinder; its edge effects cancel)."""
    d, z, rho = read_beads(data)
    dm = float(d.mean())
    top = float(np.percentile(z, 98))
    lo, hi, rc = 3 * dm, top - 3 * dm, 0.008
    sel = (rho < rc) & (z > lo) & (z < hi)
    return float((math.pi / 6 * d[sel] ** 3).sum() / (math.pi * rc * rc * (hi - lo))), dm, \
        float((math.pi / 6 * d ** 3 * RHO_P).mean())


def rate(run_dir):
    """(Q beads/s, beads left out in the window, window) of one discharge run."""
    flow = g.read_thermo(os.path.join(run_dir, "log.lammps"))[-1]
    t = flow["Time"] - flow["Time"][0]
    n = flow["v_inside"]
    sel = (t >= T_SKIP - 1e-9) & (n >= KEEP * n[0])
    if sel.sum() < 3:
        return 0.0, 0.0, (0.0, 0.0)
    tt, nn = t[sel], n[sel]
    return -np.polyfit(tt, nn, 1)[0], float(nn[0] - nn[-1]), (float(tt[0]), float(tt[-1]))


def fit(D, W):
    """k d and C rho_b sqrt(g) of W = C rho_b sqrt(g) (D - k d)^5/2: line through W^2/5."""
    slope, intercept = np.polyfit(D, W ** 0.4, 1)
    return -intercept / slope, slope ** 2.5


def main():
    out, outlets = sys.argv[1], [float(w) for w in sys.argv[2:]]
    results = {}
    for kind, label in KINDS:
        settled = os.path.join(out, "%s_settle" % kind, "settled.data")
        if not os.path.exists(settled):
            continue
        phi, d, m = packing_fraction(settled)
        rows = []
        for w in outlets:
            if not os.path.exists(os.path.join(out, "%s_D%g" % (kind, w), "log.lammps")):
                continue    # not run (yet)
            q, left, win = rate(os.path.join(out, "%s_D%g" % (kind, w)))
            rows.append((w * 1e-3, q, q * m, left >= MIN_OUT, win))
        flowing = [r for r in rows if r[3]]
        D = np.array([r[0] for r in flowing])
        W = np.array([r[2] for r in flowing])
        kd, a = fit(D, W) if len(D) >= 2 else (float("nan"), float("nan"))
        C, k = a / (phi * RHO_P * math.sqrt(G)), kd / d
        results[kind] = (label, rows, C, k, phi, d, m)
        print("%s: packing fraction %.3f, mean diameter %.3g m, mean bead mass %.3g kg"
              % (label, phi, d, m))
        print("%8s %7s %11s %11s %11s  %s" % ("D (mm)", "D / d", "Q (1/s)", "W (g/s)", "fit (g/s)",
                                              "window (s)"))
        for (Dm, q, wr, ok, win) in rows:
            fitw = C * phi * RHO_P * math.sqrt(G) * max(Dm - k * d, 0.0) ** 2.5
            print("%8.1f %7.2f %11.1f %11.3f %11.3f  %.3f-%.3f%s" % (
                Dm * 1e3, Dm / d, q, wr * 1e3, fitw * 1e3, win[0], win[1],
                "" if ok else "  (clogged: not fitted)"))
        print("Beverloo 3d fit (%s): C = %.3f, k = %.2f  (W = C rho_b sqrt(g) (D - k d)^5/2)"
              % (kind, C, k))
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    fig, ax = plt.subplots(figsize=(5.2, 3.8))
    for (kind, (label, rows, C, k, phi, d, m)), (mk, col) in zip(results.items(),
                                                                 (("o", "C0"), ("s", "C3"))):
        Dm = np.array([r[0] for r in rows])
        ax.plot(Dm / d, [r[2] * 1e3 for r in rows], mk, color=col, mfc="none" if kind == "soft"
                else col, label=label)
        if math.isfinite(C):
            dd = np.linspace(k * d, Dm.max() * 1.05, 100)
            ax.plot(dd / d, 1e3 * C * phi * RHO_P * math.sqrt(G) * (dd - k * d) ** 2.5, "-",
                    color=col, lw=1, label="Beverloo: C = %.2f, k = %.2f" % (C, k))
    ax.set_xlabel("outlet diameter D / mean bead diameter")
    ax.set_ylabel("discharge rate W (g/s)")
    ax.set_xlim(0, None)
    ax.set_ylim(0, None)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "beverloo.png"), dpi=90)
    print("wrote", os.path.join(out, "beverloo.png"))


if __name__ == "__main__":
    main()
