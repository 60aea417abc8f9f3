#!/usr/bin/env python3
"""Writes the pile scene: 750 polydisperse discs (diameters uniform in [1.6, 2.4] mm, glass
density 2500 kg/m^3, mass pi/6 d^3 rho as LAMMPS gives spheres) at rest on a jittered square
grid (30 x 25, spacing 1.1 x the largest diameter) in a box 80 mm wide, the lowest row just
above the floor. Both decks of the scene (in.pile, in.pile.soft) read this file.

    make_data.py [OUT] [ROWS] [SEED]        (defaults: data.pile, 25, 1)
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
import granular  # noqa: E402

WIDTH = 0.08
D0 = 0.002


def main():
    out, rows, seed = granular.data_args("data.pile", 25, 1)
    box, d, rho, pos, vel = granular.disc_column(WIDTH, rows, D0, spread=0.2, seed=seed, density=2500.0)
    granular.write_data(out, box, d, rho, pos, vel,
                        title="pile: %d discs, d in [1.6, 2.4] mm, width %g m, seed %d" % (len(d), WIDTH, seed))
    print("%s: %d discs, box %s" % (out, len(d), box))


if __name__ == "__main__":
    main()
