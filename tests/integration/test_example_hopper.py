#!/usr/bin/env python3
"""examples/hopper (2d flat-bottomed silo), shortened: 480 discs (d = 1.6-2.4 mm) settle for
0.15 s on a floor of frozen 1 mm discs (type 2, outside the fix group: obstacles), then drain
for 0.25 s through outlets of 8 and 12 mm (h = 1 ms).

Checked for each outlet:
  * frozen floor discs never move (positions of type 2 unchanged in every dump frame), and
    grains cross the floor only through the outlet (a grain whose centre is at floor level,
    |y| < 0.5 mm, is within D/2 of the middle);
  * discs are conserved: in the silo + fallen out of it (still in the box or lost through
    the bottom of the box) = 480;
  * no solve stopped at maxiter, f_hc[7] <= 1e-4 at every thermo step;
  * the discharge rate (slope of the discs left in the silo, beverloo.py, after 0.1 s of
    flow) is 0.70-1.10 of the full example's (960 discs: 477 /s for 8 mm, 922 /s for 12 mm),
    and the ratio Q(12 mm) / Q(8 mm) is 1.6-2.4 (Beverloo's (D - k d)^3/2 with the example's
    k = 0.59: 2.0; the measured one: 1.95).
The half-height bed drains a little slower than the full one, and a run's rate over 0.15 s
of flow (about 90 discs) moves with the solver, the flow being chaotic: measured 358 (cg)
and 412 (apgd) /s for 8 mm, 780 and 792 /s for 12 mm (0.75-0.86 of the full example; with
0.4 s of flow 395 / 380 and 725 / 718)."""

import os
import subprocess
import sys

import numpy as np

import lammps_run as lr

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
EX = os.path.join(ROOT, "examples", "hopper")
sys.path.insert(0, EX)
sys.path.insert(0, os.path.join(ROOT, "examples", "common"))
import beverloo  # noqa: E402
import granular as g  # noqa: E402

FULL = {8: 477.3, 12: 922.4}


def test():
    args = lr.test_args(__doc__)
    data = os.path.join(args.workdir, "data.silo")
    subprocess.check_call([sys.executable, os.path.join(EX, "make_data.py"), data, "16"])
    rates = {}
    for w in (8, 12):
        res = lr.run_deck(args.lmp, os.path.join(EX, "in.silo"), args.np, os.path.join(args.workdir, "D%d" % w),
                          variables={"outlet": w / 1000.0, "data": data, "tsettle": 0.15, "tflow": 0.25,
                                     "dump_dt": 0.05, "pictures": "no"}, timeout=args.timeout)
        flow = res.thermo[-1]
        print("D = %d mm: %.1f s" % (w, res.seconds))
        for blk in res.thermo:
            lr.check(int(blk["f_hc[6]"][-1]) == 0 and float(blk["f_hc[7]"].max()) <= 1e-4,
                     "D = %d mm: no maxiter, f_hc[7] <= tol (max %.3g)" % (w, float(blk["f_hc[7]"].max())))
        frames = g.read_dump(res.path("silo.dump"))
        floor0 = frames[0].columns
        fx0 = {int(i): (x, y) for i, x, y, t in zip(floor0["id"], floor0["x"], floor0["y"], floor0["type"]) if t == 2}
        moved, leaked = 0.0, 0
        for _, c, _ in frames:
            for i, x, y, t, r in zip(c["id"], c["x"], c["y"], c["type"], c["radius"]):
                if t == 2:
                    moved = max(moved, abs(x - fx0[int(i)][0]), abs(y - fx0[int(i)][1]))
                elif abs(y) < 0.0005 and abs(x - 0.04) > 0.5 * w / 1000.0:
                    leaked += 1
        lr.check(moved == 0.0, "D = %d mm: frozen floor discs never move" % w)
        lr.check(leaked == 0, "D = %d mm: grains leave only through the outlet" % w)
        inside = flow["v_inside"]
        left = flow["v_left"]     # grains still in the box
        lost = 480 - left
        lr.check(int(inside[0]) == 480 and bool(np.all(inside + (left - inside) + lost == 480)),
                 "D = %d mm: 480 discs, %d left the silo (%d of them the box)" % (w, 480 - inside[-1], lost[-1]))
        q = beverloo.rate(str(res.workdir))[0]
        rates[w] = q
        lr.check(0.70 <= q / FULL[w] <= 1.10, "D = %d mm: discharge rate %.0f /s, 0.70-1.10 of the full "
                 "example's %.0f /s" % (w, q, FULL[w]))
    ratio = rates[12] / rates[8]
    lr.check(1.6 <= ratio <= 2.4, "Q(12 mm) / Q(8 mm) = %.2f" % ratio)


if __name__ == "__main__":
    lr.main(test)
