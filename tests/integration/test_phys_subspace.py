#!/usr/bin/env python3
"""`subspace N` (solvers cg and apgd): the start of each solve moved to the best point in the
span of the last N corrections, kept only if the dual objective fell
(src/core/solvers/past_corrections.h). It changes where a solver starts, never what it stops at.

Scene: a heavy sphere (d = 10, 1000 x the mass of a small one) resting on a walled 14 x 14
tray of spheres of d = 1 on a floor (bench/perf's tray at mass ratio 1000, doc/performance.md
section 2), tol 1e-4, h = 0.02. The same deck runs twice, `subspace 0` and `subspace 10`: 200
steps to come to rest, then a window of 60. Checked for the run with the subspace, at every
step: the largest overlap f_ID[7] at most tol (it is an overlap relative to the contact
size), no maxiter stop, the kinetic energy per sphere at rest below 1e-8 m g d in the window;
and against the run without: the heavy sphere at the same height (both are the scheme's answer
to tol: 1e-6 d, plus what kept overlaps allow, src/core/kept_overlaps.h: each of the two
contacts in series under it, heavy-small and small-floor, may rest up to tol size / 10 deep,
tol (5.5 + 0.5) / 10 = 6e-5 d; measured 1.1e-6 d with cg), and the mechanism at work: the window's mean iterations per step at most half
(measured: cg 32 -> 2-4, apgd 48 -> 1.5 here, 880 -> 5-16 from bench/perf's rest state).
`subspace 10` is cg's default without friction: cg also runs without the keyword, and must give
the run with `subspace 10` step for step (iterations, height and kinetic energy to the bit). Run
at np 1, 2 and 4: every process takes the same coefficients (one reduction), or a row held by two
processes would get two forces."""

import lammps_run as lr
import physics_common as pc

TOL = 1e-4
# the heavy sphere's height: the solves' tolerance, plus the kept overlaps of the two contacts
# in series under it (sizes 5.5 and 0.5, a tenth of tol size each)
DZ_MAX = 1e-6 + TOL * (5.5 + 0.5) / 10
SETTLE, WINDOW = 200, 60

DECK = """
units           lj
dimension       3
atom_style      sphere
boundary        f f f
atom_modify     map array
region          box block 0 14 0 14 0 16
create_box      1 box
lattice         sc 1.0 origin 0.5 0.5 0.5
region          tray block 0 14 0 14 0 1
create_atoms    1 region tray
create_atoms    1 single 7.0 7.0 6.2 units box
group           heavy id 197
set             group all diameter 1.0
set             group heavy diameter 10.0
set             group all density 1.0
pair_style      none
neighbor        0.3 bin
neigh_modify    delay 0 every 1 check yes
fix             grav all gravity 1.0 vector 0 0 -1
fix             hc all hardcontact solver {solver} tol {tol} {subspace}wall xplane 0.0 14.0 wall yplane 0.0 14.0 wall zplane 0.0 NULL
timestep        0.02
variable        zh equal z[197]
thermo_style    custom step ke v_zh f_hc[1] f_hc[6] f_hc[7]
thermo_modify   format float %.16g norm no
thermo          1
run             {steps}
"""


def run(args, solver, n):
    """n: the subspace keyword's value, or None: no keyword (the fix's default)"""
    deck = DECK.format(solver=solver, tol=TOL, steps=SETTLE + WINDOW,
                       subspace="" if n is None else "subspace %d " % n)
    name = "%s/%s_subspace%s" % (args.workdir, solver, "default" if n is None else n)
    res = lr.run_deck(args.lmp, deck, args.np, name, timeout=args.timeout)
    return pc.thermo_block(res, ["Step", "KinEng", "v_zh", "f_hc[1]", "f_hc[6]", "f_hc[7]"])


def check_run(on, label):
    lr.check(len(on["Step"]) == SETTLE + WINDOW + 1,
             "%s: the run completes %d steps" % (label, SETTLE + WINDOW))
    worst = max(on["f_hc[7]"])
    lr.check(worst <= TOL * (1.0 + 1e-9),
             "%s: largest overlap at every step %.3g <= tol %g" % (label, worst, TOL))
    lr.check(on["f_hc[6]"][-1] == 0,
             "%s: no solve stopped at maxiter (%d)" % (label, on["f_hc[6]"][-1]))
    m_small = pc.sphere_mass(0.5, 1.0)
    ke = max(on["KinEng"][SETTLE + 1:]) / 197 / (m_small * 1.0)
    lr.check(ke <= 1e-8,
             "%s: at rest in the window: kinetic energy per sphere %.3g m g d <= 1e-8" % (label, ke))


def test():
    args = lr.test_args(__doc__)
    for solver in ("cg", "apgd"):
        off, on = run(args, solver, 0), run(args, solver, 10)
        if solver == "cg":
            on_cg = on
        check_run(on, solver)
        dz = abs(on["v_zh"][-1] - off["v_zh"][-1])
        lr.check(dz <= DZ_MAX, "%s: heavy sphere at the same height with and without (|dz| = %.3g "
                 "<= %.3g d)" % (solver, dz, DZ_MAX))
        w_on = sum(on["f_hc[1]"][SETTLE + 1:]) / WINDOW
        w_off = sum(off["f_hc[1]"][SETTLE + 1:]) / WINDOW
        lr.check(w_on <= 0.5 * w_off,
                 "%s: iterations per step in the window %.3g with subspace 10 <= half of %.3g "
                 "without" % (solver, w_on, w_off))
    default = run(args, "cg", None)
    same = all(list(default[k]) == list(on_cg[k]) for k in ("Step", "KinEng", "v_zh", "f_hc[1]"))
    lr.check(same, "cg without the keyword runs as with subspace 10, step for step (iterations in "
             "the window %.3g against %.3g)" % (sum(default["f_hc[1]"][SETTLE + 1:]) / WINDOW,
                                                sum(on_cg["f_hc[1]"][SETTLE + 1:]) / WINDOW))



if __name__ == "__main__":
    lr.main(test)
