"""Kinetic energy and active contacts against time from a cluster_impact log.lammps."""
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
import hctools as hc  # noqa: E402


col = hc.read_thermo(sys.argv[1])[0]
fig, ax = plt.subplots(figsize=(6, 3.5))
ax.plot(col["Time"], col["c_ke"], "o-", label="kinetic energy (J)")
ax.set_xlabel("time (s)")
ax.set_ylabel("kinetic energy (J)")
ax2 = ax.twinx()
ax2.plot(col["Time"], col["f_step[4]"], "s--", color="tab:red", label="active contacts")
ax2.set_ylabel("active contacts", color="tab:red")
ax.set_title("Cluster impact (paper 6.3), h = 0.1")
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=110)
