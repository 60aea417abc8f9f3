"""Kinetic energy and active contacts against time from a cluster_impact log.lammps."""
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt


def thermo(path):
    rows, header = [], None
    for line in open(path):
        words = line.split()
        if words[:2] == ["Step", "Time"]:
            header = words
        elif header and line.startswith("Loop time"):
            break
        elif header and len(words) == len(header):
            rows.append([float(w) for w in words])
    return header, rows


header, rows = thermo(sys.argv[1])
col = {name: [r[k] for r in rows] for k, name in enumerate(header)}
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
