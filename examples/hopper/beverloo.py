#!/usr/bin/env python3
"""Discharge rates of examples/hopper and the 2d Beverloo fit.

    beverloo.py OUTDIR D1 D2 ...        (outlet widths in mm; runs in OUTDIR/D<D>/)

For every outlet width D: the discharge rate Q (discs per second, and kg/s) is the slope of
the number of discs still in the silo (thermo v_inside of the discharge run) against time,
fitted over [t_skip, end] after the outlet opens (t_skip = 0.1 s: the flow starts). The 2d
Beverloo law W = C rho_b sqrt(g) (D - k d)^3/2 (rho_b the bulk density of the bed, d the mean
diameter; e.g. Mankoc et al., Granular Matter 9 (2007) 407) becomes, for the rate in discs,
Q = C (phi / a) sqrt(g) (D - k d)^3/2 with phi the area fraction of the bed and a the mean
disc area: Q^2/3 is linear in D; the fit gives k and C. Writes OUTDIR/beverloo.png.
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
import granular as g  # noqa: E402

G = 9.81
T_SKIP = 0.1
WIDTH = 0.08


def rate(run_dir):
    """(Q discs/s, mean disc mass kg, area fraction of the settled bed, mean diameter, mean disc
    area) of one run."""
    blocks = g.read_thermo(os.path.join(run_dir, "log.lammps"))
    flow = blocks[-1]
    t = flow["Time"] - flow["Time"][0]
    n = flow["v_inside"]
    sel = t >= T_SKIP - 1e-12
    slope = np.polyfit(t[sel], n[sel], 1)[0]
    frames = g.read_dump(os.path.join(run_dir, "silo.dump"))
    t_open = flow["Step"][0]
    settled = [c for s, c, _ in frames if s <= t_open][-1]
    grains = settled["type"] == 1
    cols = {k: v[grains] for k, v in settled.items()}
    r = cols["radius"]
    top = g.bed_height(cols, 0.98)
    d_mean = 2.0 * float(r.mean())
    phi = g.area_fraction(cols, 0.0, WIDTH, 2 * d_mean, top - 3 * d_mean)
    mass = float((math.pi / 6 * (2 * r) ** 3 * 2500.0).mean())
    return -slope, mass, phi, d_mean, float((math.pi * r ** 2).mean())


def main():
    out, widths = sys.argv[1], [float(w) for w in sys.argv[2:]]
    rows = []
    for w in widths:
        q, mass, phi, d, a = rate(os.path.join(out, "D%g" % w))
        rows.append((w * 1e-3, q, mass, phi, d, a))
    D = np.array([r[0] for r in rows])
    Q = np.array([r[1] for r in rows])
    phi = float(np.mean([r[3] for r in rows]))
    d = float(np.mean([r[4] for r in rows]))
    a = float(np.mean([r[5] for r in rows]))
    slope, intercept = np.polyfit(D, Q ** (2.0 / 3.0), 1)      # Q^2/3 = s (D - k d)
    k = -intercept / slope / d
    C = slope ** 1.5 * a / (phi * math.sqrt(G))
    print("bed area fraction %.3f, mean diameter %.3g m, mean disc area %.3g m^2" % (phi, d, a))
    print("%8s %8s %12s %12s %12s" % ("D (mm)", "D / d", "Q (1/s)", "W (kg/s)", "fit (1/s)"))
    for (w, q, mass, _, _, _) in rows:
        fit = C * phi / a * math.sqrt(G) * max(w - k * d, 0.0) ** 1.5
        print("%8.1f %8.2f %12.1f %12.4g %12.1f" % (w * 1e3, w / d, q, q * mass, fit))
    print("Beverloo 2d fit: k = %.2f, C = %.3f  (Q = C phi/a sqrt(g) (D - k d)^3/2)" % (k, C))
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    fig, ax = plt.subplots(figsize=(5.2, 3.8))
    dd = np.linspace(k * d, D.max() * 1.1, 100)
    ax.plot(D / d, Q, "o", label="fix hardcontact")
    ax.plot(dd / d, C * phi / a * math.sqrt(G) * (dd - k * d) ** 1.5, "-",
            label="Beverloo 2d: k = %.2f, C = %.2f" % (k, C))
    ax.set_xlabel("outlet width D / mean diameter")
    ax.set_ylabel("discharge rate (discs/s)")
    ax.set_xlim(0, None)
    ax.set_ylim(0, None)
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(out, "beverloo.png"), dpi=90)
    print("wrote", os.path.join(out, "beverloo.png"))


if __name__ == "__main__":
    main()
