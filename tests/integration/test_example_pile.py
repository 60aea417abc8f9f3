#!/usr/bin/env python3
"""examples/pile as it runs (0.4 s of physical time: 400 steps of h = 1e-3 s with
fix hardcontact; about 40 000 steps of 1e-5 s for the soft-sphere twin): 750 glass discs
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
  * stress (compute stress/atom, the fix's virial): at rest, with frictionless side walls, the
    virial theorem gives sum_i W_yy(i) = sum_i m_i g y_i (walls as the pair's other end at the
    contact point): within 1% at the last frame (measured 3e-5);
Soft twin (in.pile.soft, same data, potentials/glass_beads.params), checked: runs, its bed
height agrees with the hard one within 3% (0.5% in the full run), its largest overlap is a few
percent of the contact size (Hertz at 10 MPa), and examples/compare.py prints the side-by-side
table for the two runs. The twins measure the same stress: in the interior (10 mm from the
side walls, 20-80 % of the bed height) the stress per grain area, averaged over the last three
dumps (0.3-0.4 s), sigma_yy within 3 % (measured 1.7 %) and the mean stress (sigma_xx +
sigma_yy)/2 within 5 % (measured 3.6 %; the lateral stress ratio K = sigma_xx/sigma_yy is 0.88
hard, 0.93 soft, a packing property)."""

import os
import subprocess
import sys

import numpy as np

import lammps_run as lr

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
EX = os.path.join(ROOT, "examples", "pile")
sys.path.insert(0, os.path.join(ROOT, "examples", "common"))
import granular as g  # noqa: E402

TEND = 0.4
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
    lr.check(int(th["Step"][-1]) == 400 and bool(np.all(th["Atoms"] == 750)), "hard: 400 steps, 750 atoms")
    lr.check(int(th["f_hc[6]"][-1]) == 0, "hard: no solve stopped at maxiter")
    lr.check(float(th["f_hc[7]"].max()) <= 1e-4, "hard: f_hc[7] <= tol at every thermo step (max %.3g)"
             % float(th["f_hc[7]"].max()))
    frames = g.read_dump(hard.path("pile.dump"))
    worst = max(g.overlaps(c, WALLS)[1] for _, c, _ in frames)
    lr.check(worst <= 1e-4 + 1e-6, "hard: dumped positions, largest overlap %.3g of the contact size" % worst)
    ke = th["c_ke"]
    lr.check(ke[-1] <= 1e-3 * ke.max(), "hard: settled, KE %.3g J at the end, peak %.3g J" % (ke[-1], ke.max()))
    last = frames[-1].columns
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
    m = g.sphere_mass(2 * last["radius"], 2500.0)
    w_yy, want = float(-last["c_stress[2]"].sum()), float((m * 9.81 * last["y"]).sum())
    lr.check(abs(w_yy - want) <= 0.01 * want,
             "hard: sum of stress/atom yy %.6g = sum m g y %.6g (%.2g)" % (w_yy, want, w_yy / want - 1))

    soft = lr.run_deck(args.lmp, os.path.join(EX, "in.pile.soft"), args.np, os.path.join(args.workdir, "soft"),
                       variables=common, timeout=args.timeout)
    ths = soft.thermo[-1]
    print("soft: %d steps in %.1f s" % (ths["Step"][-1], soft.seconds))
    sframes = g.read_dump(soft.path("pile.dump"))
    top_soft = g.bed_height(sframes[-1].columns)
    lr.check(abs(top_soft - top_hard) <= 0.03 * top_hard, "soft: bed height %.4g m (hard %.4g m)" % (top_soft, top_hard))
    ov = max(g.overlaps(c, WALLS)[1] for _, c, _ in sframes)
    lr.check(1e-3 < ov < 0.05, "soft: largest overlap %.3g of the contact size" % ov)

    # the same stress inside the bed, hard and soft: per grain area, mean of the last 3 dumps
    def interior_stress(frames):
        xx, yy = [], []
        for _, c, _ in frames[-3:]:
            h = g.bed_height(c)
            sel = (c["x"] > 0.01) & (c["x"] < 0.07) & (c["y"] > 0.2 * h) & (c["y"] < 0.8 * h)
            area = float((np.pi * c["radius"][sel] ** 2).sum())
            xx.append(-float(c["c_stress[1]"][sel].sum()) / area)
            yy.append(-float(c["c_stress[2]"][sel].sum()) / area)
        return float(np.mean(xx)), float(np.mean(yy))
    hxx, hyy = interior_stress(frames)
    sxx, syy = interior_stress(sframes)
    print("interior stress per grain area (N/m): hard xx %.4g yy %.4g, soft xx %.4g yy %.4g" % (hxx, hyy, sxx, syy))
    lr.check(abs(hyy - syy) <= 0.03 * syy, "stress: interior sigma_yy hard %.4g, soft %.4g (%.2g)" % (hyy, syy, hyy / syy - 1))
    hp, sp = (hxx + hyy) / 2, (sxx + syy) / 2
    lr.check(abs(hp - sp) <= 0.05 * sp, "stress: interior mean stress hard %.4g, soft %.4g (%.2g; K %.2f hard, %.2f soft)"
             % (hp, sp, hp / sp - 1, hxx / hyy, sxx / syy))

    out = subprocess.run([sys.executable, os.path.join(ROOT, "examples", "compare.py"), "pile",
                          str(hard.workdir), str(soft.workdir), os.path.join(args.workdir, "compare.png")],
                         stdout=subprocess.PIPE, universal_newlines=True, check=True).stdout
    print(out)
    lr.check("wall time ratio soft / hard" in out and "packing fraction" in out, "compare.py prints the table")


if __name__ == "__main__":
    lr.main(test)
