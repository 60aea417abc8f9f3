#!/usr/bin/env python3
"""NOT REGISTERED (fails with the fix as of 6397911): the neighbor-list rebuild look-ahead of
fix hardcontact ignores that velocities change from one step to the next.

A single sphere (r = 0.5) falls under `fix gravity 2.0` with v_x = 0.9 onto
`wall zplane 0.0 NULL`, h = 0.05, `neighbor 1.0 bin`. The largest move of any step before the
landing is 0.11, so the skin is 9 x that (the documentation asks for 4 x). Expected: the run
completes and the sphere rests on the floor. What happens: at step 20 the fix stops with
"an atom moved 0.503115 since the last neighbor list build, more than half the skin (0.5) ...
The largest move in one step was 0.109659: use 'neighbor 0.439 bin' (4 x that)" - advice
smaller than the skin in use.

Cause (src/lammps/integrate.cpp, Integrate::move): after the move of step n it
forces a rebuild when disp + h |u^n| > skin/2, i.e. it assumes the next move equals this
one. Under a force (or after a contact impulse that speeds an atom up) the next move is
h |u^{n+1}| > h |u^n|: here at step 19 disp + h|u^19| = 0.498692 < 0.5 (no rebuild) and at
step 20 disp = 0.503115 > 0.5 (error). Any skin can hit such a window (1.5 fails at step 38).
A fix: bound the next move with a margin, e.g. rebuild when disp + 2 h max|u| > skin/2 (or
add h^2 |f|/m), and make the error advice never smaller than the skin in use."""

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
