#!/usr/bin/env python3
"""The scene of SCoPI's box_spheres_3d demo (issue 15, target 3), as a LAMMPS data file:
n^3 spheres (n = 10) of radius uniform in [0.8, 0.9] r0 (r0 = 0.5) and mass uniform in [1, 2]
(independent of the radius), on a lattice of pitch 2 r0 in x and z and 2.1 r0 in y (gravity
along -y, g = 1), each centre moved by up to 0.05 along each axis, above a floor y = 0 between
side walls x = 0, x = 11 and z = 0, z = 11 (width 10 + 2 r0). The demo's step is 0.045 (0.2 x
0.9 r0 / (2 g)) and its tolerance 1e-3. Positions, radii and masses come from numpy's seeded
generator, not the demo's: the same distributions, not the same draws.

    make_data.py OUT [N] [SEED]"""

import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
import hctools as hc  # noqa: E402


def main():
    out = sys.argv[1]
    n = int(sys.argv[2]) if len(sys.argv) > 2 else 10
    rng = np.random.default_rng(int(sys.argv[3]) if len(sys.argv) > 3 else 7)
    r0 = 0.5
    width = 10.0 + 2.0 * r0
    atoms = []
    for i in range(n):
        for j in range(n):
            for k in range(n):
                r = rng.uniform(0.8 * r0, 0.9 * r0)
                m = rng.uniform(1.0, 2.0)
                d = rng.uniform(-0.05, 0.05, 3)
                x = r0 + 0.1 + i * 2.0 * r0 + d[0]
                y = 1.1 * r0 + 2.1 * r0 * j + d[1]
                z = r0 + 0.1 + k * 2.0 * r0 + d[2]
                atoms.append((2.0 * r, m / (4.0 / 3.0 * math.pi * r ** 3), x, y, z))
    top = max(a[3] for a in atoms) + 2.0
    dia, rho, pos = zip(*[(a[0], a[1], a[2:]) for a in atoms])
    hc.write_data(out, ((0.0, width), (-0.5, top), (0.0, width)), dia, rho, pos, velocities=False,
                  number=lambda x: "%.9g" % x,
                  title="SCoPI box_spheres_3d scene: %d spheres (bench/scopi/make_data.py)" % len(atoms))


if __name__ == "__main__":
    main()
