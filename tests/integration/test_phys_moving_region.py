#!/usr/bin/env python3
"""Moving region walls (`wall region ID` with `region ... move/rotate`): each row carries the
velocity of the surface at its contact point (LAMMPS's Region::velocity_contact); its normal
part moves the row's gap target, its tangential part is the wall's share of the slip
(core/contact_problem.h, core/targets.cpp).

1. Conveyor: a plane region sliding in its own plane at V = 2 under a sphere at rest (g = 1,
   friction 0.3): the sphere accelerates at mu g and spins up at 5 mu g / (2 r) until it rolls
   on the moving floor, from t* = 2 V / (7 mu g) on at 2/7 V with omega r = -5/7 V (the
   launched sphere of test_phys_friction seen from the floor); its centre stays at height r.
   The work the floor does through friction is allowed by the energy test (no solve stops at
   maxiter).
2. Lift: the same plane rising at 0.5 (frictionless) carries the sphere: z = z_floor + r at
   every step, vz = 0.5.
3. Drum: 180 spheres in a horizontal cylinder (radius 5) rotating about its axis at 0.3 rad per
   time unit, friction 0.5, gravity: the bed is dragged up the rising side (its centre of mass
   moves towards it), no centre ever gets farther from the axis than R - r (+ the tolerance),
   the largest overlap stays below tol, no sphere is lost.
4. Restart: the conveyor split by write_restart / read_restart continues as the straight run.
Serially and under mpirun (the rank count ctest gives); the sphere of 1, 2 and 4 crosses the
processors' sub-domains.
"""


import numpy as np

import lammps_run as lr
import physics_common as pc

H = 0.01
MU = 0.3
V = 2.0

CONVEYOR = pc.HEADER_3D_FLOOR + """region          box block -30 30 -2 2 -1 40
create_box      1 box
create_atoms    1 single -2 0 0.5
set             atom 1 diameter 1.0 density 1.0
pair_style      none
neighbor        0.5 bin
variable        xf equal {vx}*time
variable        zf equal {vz}*time
region          floor plane 0 0 0 0 0 1 side in move v_xf NULL v_zf
fix             hc all hardcontact tol 1e-4 {friction} wall region floor
fix             g all gravity 1.0 vector 0 0 -1
timestep        {h}
compute         om all property/atom omegay
compute         wy all reduce sum c_om
variable        wy equal c_wy    # one atom: the sum is its spin
variable        vx equal vx[1]
variable        vz equal vz[1]
variable        gap equal z[1]-0.5-v_zf
thermo_style    custom step v_vx v_vz v_wy v_gap f_hc[6] f_hc[7]
thermo_modify   format float %.15g
thermo          1
"""


def conveyor(args, name, vx, vz, friction, n):
    wd = lr.fresh_workdir("%s/%s" % (args.workdir, name))
    deck = CONVEYOR.format(vx=vx, vz=vz, friction=friction, h=H) + "run %d\n" % n
    res = lr.run_deck(args.lmp, deck, args.np, wd, timeout=args.timeout)
    th = res.thermo[-1]
    return res, np.asarray(th["Step"], dtype=float) * H, th


def conveyor_test(args):
    _, t, th = conveyor(args, "conveyor", V, 0.0, "friction %g" % MU, 300)
    pc.check_conveyor(t, th, V, MU, H, "a plane region")


def lift_test(args):
    _, _, th = conveyor(args, "lift", 0.0, 0.5, "", 200)
    pc.check_lift(th, 0.5, "a plane region")


def restart_test(args):
    """The conveyor split at step 100 by write_restart/read_restart (the region, which the
    restart file does not hold, defined again): the same velocities at step 250."""
    wd = lr.fresh_workdir("%s/restart" % args.workdir)
    straight = CONVEYOR.format(vx=V, vz=0.0, friction="friction %g" % MU, h=H) + "run 250\n"
    first = (CONVEYOR.format(vx=V, vz=0.0, friction="friction %g" % MU, h=H)
             + "run 100\nwrite_restart conveyor.restart\n")
    head = CONVEYOR.format(vx=V, vz=0.0, friction="friction %g" % MU, h=H)
    lines = head.splitlines()
    keep = ("variable", "region          floor", "pair_style", "neighbor", "fix", "timestep",
            "compute", "thermo")
    second = "read_restart conveyor.restart\n" + "\n".join(
        line for line in lines if line.startswith(keep) and "region          box" not in line) + \
        "\nrun 150\n"
    res_a = lr.run_deck(args.lmp, straight, args.np, wd, deck_name="in.straight",
                        log_name="log.straight", timeout=args.timeout)
    lr.run_deck(args.lmp, first, args.np, wd, deck_name="in.first", log_name="log.first",
                timeout=args.timeout)
    res_b = lr.run_deck(args.lmp, second, args.np, wd, deck_name="in.second",
                        log_name="log.second", timeout=args.timeout)
    a, b = res_a.thermo[-1], res_b.thermo[-1]
    da = max(abs(float(a[k][-1]) - float(b[k][-1])) for k in ("v_vx", "v_wy", "v_gap"))
    lr.check(int(float(b["Step"][-1])) == 250 and da <= 1e-6,
             "restart: the conveyor continued from step 100 ends as the straight run at step 250 "
             "(largest difference of vx, omega, gap %.3g)" % da)


DRUM = lr.preamble("f p f", ghost_velocities=True) + """
region          box block -6 6 0 4.8 -6 6
create_box      1 box
region          fill cylinder y 0 0 4.45 -100 100 side in units box
lattice         sc 0.5787037    # spacing 1.2: 4 layers across the periodic length 4.8
create_atoms    1 region fill
set             type 1 diameter 1.0 density 1.0
variable        theta equal {omega}*time
region          drum cylinder y 0 0 5 -100 100 side in open 1 open 2 rotate v_theta 0 0 0 0 1 0 units box
pair_style      none
neighbor        0.5 bin
fix             hc all hardcontact tol {tol} friction 0.5 wall region drum
fix             g all gravity 1.0 vector 0 0 -1
timestep        {h}
variable        xc equal xcm(all,x)
variable        zc equal xcm(all,z)
variable        rad atom sqrt(x*x+z*z)
compute         rmax all reduce max v_rad
thermo_style    custom step atoms v_xc v_zc c_rmax f_hc[6] f_hc[7]
thermo_modify   format float %.15g
thermo          10
run             {n}
"""


def drum_test(args):
    wd = lr.fresh_workdir("%s/drum" % args.workdir)
    omega, n, tol = 0.3, 500, 1e-4
    res = lr.run_deck(args.lmp, DRUM.format(omega=omega, h=H, n=n, tol=1e-4), args.np, wd,
                      timeout=args.timeout)
    th = res.thermo[-1]
    atoms = np.asarray(th["Atoms"], dtype=float)
    xc = np.asarray(th["v_xc"])
    rmax = float(np.asarray(th["c_rmax"]).max())
    overlap = float(np.asarray(th["f_hc[7]"]).max())
    maxiter = float(np.asarray(th["f_hc[6]"]).max())
    lr.check(atoms.min() == atoms[0] == atoms.max() and atoms[0] > 140,
             "drum: all %d spheres stay" % atoms[0])
    # the surface at the bottom moves towards -x (omega about +y): the bed climbs that side
    lr.check(float(xc[-1]) < -0.5,
             "drum: the bed is dragged up the rising side (centre of mass x %.3g < -0.5)"
             % float(xc[-1]))
    lr.check(rmax <= 4.5 + tol * 0.5 + 1e-9,
             "drum: no centre farther from the axis than R - r = 4.5 (largest %.9g)" % rmax)
    lr.check(overlap <= tol and maxiter == 0,
             "drum: largest overlap %.3g <= tol %g after every step; solves at maxiter: %g"
             % (overlap, tol, maxiter))


def test():
    args = lr.test_args()
    conveyor_test(args)
    lift_test(args)
    drum_test(args)
    restart_test(args)


if __name__ == "__main__":
    lr.main(test)
