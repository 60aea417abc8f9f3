#!/usr/bin/env python3
"""A frictional 3D pile at rest stays at rest, with every solve converged (soak).

Scene: bench/compare/in.pile3d at 20 layers (2000 polydisperse spheres, d 0.8-1.0, density 1,
on a loose simple-cubic lattice, spacing 1.1) falling into a walled 11 x 11 box, `friction 0.5`
(apgd, the default with friction), tol 1e-4, h = 0.02: SETTLE steps to fall and come to rest,
then a window of WINDOW steps.
Why: at rest a new contact can leave a few sticking contacts just above tol, which apgd's one
global step does not settle (the tangential forces of a frictional pile are indeterminate and it
moves all of them): before its stalled solves got Gauss-Seidel sweeps over the violated rows
(src/core/solvers/apgd.cpp), such a pile had 40 solves in a row stop at maxiter, its kinetic
energy rose 4000-fold and it lost a fifth of its contacts (doc/performance.md section 10.4).
Asserted over the window: no solve stopped at maxiter (f_hc[6] unchanged), the largest overlap
at most tol at every step (f_hc[7]), the kinetic energy per sphere below 1e-8 m g d at every
step, the active contacts at the end at least 0.95 x those at the start, and the mean
iterations per step at most 100 (measured: 12-20, the settle 200)."""

import lammps_run as lr
import physics_common as pc

TOL = 1e-4
SETTLE, WINDOW = 2500, 1000

DECK = """
units           lj
atom_style      sphere
dimension       3
boundary        f f f
atom_modify     map array
region          box block 0 11 0 11 0 40
create_box      1 box
lattice         sc 1.1 origin 0.5 0.5 0.5
region          fill block 0 11 0 11 0 20
create_atoms    1 region fill
variable        hsh atom 43758.5453*sin(12.9898*id+78.233)
variable        d atom 0.8+0.2*(v_hsh-floor(v_hsh))
set             group all diameter v_d
set             group all density 1.0
pair_style      none
neighbor        0.3 bin
neigh_modify    delay 0 every 1 check yes
fix             hc all hardcontact tol {tol} friction 0.5 wall xplane 0 11 wall yplane 0 11 wall zplane 0 NULL
fix             g all gravity 1.0 vector 0 0 -1
timestep        0.02
thermo_style    custom step atoms ke f_hc[1] f_hc[4] f_hc[6] f_hc[7]
thermo_modify   norm no format float %.10g
thermo          100
run             {settle}
thermo          1
run             {window}
"""


def test():
    args = lr.test_args(__doc__)
    res = lr.run_deck(args.lmp, DECK.format(tol=TOL, settle=SETTLE, window=WINDOW), args.np,
                      "%s/friction_rest" % args.workdir, timeout=args.timeout)
    cols = ["Step", "Atoms", "KinEng", "f_hc[1]", "f_hc[4]", "f_hc[6]", "f_hc[7]"]
    lr.check(len(res.thermo) == 2, "two thermo blocks: the settle and the window")
    win = res.thermo[-1]
    missing = [c for c in cols if c not in win]
    lr.check(not missing, "thermo columns present (missing: %s)" % missing)
    lr.check(len(win["Step"]) == WINDOW + 1 and win["Step"][-1] == SETTLE + WINDOW,
             "the window runs %d steps after %d of settling" % (WINDOW, SETTLE))
    n = win["Atoms"][-1]
    lr.check(n == 2000, "no atom lost (%d)" % n)
    stops = win["f_hc[6]"][-1] - win["f_hc[6]"][0]
    lr.check(stops == 0, "no solve of the window stopped at maxiter (%d did)" % stops)
    worst = max(win["f_hc[7]"])
    lr.check(worst <= TOL * (1.0 + 1e-9), "largest overlap at every step %.3g <= tol %g" % (worst, TOL))
    mgd = pc.sphere_mass(0.45, 1.0) * 1.0 * 0.9    # mean sphere: d 0.9
    ke = max(win["KinEng"]) / n / mgd
    lr.check(ke <= 1e-8, "at rest: kinetic energy per sphere %.3g m g d <= 1e-8 at every step" % ke)
    a0, a1 = win["f_hc[4]"][0], win["f_hc[4]"][-1]
    lr.check(a1 >= 0.95 * a0, "active contacts kept: %d at the end, %d at the start" % (a1, a0))
    it = sum(win["f_hc[1]"][1:]) / WINDOW
    lr.check(it <= 100, "mean iterations per step in the window %.1f <= 100" % it)


if __name__ == "__main__":
    lr.main(test)
