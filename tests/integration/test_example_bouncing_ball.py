#!/usr/bin/env python3
"""examples/bouncing_ball: the deck as shipped (16 time units, two balls). The ball on the still
floor reaches e^(2k) H at its k-th apex within 1 % for k = 1..9, rests from the tenth impact on
(impact speed 2 e^9 below `bounce` 0.3), and the ball on the vibrated floor never overlaps it
and is thrown higher than it started."""

import os

import numpy as np

import lammps_run as lr

EX = os.path.join(os.environ.get("HARDCONTACT_SOURCE_DIR", "."), "examples", "bouncing_ball")


def test():
    args = lr.test_args(__doc__)
    res = lr.run_deck(args.lmp, os.path.join(EX, "in.bounce"), args.np, args.workdir,
                      timeout=args.timeout, args=["-var", "tend", "16"])
    th = res.thermo[-1]
    z1, z2, floor = th["v_z1"], th["v_z2"], th["v_floor"]
    e, H = 0.8, float(z1[0])
    apex = [float(z1[k]) for k in range(1, len(z1) - 1) if z1[k - 1] < z1[k] >= z1[k + 1] and z1[k] > 1e-3]
    lr.check(len(apex) == 9, "still floor: nine flights before the impact speed falls below "
             "bounce (%d)" % len(apex))
    for k, a in enumerate(apex, start=1):
        want = e ** (2 * k) * H
        lr.check(abs(a - want) <= 0.01 * want + 2e-4, "apex %d at %.5f, e^%d H = %.5f" % (k, a, 2 * k, want))
    lr.check(abs(float(z1[-1])) <= 1e-9, "then at rest on the floor (%.2e)" % float(z1[-1]))
    gap = z2 - floor
    lr.check(float(gap.min()) >= -1e-6, "vibrated floor: never an overlap (%.2e)" % float(gap.min()))
    lr.check(float(z2.max()) > H, "vibrated floor: the ball is thrown above its start (%.3f)" % float(z2.max()))


if __name__ == "__main__":
    lr.main(test)
