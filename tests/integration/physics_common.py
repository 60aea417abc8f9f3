"""Shared pieces of the physics deck tests (test_phys_*.py): data files of spheres given by
radius (hctools writes them), the masses LAMMPS gives such atoms, and a few checks on dumps.

Why a data file: create_atoms numbers atoms differently with the number of MPI ranks and
random() in atom-style variables is per rank, so decks meant to be compared across rank counts
read the same file, written here with fixed seeds and every float at full precision (repr).
"""

import math

import numpy as np

import lammps_run as lr
import hctools as hc    # on sys.path through lammps_run

# dump custom columns of the tests (f_hc = the fix); the decks add format float %.16g or %.17g
DUMP_COLUMNS = "id type radius mass x y z vx vy vz f_hc[1] f_hc[2] f_hc[3] f_hc[4]"


# The end of a deck that writes every step at full precision: thermo, the atoms (columns
# {cols}, e.g. DUMP_COLUMNS) and the contacts (the fix's local array), then runs {n} steps.
EVERY_STEP_OUTPUT = """thermo_modify   format float %.16g
thermo          1
dump            d all custom 1 dump.atoms {cols}
dump_modify     d format float %.16g sort id
dump            l all local 1 dump.local f_hc[1] f_hc[2] f_hc[3] f_hc[4] f_hc[5] f_hc[6] f_hc[7]
dump_modify     l format float %.16g
run             {n}
"""


# The first lines of a 3D deck of spheres in a box with free (non-periodic) boundaries.
HEADER_3D_FREE = lr.preamble()

# The same over a floor: periodic in x and y, ghost velocities for friction and moving walls.
HEADER_3D_FLOOR = lr.preamble("p p f", ghost_velocities=True)


# One sphere of diameter 1 above a floor at z = 0 (periodic in x, y) under g = 1: format with
# x, y, z (centre), fix_extra (keywords after the wall), h, and the output and run lines.
DROP_ON_FLOOR = lr.preamble("p p f") + """
region          box block -2 2 -2 2 0 10
create_box      1 box
create_atoms    1 single {x} {y} {z}
set             atom 1 diameter 1.0 density 1.0
pair_style      none
neighbor        0.5 bin
fix             hc all hardcontact wall zplane 0 NULL {fix_extra}
fix             g all gravity 1.0 vector 0 0 -1
timestep        {h}
{output}
run             {n}
"""


def sphere_mass(radius, density):
    """Mass LAMMPS gives an atom_style sphere atom from a data file (diameter, density) or
    `set density`: 4/3 pi r^3 rho, also in 2d (what the paper's 6.3 wants: spheres in a
    plane; LIGGGHTS in 2d: hctools.write_data's host)."""
    return hc.sphere_mass(2.0 * np.asarray(radius, dtype=float), density)


def write_sphere_data(path, box, radius, density, x, v=None, title="hardcontact physics test",
                      host=None, dimension=3, omega=None):
    """hctools.write_data with radii (2 r is exact in floating point): type 1, every float
    exact; host and dimension make a 2d file give LIGGGHTS the masses LAMMPS gives; omega:
    the spins (default 0)."""
    hc.write_data(path, box, 2.0 * np.asarray(radius, dtype=float), density, x, v, title=title,
                  host=host, dimension=dimension, omega=omega)


def positions(frame):
    c = frame.columns
    return np.column_stack([c["x"], c["y"], c["z"]])


def velocities(frame):
    c = frame.columns
    return np.column_stack([c["vx"], c["vy"], c["vz"]])


def momentum(frame):
    return (frame.columns["mass"][:, None] * velocities(frame)).sum(axis=0)


def kinetic_energy(frame):
    return 0.5 * float((frame.columns["mass"] * (velocities(frame) ** 2).sum(axis=1)).sum())


def pair_overlaps(x, radius, block=512):
    """Largest overlap over all pairs, relative to r_i + r_j (0 if none), and the pair
    (i, j) (0-based, in the order given) where it occurs. Brute force over all pairs in
    blocks: an independent recomputation, no neighbour list involved."""
    x = np.asarray(x, dtype=float)
    radius = np.asarray(radius, dtype=float)
    n = len(x)
    worst, where = 0.0, None
    for a in range(0, n, block):
        xa = x[a:a + block]
        d = np.sqrt(((xa[:, None, :] - x[None, :, :]) ** 2).sum(axis=2))
        size = radius[a:a + block, None] + radius[None, :]
        rel = (size - d) / size
        idx = np.arange(a, min(a + block, n))
        rel[idx - a, idx] = -np.inf    # a sphere with itself
        k = np.unravel_index(np.argmax(rel), rel.shape)
        if rel[k] > worst:
            worst, where = float(rel[k]), (int(idx[k[0]]), int(k[1]))
    return worst, where


def check_conveyor(t, th, v, mu, h, floor):
    """A sphere of radius 0.5 at rest on a floor that slides at v (g = 1, friction mu): it
    accelerates at mu g and spins up at 5 mu g / 2r until t* = 2 v / (7 mu g), then rolls at
    2/7 v with omega r = -5/7 v (errors <= 1e-5 away from t* +- 2h), its centre at height r
    within 1e-6, no solve at maxiter (the floor's work through friction is allowed by the
    energy test). th: thermo with v_vx, v_wy, v_gap, f_hc[6]; floor names the floor."""
    r = 0.5
    tstar = 2.0 * v / (7.0 * mu)
    vx, wy = np.asarray(th["v_vx"]), np.asarray(th["v_wy"])
    slide, roll = t < tstar - 2 * h, t > tstar + 2 * h
    err_slide = max(float(np.abs(vx[slide] - mu * t[slide]).max()),
                    float(np.abs(wy[slide] + 5.0 * mu * t[slide] / (2.0 * r)).max()))
    err_roll = max(float(np.abs(vx[roll] - 2.0 / 7.0 * v).max()),
                   float(np.abs(wy[roll] * r + 5.0 / 7.0 * v).max()))
    gap = float(np.abs(np.asarray(th["v_gap"])).max())
    lr.check(err_slide <= 1e-5 and err_roll <= 1e-5,
             "conveyor: %s slides at V = %g; the sphere accelerates at mu g and spins up at "
             "5 mu g / 2r until t* = 2 V / (7 mu g) = %.4g, then rolls at 2/7 V = %.6g with "
             "omega r = -5/7 V (errors %.3g sliding, %.3g rolling)"
             % (floor, v, tstar, 2.0 / 7.0 * v, err_slide, err_roll))
    lr.check(gap <= 1e-6, "conveyor: centre at height r within 1e-6 (largest %.3g)" % gap)
    maxiter = float(np.asarray(th["f_hc[6]"]).max())
    lr.check(maxiter == 0, "conveyor: no solve stopped at maxiter: %g" % maxiter)


def check_lift(th, vz, floor):
    """A sphere on a floor rising at vz: carried at z_floor + r (|gap| <= 1e-6) at vz (within
    1e-6 after the first two steps). th: thermo with v_gap, v_vz."""
    gap = float(np.abs(np.asarray(th["v_gap"])).max())
    err = float(np.abs(np.asarray(th["v_vz"])[2:] - vz).max())
    lr.check(gap <= 1e-6 and err <= 1e-6,
             "lift: %s rising at %g carries the sphere at z_floor + r (largest |gap| %.3g) and "
             "vz = %g (largest error %.3g)" % (floor, vz, gap, vz, err))


def thermo_block(res, columns):
    """The single thermo block of a run, checked to hold the given columns."""
    lr.check(len(res.thermo) == 1, "one thermo block")
    th = res.thermo[0]
    missing = [c for c in columns if c not in th]
    lr.check(not missing, "thermo columns present (missing: %s)" % missing)
    return th


def isotonic(target, weight):
    """Weighted least-squares nondecreasing fit of target (pool adjacent violators): exact."""
    blocks = []    # [value, weight, count]
    for t, w in zip(target, weight):
        blocks.append([float(t), float(w), 1])
        while len(blocks) > 1 and blocks[-2][0] > blocks[-1][0]:
            v2, w2, c2 = blocks.pop()
            v1, w1, c1 = blocks.pop()
            blocks.append([(w1 * v1 + w2 * v2) / (w1 + w2), w1 + w2, c1 + c2])
    out = []
    for v, _, c in blocks:
        out += [v] * c
    return np.array(out)


def line_step(q, u_free, radius, mass, h):
    """One step of scheme (S) for spheres on a line, sorted by position q (1D coordinates along
    the line, u_free the speeds along it), exactly: u = argmin sum m (u - u_free)^2 subject to
    D_k + h (u_{k+1} - u_k) >= 0 for neighbours k, k+1 (the only pairs that can touch first),
    solved by substitution w_k = u_k - c_k (c_{k+1} = c_k - D_k / h) and isotonic regression.
    Returns (q_next, u)."""
    q = np.asarray(q, dtype=float)
    d = (q[1:] - q[:-1]) - (radius[1:] + radius[:-1])
    c = np.concatenate([[0.0], -np.cumsum(d / h)])
    u = isotonic(np.asarray(u_free, dtype=float) - c, mass) + c
    return q + h * u, u


def disc_cluster(radius_of_cluster, r0, seed, spacing_factor=2.4 * 1.001):
    """The paper's 6.3 cluster: discs (z = 0) on a hexagonal lattice of spacing
    spacing_factor r0 inside a circle of the given radius centred on the origin, radii uniform
    in [0.8 r0, 1.2 r0] from numpy's default_rng(seed). With spacing > 2.4 r0 no two discs
    touch. Returns (positions (N, 3), radii (N,)), ordered by lattice row then column."""
    a = spacing_factor * r0
    ny = int(radius_of_cluster / (a * math.sqrt(3) / 2)) + 1
    nx = int(radius_of_cluster / a) + 1
    pts = []
    for j in range(-ny, ny + 1):
        y = j * a * math.sqrt(3) / 2
        for i in range(-nx - 1, nx + 2):
            x = (i + 0.5 * (j % 2)) * a
            if x * x + y * y <= radius_of_cluster ** 2:
                pts.append((x, y, 0.0))
    rng = np.random.default_rng(seed)
    radii = rng.uniform(0.8 * r0, 1.2 * r0, len(pts))
    return np.array(pts), radii
