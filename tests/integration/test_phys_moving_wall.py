#!/usr/bin/env python3
"""Moving plane walls (`wall zplane v_lo v_hi`: a position from an equal-style variable): the
wall's velocity over each step enters the rows' targets (core/targets.cpp), so a sphere never
overlaps where the wall will be.

1. Lift: a floor rising at V = 0.5 under g = 1 carries a resting sphere: z = z_floor + r and
   vz = V at every step (to 1e-9).
2. Vibrated floor z_f = A sin(2 pi t / T): with A (2 pi / T)^2 < g the sphere follows the floor
   (|gap| <= 1e-6 at every step), with restitution e = 0.5 too when `bounce 0.01` keeps
   resting contact inelastic (without it the floor's change of speed in a step, A w^2 h, is an
   approach speed that e turns into hops of a few 1e-3); with A (2 pi / T)^2 > g it leaves it (gap > 0.1 at some step) and never
   overlaps it, and with e = 0.5 it flies higher than with e = 0.
3. Piston: a ceiling coming down at V onto three spheres resting apart, no gravity: nothing
   moves until it arrives; then the top sphere moves down with it at V (z = z_c - r), the
   others stay; never an overlap with the ceiling or between spheres.
4. A bouncing ball on a moving floor: dropped onto a floor rising at U with restitution e, it
   leaves with vz = U + e (U - vz^n) (Newton's law relative to the wall, vz^n its velocity at
   the start of the step), to 1e-9; with e = 0 it leaves with the floor's U.
5. Piston on a packing: 64 spheres of a gas (scattered velocities, no gravity) in a box periodic
   in x and y, compressed by a ceiling coming down at constant speed to a quarter of the
   height (packing fraction 0.34): never an overlap beyond tol, no centre above the ceiling,
   every solve converged, the spheres end below z_c - r.
Serially and under mpirun (the rank count ctest gives).
"""

import math

import numpy as np

import lammps_run as lr
import physics_common as pc

LIFT = pc.DROP_ON_FLOOR.replace("wall zplane 0 NULL", "wall zplane v_zf NULL").replace(
    "region          box block -2 2 -2 2 0 10", "region          box block -2 2 -2 2 -1 10")

OUTPUT = """variable        gap equal z[1]-0.5-v_zf
variable        vz equal vz[1]
thermo_style    custom step v_zf v_gap v_vz f_hc[1]
thermo_modify   format float %.15g
thermo          1"""

PISTON = lr.preamble("p p f") + """
region          box block -2 2 -2 2 0 10
create_box      1 box
create_atoms    1 single 0.0 0.0 0.5
create_atoms    1 single 0.0 0.0 2.0
create_atoms    1 single 0.0 0.0 3.5
set             group all diameter 1.0 density 1.0
variable        zc equal 5.0-{v}*step*dt
pair_style      none
neighbor        0.5 bin
fix             hc all hardcontact wall zplane 0 v_zc
timestep        {h}
variable        z1 equal z[1]
variable        z2 equal z[2]
variable        z3 equal z[3]
variable        vz3 equal vz[3]
thermo_style    custom step v_zc v_z1 v_z2 v_z3 v_vz3
thermo_modify   format float %.15g
thermo          1
run             {n}
"""


def test():
    args = lr.test_args(__doc__)

    # 1. lift
    V = 0.5
    deck = "variable        zf equal %r*step*dt\n" % V + LIFT.format(
        x=0.0, y=0.0, z=0.5, fix_extra="", h=0.01, n=200, output=OUTPUT)
    res = lr.run_deck(args.lmp, deck, args.np, args.workdir + "/lift", timeout=args.timeout)
    th = res.thermo[-1]
    gap, vz = th["v_gap"], th["v_vz"]
    lr.check(float(np.abs(gap).max()) <= 1e-9, "lift: the sphere stays on the rising floor (|gap| "
             "<= %.3g)" % float(np.abs(gap).max()))
    lr.check(float(np.abs(vz[1:] - V).max()) <= 1e-9, "lift: and moves with it at V = %g" % V)

    # 2. vibrated floor (and, above g, with restitution: it bounces higher than inelastic)
    T = 1.0
    flights = {}
    for A, follows, e in ((0.02, True, 0.0), (0.02, True, 0.5), (0.1, False, 0.0),
                          (0.1, False, 0.5)):
        accel = A * (2 * math.pi / T) ** 2
        deck = "variable        zf equal %r*sin(2*PI*step*dt/%r)\n" % (A, T) + LIFT.format(
            x=0.0, y=0.0, z=0.5, fix_extra="restitution %g bounce 0.01" % e if e else "", h=0.001,
            n=3000,
            output=OUTPUT)
        res = lr.run_deck(args.lmp, deck, args.np, "%s/vibrated_%g_e%g" % (args.workdir, A, e),
                          timeout=args.timeout)
        gap = res.thermo[-1]["v_gap"]
        lr.check(float(gap.min()) >= -1e-6, "vibrated floor A w^2 = %.3g g: never an overlap "
                 "(%.3g)" % (accel, float(gap.min())))
        if follows:
            # the floor starts at its top speed A w: with e > 0 the sphere hops once (by about
            # (e A w)^2 / 2g), lands and then follows
            late = gap[1000:] if e else gap
            lr.check(float(np.abs(late).max()) <= 1e-6, "vibrated floor A w^2 = %.3g g < g, e = "
                     "%g: the sphere follows it (|gap| <= %.3g%s)"
                     % (accel, e, float(np.abs(late).max()), " after t = 1" if e else ""))
        else:
            lr.check(float(gap.max()) > 0.1, "vibrated floor A w^2 = %.3g g > g, e = %g: the "
                     "sphere leaves it (largest gap %.3g)" % (accel, e, float(gap.max())))
            flights[e] = float(gap.max())
    lr.check(flights[0.5] > 1.5 * flights[0.0],
             "vibrated floor above g: with e = 0.5 the sphere bounces higher than inelastic "
             "(largest gap %.3g vs %.3g)" % (flights[0.5], flights[0.0]))

    # 3. piston, stopped before the column jams (ceiling at 3.2 > 3 diameters)
    v, h = 0.5, 0.01
    n = int(round((5.0 - 3.2) / (v * h)))
    res = lr.run_deck(args.lmp, PISTON.format(v=v, h=h, n=n), args.np, args.workdir + "/piston",
                      timeout=args.timeout)
    th = res.thermo[-1]
    zc, z1, z2, z3, vz3 = (th[k] for k in ("v_zc", "v_z1", "v_z2", "v_z3", "v_vz3"))
    size_tol = 1e-4 * 1.0
    lr.check(float((z3 + 0.5 - zc).max()) <= size_tol, "piston: the top sphere never overlaps "
             "the ceiling (%.3g)" % float((z3 + 0.5 - zc).max()))
    lr.check(float((z2 + 1.0 - z3).max()) <= size_tol and float((z1 + 1.0 - z2).max()) <= size_tol,
             "piston: no overlap between the spheres")
    before = zc >= 4.0
    lr.check(bool(np.all(z3[before] == 3.5)), "piston: nothing moves before the ceiling arrives")
    pushed = zc <= 3.9
    lr.check(float(np.abs(z3[pushed] - (zc[pushed] - 0.5)).max()) <= 1e-4,
             "piston: then the top sphere moves with the ceiling (z3 = z_c - r within 1e-4)")
    lr.check(float(np.abs(vz3[pushed] + v).max()) <= 1e-3, "piston: at the ceiling's speed %g" % v)
    lr.check(bool(np.all(z1 == 0.5)), "piston: the bottom sphere never moves")

    # 4. restitution against a moving floor
    U = 0.5
    for e in (0.6, 0.0):
        deck = "variable        zf equal %r*step*dt\n" % U + LIFT.format(
            x=0.0, y=0.0, z=3.0, fix_extra="restitution %g" % e, h=0.01, n=400, output=OUTPUT)
        res = lr.run_deck(args.lmp, deck, args.np, "%s/bounce_e%g" % (args.workdir, e),
                          timeout=args.timeout)
        th = res.thermo[-1]
        vz, gap = np.asarray(th["v_vz"]), np.asarray(th["v_gap"])
        k = int(np.argmax((vz[:-1] < 0.0) & (vz[1:] > 0.0))) + 1    # the impact step
        want = U + e * (U - vz[k - 1])
        lr.check(k > 1 and abs(vz[k] - want) <= 1e-9 and float(gap.min()) >= -1e-9,
                 "bounce on a floor rising at %g, e = %g: leaves at U + e (U - v) = %.9g (got "
                 "%.9g), never an overlap (%.3g)" % (U, e, want, vz[k], float(gap.min())))

    # 5. piston compressing a gas into a packing
    res = lr.run_deck(args.lmp, packing_deck(), args.np, args.workdir + "/packing",
                      timeout=args.timeout)
    th = res.thermo[-1]
    zc, top = np.asarray(th["v_zc"]), np.asarray(th["c_top"])
    overlap, maxiter = float(np.asarray(th["f_hc[7]"]).max()), float(np.asarray(th["f_hc[6]"]).max())
    lr.check(overlap <= 1e-4 and maxiter == 0,
             "packing: the ceiling compresses 64 spheres from z = 14 to %.3g with no overlap beyond "
             "tol (largest %.3g) and every solve converged (%g at maxiter)"
             % (zc[-1], overlap, maxiter))
    lr.check(float((top + 0.5 - zc).max()) <= 1e-4 and float(top[-1]) <= zc[-1] - 0.5 + 1e-4,
             "packing: no sphere above the ceiling (largest z + r - z_c %.3g)"
             % float((top + 0.5 - zc).max()))


def packing_deck():
    lines = []
    rng = np.random.default_rng(7)
    for layer in range(4):
        for i in range(4):
            for j in range(4):
                x, y = 0.625 + 1.25 * i, 0.625 + 1.25 * j
                z = 1.5 + 3.0 * layer + rng.uniform(-0.5, 0.5)
                lines.append("create_atoms    1 single %.6f %.6f %.6f" % (x, y, z))
    return PACKING.format(atoms="\n".join(lines))


PACKING = pc.HEADER_3D_FLOOR + """region          box block 0 5 0 5 0 15 units box
create_box      1 box
{atoms}
set             group all diameter 1.0 density 1.0
variable        vx atom 0.7*sin(7*id)    # a gas: fixed pseudo-random velocities
variable        vy atom 0.7*cos(5*id)
variable        vz atom 0.7*sin(3*id+1)
velocity        all set v_vx v_vy v_vz
variable        zc equal 14.0-0.5*step*dt
pair_style      none
neighbor        0.5 bin
fix             hc all hardcontact wall zplane 0 v_zc
timestep        0.01
compute         z all property/atom z
compute         top all reduce max c_z
thermo_style    custom step v_zc c_top f_hc[6] f_hc[7] ke
thermo_modify   format float %.15g
thermo          10
run             2000
"""


if __name__ == "__main__":
    lr.main(test)
