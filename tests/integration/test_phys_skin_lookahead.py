#!/usr/bin/env python3
"""The neighbour-list rebuild look-ahead of fix hardcontact under an acceleration, with LAMMPS's
default neigh_modify (every 1 delay 0 check yes): the fix itself forces the rebuilds it needs.

A single sphere (r = 0.5) falls under `fix gravity 2.0` with v_x = 0.9 onto
`wall zplane 0.0 NULL`, h = 0.05, `neighbor 1.0 bin`; its largest move in a step before the
landing is 0.11, the skin 9 x that. The run must complete and the sphere rest on the floor.

Once a regression (fixed since; the test was then not registered): the look-ahead assumed the
next move equals the last one, so a sphere sped up by gravity could cross skin/2 between two
checks and the fix stopped the run at step 20 with advice smaller than the skin in use. Now
(src/lammps/integrate.cpp, Integrate::move) a rebuild is forced when the two largest
displacements since the last build plus twice this step's move could reach the skin, and the
error's advice is never below twice the skin in use."""

import lammps_run as lr
import physics_common as pc

DECK = """
units           lj
atom_style      sphere
boundary        p p f
atom_modify     map array
read_data       data.one
pair_style      none
neighbor        1.0 bin
fix             grav all gravity 2.0 vector 0 0 -1
fix             hc all hardcontact wall zplane 0.0 NULL
timestep        0.05
thermo          1
variable        z equal z[1]
variable        vz equal vz[1]
thermo_style    custom step atoms v_z v_vz f_hc[7]
thermo_modify   format float %.16g
run             60
"""


def test():
    args = lr.test_args(__doc__)
    pc.write_sphere_data(args.workdir + "/data.one", ((-2.0, 2.0), (-2.0, 2.0), (0.0, 5.0)), 0.5, 2.0,
                         [[0.0, 0.0, 3.0]], [[0.9, 0.0, 0.0]])
    try:
        res = lr.run_deck(args.lmp, DECK, args.np, args.workdir, timeout=args.timeout)
    except lr.LammpsRunError as e:
        raise AssertionError("free fall with skin = 9 x the largest step stops: %s" % e)
    th = pc.thermo_block(res, ["Step", "v_z", "v_vz"])
    lr.check(int(th["Step"][-1]) == 60, "run completes 60 steps")
    lr.check(abs(th["v_z"][-1] - 0.5) <= 1e-4 * 0.5 and abs(th["v_vz"][-1]) <= 1e-12,
             "sphere at rest on the floor (z %.12g, v_z %.3g)" % (th["v_z"][-1], th["v_vz"][-1]))


if __name__ == "__main__":
    lr.main(test)
