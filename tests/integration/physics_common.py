"""Shared pieces of the physics deck tests (test_phys_*.py): a deterministic data-file writer
for atom_style sphere, the masses LAMMPS gives such atoms, and a few checks on dumps.

Why a data file: create_atoms numbers atoms differently with the number of MPI ranks and
random() in atom-style variables is per rank, so decks meant to be compared across rank counts
read the same file, written here with fixed seeds and every float at full precision (repr).
"""

import math

import numpy as np

import lammps_run as lr

# dump custom columns of the tests (f_hc = the fix); the decks add format float %.16g or %.17g
DUMP_COLUMNS = "id type radius mass x y z vx vy vz f_hc[1] f_hc[2] f_hc[3] f_hc[4]"


# The first lines of a 3D deck of spheres in a box with free (non-periodic) boundaries.
HEADER_3D_FREE = """
units           lj
atom_style      sphere
dimension       3
boundary        f f f
atom_modify     map array
"""

# The same over a floor: periodic in x and y, ghost velocities for friction and moving walls.
HEADER_3D_FLOOR = """
units           lj
atom_style      sphere
dimension       3
boundary        p p f
atom_modify     map array
comm_modify     vel yes
"""


# One sphere of diameter 1 above a floor at z = 0 (periodic in x, y) under g = 1: format with
# x, y, z (centre), fix_extra (keywords after the wall), h, and the output and run lines.
DROP_ON_FLOOR = """
units           lj
atom_style      sphere
dimension       3
boundary        p p f
atom_modify     map array
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
    plane; LIGGGHTS in 2d: see write_sphere_data)."""
    return 4.0 / 3.0 * math.pi * radius ** 3 * density


def write_sphere_data(path, box, radius, density, x, v=None, title="hardcontact physics test",
                      host=None, dimension=3):
    """Write a LAMMPS data file for atom_style sphere, atoms numbered 1..N in the given order,
    type 1. box = ((xlo, xhi), (ylo, yhi), (zlo, zhi)); radius, density: per atom (or scalar);
    x: (N, 3) positions; v: (N, 3) velocities (default 0). Floats are written with repr, so
    the file holds exactly the doubles given.
    host, dimension: the Host that reads the file and the deck's dimension. In a 2d box
    LIGGGHTS gives a sphere the mass of a disc, pi r^2 rho, where LAMMPS gives 4/3 pi r^3 rho;
    for LIGGGHTS the file then holds the density 4/3 r rho, so that both hosts simulate the same
    masses (sphere_mass) and the measured bounds of the tests hold on both."""
    x = np.asarray(x, dtype=float).reshape(-1, 3)
    n = len(x)
    radius = np.broadcast_to(np.asarray(radius, dtype=float), (n,))
    density = np.broadcast_to(np.asarray(density, dtype=float), (n,))
    if dimension == 2 and getattr(host, "name", None) == "liggghts":
        density = density * (4.0 / 3.0) * radius
    v = np.zeros((n, 3)) if v is None else np.asarray(v, dtype=float).reshape(n, 3)
    r = repr
    lines = [title, "", "%d atoms" % n, "1 atom types", ""]
    for (lo, hi), name in zip(box, ("x", "y", "z")):
        lines.append("%s %s %slo %shi" % (r(float(lo)), r(float(hi)), name, name))
    lines += ["", "Atoms # sphere", ""]
    for i in range(n):
        # the data file holds the diameter; 2 * r is exact in floating point
        lines.append("%d 1 %s %s %s %s %s" % (i + 1, r(2.0 * float(radius[i])), r(float(density[i])),
                                              r(float(x[i, 0])), r(float(x[i, 1])), r(float(x[i, 2]))))
    lines += ["", "Velocities", ""]
    for i in range(n):
        lines.append("%d %s %s %s 0 0 0" % (i + 1, r(float(v[i, 0])), r(float(v[i, 1])), r(float(v[i, 2]))))
    with open(str(path), "w") as f:
        f.write("\n".join(lines) + "\n")


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
