#!/usr/bin/env python3
"""Writes the disc_packing scene: N bidisperse glass discs (half of diameter 2 mm, type 1, half
of 2.8 mm, type 2: the 1:1.4 mixture that does not crystallise), placed at random without
overlap (random sequential addition, numpy, fixed seed) in a box periodic in x, 80 mm wide, at
an area fraction of 0.35 above the floor, at rest. Both decks (in.packing, in.packing.soft)
read it.

    make_data.py [OUT] [N] [SEED]          (defaults: data.packing, 1000, 7)
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
import granular  # noqa: E402

WIDTH = 0.08
D_SMALL, D_LARGE = 0.002, 0.0028
PHI0 = 0.35


def scene(n=1000, seed=7):
    rng = np.random.default_rng(seed)
    d = np.where(np.arange(n) % 2 == 0, D_SMALL, D_LARGE)
    types = np.where(np.arange(n) % 2 == 0, 1, 2)
    area = float((math.pi / 4 * d ** 2).sum())
    height = area / (PHI0 * WIDTH)
    pos = np.zeros((n, 3))
    placed = 0
    order = np.argsort(-d, kind="stable")       # large discs first
    for k in order:
        r = 0.5 * d[k]
        for _ in range(100000):
            p = np.array([rng.uniform(0, WIDTH), rng.uniform(r, height - r)])
            if placed:
                q = pos[order[:placed], :2]
                dx = q[:, 0] - p[0]
                dx -= WIDTH * np.round(dx / WIDTH)           # periodic in x
                dist2 = dx ** 2 + (q[:, 1] - p[1]) ** 2
                if np.any(dist2 < (0.5 * d[order[:placed]] + r) ** 2 * 1.0001):
                    continue
            pos[k, :2] = p
            placed += 1
            break
        else:
            raise RuntimeError("could not place disc %d" % k)
    box = ((0.0, WIDTH), (0.0, 1.5 * height), (-D_LARGE, D_LARGE))
    return box, d, np.full(n, 2500.0), pos, types


def main():
    out, n, seed = granular.data_args("data.packing", 1000, 7)
    box, d, rho, pos, types = scene(n, seed)
    granular.write_data(out, box, d, rho, pos, None, types,
                        title="disc_packing: %d bidisperse discs (2 and 2.8 mm), seed %d" % (n, seed))
    print("%s: %d discs, box %s" % (out, n, box))


if __name__ == "__main__":
    main()
