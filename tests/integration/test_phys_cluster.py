#!/usr/bin/env python3
"""The paper's section 6.3 cluster: 2029 polydisperse discs (dimension 2, atom_style sphere,
radii uniform in [0.8 r0, 1.2 r0], r0 = 0.015, mass 4/3 pi r^3 rho via the data file's
density), on a hexagonal lattice inside a circle of radius 0.85, h = 0.1 (a disc moves about
three diameters per step), neighbor skin 0.45, fix enforce2d, tol 1e-6, 12 steps. The data file
is written by physics_common.disc_cluster (fixed seed), so every rank count runs the same discs.

--case wall: the cluster (centre at y = 1) moves at U0 = -1 in y onto `wall yplane 0.0 NULL`
  (x periodic). Checked:
  * free flight, exactly (x^n = x^0 + n h U0, v^n = U0), up to the first step n1 whose solve
    starts from a gap D < h |U0| between the lowest disc and the wall; at step n1 the lowest
    disc ends touching the wall (|y - r| <= tol r);
  * no overlap at any step: f_hc[7] <= tol, and recomputed from the dumped positions for
    every pair (brute force with numpy) and every step: (r_i + r_j - d_ij) / (r_i + r_j) <= tol;
    no disc closer to the wall than its radius (y_i - r_i >= -tol r_i); 2029 atoms at every step;
  * kinetic energy never increases (Prop. 3: no force, the wall is fixed);
  * momentum: p_x = 0 to round-off (the wall pushes along y only, x periodic); p_y never
    decreases (the wall only pushes up: an impulse with mu >= 0) and its change per step is
    h times the sum of the per-atom contact forces (pair forces cancel), whose x sum is 0;
  * the impact takes the downward momentum: p_y(12) >= 0.5 p_y(0) and KE(12) <= 0.5 KE(0)
    (sanity bounds: without the wall both stay at their initial values; the run gives about
    0.22 and 0.24). The cluster does not come to rest: frictionless discs spread sideways.
--case free: no wall, no force, box periodic: the left half of the cluster (x < 0) moves at
  (+1, 0.25), the right half at (-1, 0.25): the halves collide from the first step. Checked:
  total momentum exact (1e-13 of sum m|v|) at every step, centre of mass on its exact straight
  path x_c(n) = x_c(0) + n h p / M (Remark 10/11, unwrapped coordinates, 1e-12), kinetic energy
  never increasing, no overlap (f_hc[7] and all pairs from the dump), atoms conserved.
Serial and under mpirun: the same assertions whatever the rank count; agreement between rank
counts is test_phys_cluster_ranks.py."""

import argparse

import numpy as np

import lammps_run as lr
import physics_common as pc

R0 = 0.015
TOL = 1e-6
H = 0.1
U0 = 1.0
NSTEPS = 12
SEED = 63
SKIN = 0.45

DECK = """
units           si
dimension       2
atom_style      sphere
boundary        {boundary}
atom_modify     map array
read_data       data.cluster
pair_style      none
neighbor        {skin} bin
fix             hc all hardcontact tol {tol} {walls}
fix             2d all enforce2d
timestep        {h}
compute         ke all ke
variable        px atom mass*vx
variable        py atom mass*vy
compute         p all reduce sum v_px v_py
thermo_style    custom step atoms c_ke c_p[1] c_p[2] f_hc[1] f_hc[3] f_hc[4] f_hc[5] f_hc[6] f_hc[7] f_hc[9]
thermo_modify   format float %.17g norm no
thermo          1
dump            d all custom {every} dump.atoms id type radius mass x y z xu yu vx vy vz f_hc[1] f_hc[2] f_hc[3] f_hc[4]
dump_modify     d format float %.17g sort id
run             {n}
"""


def wall_setup():
    x, r = pc.disc_cluster(0.85, R0, SEED)
    x[:, 1] += 1.0
    v = np.zeros_like(x)
    v[:, 1] = -U0
    return x, r, v, ((-2.0, 2.0), (0.0, 3.0), (-0.5, 0.5))


def free_setup():
    x, r = pc.disc_cluster(0.85, R0, SEED)
    v = np.zeros_like(x)
    v[:, 0] = np.where(x[:, 0] < 0.0, U0, -U0)
    v[:, 1] = 0.25
    return x, r, v, ((-3.0, 3.0), (-3.0, 3.0), (-0.5, 0.5))


def deck(case, every=1, n=NSTEPS):
    if case == "wall":
        return DECK.format(boundary="p f p", walls="wall yplane 0.0 NULL", skin=SKIN, tol=TOL, h=H,
                           every=every, n=n)
    return DECK.format(boundary="p p p", walls="", skin=SKIN, tol=TOL, h=H, every=every, n=n)


def common_checks(name, th, frames, natoms):
    lr.check(list(th["Step"]) == list(range(NSTEPS + 1)) and bool(np.all(th["Atoms"] == natoms)),
             "%s: %d steps, %d atoms at every step" % (name, NSTEPS, natoms))
    lr.check([f.timestep for f in frames] == list(range(NSTEPS + 1)) and
             all(len(f.columns["id"]) == natoms for f in frames), "%s: every atom in every frame" % name)
    lr.check(float(th["f_hc[7]"].max()) <= TOL, "%s: f_hc[7] <= tol at every step (max %.3g)"
             % (name, float(th["f_hc[7]"].max())))
    lr.check(float(th["f_hc[6]"][-1]) == 0, "%s: no solve stopped at maxiter" % name)
    worst = 0.0
    for f in frames:
        ov, where = pc.pair_overlaps(pc.positions(f), f.columns["radius"])
        worst = max(worst, ov)
        lr.check(ov <= TOL + 1e-12, "%s step %d: no pair overlaps beyond tol (largest %.3g, atoms %s)"
                 % (name, f.timestep, ov, None if where is None else tuple(f.columns["id"][list(where)])))
    ke = th["c_ke"]
    rises = np.diff(ke) / ke[0]
    lr.check(float(rises.max()) <= 1e-13, "%s: kinetic energy never increases (largest rise %.3g of KE0)"
             % (name, float(rises.max())))
    return worst


def check_wall(args, res, x0, r, v0):
    th = pc.thermo_block(res, ["Step", "Atoms", "c_ke", "c_p[1]", "c_p[2]", "f_hc[6]", "f_hc[7]"])
    frames = lr.read_dump(res.path("dump.atoms"))
    n = len(x0)
    common_checks("wall", th, frames, n)
    mass = frames[0].columns["mass"]
    lr.check(np.allclose(mass, pc.sphere_mass(r, 1000.0), rtol=1e-14, atol=0), "wall: masses 4/3 pi r^3 rho")

    # free flight up to the first contact with the wall, then the lowest disc touches it
    d_min = float((x0[:, 1] - r).min())
    n1 = next(k for k in range(1, NSTEPS + 1) if d_min - H * U0 * (k - 1) < H * U0)
    lr.check(1 < n1 < NSTEPS // 2, "wall: first contact with the wall at step %d" % n1)
    for f in frames[:n1]:
        k = f.timestep
        xe = x0.copy()
        xe[:, 1] -= k * H * U0
        err = max(float(np.abs(pc.positions(f) - xe).max()), float(np.abs(pc.velocities(f) - v0).max()))
        lr.check(err <= 1e-12, "wall step %d: free flight, exact (%.3g)" % (k, err))
    gap1 = frames[n1].columns["y"] - r
    lr.check(abs(float(gap1.min())) <= TOL * R0 * 1.2,
             "wall step %d: the lowest disc ends touching the wall (y - r = %.3g)" % (n1, float(gap1.min())))

    # the wall: never crossed
    worst = max(float(((r - f.columns["y"]) / r).max()) for f in frames)
    lr.check(worst <= TOL + 1e-12, "wall: no disc closer to the wall than its radius (largest (r - y)/r %.3g)" % worst)

    # momentum: x exact, y only gains from the wall, by h times the contact forces
    px, py = th["c_p[1]"], th["c_p[2]"]
    scale = float(np.abs(py[0]))
    lr.check(float(np.abs(px).max()) <= 1e-13 * scale, "wall: p_x = 0 to round-off (%.3g)" % float(np.abs(px).max()))
    dpy = np.diff(py)
    lr.check(float(dpy.min()) >= -1e-13 * scale, "wall: p_y never decreases (smallest change %.3g)" % float(dpy.min()))
    for f, fp in zip(frames[1:], frames[:-1]):
        fx, fy = float(f.columns["f_hc[2]"].sum()), float(f.columns["f_hc[3]"].sum())
        dp = (mass[:, None] * (pc.velocities(f) - pc.velocities(fp))).sum(axis=0)
        lr.check(abs(H * fy - dp[1]) <= 1e-9 * scale and abs(H * fx) <= 1e-9 * scale,
                 "wall step %d: dp_y = h sum F_y = %.12g (%.12g), sum F_x = %.3g"
                 % (f.timestep, H * fy, dp[1], fx))
    lr.check(py[-1] >= 0.5 * py[0] and th["c_ke"][-1] <= 0.5 * th["c_ke"][0],
             "wall: the impact took the downward momentum: p_y %.4g -> %.4g, KE %.4g -> %.4g"
             % (py[0], py[-1], th["c_ke"][0], th["c_ke"][-1]))


def check_free(args, res, x0, r, v0):
    th = pc.thermo_block(res, ["Step", "Atoms", "c_ke", "c_p[1]", "c_p[2]", "f_hc[6]", "f_hc[7]"])
    frames = lr.read_dump(res.path("dump.atoms"))
    common_checks("free", th, frames, len(x0))
    mass = frames[0].columns["mass"]
    p0 = (mass[:, None] * v0).sum(axis=0)
    scale = float((mass * np.linalg.norm(v0, axis=1)).sum())
    worst = max(float(np.abs(pc.momentum(f) - p0).max()) for f in frames)
    worst_th = max(float(np.abs(th["c_p[1]"] - p0[0]).max()), float(np.abs(th["c_p[2]"] - p0[1]).max()))
    lr.check(max(worst, worst_th) <= 1e-13 * scale,
             "free: momentum (%.6g, %.6g) exact at every step (largest error: dump %.3g, thermo %.3g; "
             "bound 1e-13 sum m|v| = %.3g)" % (p0[0], p0[1], worst, worst_th, 1e-13 * scale))
    M = float(mass.sum())
    c0 = (mass[:, None] * x0).sum(axis=0) / M
    worst_c = 0.0
    for f in frames:
        xu = np.column_stack([f.columns["xu"], f.columns["yu"], f.columns["z"]])
        c = (mass[:, None] * xu).sum(axis=0) / M
        worst_c = max(worst_c, float(np.abs(c - (c0 + f.timestep * H * p0 / M)).max()))
    lr.check(worst_c <= 1e-12, "free: centre of mass on its exact path (largest error %.3g)" % worst_c)
    ke = th["c_ke"]
    lr.check(ke[-1] < 0.9 * ke[0], "free: the halves collided (KE %.4g -> %.4g)" % (ke[0], ke[-1]))


def test():
    pre = argparse.ArgumentParser(add_help=False)
    pre.add_argument("--case", choices=["wall", "free"], required=True)
    case_args, rest = pre.parse_known_args()
    args = lr.test_args(__doc__, rest)
    x0, r, v0, box = wall_setup() if case_args.case == "wall" else free_setup()
    pc.write_sphere_data(args.workdir + "/data.cluster", box, r, 1000.0, x0, v0,
                         host=args.lmp, dimension=2)
    res = lr.run_deck(args.lmp, deck(case_args.case), args.np, args.workdir, timeout=args.timeout)
    print("run: %.1f s on %d rank(s)" % (res.seconds, args.np))
    (check_wall if case_args.case == "wall" else check_free)(args, res, x0, r, v0)


if __name__ == "__main__":
    lr.main(test)
