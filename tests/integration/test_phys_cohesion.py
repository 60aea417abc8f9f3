#!/usr/bin/env python3
"""Cohesion (`cohesion F [I J]`): a touching contact holds up to F of pull before it opens
(core/cohesion.h: the law's bound shifted to mu >= -F).

1. A sphere hanging under a ceiling (g = 1, m g = 0.5236): with F = 0.6 > m g it stays where it
   is (z and vz exact to 1e-9) and the ceiling pulls it up with m g (the per-atom contact force
   f_ID[4] = m g); with F = 0.4 < m g it falls.
2. Two touching spheres pulled apart by opposite forces f (fix addforce), no gravity: with
   f < F they stay in contact (distance r1 + r2); with f > F they separate.
3. `cohesion 0` runs the paper's scheme: the same output, bit for bit, as no keyword.
4. With friction too (`friction 0.5 cohesion 0.5`: the bodies spin, and the pull moves u_free
   with its spins laid out after the velocities): the pair holds at f < F and opens at f > F
   as without friction, and nothing spins (the pull is along the line of centres: rotational energy 0).
Serially and under mpirun (the rank count ctest gives).
"""

import math

import numpy as np

import lammps_run as lr
import physics_common as pc

HANG = pc.DROP_ON_FLOOR.replace("wall zplane 0 NULL", "wall zplane NULL 10.0")

PAIR = pc.HEADER_3D_FREE + """region          box block -5 5 -5 5 -5 5
create_box      1 box
create_atoms    1 single -0.5 0.0 0.0
create_atoms    1 single 0.5 0.0 0.0
set             group all diameter 1.0 density 1.0
group           left id 1
group           right id 2
pair_style      none
neighbor        0.5 bin
fix             hc all hardcontact {keywords}
fix             pl left addforce -{f} 0 0
fix             pr right addforce {f} 0 0
timestep        0.01
variable        dist equal x[2]-x[1]
thermo_style    custom step v_dist
thermo_modify   format float %.15g
thermo          1
run             200
"""


def test():
    args = lr.test_args(__doc__)
    mg = 4.0 / 3.0 * math.pi * 0.5 ** 3
    out = ("variable        z equal z[1]\nvariable        vz equal vz[1]\n"
           "compute         fa all reduce sum f_hc[4]\n"
           "thermo_style    custom step v_z v_vz c_fa\nthermo_modify   format float %.15g\n"
           "thermo          1")

    # 1. hanging
    for F, holds in ((0.6, True), (0.4, False)):
        deck = HANG.format(x=0.0, y=0.0, z=9.5, fix_extra="cohesion %r" % F, h=0.01, n=200, output=out)
        res = lr.run_deck(args.lmp, deck, args.np, "%s/hang_%g" % (args.workdir, F), timeout=args.timeout)
        th = res.thermo[-1]
        z, vz, fz = th["v_z"], th["v_vz"], th["c_fa"]
        if holds:
            lr.check(float(np.abs(z - 9.5).max()) <= 1e-9 and float(np.abs(vz).max()) <= 1e-9,
                     "hanging, F = %g > m g: the sphere stays under the ceiling" % F)
            lr.check(abs(float(fz[-1]) - mg) <= 1e-6 * mg, "hanging: the ceiling pulls it up with "
                     "m g (contact force %.9g, m g = %.9g)" % (float(fz[-1]), mg))
        else:
            lr.check(float(z[-1]) < 9.5 - 1.0, "hanging, F = %g < m g: the sphere falls (z = %.4g)"
                     % (F, float(z[-1])))

    # 2. a pair pulled apart; 4. the same with friction, where nothing may spin
    spun = PAIR.replace("variable        dist equal x[2]-x[1]\n",
                        "variable        dist equal x[2]-x[1]\n"
                        "compute         w all erotate/sphere\n")
    spun = spun.replace("custom step v_dist", "custom step v_dist c_w")
    for deck, keywords, what in ((PAIR, "cohesion 0.5", "pair"),
                                 (spun, "friction 0.5 cohesion 0.5", "with friction")):
        for f, holds in ((0.3, True), (0.7, False)):
            res = lr.run_deck(args.lmp, deck.format(keywords=keywords, f=f), args.np,
                              "%s/%s_%g" % (args.workdir, what.replace(" ", "_"), f),
                              timeout=args.timeout)
            dist = res.thermo[-1]["v_dist"]
            if holds:
                lr.check(float(np.abs(dist - 1.0).max()) <= 1e-9, "%s, f = %g < F: stays in "
                         "contact (largest |distance - 1| %.3g)"
                         % (what, f, float(np.abs(dist - 1.0).max())))
            else:
                lr.check(float(dist[-1]) > 1.5, "%s, f = %g > F: separates (distance %.4g)"
                         % (what, f, float(dist[-1])))
            if deck is spun:
                w = res.thermo[-1]["c_w"]
                lr.check(float(np.abs(w).max()) <= 1e-24, "%s, f = %g: nothing spins (largest "
                         "rotational energy %.3g)" % (what, f, float(np.abs(w).max())))

    # 3. cohesion 0 is the paper's scheme, to the last bit
    a = lr.run_deck(args.lmp, PAIR.format(keywords="", f=0.3), args.np, args.workdir + "/plain",
                    timeout=args.timeout).thermo[-1]["v_dist"]
    b = lr.run_deck(args.lmp, PAIR.format(keywords="cohesion 0", f=0.3), args.np,
                    args.workdir + "/zero", timeout=args.timeout).thermo[-1]["v_dist"]
    lr.check(np.array_equal(a, b), "cohesion 0: the same output as no keyword, bit for bit")


if __name__ == "__main__":
    lr.main(test)
