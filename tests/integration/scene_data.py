"""Deterministic scenes for the restart and output tests of fix hardcontact, written as LAMMPS
data files (atom_style sphere) from Python, so that a scene is the same for any number of MPI
ranks (create_atoms IDs and random atom-style variables are not).

    import scene_data as sd
    s = sd.pile(n_side=5, layers=4, seed=1)
    sd.write_data(workdir / "pile.data", s)
"""

import math
from collections import namedtuple

import numpy as np

import lammps_run    # noqa: F401 - puts python/ (hctools) on sys.path
import hctools as hc

# box: (3, 2) array of lo/hi; pos, vel: (N, 3); diameter, density: (N,)
Scene = namedtuple("Scene", "box pos vel diameter density")


def mass(scene):
    """Per-atom mass as read_data sets it: density x volume of the sphere."""
    return hc.sphere_mass(scene.diameter, scene.density)


def write_data(path, scene, comment="hardcontact test scene"):
    """The scene as a LAMMPS data file (hctools.write_data: every float exact)."""
    hc.write_data(path, scene.box, scene.diameter, scene.density, scene.pos, scene.vel, title=comment)


def jittered_lattice(counts, spacing, origin, jitter, rng):
    """Points of a simple cubic lattice (counts = (nx, ny, nz)), each moved by up to
    +-jitter per coordinate."""
    idx = np.array([(i, j, k) for k in range(counts[2]) for j in range(counts[1])
                    for i in range(counts[0])], dtype=float)
    pos = np.asarray(origin, dtype=float) + spacing * idx
    return pos + rng.uniform(-jitter, jitter, size=pos.shape)


def pile(n_side=5, layers=4, spacing=1.2, d_min=0.8, d_max=1.0, jitter=0.08, v_down=2.0,
         v_random=0.5, seed=1, height=20.0):
    """Polydisperse spheres on a jittered lattice just above a floor at z = 0, inside a box
    [0, n_side*spacing]^2 x [0, height], moving down at v_down with random components up to
    v_random: a pile forms on the floor within a few tens of steps. No overlap at the start
    (d_max + 2 jitter <= spacing)."""
    assert d_max + 2 * jitter < spacing
    rng = np.random.default_rng(seed)
    width = n_side * spacing
    pos = jittered_lattice((n_side, n_side, layers), spacing,
                           (0.5 * spacing, 0.5 * spacing, 0.5 * spacing + 0.05), jitter, rng)
    n = len(pos)
    diameter = rng.uniform(d_min, d_max, n)
    density = np.ones(n)
    vel = rng.uniform(-v_random, v_random, (n, 3))
    vel[:, 2] -= v_down
    box = np.array([[0.0, width], [0.0, width], [0.0, height]])
    return Scene(box, pos, vel, diameter, density)


def gas(n_side=6, spacing=1.25, d_min=0.8, d_max=1.0, jitter=0.1, speed=1.0, converge=0.0,
        density_range=(0.5, 2.0), seed=2):
    """Polydisperse spheres of different densities on a jittered lattice in a periodic cube of
    side n_side*spacing, random velocities (normal, std `speed` per component) minus the mean
    (zero total momentum) plus a converging field -converge*(x - centre): dense enough that
    many pairs collide within tens of steps, across the periodic boundaries and across
    processor boundaries."""
    assert d_max + 2 * jitter <= spacing
    rng = np.random.default_rng(seed)
    side = n_side * spacing
    pos = jittered_lattice((n_side, n_side, n_side), spacing, (0.5 * spacing,) * 3, jitter, rng)
    n = len(pos)
    diameter = rng.uniform(d_min, d_max, n)
    density = rng.uniform(density_range[0], density_range[1], n)
    vel = rng.normal(0.0, speed, (n, 3)) - converge * (pos - 0.5 * side)
    m = density * diameter ** 3
    vel -= (m[:, None] * vel).sum(axis=0) / m.sum()
    box = np.array([[0.0, side]] * 3)
    return Scene(box, pos, vel, diameter, density)


def square_stack(n_side=4, layers=3, spacing=1.01, diameter=1.0, lift=0.01, height=10.0):
    """Monodisperse spheres stacked on a floor at z = 0 in a box periodic in x and y
    (side n_side*spacing): odd layers on a square lattice, even layers in its hollows (a
    frictionless pile that is mechanically stable, unlike a disordered one, which keeps
    creeping). Every layer starts `lift` above its resting height, at rest: the stack drops
    into place within a few steps."""
    rest_dz = math.sqrt(diameter ** 2 - 2.0 * (0.5 * spacing) ** 2)
    pos = []
    for k in range(layers):
        shift = 0.5 * spacing if k % 2 else 0.0
        z = 0.5 * diameter + k * rest_dz + (k + 1) * lift
        for j in range(n_side):
            for i in range(n_side):
                pos.append(((i + 0.5) * spacing + shift, (j + 0.5) * spacing + shift, z))
    pos = np.array(pos)
    side = n_side * spacing
    pos[:, :2] %= side
    n = len(pos)
    box = np.array([[0.0, side], [0.0, side], [0.0, height]])
    return Scene(box, pos, np.zeros((n, 3)), np.full(n, float(diameter)), np.ones(n))
