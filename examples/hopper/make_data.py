#!/usr/bin/env python3
"""Writes the silo scene of examples/hopper: a flat-bottomed 2d silo 80 mm wide.
Type 1: N polydisperse glass discs (diameters uniform in [1.6, 2.4] mm, 2500 kg/m^3) at rest on
a jittered grid above the floor (spacing 1.1 x the largest diameter, numpy, fixed seed).
Type 2: the floor, a row of 80 touching discs of 1 mm at y = 0 (centres x = 0.5, 1.5, ...,
79.5 mm); the deck freezes them (outside the fix group) and removes those whose centres lie
within D/2 of the middle to open an outlet of width exactly D (a whole number of mm).
The box reaches 60 mm below the floor: discs that fall out of the silo leave it there.

    make_data.py [OUT] [ROWS] [SEED]        (defaults: data.silo, 32, 3: 960 discs)
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
import granular  # noqa: E402

WIDTH = 0.08
D0 = 0.002
D_FLOOR = 0.001


def scene(rows=32, seed=3):
    box, d, rho, pos, vel = granular.disc_column(WIDTH, rows, D0, spread=0.2, y0=0.5 * D_FLOOR, seed=seed)
    nf = int(round(WIDTH / D_FLOOR))
    floor = np.zeros((nf, 3))
    floor[:, 0] = D_FLOOR * (np.arange(nf) + 0.5)
    top = float((pos[:, 1] + 0.5 * d).max())
    box = ((0.0, WIDTH), (-0.06, top + 0.01), (-D0, D0))
    diam = np.concatenate([d, np.full(nf, D_FLOOR)])
    dens = np.full(len(diam), 2500.0)
    types = np.concatenate([np.ones(len(d), dtype=int), np.full(nf, 2)])
    return box, diam, dens, np.vstack([pos, floor]), types


def main():
    out, rows, seed = granular.data_args("data.silo", 32, 3)
    box, d, rho, pos, types = scene(rows, seed)
    granular.write_data(out, box, d, rho, pos, None, types,
                        title="silo: %d discs (1.6-2.4 mm) + %d floor discs (1 mm), seed %d"
                        % (int((types == 1).sum()), int((types == 2).sum()), seed))
    print("%s: %d discs + %d floor discs, box %s" % (out, (types == 1).sum(), (types == 2).sum(), box))


if __name__ == "__main__":
    main()
