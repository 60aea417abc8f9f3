#!/usr/bin/env python3
"""Writes the scene of examples/hopper3d: a conical hopper (3d) with a flat floor.
Type 1: N polydisperse glass beads (diameters uniform in [1.6, 2.4] mm, 2500 kg/m^3) at rest on
the sites of an fcc lattice (nearest neighbours 2.45 mm apart, so none touch) inside the cone,
the lowest N sites that keep a bead clear of the cone and of the floor (numpy, fixed seed).
Type 2: the floor, a square layer of touching 1 mm spheres (centres 0.5 mm below z = 0)
filling the cone's cross-section; the decks freeze them and remove those within D/2 + 0.5 mm
of the axis to open a round outlet of diameter D.
The cone (the decks' region `hopper`): half-angle 30 degrees from the vertical, radius 12 mm at
z = 0; the region reaches below the box, so beads that fall through the outlet stay inside it
until they leave the box 4 mm below the floor.

    make_data.py [OUT] [COUNT] [SEED]        (defaults: data.hopper3d, 1500, 5)
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
import granular  # noqa: E402

R0 = 0.012                          # cone radius at the floor (z = 0)
TAN = math.tan(math.radians(30.0))  # cone half-angle
D_MIN, D_MAX = 0.0016, 0.0024
D_FLOOR = 0.001
SPACING = 0.00245                   # fcc nearest-neighbour distance > D_MAX
BOX = ((-0.040, 0.040), (-0.040, 0.040), (-0.004, 0.046))


def cone_radius(z):
    return R0 + TAN * z


def fcc_sites(spacing, half_width, height):
    """fcc lattice sites (nearest neighbours `spacing` apart) in |x|, |y| <= half_width,
    0 <= z <= height."""
    a = spacing * math.sqrt(2.0)
    n = int(half_width / a) + 1
    base = np.array([[0, 0, 0], [0.5, 0.5, 0], [0.5, 0, 0.5], [0, 0.5, 0.5]])
    i, j, k = np.mgrid[-n:n + 1, -n:n + 1, 0:int(height / a) + 1]
    cells = np.stack([i.ravel(), j.ravel(), k.ravel()], axis=1).astype(float)
    sites = (cells[:, None, :] + base[None, :, :]).reshape(-1, 3) * a
    return sites


def scene(count=1500, seed=5):
    rng = np.random.default_rng(seed)
    sites = fcc_sites(SPACING, BOX[0][1], BOX[2][1])
    sites[:, 2] += 0.5 * D_MAX + 0.0002            # the lowest layer clear of the floor (z = 0)
    rho = np.hypot(sites[:, 0], sites[:, 1])
    # distance to the cone wall, measured normal to it: (R(z) - rho) cos(theta)
    clear = (cone_radius(sites[:, 2]) - rho) * math.cos(math.atan(TAN))
    ok = (clear >= 0.5 * D_MAX + 0.0002) & (sites[:, 2] + 0.5 * D_MAX < BOX[2][1] - 0.002)
    sites = sites[ok]
    if len(sites) < count:
        sys.exit("make_data.py: only %d sites in the cone for %d beads" % (len(sites), count))
    order = np.lexsort((sites[:, 1], sites[:, 0], sites[:, 2]))    # bottom up, deterministic
    beads = sites[order[:count]]
    d = rng.uniform(D_MIN, D_MAX, count)
    # the floor: square layer of 1 mm spheres covering the cone's section at z = 0
    n = int(R0 / D_FLOOR) + 1
    gx, gy = np.meshgrid(np.arange(-n, n + 1) * D_FLOOR, np.arange(-n, n + 1) * D_FLOOR)
    gx, gy = gx.ravel(), gy.ravel()
    keep = np.hypot(gx, gy) <= cone_radius(-0.5 * D_FLOOR) - 0.5 * D_FLOOR
    floor = np.stack([gx[keep], gy[keep], np.full(keep.sum(), -0.5 * D_FLOOR)], axis=1)
    pos = np.vstack([beads, floor])
    diam = np.concatenate([d, np.full(len(floor), D_FLOOR)])
    types = np.concatenate([np.ones(count, dtype=int), np.full(len(floor), 2)])
    return BOX, diam, np.full(len(diam), 2500.0), pos, types


def main():
    out, count, seed = granular.data_args("data.hopper3d", 1500, 5)
    box, d, rho, pos, types = scene(count, seed)
    granular.write_data(out, box, d, rho, pos, None, types,
                        title="hopper3d: %d beads (1.6-2.4 mm) + %d floor spheres (1 mm), seed %d"
                        % (int((types == 1).sum()), int((types == 2).sum()), seed))
    top = float((pos[types == 1, 2] + 0.5 * d[types == 1]).max())
    print("%s: %d beads (top %.1f mm) + %d floor spheres" % (out, (types == 1).sum(), top * 1e3,
                                                            (types == 2).sum()))


if __name__ == "__main__":
    main()
