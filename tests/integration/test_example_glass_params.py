#!/usr/bin/env python3
"""potentials/glass_beads.params: the soft-sphere coefficients it derives give the restitution
asked for. Two glass discs (d = 2 mm, E = 10 MPa as the twins use) collide head-on at the
relative speed gb_speed = 1 m/s with pair_style gran/hertz/history, and a third one hits
fix wall/gran at 1 m/s; dt = contact time / 20 (gb_dt). Checked for e = 0.1, 0.5 and 0.9:
the measured restitution (separation speed / approach speed) is within 10% of the target
for e = 0.1 (0.093: the time step is coarse for a strongly damped contact) and within 1% for
0.5 and 0.9, for the pair and for the wall; the contact time printed by the file (undamped
Hertz) is Hertz's 2.868 (m*^2 / (R* E*^2 v))^1/5 = 2.077e-4 s."""

import math

import os

import lammps_run as lr

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

DECK = """
variable gb_diameter index 0.002
variable gb_speed index 1.0
variable gb_youngs index 1.0e7
include {params}
print "CONTACT_TIME ${{gb_tcontact}}"
units si
dimension 2
atom_style sphere
atom_modify map array
boundary f f p
newton off
comm_modify vel yes
region box block -0.05 0.05 -0.05 0.05 -0.001 0.001 units box
create_box 1 box
create_atoms 1 single -0.0015 0.005 0 units box
create_atoms 1 single 0.0015 0.005 0 units box
create_atoms 1 single -0.02 0.003 0 units box
set group all diameter ${{gb_diameter}}
set group all density ${{gb_density}}
group a id 1
group b id 2
group c id 3
velocity a set 0.5 0 0 units box
velocity b set -0.5 0 0 units box
velocity c set 0 -1.0 0 units box
pair_style gran/hertz/history ${{gb_kn}} ${{gb_kt}} ${{gb_gamman}} ${{gb_gammat}} ${{gb_xmu}} 0
pair_coeff * *
fix 1 all nve/sphere
fix w all wall/gran hertz/history ${{gb_kn}} ${{gb_kt}} ${{gb_gamman_wall}} ${{gb_gammat_wall}} ${{gb_xmu}} 0 yplane 0 NULL
fix 2 all enforce2d
timestep ${{gb_dt}}
variable va equal vx[1]
variable vb equal vx[2]
variable vc equal vy[3]
thermo_style custom step v_va v_vb v_vc
thermo_modify format float %.10g
thermo 2000
run 2000
"""


def test():
    args = lr.test_args(__doc__)
    deck = DECK.format(params=os.path.join(ROOT, "potentials", "glass_beads.params"))
    for e, rel in ((0.1, 0.10), (0.5, 0.01), (0.9, 0.01)):
        res = lr.run_deck(args.lmp, deck, args.np, os.path.join(args.workdir, "e%g" % e),
                          variables={"gb_restitution": e}, timeout=args.timeout)
        tc = float(next(l.split()[1] for l in res.stdout.splitlines() if l.startswith("CONTACT_TIME")))
        th = res.thermo[-1]
        e_pair = float(th["v_vb"][-1] - th["v_va"][-1])
        e_wall = float(th["v_vc"][-1])
        m = math.pi / 6 * 0.002 ** 3 * 2500.0
        estar = 1e7 / (2 * (1 - 0.22 ** 2))
        hertz = 2.868 * ((m / 2) ** 2 / (0.0005 * estar ** 2 * 1.0)) ** 0.2
        lr.check(abs(tc / hertz - 1) < 1e-3, "e = %g: contact time %.5g s (Hertz %.5g s)" % (e, tc, hertz))
        lr.check(abs(e_pair - e) <= rel * e, "e = %g: pair restitution %.4f" % (e, e_pair))
        lr.check(abs(e_wall - e) <= rel * e, "e = %g: wall restitution %.4f" % (e, e_wall))


if __name__ == "__main__":
    lr.main(test)
