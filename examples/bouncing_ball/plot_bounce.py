#!/usr/bin/env python3
"""Heights of the two balls of in.bounce against time, with the apexes e^(2k) H the restitution
law predicts, from a log.lammps; prints the measured apexes against them.
    plot_bounce.py log.lammps out.png E"""
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
import hctools as hc  # noqa: E402


def apexes(z):
    """Tops of the flights (the ball at rest on the floor has none)."""
    return [k for k in range(1, len(z) - 1) if z[k - 1] < z[k] >= z[k + 1] and z[k] > 1e-3]


def main():
    log, png, e = sys.argv[1], sys.argv[2], float(sys.argv[3])
    t = hc.read_thermo(log)[-1]
    time, z1, z2, floor = t["Time"], t["v_z1"], t["v_z2"], t["v_floor"]
    H = z1[0]
    print("ball on the still floor: apex k, measured height, e^(2k) H")
    for k, i in enumerate(apexes(z1), start=1):
        print("  %d  %.5f  %.5f" % (k, z1[i], e ** (2 * k) * H))
    flying = np.nonzero(z1 > 1e-6)[0]
    print("at rest on the floor from t = %.3f on (height at the end %.2e)"
          % (time[flying[-1] + 1] if len(flying) else 0.0, z1[-1]))
    print("ball on the vibrated floor: highest flight %.3f above the floor's mean" % z2.max())
    fig, ax = plt.subplots(figsize=(7, 3.6))
    ax.plot(time, z1, label="still floor")
    ax.plot(time, z2, label="vibrated floor (amplitude 0.05, period 0.2)", lw=0.8)
    ax.plot(time, floor, color="0.5", lw=0.6, label="vibrated floor position")
    for k in range(1, 8):
        ax.axhline(e ** (2 * k) * H, color="k", lw=0.4, ls=":")
    ax.set_xlabel("time")
    ax.set_ylabel("height of the lowest point")
    ax.set_title("Restitution e = %g: apexes at e^(2k) H (dotted)" % e)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png, dpi=110)


if __name__ == "__main__":
    main()
