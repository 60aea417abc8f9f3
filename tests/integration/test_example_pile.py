#!/usr/bin/env python3
"""examples/pile, shortened to 0.2 s of physical time (200 steps of h = 1e-3 s with
fix hardcontact; about 20 000 steps of 1e-5 s for the soft-sphere twin): 750 glass discs
(d = 1.6-2.4 mm, data file from make_data.py) fall into a box 80 mm wide and settle.

Hard contacts (in.pile), checked:
  * 750 atoms at every step; no solve stopped at maxiter (f_hc[6] = 0);
  * no overlap beyond the tolerance: f_hc[7] <= 1e-4 at every step, and from the dumped
    positions (%.10g) every pair and every wall within 1e-4 of the contact size (+ print
    rounding);
  * the bed settles: kinetic energy at the end below 1e-3 of its peak; bed height 34-38 mm
    (full run: 35.6 mm);
  * the floor carries the weight: at the last step the forces of the floor contacts
    (dump local, wall 3 = yplane lo) sum to M g within 5% (frictionless discs: the side
    walls carry no weight; the bed still creeps, the load fluctuates by 1-2% from step to
    step even at 0.4 s), the per-atom contact forces (f_hc[3], pair forces cancel) add up
    to the same load, and side-wall forces are horizontal;
Soft twin (in.pile.soft, same data, potentials/glass_beads.params), checked: runs, its bed
height agrees with the hard one within 3% (0.5% in the full run), its largest overlap is a few
percent of the contact size (Hertz at 10 MPa), and examples/compare.py prints the side-by-side
table for the two runs."""

import os
import subprocess
import sys

import numpy as np

import lammps_run as lr

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
EX = os.path.join(ROOT, "examples", "pile")
sys.path.insert(0, os.path.join(ROOT, "examples", "common"))
import granular as g  # noqa: E402

TEND = 0.2
WALLS = [(0, 0.0, 1), (0, 0.08, -1), (1, 0.0, 1)]


def test():
    args = lr.test_args(__doc__)
    data = os.path.join(args.workdir, "data.pile")
    subprocess.check_call([sys.executable, os.path.join(EX, "make_data.py"), data])
    common = {"data": data, "tend": TEND, "potentials": os.path.join(ROOT, "potentials")}

    hard = lr.run_deck(args.lmp, os.path.join(EX, "in.pile"), args.np, os.path.join(args.workdir, "hard"),
                       variables=common, timeout=args.timeout)
    th = hard.thermo[-1]
    print("hard: %d steps in %.1f s" % (th["Step"][-1], hard.seconds))
    lr.check(int(th["Step"][-1]) == 200 and bool(np.all(th["Atoms"] == 750)), "hard: 200 steps, 750 atoms")
    lr.check(int(th["f_hc[6]"][-1]) == 0, "hard: no solve stopped at maxiter")
    lr.check(float(th["f_hc[7]"].max()) <= 1e-4, "hard: f_hc[7] <= tol at every thermo step (max %.3g)"
             % float(th["f_hc[7]"].max()))
    frames = g.read_dump(hard.path("pile.dump"))
    worst = max(g.overlaps(c, WALLS)[1] for _, _, c in frames)
    lr.check(worst <= 1e-4 + 1e-6, "hard: dumped positions, largest overlap %.3g of the contact size" % worst)
    ke = th["c_ke"]
    lr.check(ke[-1] <= 1e-3 * ke.max(), "hard: settled, KE %.3g J at the end, peak %.3g J" % (ke[-1], ke.max()))
    last = frames[-1][2]
    top_hard = g.bed_height(last)
    lr.check(0.034 <= top_hard <= 0.038, "hard: bed height %.4g m" % top_hard)

    # the floor carries the weight (last frame of the contact dump)
    local = lr.read_dump_local(hard.path("contacts.dump"))[-1]
    c = local.columns
    wall = c["f_hc[7]"].astype(int)
    fy_floor = float((c["f_hc[3]"] * -c["f_hc[5]"])[wall == 3].sum())   # normal points to the wall
    weight = float((g.sphere_mass(2 * last["radius"], 2500.0) * 9.81).sum())
    lr.check(abs(fy_floor - weight) <= 0.05 * weight,
             "hard: floor load %.6g N = weight %.6g N (%.2g)" % (fy_floor, weight, fy_floor / weight - 1))
    # pair forces cancel: the per-atom contact forces add up to the wall forces, exactly
    fy_atoms = float(last["f_hc[3]"].sum())
    lr.check(abs(fy_atoms - fy_floor) <= 1e-6 * weight,
             "hard: per-atom contact forces sum to the floor load (%.9g N, %.9g N)" % (fy_atoms, fy_floor))
    side = (wall == 1) | (wall == 2)
    lr.check(bool(np.all(np.abs(c["f_hc[5]"][side]) < 1e-12)), "hard: side-wall contacts are horizontal")

    soft = lr.run_deck(args.lmp, os.path.join(EX, "in.pile.soft"), args.np, os.path.join(args.workdir, "soft"),
                       variables=common, timeout=args.timeout)
    ths = soft.thermo[-1]
    print("soft: %d steps in %.1f s" % (ths["Step"][-1], soft.seconds))
    sframes = g.read_dump(soft.path("pile.dump"))
    top_soft = g.bed_height(sframes[-1][2])
    lr.check(abs(top_soft - top_hard) <= 0.03 * top_hard, "soft: bed height %.4g m (hard %.4g m)" % (top_soft, top_hard))
    ov = max(g.overlaps(c, WALLS)[1] for _, _, c in sframes)
    lr.check(1e-3 < ov < 0.05, "soft: largest overlap %.3g of the contact size" % ov)

    out = subprocess.run([sys.executable, os.path.join(ROOT, "examples", "compare.py"), "pile",
                          str(hard.workdir), str(soft.workdir), os.path.join(args.workdir, "compare.png")],
                         stdout=subprocess.PIPE, universal_newlines=True, check=True).stdout
    print(out)
    lr.check("wall time ratio soft / hard" in out and "packing fraction" in out, "compare.py prints the table")


if __name__ == "__main__":
    lr.main(test)
