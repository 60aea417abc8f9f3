#!/usr/bin/env python3
"""The contact forces in pressure and stress (the fix's virial, src/lammps/contact_virial.h):
`compute pressure` and `compute stress/atom` include them by default; `fix_modify ID virial no`
takes them out.

Cases:
  column: 16 single-file columns of 7 touching spheres (d = 1, m = pi/6) on a floor under
          g = 1, at rest from the start, in a box periodic in x and y (every sphere also touches
          its 4 neighbours of the layer, through the periodic boundary too, with no force).
          Analytic: the contact below sphere k (k = 0 at the floor) carries (N - k) m g, its
          lever is 2 r (r for the floor, whose lever ends on its surface), each pair half to
          each sphere, so the per-atom virial is W_zz(k) = r m g (2N - 2k - 1) and every
          other component 0; compute stress/atom gives -W (LAMMPS's sign). The global virial
          is sum_k = 16 r m g N^2: pressure zz = that / V. Tolerances 1e-9 relative (tol 1e-10; 1e-7 with friction).
          `fix_modify hc virial no`: pressure and stress 0. With friction 0.5 (block 3): the
          same numbers. Per rank count: the same per-atom values (pairs across processors).
  box:    150 frictional spheres (mu 0.3 between spheres, r 0.4-0.5) settle in a box with
          frictionless walls on four sides and a floor (free top), then the right wall moves in at 0.1 (sqrt(g d) = 1),
          compressing the pile (which rises). The virial identity of scheme (S), exact at
          every step: with levers at q^{n+1},
            W = sum_i x_i^{n+1} (x) m_i ((v^{n+1} - v^n)/h - g) + sum_walls p (x) F_wall,
          p on the wall's plane (its lever ends there); so W_xx = sum_i x_i m_i dv_x/h + L F_right
          (the left wall at x = 0), W_zz = sum_i z_i m_i (dv_z/h + g) (the floor at z = 0):
          checked on 4 consecutive dumped steps of the compression, from the dumped x, v
          (%.17g) and the wall rows of dump local, to 1e-7 of the largest term.
          The physics (virial theorem): over the slow compression the mean P_xx V (kinetic +
          virial) equals L times the mean force on the moving wall - the only wall that pushes
          along x, the others being frictionless - within 5 % (measured 0.2 %; the inertia
          term sum x m a averages to the change of sum x m v over the window, small at this
          speed), i.e. the wall's force over its area is the pressure inside.
Serial and under mpirun: the pairs across processors share the virial half and half."""

import numpy as np

import lammps_run as lr
import physics_common as pc

G = 1.0

COLUMN = lr.preamble("p p f", ghost_velocities=True) + """
read_data       data.column
pair_style      none
neighbor        0.3 bin
fix             g all gravity {g} vector 0 0 -1
fix             hc all hardcontact wall zplane 0 NULL tol 1e-10 {keywords}
{modify}
compute         s all stress/atom NULL virial
compute         p all pressure NULL virial
thermo_style    custom step atoms c_p[1] c_p[2] c_p[3] c_p[4] c_p[5] c_p[6] vol f_hc[1]
thermo_modify   format float %.16g
thermo          10
timestep        0.01
dump            d all custom 40 dump.s id z c_s[1] c_s[2] c_s[3] c_s[4] c_s[5] c_s[6]
dump_modify     d sort id format float %.16g
run             40
"""

NCOL, NLAYER, R = 4, 7, 0.5


def column(args, name, keywords, modify):
    wd = "%s/%s" % (args.workdir, name)
    lr.fresh_workdir(wd)
    x = [[0.5 + i, 0.5 + j, R + 2 * R * k] for k in range(NLAYER) for j in range(NCOL) for i in range(NCOL)]
    pc.write_sphere_data(wd + "/data.column", ((0.0, NCOL), (0.0, NCOL), (0.0, 10.0)), R, 1.0, x)
    res = lr.run_deck(args.lmp, COLUMN.format(g=G, keywords=keywords, modify=modify), args.np, wd,
                      timeout=args.timeout)
    th = pc.thermo_block(res, ["Step", "c_p[3]", "Volume"])
    frame = lr.read_dump(res.path("dump.s"))[-1].columns
    return th, frame


def test_column(args):
    m = pc.sphere_mass(R, 1.0)
    # the frictional solve (apgd) stops a little farther from the exact forces at the same tol
    for label, keywords, rel in (("frictionless", "", 1e-9), ("friction", "friction 0.5", 1e-7)):
        th, f = column(args, "column_" + label, keywords, "")
        layer = np.rint((f["z"] - R) / (2 * R)).astype(int)
        want = -R * m * G * (2 * NLAYER - 2 * layer - 1)
        szz = f["c_s[3]"]
        err = np.abs(szz - want).max() / abs(want).max()
        lr.check(err <= rel, "column %s: stress/atom zz = -r m g (2N - 2k - 1) in every layer "
                 "(%s .. %s), worst %.2g relative" % (label, want.min(), want.max(), err))
        other = max(np.abs(f["c_s[%d]" % k]).max() for k in (1, 2, 4, 5, 6))
        lr.check(other <= rel * abs(want).max(), "column %s: other components 0 (%.2g)" % (label, other))
        p_want = NCOL * NCOL * R * m * G * NLAYER ** 2 / float(th["Volume"][-1])
        pzz = th["c_p[3]"][1:]
        lr.check(np.abs(pzz - p_want).max() <= rel * p_want,
                 "column %s: pressure zz = 16 r m g N^2 / V = %.12g at every step after the first "
                 "(%.12g .. %.12g)" % (label, p_want, pzz.min(), pzz.max()))
        lr.check(th["c_p[3]"][0] == 0.0, "column %s: step 0 (no solve yet): no contact virial" % label)
    th, f = column(args, "column_off", "", "fix_modify      hc virial no")
    off = max(np.abs(th["c_p[3]"]).max(), max(np.abs(f["c_s[%d]" % k]).max() for k in range(1, 7)))
    lr.check(off == 0.0, "column: fix_modify hc virial no: pressure and stress/atom 0 (%.3g)" % off)


BOX = lr.preamble(ghost_velocities=True) + """
read_data       data.box
pair_style      none
neighbor        0.4 bin
variable        xr equal "{lx} - {speed} * (step > {settle}) * (step - {settle}) * dt"
fix             g all gravity {g} vector 0 0 -1
fix             hc all hardcontact friction 0.3 wall xplane 0 v_xr friction 0 wall yplane 0 {ly} friction 0 &
                wall zplane 0 NULL friction 0
timestep        {h}
compute         p all pressure thermo_temp
compute         w all pressure NULL virial
variable        lx equal v_xr
thermo_style    custom step atoms ke c_p[1] c_w[1] c_w[3] v_lx vol f_hc[1] f_hc[6] f_hc[7]
thermo_modify   format float %.17g
thermo          {every}
run             {settle}
thermo          1
dump            a all custom 1 dump.box id mass x y z vx vy vz
dump_modify     a sort id format float %.17g
dump            l all local 1 dump.rows f_hc[1] f_hc[3] f_hc[4] f_hc[5] f_hc[6] f_hc[7] f_hc[8] f_hc[9] f_hc[10]
dump_modify     l format float %.17g
run             4
thermo          {every}
undump          a
undump          l
dump            l all local {every} dump.walls f_hc[3] f_hc[4] f_hc[7]
dump_modify     l format float %.17g
run             {compress}
"""


def box_data(path, lx, ly, seed=5):
    rng = np.random.default_rng(seed)
    x = []
    for k in range(10):
        for j in range(3):
            for i in range(5):
                x.append([0.7 + 1.15 * i + 0.1 * rng.uniform(-1, 1), 0.8 + 1.2 * j + 0.1 * rng.uniform(-1, 1),
                          0.6 + 1.15 * k])
    r = rng.uniform(0.4, 0.5, len(x))
    pc.write_sphere_data(path, ((-0.5, lx + 0.5), (-0.5, ly + 0.5), (-0.5, 20.0)), r, 1.0, x)
    return len(x)


def test_box(args):
    lx, ly, h, speed, settle, compress, every = 6.0, 4.0, 0.02, 0.1, 600, 500, 5
    wd = "%s/box" % args.workdir
    lr.fresh_workdir(wd)
    n = box_data(wd + "/data.box", lx, ly)
    res = lr.run_deck(args.lmp, BOX.format(lx=lx, ly=ly, h=h, speed=speed, settle=settle, compress=compress,
                                           every=every, g=G), args.np, wd, timeout=args.timeout)
    lr.check(all(int(b["Atoms"][-1]) == n for b in res.thermo), "box: %d atoms throughout" % n)
    lr.check(max(float(b["f_hc[6]"][-1]) for b in res.thermo) == 0, "box: no solve at maxiter")
    # the exact identity on 4 consecutive steps (dump every step from the end of the settle)
    frames = lr.read_dump(res.path("dump.box"))
    rows = {f.timestep: f.columns for f in lr.read_dump_local(res.path("dump.rows"))}
    virial = {}
    for b in res.thermo:
        for s, w1, w3, l, v in zip(b["Step"], b["c_w[1]"], b["c_w[3]"], b["v_lx"], b["Volume"]):
            virial[int(s)] = (w1 * v, w3 * v, l)    # pressure times the domain's volume
    checked = 0
    for a, b in zip(frames[:-1], frames[1:]):
        s = b.timestep
        if s not in virial or s not in rows:
            continue
        x = np.column_stack([b.columns[k] for k in ("x", "y", "z")])
        m = b.columns["mass"]
        dv = np.column_stack([b.columns[k] - a.columns[k] for k in ("vx", "vy", "vz")]) / h
        force = m[:, None] * (dv + np.array([0.0, 0.0, G]))    # the contact force on each sphere
        c = rows[s]
        wall = c["f_hc[7]"].astype(int)
        f = (c["f_hc[3]"][:, None] * np.column_stack([c["f_hc[%d]" % k] for k in (4, 5, 6)])
             + np.column_stack([c["f_hc[%d]" % k] for k in (8, 9, 10)]))    # on the wall
        # the contact point: the sphere's centre projected on the wall's plane
        plane = {1: (0, 0.0), 2: (0, virial[s][2]), 3: (1, 0.0), 4: (1, ly), 5: (2, 0.0)}
        index = {int(t): k for k, t in enumerate(b.columns["id"])}
        wall_xx = wall_zz = 0.0
        for r in np.nonzero(wall > 0)[0]:    # pairs: their forces are in sum_i x_i (x) F_i
            p = x[index[int(c["f_hc[1]"][r])]].copy()
            axis, at = plane[wall[r]]
            p[axis] = at
            wall_xx += p[0] * f[r, 0]
            wall_zz += p[2] * f[r, 2]
        want_xx = float((x[:, 0] * force[:, 0]).sum() + wall_xx)
        want_zz = float((x[:, 2] * force[:, 2]).sum() + wall_zz)
        w_xx, w_zz = virial[s][0], virial[s][1]
        scale = float(np.abs(x * force).sum())
        lr.check(abs(w_xx - want_xx) <= 1e-7 * scale and abs(w_zz - want_zz) <= 1e-7 * scale,
                 "box step %d: W = sum_i x_i (x) F_i + sum_walls p (x) F_wall: xx %.10g (%.10g), "
                 "zz %.10g (%.10g)" % (s, w_xx, want_xx, w_zz, want_zz))
        checked += 1
    lr.check(checked == 4, "box: the identity on 4 steps (%d)" % checked)
    # the slow compression: mean P_xx against the mean force on the moving wall over its area
    walls = {f.timestep: f.columns for f in lr.read_dump_local(res.path("dump.walls"))}
    last = res.thermo[-1]
    # P_xx over the volume the walls enclose (L Ly Lz) against the wall's force over its area
    # (Ly Lz): P_xx V_domain / L against F_right
    p_in, f_out = [], []
    for s, pxx, l, v in zip(last["Step"], last["c_p[1]"], last["v_lx"], last["Volume"]):
        s = int(s)
        if s <= settle + 50 or s not in walls:
            continue
        c = walls[s]
        f_out.append(float((c["f_hc[3]"] * c["f_hc[4]"])[c["f_hc[7]"].astype(int) == 2].sum()))
        p_in.append(float(pxx) * float(v) / float(l))
    p_mean, f_mean = float(np.mean(p_in)), float(np.mean(f_out))
    lr.check(f_mean > 0.0 and abs(p_mean - f_mean) <= 0.05 * f_mean,
             "box, compressed by the moving wall: mean P_xx V / L = %.6g, mean force on the wall "
             "%.6g (%.3g; %d samples over %d steps)" % (p_mean, f_mean, p_mean / f_mean - 1, len(p_in), compress))


def test():
    args = lr.test_args(__doc__)
    test_column(args)
    test_box(args)


if __name__ == "__main__":
    lr.main(test)
