"""Deterministic scenes of the accuracy-vs-time benchmark, written as LAMMPS data files
(atom_style sphere, full double precision) from fixed numpy seeds.

Units are SI (LAMMPS `units si`): grains of about 1 mm, glass density 2500 kg/m^3, g = 9.81.
Every scene but pile3d is 2d (discs in the x-y plane, `dimension 2`, `fix enforce2d`); pile3d
is a 3D pile of spheres (`dimension 3`, gravity along -y as in the 2d scenes, the floor a
y plane and walls in x and z). Masses are those LAMMPS gives a sphere of that diameter and
density (read_data), as in the paper's 6.3.

A scene is a dict: name, data (file name), box, walls (hardcontact `wall` keywords), walls
list for Python checks [(dim, coord, +1 lo / -1 hi)], h (step of hardcontact), skin,
gravity (m/s^2 along -y, 0 for none), dim (2 or 3; 2 when absent), and the arrays pos, vel,
diameter, density.
"""

import math

import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "python"))
import hctools as hc  # noqa: E402

D = 1.0e-3          # mean grain diameter (m)
RHO = 2500.0        # grain density (kg/m^3)
G = 9.81            # gravity (m/s^2)


def write_data(path, sc, title="hardcontact accuracy benchmark scene"):
    """The scene as a data file, every float exact (hctools.write_data)."""
    hc.write_data(path, sc["box"], sc["diameter"], sc["density"], sc["pos"], sc["vel"], title=title)

def _box_walls(width, top, ylo=0.0):
    walls = "wall xplane 0.0 %r wall yplane %r NULL" % (width, ylo)
    wl = [(0, 0.0, 1), (0, width, -1), (1, ylo, 1)]
    box = ((0.0, width), (ylo, top), (-0.5 * D, 0.5 * D))
    return box, walls, wl


def pile(layers, width_d=20, seed=1):
    """layers x width_d polydisperse discs (diameters uniform in [0.8, 1.2] mm) on a loose
    jittered lattice (spacing 1.3 mm) in a box of walls width_d mm wide: they fall and settle
    into a disordered pile about `layers` grain diameters deep (the deck settles it)."""
    rng = np.random.default_rng(seed)
    n = layers * width_d
    width = width_d * D
    a = 1.3 * D
    ncol = int(width // a)
    nrow = int(math.ceil(n / ncol))
    x0 = 0.5 * (width - (ncol - 1) * a)
    ij = np.array([(i, j) for j in range(nrow) for i in range(ncol)])[:n]
    pos = np.zeros((n, 3))
    pos[:, 0] = x0 + a * ij[:, 0] + rng.uniform(-0.04, 0.04, n) * D
    pos[:, 1] = 0.65 * D + a * ij[:, 1] + rng.uniform(-0.04, 0.04, n) * D
    dia = rng.uniform(0.8, 1.2, n) * D
    top = pos[:, 1].max() + 3 * D
    box, walls, wl = _box_walls(width, top)
    desc = ("%d polydisperse discs (d in [0.8, 1.2] mm) dropped from a loose lattice into a box "
            "of walls %d mm wide and settled: a pile about %d grains deep" % (n, width_d, layers))
    return dict(name="pile%d" % layers, desc=desc, pos=pos, vel=np.zeros((n, 3)), diameter=dia,
                density=np.full(n, RHO), box=box, walls=walls, wall_list=wl, h=1.0e-3,
                skin=1.0 * D, gravity=G, layers=layers)


def pile3d(layers, width_d=10, seed=5):
    """The 3D pile: layers x width_d^2 polydisperse spheres (diameters uniform in [0.8, 1.2]
    mm) on a loose jittered cubic lattice (spacing 1.25 mm) in a box of walls width_d mm wide
    in x and z: they fall (along -y) and settle into a disordered pile about `layers` grain
    diameters deep (a random packing of these spheres holds about width_d^2 per layer)."""
    rng = np.random.default_rng(seed)
    n = layers * width_d * width_d
    width = width_d * D
    a = 1.25 * D
    ncol = int(width // a)
    per = ncol * ncol
    nrow = int(math.ceil(n / per))
    x0 = 0.5 * (width - (ncol - 1) * a)
    ijk = np.array([(i, j, k) for j in range(nrow) for k in range(ncol) for i in range(ncol)])[:n]
    pos = np.zeros((n, 3))
    pos[:, 0] = x0 + a * ijk[:, 0] + rng.uniform(-0.04, 0.04, n) * D
    pos[:, 1] = 0.65 * D + a * ijk[:, 1] + rng.uniform(-0.04, 0.04, n) * D
    pos[:, 2] = x0 + a * ijk[:, 2] + rng.uniform(-0.04, 0.04, n) * D
    dia = rng.uniform(0.8, 1.2, n) * D
    top = pos[:, 1].max() + 3 * D
    walls = "wall xplane 0.0 %r wall zplane 0.0 %r wall yplane 0.0 NULL" % (width, width)
    wl = [(0, 0.0, 1), (0, width, -1), (2, 0.0, 1), (2, width, -1), (1, 0.0, 1)]
    box = ((0.0, width), (0.0, top), (0.0, width))
    desc = ("3D: %d polydisperse spheres (d in [0.8, 1.2] mm) dropped from a loose lattice into a "
            "box of walls %d x %d mm and settled: a pile about %d grains deep" % (
                n, width_d, width_d, layers))
    return dict(name="pile3d", desc=desc, pos=pos, vel=np.zeros((n, 3)), diameter=dia,
                density=np.full(n, RHO), box=box, walls=walls, wall_list=wl, h=1.0e-3,
                skin=1.0 * D, gravity=G, layers=layers, dim=3)


def crystal(ncol=30, nrow=30):
    """Monodisperse hexagonal crystal (d = 1 mm), every disc touching its six neighbours (and
    the walls on alternate rows), resting on the floor under gravity: redundant contacts
    (more contacts than degrees of freedom), non-unique multipliers (Lemma 1)."""
    n = ncol * nrow
    pos = np.zeros((n, 3))
    k = 0
    for j in range(nrow):
        for i in range(ncol):
            pos[k, 0] = (i + 0.5 + 0.5 * (j % 2)) * D
            pos[k, 1] = (0.5 + j * math.sqrt(3.0) / 2.0) * D
            k += 1
    width = (ncol + 0.5) * D
    top = pos[:, 1].max() + 3 * D
    box, walls, wl = _box_walls(width, top)
    desc = ("%d x %d equal discs (d = 1 mm) in hexagonal order, every disc touching six "
            "neighbours or a wall, on the floor of a box (redundant contacts)" % (ncol, nrow))
    return dict(name="crystal", desc=desc, pos=pos, vel=np.zeros((n, 3)), diameter=np.full(n, D),
                density=np.full(n, RHO), box=box, walls=walls, wall_list=wl, h=1.0e-3,
                skin=1.0 * D, gravity=G, layers=nrow)


def cluster(radius=0.4, r0=0.015, seed=3, clearance=0.15):
    """Paper 6.3 (examples/cluster_impact): a disc-shaped cluster of polydisperse discs
    (radii uniform in [0.8 r0, 1.2 r0], hexagonal lattice of spacing 2.4 r0, density 1000)
    whose lowest centre is `clearance` above the wall (0.15 m as in the example: the first
    contacts come at step 2), moving down at 1 m/s onto the wall y = 0, no gravity, h = 0.1 s
    (each disc moves about three diameters per step). radius 0.85 m gives the paper's ~2000
    discs; the benchmark uses a smaller cluster."""
    rng = np.random.default_rng(seed)
    a = 2.4 * r0
    pts = []
    nx = int(radius / a) + 2
    ny = int(radius / (a * math.sqrt(3) / 2)) + 2
    for j in range(-ny, ny + 1):
        for i in range(-nx, nx + 1):
            x = (i + 0.5 * (j % 2)) * a
            y = j * a * math.sqrt(3) / 2
            if x * x + y * y <= radius * radius:
                pts.append((x, radius + clearance + y))
    pts = np.array(pts)
    n = len(pts)
    pos = np.zeros((n, 3))
    pos[:, :2] = pts
    dia = 2.0 * r0 * rng.uniform(0.8, 1.2, n)
    vel = np.zeros((n, 3))
    vel[:, 1] = -1.0
    box = ((-4.0, 4.0), (0.0, 2.4), (-0.5 * r0, 0.5 * r0))
    desc = ("paper 6.3 with a cluster of radius %g m: %d discs (radii in [0.8, 1.2] x 15 mm) "
            "moving down at 1 m/s onto a wall, no gravity, 3 diameters per step" % (radius, n))
    return dict(name="cluster", desc=desc, pos=pos, vel=vel, diameter=dia, density=np.full(n, 1000.0),
                box=box, walls="wall yplane 0.0 NULL", wall_list=[(1, 0.0, 1)], h=0.1,
                skin=0.45, gravity=0.0, layers=None)


def pour(n=400, width_d=20, y0_d=10.0, phi=0.25, seed=4):
    """A loose random cloud of n polydisperse discs (diameters uniform in [0.8, 1.2] mm, area
    fraction phi, random non-overlapping positions, at rest) starting y0_d diameters above the
    floor of a box width_d mm wide: it falls under gravity and piles up in the box."""
    rng = np.random.default_rng(seed)
    width = width_d * D
    dia = rng.uniform(0.8, 1.2, n) * D
    area = float(np.sum(math.pi / 4 * dia ** 2))
    height = area / (phi * width)
    y0 = y0_d * D
    pos = np.zeros((n, 3))
    placed = 0
    cell = 1.2 * D
    grid = {}
    while placed < n:
        r = 0.5 * dia[placed]
        x = rng.uniform(r, width - r)
        y = rng.uniform(y0 + r, y0 + height - r)
        cx, cy = int(x // cell), int(y // cell)
        ok = True
        for gx in (cx - 1, cx, cx + 1):
            for gy in (cy - 1, cy, cy + 1):
                for k in grid.get((gx, gy), ()):
                    if (pos[k, 0] - x) ** 2 + (pos[k, 1] - y) ** 2 < (r + 0.5 * dia[k] + 0.02 * D) ** 2:
                        ok = False
                        break
        if not ok:
            continue
        pos[placed, 0], pos[placed, 1] = x, y
        grid.setdefault((cx, cy), []).append(placed)
        placed += 1
    order = np.argsort(pos[:, 1], kind="stable")    # IDs from the bottom up
    pos, dia = pos[order], dia[order]
    top = y0 + height + 3 * D
    box, walls, wl = _box_walls(width, top)
    desc = ("%d discs (d in [0.8, 1.2] mm) in a loose random cloud (area fraction %g) starting "
            "%g mm above the floor of a box %d mm wide, falling and piling up" % (n, phi, y0_d, width_d))
    return dict(name="pour", desc=desc, pos=pos, vel=np.zeros((n, 3)), diameter=dia, density=np.full(n, RHO),
                box=box, walls=walls, wall_list=wl, h=5.0e-4, skin=2.0 * D, gravity=G, layers=None)


def slide(h, vt=0.1, accel=100.0):
    """The spurious gap of a sliding contact: disc 2 (d = 1 mm) touches the fixed disc 1
    (outside the fix group: an obstacle) and moves tangentially at vt, pulled towards the
    centre of disc 1 by a central acceleration `accel` (a fix addforce in the deck), so it
    orbits in contact. Returns the data and the parameters; no gravity."""
    pos = np.array([[0.0, 0.0, 0.0], [0.0, D, 0.0]])
    vel = np.array([[0.0, 0.0, 0.0], [vt, 0.0, 0.0]])
    box = ((-3 * D, 3 * D), (-3 * D, 3 * D), (-0.5 * D, 0.5 * D))
    return dict(name="slide", pos=pos, vel=vel, diameter=np.full(2, D), density=np.full(2, RHO),
                box=box, walls="", wall_list=[], h=h, skin=max(0.3 * D, 5 * h * vt), gravity=0.0, layers=None,
                vt=vt, accel=accel)


def mass(sc):
    return sc["density"] * math.pi / 6.0 * sc["diameter"] ** 3
