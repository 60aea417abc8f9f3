#!/usr/bin/env python3
"""Writes the initial state of the paper's section 6.2 (sticky particles) as a LAMMPS data file:
N point-like particles on the x axis, q0 = (0, a, 2a, ..., 1) with a = 1/(N-1), velocities
u0 drawn uniformly in [-1, 1] (Python's Mersenne Twister, fixed seed: the same file on every
machine), unit masses, radius 1e-4 a (the particles are spheres kept on the x axis: y = z = 0,
no velocity along y or z, so every contact normal is exactly +-x).

    make_data.py [N] [SEED] > data.sticky      (defaults: N = 20, SEED = 37)
"""
import math
import random
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
import hctools as hc  # noqa: E402


def particles(n=20, seed=37):
    a = 1.0 / (n - 1)
    rng = random.Random(seed)
    q = [i * a for i in range(n)]
    u = [rng.uniform(-1.0, 1.0) for _ in range(n)]
    return q, u, 1e-4 * a


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 20
    seed = int(sys.argv[2]) if len(sys.argv) > 2 else 37
    q, u, r = particles(n, seed)
    dens = 1.0 / (4.0 / 3.0 * math.pi * r ** 3)        # unit mass
    zero = [0.0] * n
    hc.write_data("/dev/stdout", ((-1.0, 2.0), (-0.5, 0.5), (-0.5, 0.5)), 2 * r, dens,
                  list(zip(q, zero, zero)), list(zip(u, zero, zero)), number=lambda x: "%.17g" % x,
                  title="# sticky particles (Maury 2006, section 6.2): N=%d seed=%d, radius %.17g, mass 1"
                  % (n, seed, r))


if __name__ == "__main__":
    main()
