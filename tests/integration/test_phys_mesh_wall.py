#!/usr/bin/env python3
"""Triangle-mesh walls (`wall stl FILE [scale s]`, src/lammps/sources/mesh_wall_source.h): the
rows of a sphere are its distances to the nearest features of the surface (faces, ridges,
corners), each once (core/mesh/triangle_mesh.h).

1. Incline: a sphere rolls down a 20 degree slope made of 2 x 33 x 6 triangles (cells of 0.37:
   it crosses 12 rows of edges and diagonals), friction 0.5, tol 1e-6: along the slope it
   accelerates at 5/7 g sin(20) (rolling, mu > 2/7 tan), as the same slope made of a `region
   plane` wall does, step by step (not on LIGGGHTS, which has no region walls); its centre
   stays at r above the slope (no bump at an edge).
2. Floor: two frictionless spheres slide across a floor of 2 x 55 x 30 triangles under
   gravity for 900 steps, one along the triangles' diagonals through their shared vertices, one
   across edges and diagonals: velocities unchanged, heights r, at every step.
3. Box: 27 spheres in a closed cube read from a binary STL (scale 2: the file's unit cube),
   thrown at 0.7 -0.4 0.5 under gravity towards the opposite corner: (a) frictionless, the first 150 steps equal
   those in the same box made of plane walls; (b) with friction 0.3 for 800 steps, no centre
   leaves the cube by more than the tolerance, the largest overlap stays below tol, every
   sphere stays.
4. Moving meshes (`move`, `rotate`): a floor of two triangles sliding in its own plane at V = 2
   under a sphere at rest (friction 0.3) accelerates it at mu g and spins it up until it rolls,
   from t* = 2 V / (7 mu g) on, at 2/7 V with omega r = -5/7 V, its centre at height r; the
   same floor rising at 0.5 carries it (z = z_floor + r, vz = 0.5); 180 spheres in a drum of
   72 x 2 triangles rotating at 0.3 rad per unit time are dragged up its rising side, none
   leaves it or comes nearer its facets than r (within tol), no solve stops at maxiter.
5. Cone: a sphere dropped on the axis of a 45-degree cone of 128 triangles (test_phys_region_wall's
   hopper, radius 0.2 + z) comes to rest at the height the facets give, r / sin(atan(cos(pi /
   64))) above the apex, within 1e-6; the same cone as a `region cone` rests it at r sqrt 2 above
   the apex (within 1e-4, as there): the two differ by the facets alone.
6. Restart: the sliding-floor conveyor split at step 100 by write_restart / read_restart (the
   fix defined again, reading its STL again) ends as the straight run at step 250.
7. LIGGGHTS only, `wall mesh ID` on a `fix mesh/surface`: the slope of 1 read that way rolls the
   sphere exactly as `wall stl` on the same file; a mesh floor moved by `fix move/mesh linear`
   is the conveyor of 4, and so is a mesh at rest whose surface moves (`surface_vel`, a belt);
   a turntable (`surface_ang_vel`) pushes a resting sphere along its surface's motion at mu g;
   the drum of 4 turned by `fix move/mesh rotate` drags its bed up, keeps every sphere within
   its facets, no solve at maxiter.
Serially and under mpirun (the rank count ctest gives).
"""

import math
import os
import sys

import numpy as np

import lammps_run as lr
import physics_common as pc
import test_phys_moving_region as mr

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "examples", "common"))
import granular as gr    # noqa: E402

H = 0.01
THETA = math.radians(20.0)


def write_ascii_stl(path, triangles):
    gr.write_stl(path, triangles)


def write_binary_stl(path, triangles):
    gr.write_stl(path, triangles, binary=True)


def drum_triangles(R, N, y0, y1):
    """A drum of radius R about the y axis from y0 to y1: N flat facets, 2 triangles each."""
    tris = []
    for k in range(N):
        a0, a1 = 2 * math.pi * k / N, 2 * math.pi * ((k + 1) % N) / N
        p = [(R * math.cos(a), R * math.sin(a)) for a in (a0, a1)]
        q = [((x, y0, z), (x, y1, z)) for x, z in p]
        tris.append((q[0][0], q[1][0], q[1][1]))
        tris.append((q[0][0], q[1][1], q[0][1]))
    return tris


def slope_triangles():
    """The 20-degree slope of test 1: cells of 0.37 along it, 33 x 6, from s = -1.5."""
    c, s = math.cos(THETA), math.sin(THETA)
    along = np.array([c, 0.0, -s])
    origin = -1.5 * along - 1.1 * np.array([0, 1, 0])
    return grid(origin, 0.37 * along, [0, 0.37, 0], 33, 6)


def grid(origin, du, dv, nu, nv):
    """nu x nv cells spanned by du, dv from origin, each split along its diagonal."""
    o, du, dv = (np.asarray(x, dtype=float) for x in (origin, du, dv))
    tris = []
    for i in range(nu):
        for j in range(nv):
            p00 = o + i * du + j * dv
            p10, p11, p01 = p00 + du, p00 + du + dv, p00 + dv
            tris.append((p00, p10, p11))
            tris.append((p00, p11, p01))
    return [[tuple(float(c) for c in v) for v in t] for t in tris]


INCLINE = lr.preamble(ghost_velocities=True) + """
region          box block -2 14 -2 2 -6 3
create_box      1 box
create_atoms    1 single {x0} 0 {z0} units box
set             atom 1 diameter 1.0 density 1.0
pair_style      none
neighbor        0.5 bin
{wall_setup}
fix             hc all hardcontact tol 1e-6 friction 0.5 {wall}
fix             g all gravity 1.0 vector 0 0 -1
timestep        {h}
variable        s equal x[1]*{c}-z[1]*{s}
variable        vs equal vx[1]*{c}-vz[1]*{s}
variable        hgt equal x[1]*{s}+z[1]*{c}-0.5
thermo_style    custom step v_s v_vs v_hgt f_hc[6] f_hc[7]
thermo_modify   format float %.15g
thermo          1
run             600
"""


def run_incline(args, tag, wall_setup, wall):
    """The sphere rolling down the slope (the INCLINE deck) with the given wall, in
    <workdir>/<tag> beside the slope's STL file; its thermo."""
    c, s = math.cos(THETA), math.sin(THETA)
    # sphere touching the slope at its origin
    x0, _, z0 = 0.5 * np.array([s, 0.0, c])
    fmt = dict(x0=repr(float(x0)), z0=repr(float(z0)), h=H, c=repr(c), s=repr(s))
    wd = lr.fresh_workdir("%s/%s" % (args.workdir, tag))
    write_ascii_stl("%s/slope.stl" % wd, slope_triangles())
    deck = INCLINE.format(wall_setup=wall_setup, wall=wall, **fmt)
    return lr.run_deck(args.lmp, deck, args.np, wd, timeout=args.timeout).thermo[-1]


def incline_test(args):
    s = math.sin(THETA)
    m = run_incline(args, "incline_mesh", "", "wall stl slope.stl")
    # LIGGGHTS 3.8 has no region walls (lammps_compat.h): there the analytic answer alone
    r = None
    if getattr(args.lmp, "name", "") != "liggghts":
        r = run_incline(args, "incline_region", "region slope plane 0 0 0 %r 0 %r side in"
                        % (s, math.cos(THETA)), "wall region slope")
    t = np.asarray(m["Step"], dtype=float) * H
    a = 5.0 / 7.0 * s
    vs = np.asarray(m["v_vs"])
    err_v = float(np.abs(vs - a * t).max())
    err_h = float(np.abs(np.asarray(m["v_hgt"])).max())
    travelled = float(np.asarray(m["v_s"])[-1])
    lr.check(travelled > 12 * 0.37 - 0.5,
             "incline: the sphere crosses about 12 rows of triangles (travels %.3g)" % travelled)
    lr.check(err_v <= 1e-5,
             "incline: rolls down the mesh at 5/7 g sin(20 deg) (speed error %.3g at worst, "
             "every step)" % err_v)
    lr.check(err_h <= 1e-6, "incline: centre at r above the slope at every step (|error| "
             "%.3g): no bump at the edges" % err_h)
    if r is not None:
        diff = max(float(np.abs(np.asarray(m[k]) - np.asarray(r[k])).max())
                   for k in ("v_s", "v_vs"))
        lr.check(diff <= 1e-6, "incline: the mesh slope and a region plane give the same motion "
                 "step by step (largest difference %.3g)" % diff)
    lr.check(float(np.asarray(m["f_hc[6]"]).max()) == 0, "incline: no solve at maxiter")


FLOOR = lr.preamble(ghost_velocities=True) + """
region          box block -1 22 -1 12 -1 3
create_box      1 box
create_atoms    1 single 0.37 0.37 0.5 units box
create_atoms    1 single 3.2 0.2 0.5 units box
set             type 1 diameter 1.0 density 1.0
region          across block 3 22 -1 12 -1 3 units box
velocity        all set 1.0 1.0 0.0 units box
group           across region across
velocity        across set 1.0 0.43 0.0 units box
pair_style      none
neighbor        0.5 bin
fix             hc all hardcontact tol 1e-6 wall stl floor.stl
fix             g all gravity 1.0 vector 0 0 -1
timestep        {h}
thermo_style    custom step v_vx1 v_vy1 v_vz1 v_z1 v_vx2 v_vy2 v_vz2 v_z2 f_hc[7]
thermo_modify   format float %.15g
thermo          1
run             900
"""


def floor_test(args):
    wd = lr.fresh_workdir("%s/floor" % args.workdir)
    write_ascii_stl("%s/floor.stl" % wd, grid([0, 0, 0], [0.37, 0, 0], [0, 0.37, 0], 55, 30))
    per_atom = "".join("variable        %s%d equal %s[%d]\n" % (k, i, k, i)
                       for i in (1, 2) for k in ("vx", "vy", "vz", "z"))
    deck = FLOOR.format(h=H).replace("thermo_style", per_atom + "thermo_style", 1)
    th = lr.run_deck(args.lmp, deck, args.np, wd, timeout=args.timeout).thermo[-1]
    errs = {}
    for i, (vx, vy) in ((1, (1.0, 1.0)), (2, (1.0, 0.43))):
        errs[i] = max(float(np.abs(np.asarray(th["v_vx%d" % i]) - vx).max()),
                      float(np.abs(np.asarray(th["v_vy%d" % i]) - vy).max()),
                      float(np.abs(np.asarray(th["v_vz%d" % i])).max()),
                      float(np.abs(np.asarray(th["v_z%d" % i]) - 0.5).max()))
    lr.check(errs[1] <= 1e-6,
             "floor: a sphere sliding along the triangles' diagonals, through their shared "
             "vertices, keeps its velocity and height r (largest error %.3g)" % errs[1])
    lr.check(errs[2] <= 1e-6,
             "floor: a sphere sliding across edges and diagonals keeps its velocity and height r "
             "(largest error %.3g)" % errs[2])


BOX = lr.preamble(ghost_velocities=True) + """
region          box block -1 3 -1 3 -1 3
create_box      1 box
lattice         sc 4.6296296296 origin 0.5 0.5 0.5    # spacing 0.6
region          fill block 0.25 1.75 0.25 1.75 0.25 1.75 units box
create_atoms    1 region fill
set             type 1 diameter 0.4 density 1.0
velocity        all set 0.7 -0.4 0.5    # LIGGGHTS 3.8 refuses velocity create here
pair_style      none
neighbor        0.3 bin
fix             hc all hardcontact {extra} {walls}
fix             g all gravity 1.0 vector -1 -1 -1
timestep        {h}
variable        o1 atom 0.2-x
variable        o2 atom x-1.8
variable        o3 atom 0.2-y
variable        o4 atom y-1.8
variable        o5 atom 0.2-z
variable        o6 atom z-1.8
compute         out all reduce max v_o1 v_o2 v_o3 v_o4 v_o5 v_o6
compute         xs all reduce sum x y z
thermo_style    custom step atoms c_out[1] c_out[2] c_out[3] c_out[4] c_out[5] c_out[6] c_xs[1] c_xs[2] c_xs[3] f_hc[6] f_hc[7]
thermo_modify   format float %.15g
thermo          10
run             {n}
"""


def cube():
    tris = []
    for axis in range(3):
        for side in (0.0, 1.0):
            a, b = (axis + 1) % 3, (axis + 2) % 3

            def corner(u, v):
                p = [0.0, 0.0, 0.0]
                p[axis], p[a], p[b] = side, u, v
                return tuple(p)
            tris.append((corner(0, 0), corner(1, 0), corner(1, 1)))
            tris.append((corner(0, 0), corner(1, 1), corner(0, 1)))
    return tris


def box_test(args):
    planes = "wall xplane 0 2 wall yplane 0 2 wall zplane 0 2"
    runs = {}
    for kind, walls in (("mesh", "wall stl cube.stl scale 2"), ("planes", planes)):
        wd = lr.fresh_workdir("%s/box_%s" % (args.workdir, kind))
        write_binary_stl("%s/cube.stl" % wd, cube())
        deck = BOX.format(extra="tol 1e-6", walls=walls, h=H, n=150)
        runs[kind] = lr.run_deck(args.lmp, deck, args.np, wd, timeout=args.timeout).thermo[-1]
    diff = max(float(np.abs(np.asarray(runs["mesh"][k]) - np.asarray(runs["planes"][k])).max())
               for k in ("c_xs[1]", "c_xs[2]", "c_xs[3]"))
    lr.check(diff <= 1e-6, "box: 27 spheres in a cube read from a binary STL move as in the same "
             "box of plane walls for 150 steps (largest difference of the mean coordinates "
             "%.3g)" % diff)
    wd = lr.fresh_workdir("%s/box_friction" % args.workdir)
    write_binary_stl("%s/cube.stl" % wd, cube())
    tol = 1e-4
    th = lr.run_deck(args.lmp, BOX.format(extra="tol %g friction 0.3" % tol,
                                          walls="wall stl cube.stl scale 2", h=H, n=800),
                     args.np, wd, timeout=args.timeout).thermo[-1]
    atoms = np.asarray(th["Atoms"], dtype=float)
    out = max(float(np.asarray(th["c_out[%d]" % k]).max()) for k in range(1, 7))
    overlap = float(np.asarray(th["f_hc[7]"]).max())
    lr.check(atoms.min() == atoms.max() == 27, "box: all 27 spheres stay (%d..%d)"
             % (atoms.min(), atoms.max()))
    lr.check(out <= tol * 0.2, "box: no centre comes nearer a face than r - tol r (largest "
             "excursion %.3g)" % out)
    lr.check(overlap <= tol, "box: largest overlap %.3g <= tol %g after every step" % (overlap, tol))


# the conveyor and the lift of test_phys_moving_region.py, their floor a sliding mesh
CONVEYOR = mr.CONVEYOR.replace(
    "region          floor plane 0 0 0 0 0 1 side in move v_xf NULL v_zf\n", "").replace(
    "wall region floor", "wall stl floor.stl move v_xf NULL v_zf")


def conveyor(args, name, vx, vz, friction, n):
    wd = lr.fresh_workdir("%s/%s" % (args.workdir, name))
    # a floor larger than the box (periodic in x, y): every image of the sphere is over it
    write_ascii_stl("%s/floor.stl" % wd, [((-60, -6, 0), (60, -6, 0), (60, 6, 0)),
                                         ((-60, -6, 0), (60, 6, 0), (-60, 6, 0))])
    deck = CONVEYOR.format(vx=vx, vz=vz, friction=friction, h=H) + "run %d\n" % n
    th = lr.run_deck(args.lmp, deck, args.np, wd, timeout=args.timeout).thermo[-1]
    return np.asarray(th["Step"], dtype=float) * H, th


def moving_floor_test(args):
    t, th = conveyor(args, "conveyor", 2.0, 0.0, "friction 0.3", 300)
    pc.check_conveyor(t, th, 2.0, 0.3, H, "a mesh floor")
    _, th = conveyor(args, "lift", 0.0, 0.5, "", 200)
    pc.check_lift(th, 0.5, "a mesh floor")


# the drum of test_phys_moving_region.py, its wall the facets of drum.stl rotating with it
DRUM = mr.DRUM.replace(
    "region          drum cylinder y 0 0 5 -100 100 side in open 1 open 2 rotate v_theta 0 0 0 0 1 "
    "0 units box\n", "").replace("wall region drum", "wall stl drum.stl rotate v_theta 0 0 0 0 1 0")


def drum_test(args):
    wd = lr.fresh_workdir("%s/drum" % args.workdir)
    R, N, omega, n, tol = 5.0, 72, 0.3, 500, 1e-4
    # beyond the periodic length 4.8
    write_ascii_stl("%s/drum.stl" % wd, drum_triangles(R, N, -1.5, 6.3))
    th = lr.run_deck(args.lmp, DRUM.format(omega=omega, h=H, n=n, tol=tol), args.np, wd,
                     timeout=args.timeout).thermo[-1]
    atoms = np.asarray(th["Atoms"], dtype=float)
    xc = np.asarray(th["v_xc"])
    rmax = float(np.asarray(th["c_rmax"]).max())
    overlap = float(np.asarray(th["f_hc[7]"]).max())
    maxiter = float(np.asarray(th["f_hc[6]"]).max())
    # the facets' corners are R from the axis, their middles R cos(pi / N): a sphere in a
    # corner touches two facets, its centre (R cos(pi / N) - r) / cos(pi / N) from the axis
    reach = (R * math.cos(math.pi / N) - 0.5) / math.cos(math.pi / N)
    lr.check(atoms.min() == atoms[0] == atoms.max() and atoms[0] > 140,
             "drum: all %d spheres stay" % atoms[0])
    lr.check(float(xc[-1]) < -0.5, "drum: the bed is dragged up the rising side of the rotating "
             "mesh (centre of mass x %.3g < -0.5)" % float(xc[-1]))
    lr.check(rmax <= reach + tol * 0.5 + 1e-9, "drum: no centre farther from the axis than a "
             "facet corner allows, %.6f (largest %.9g)" % (reach, rmax))
    lr.check(overlap <= tol and maxiter == 0, "drum: largest overlap %.3g <= tol %g after every "
             "step; solves at maxiter: %g" % (overlap, tol, maxiter))


CONE = lr.preamble(ghost_velocities=True) + """
region          box block -4 4 -4 4 -1 5
create_box      1 box
create_atoms    1 single 0.3 0.1 2.0 units box
set             atom 1 diameter 1.0 density 1.0
pair_style      none
neighbor        0.5 bin
{setup}
fix             hc all hardcontact tol 1e-6 {wall}
fix             g all gravity 1.0 vector 0 0 -1
timestep        {h}
variable        z equal z[1]
variable        rxy equal sqrt(x[1]^2+y[1]^2)
thermo_style    custom step v_z v_rxy f_hc[6]
thermo_modify   format float %.15g
thermo          50
run             1500
"""


def cone_test(args):
    N, r = 64, 0.5
    tris = []
    # radius 0.2 + z from z = 0 to 3 (test_phys_region_wall's hopper), open at the bottom
    for k in range(N):
        a0, a1 = 2 * math.pi * k / N, 2 * math.pi * ((k + 1) % N) / N
        low = [(0.2 * math.cos(a), 0.2 * math.sin(a), 0.0) for a in (a0, a1)]
        top = [(3.2 * math.cos(a), 3.2 * math.sin(a), 3.0) for a in (a0, a1)]
        tris.append((low[0], low[1], top[1]))
        tris.append((low[0], top[1], top[0]))
    rest = {}
    for kind in ("mesh", "region"):
        if kind == "region" and getattr(args.lmp, "name", "") == "liggghts":
            continue    # no region walls on LIGGGHTS
        wd = lr.fresh_workdir("%s/cone_%s" % (args.workdir, kind))
        if kind == "mesh":
            write_ascii_stl("%s/cone.stl" % wd, tris)
            deck = CONE.format(setup="", wall="wall stl cone.stl", h=H)
        else:
            deck = CONE.format(setup="region cone cone z 0 0 0.2 3.2 0 3 side in units box",
                               wall="wall region cone", h=H)
        th = lr.run_deck(args.lmp, deck, args.np, wd, timeout=args.timeout).thermo[-1]
        rest[kind] = (float(th["v_z"][-1]), float(th["v_rxy"][-1]))
    # the cone's apex is at z = -0.2; each facet's plane leans at atan(cos(pi / N)) from the axis
    facet = r / math.sin(math.atan(math.cos(math.pi / N))) - 0.2
    round_ = r * math.sqrt(2.0) - 0.2
    z, rxy = rest["mesh"]
    lr.check(abs(z - facet) <= 1e-6 and rxy <= 1e-9, "cone: a sphere on the axis of a cone of %d "
             "facets rests at r / sin(atan(cos(pi / %d))) - 0.2 = %.9f (at %.9f, %.2g off the "
             "axis)" % (N, N, facet, z, rxy))
    if "region" in rest:
        zr = rest["region"][0]
        lr.check(abs(zr - round_) <= 1e-4 and abs((z - zr) - (facet - round_)) <= 1e-4,
                 "cone: the region cone rests it at %.6f (r sqrt 2 - 0.2 = %.6f): the mesh's "
                 "height differs by the facets' %.2e alone" % (zr, round_, facet - round_))


def restart_test(args):
    V, MU = 2.0, 0.3
    wd = lr.fresh_workdir("%s/restart" % args.workdir)
    write_ascii_stl("%s/floor.stl" % wd, grid([-20, -1.9, 0], [1, 0, 0], [0, 0.95, 0], 40, 4))
    head = CONVEYOR.format(vx=V, vz=0.0, friction="friction %g" % MU, h=H)
    straight = head + "run 250\n"
    first = head + "run 100\nwrite_restart floor.restart\n"
    keep = ("variable", "pair_style", "neighbor", "fix", "timestep", "compute", "thermo")
    second = "atom_modify map array\nread_restart floor.restart\n" + "\n".join(
        line for line in head.splitlines() if line.startswith(keep)) + "\nrun 150\n"
    a = lr.run_deck(args.lmp, straight, args.np, wd, deck_name="in.straight",
                    log_name="log.straight", timeout=args.timeout).thermo[-1]
    lr.run_deck(args.lmp, first, args.np, wd, deck_name="in.first", log_name="log.first",
                timeout=args.timeout)
    b = lr.run_deck(args.lmp, second, args.np, wd, deck_name="in.second", log_name="log.second",
                    timeout=args.timeout).thermo[-1]
    da = max(abs(float(a[k][-1]) - float(b[k][-1])) for k in ("v_vx", "v_wy", "v_gap"))
    lr.check(int(float(b["Step"][-1])) == 250 and da <= 1e-6,
             "restart: the mesh conveyor continued from step 100 ends as the straight run at step "
             "250 (largest difference of vx, omega, gap %.3g)" % da)


def run_liggghts_floor(args, tag, vx, steps, mesh_fix, vz_column=None):
    """The conveyor deck (friction 0.3, the floor moving at vx) on LIGGGHTS with its floor read
    by mesh_fix (a fix mesh/surface named cad, with what moves it) in place of `wall stl ...
    move`; v_vz reports vz_column when given. Its thermo after `steps` steps."""
    wd = lr.fresh_workdir("%s/%s" % (args.workdir, tag))
    # LIGGGHTS keeps a moving mesh inside the box: this floor goes from x = -20..20 to -14..26
    # (and bins its triangles by their size within the box: cells of 1 x 0.95)
    write_ascii_stl("%s/floor.stl" % wd, grid([-20, -1.9, 0], [1, 0, 0], [0, 0.95, 0], 40, 4))
    deck = (CONVEYOR.format(vx=vx, vz=0.0, friction="friction 0.3", h=H) + "run %d\n" % steps)
    deck = deck.replace("fix             hc all hardcontact tol 1e-4 friction 0.3 wall stl "
                        "floor.stl move v_xf NULL v_zf", mesh_fix + "\nfix             hc all "
                        "hardcontact tol 1e-4 friction 0.3 wall mesh cad")
    if vz_column:
        deck = deck.replace("variable        vz equal vz[1]", "variable        vz equal " + vz_column)
    return lr.run_deck(args.lmp, deck, args.np, wd, timeout=args.timeout).thermo[-1]


def liggghts_mesh_fix_test(args):
    """LIGGGHTS's own mesh walls, read through fix mesh/surface (the host rewrites the deck)."""
    runs = {"stl": run_incline(args, "lig_incline_stl", "", "wall stl slope.stl"),
            "fix": run_incline(args, "lig_incline_fix", "fix             cad all mesh/surface "
                               "file slope.stl type 1", "wall mesh cad")}
    diff = max(float(np.abs(np.asarray(runs["stl"][k]) - np.asarray(runs["fix"][k])).max())
               for k in ("v_s", "v_vs", "v_hgt"))
    lr.check(diff == 0.0, "LIGGGHTS wall mesh: the slope read through fix mesh/surface rolls the "
             "sphere as wall stl on the same file, to the bit (largest difference %.3g)" % diff)
    # the conveyor: fix move/mesh linear in place of move v_xf
    V, MU = 2.0, 0.3
    th = run_liggghts_floor(args, "lig_conveyor", V, 300, "fix             cad all mesh/surface "
                            "file floor.stl type 1\nfix             mv all move/mesh mesh cad "
                            "linear %g 0 0" % V)
    t = np.asarray(th["Step"], dtype=float) * H
    pc.check_conveyor(t, th, V, MU, H, "a LIGGGHTS mesh floor moved by fix move/mesh linear")
    # the same conveyor as a belt: the floor stays, its surface moves (surface_vel)
    th = run_liggghts_floor(args, "lig_belt", 0.0, 300, "fix             cad all mesh/surface "
                            "file floor.stl type 1 surface_vel %g 0 0" % V)
    pc.check_conveyor(t, th, V, MU, H, "a LIGGGHTS belt (fix mesh/surface ... surface_vel, the "
                      "mesh at rest)")
    # a turntable (surface_ang_vel): the sphere at rest 2 from the axis, the surface under it
    # moving at omega 2 along +y, is pushed along +y at mu g while it slides
    th = run_liggghts_floor(args, "lig_turntable", 0.0, 40, "fix             cad all "
                            "mesh/surface file floor.stl type 1 surface_ang_vel origin -4 0 0 "
                            "axis 0 0 1 omega 0.5", vz_column="vy[1]")
    t = np.asarray(th["Step"], dtype=float) * H
    err = float(np.abs(np.asarray(th["v_vz"]) - MU * t).max())
    # (the surface's direction under the sphere turns as it moves: 3e-6 by t = 0.4)
    lr.check(err <= 1e-5, "LIGGGHTS wall mesh: a turntable (surface_ang_vel, omega 0.5 about an "
             "axis 2 away) pushes the sphere along the surface's motion at mu g while it slides "
             "(largest error %.3g over 0.4 time units)" % err)
    # the drum: fix move/mesh rotate (period 2 pi / omega)
    wd = lr.fresh_workdir("%s/lig_drum" % args.workdir)
    R, N, omega, n, tol = 5.0, 72, 0.3, 500, 1e-4
    # the periodic length: LIGGGHTS keeps a moving mesh inside the box
    write_ascii_stl("%s/drum.stl" % wd, drum_triangles(R, N, 0.0, 4.8))
    deck = DRUM.format(omega=omega, h=H, n=n, tol=tol).replace(
        "wall stl drum.stl rotate v_theta 0 0 0 0 1 0", "wall mesh cad").replace(
        "fix             hc", "fix             cad all mesh/surface file drum.stl type 1\n"
        "fix             mv all move/mesh mesh cad rotate origin 0 0 0 axis 0 1 0 period %r\n"
        "fix             hc" % (2 * math.pi / omega), 1)
    th = lr.run_deck(args.lmp, deck, args.np, wd, timeout=args.timeout).thermo[-1]
    atoms = np.asarray(th["Atoms"], dtype=float)
    reach = (R * math.cos(math.pi / N) - 0.5) / math.cos(math.pi / N)
    rmax = float(np.asarray(th["c_rmax"]).max())
    xc = float(np.asarray(th["v_xc"])[-1])
    ok = (atoms.min() == atoms.max() and xc < -0.5 and rmax <= reach + tol * 0.5 + 1e-9
          and float(np.asarray(th["f_hc[6]"]).max()) == 0
          and float(np.asarray(th["f_hc[7]"]).max()) <= tol)
    lr.check(ok, "LIGGGHTS wall mesh: the drum turned by fix move/mesh rotate drags its bed up "
             "(centre of mass x %.3g < -0.5), keeps all %d spheres, none beyond the facets "
             "(largest %.6f, bound %.6f), overlaps <= tol, no maxiter" % (xc, atoms[0], rmax, reach))


def test():
    args = lr.test_args()
    if getattr(args.lmp, "name", "") == "liggghts":
        liggghts_mesh_fix_test(args)
    incline_test(args)
    floor_test(args)
    box_test(args)
    moving_floor_test(args)
    drum_test(args)
    cone_test(args)
    restart_test(args)


if __name__ == "__main__":
    lr.main(test)
