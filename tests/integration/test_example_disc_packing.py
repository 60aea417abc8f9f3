#!/usr/bin/env python3
"""examples/disc_packing, shortened to 500 bidisperse discs (2 and 2.8 mm, 1:1, random loose
start from make_data.py, box periodic in x, 80 mm wide) compressed by gravity for 0.4 s
(400 steps of h = 1e-3 s with fix hardcontact; about 42 000 steps for the soft twin).

Hard contacts (in.packing), checked on the final state (examples/disc_packing/packing.py):
  * no solve stopped at maxiter; f_hc[7] <= 1e-4 at every thermo step; no dumped pair or
    floor contact overlapping beyond 1e-4 of the contact size;
  * random close packing of frictionless discs: area fraction in the bulk 0.82-0.86
    (full example: 0.840);
  * isostatic: the force-carrying contacts (pairs + floor, force > 0 in contacts.dump) number
    2 N within 3% (2 degrees of freedom per disc; full example: 1993 for 2000), no disc
    without contact;
Soft twin (in.packing.soft): its bulk area fraction is within 0.02 of the hard one (it is
denser: the discs overlap)."""

import os
import subprocess
import sys

import lammps_run as lr

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
EX = os.path.join(ROOT, "examples", "disc_packing")
sys.path.insert(0, EX)
sys.path.insert(0, os.path.join(ROOT, "examples", "common"))
import granular as g  # noqa: E402
import packing  # noqa: E402

N = 500


def test():
    args = lr.test_args(__doc__)
    data = os.path.join(args.workdir, "data.packing")
    subprocess.check_call([sys.executable, os.path.join(EX, "make_data.py"), data, str(N)])
    common = {"data": data, "tend": 0.4, "dump_dt": 0.1, "potentials": os.path.join(ROOT, "potentials")}
    hard = lr.run_deck(args.lmp, os.path.join(EX, "in.packing"), args.np, os.path.join(args.workdir, "hard"),
                       variables=common, timeout=args.timeout)
    th = hard.thermo[-1]
    print("hard: %d steps in %.1f s" % (th["Step"][-1], hard.seconds))
    lr.check(int(th["f_hc[6]"][-1]) == 0, "hard: no solve stopped at maxiter")
    lr.check(float(th["f_hc[7]"].max()) <= 1e-4, "hard: f_hc[7] <= tol (max %.3g)" % float(th["f_hc[7]"].max()))
    worst = max(g.overlaps(c, [(1, 0.0, 1)])[1] for _, c, _ in g.read_dump(hard.path("packing.dump")))
    lr.check(worst <= 1e-4 + 1e-6, "hard: dumped frames, largest overlap %.3g of the contact size" % worst)
    m = packing.measure(str(hard.workdir))
    lr.check(0.82 <= m["phi"] <= 0.86, "hard: bulk area fraction %.4f" % m["phi"])
    lr.check(abs(m["nc"] - 2 * N) <= 0.03 * 2 * N and m["loose"] == 0,
             "hard: isostatic, %d force-carrying contacts for 2N = %d, %d discs without contact"
             % (m["nc"], 2 * N, m["loose"]))

    soft = lr.run_deck(args.lmp, os.path.join(EX, "in.packing.soft"), args.np, os.path.join(args.workdir, "soft"),
                       variables=common, timeout=args.timeout)
    print("soft: %d steps in %.1f s" % (soft.thermo[-1]["Step"][-1], soft.seconds))
    ms = packing.measure(str(soft.workdir))
    lr.check(abs(ms["phi"] - m["phi"]) <= 0.02, "soft: bulk area fraction %.4f (hard %.4f)" % (ms["phi"], m["phi"]))


if __name__ == "__main__":
    lr.main(test)
