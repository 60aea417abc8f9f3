"""Shared helpers of the hardcontact examples (standard library + numpy; scipy if present):
deterministic scenes (written as LAMMPS data files by the project's toolkit, python/hctools,
whose writers and readers this module re-exports), and the measures the READMEs report
(largest overlap, packing fraction, bed height).

Why data files: create_atoms numbers atoms differently with the number of MPI ranks, and
random() in atom-style variables is per rank; a scene written here is the same everywhere and
both decks of a scene (hard contacts and the soft-sphere twin) read the same file.

Masses: LAMMPS gives an atom_style sphere atom of diameter d and density rho the mass
pi/6 d^3 rho, in 2d too (read_data and `set density`); every deck here relies on that.
"""

import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), "python"))
# the toolkit's writers and readers, under the names the examples use
from hctools import (read_dump, read_loop_times, read_thermo, sphere_mass,  # noqa: E402,F401
                     write_data, write_stl)


# ------------------------------------------------------------------------------ scenes


def data_args(out, count, seed):
    """The command line of the scene writers, make_data.py [OUT] [COUNT] [SEED]: (OUT, COUNT,
    SEED) from sys.argv, each defaulting to the given value."""
    argv = sys.argv[1:]
    return (argv[0] if len(argv) > 0 else out,
            int(argv[1]) if len(argv) > 1 else count,
            int(argv[2]) if len(argv) > 2 else seed)


def jittered_grid(nx, ny, sx, sy, origin, jitter, rng):
    """Points of an nx x ny rectangular grid (spacings sx, sy) in the xy plane (z = 0), row by
    row from the bottom, each moved by up to +-jitter in x and y."""
    j, i = np.mgrid[0:ny, 0:nx]
    pos = np.zeros((nx * ny, 3))
    pos[:, 0] = origin[0] + sx * i.ravel()
    pos[:, 1] = origin[1] + sy * j.ravel()
    pos[:, :2] += rng.uniform(-jitter, jitter, size=(nx * ny, 2))
    return pos


def disc_column(width, rows, d0, spread=0.2, y0=0.0, seed=1, density=2500.0, height=None):
    """Polydisperse discs (diameters uniform in [(1 - spread) d0, (1 + spread) d0]) on a
    jittered square grid filling x in [0, width], `rows` rows from y0 up, at rest, no overlap
    (spacing 1.1 d_max). Returns (box, diameter, density, pos, vel) for write_data; the box
    is [0, width] x [0, height] (default: twice the column) x [-d0, d0]."""
    rng = np.random.default_rng(seed)
    dmax = (1.0 + spread) * d0
    spacing = 1.1 * dmax
    nx = int(width // spacing)
    spacing_x = width / nx
    jitter = 0.5 * (spacing - dmax) * 0.9
    pos = jittered_grid(nx, rows, spacing_x, spacing, (0.5 * spacing_x, y0 + 0.5 * spacing), jitter, rng)
    n = len(pos)
    diameter = rng.uniform((1.0 - spread) * d0, dmax, n)
    top = y0 + rows * spacing
    height = height if height is not None else 2.0 * top
    box = ((0.0, width), (0.0, height), (-d0, d0))
    return box, diameter, np.full(n, density), pos, np.zeros((n, 3))


# ------------------------------------------------------------------------------ measures

def neighbour_pairs(pos, cutoff):
    """Index pairs (i < j) closer than cutoff (scipy cKDTree, or a numpy sweep)."""
    try:
        from scipy.spatial import cKDTree
        return np.array(sorted(cKDTree(pos).query_pairs(cutoff)), dtype=int).reshape(-1, 2)
    except ImportError:
        out = []
        for i in range(len(pos) - 1):
            d = np.linalg.norm(pos[i + 1:] - pos[i], axis=1)
            for j in np.nonzero(d < cutoff)[0]:
                out.append((i, i + 1 + j))
        return np.array(out, dtype=int).reshape(-1, 2)


def overlaps(cols, walls=()):
    """Largest overlap between two spheres and between a sphere and a wall, in distance units
    and relative to the contact size (r_i + r_j, or r_i): (abs, rel). walls: list of
    (axis 0/1/2, position, +1 for a lower wall / -1 for an upper one)."""
    pos = np.column_stack([cols["x"], cols["y"], cols["z"]])
    r = cols["radius"]
    worst, worst_rel = 0.0, 0.0
    pairs = neighbour_pairs(pos, 2.0 * float(r.max()))
    if len(pairs):
        d = np.linalg.norm(pos[pairs[:, 0]] - pos[pairs[:, 1]], axis=1)
        s = r[pairs[:, 0]] + r[pairs[:, 1]]
        ov = s - d
        worst = max(worst, float(ov.max()))
        worst_rel = max(worst_rel, float((ov / s).max()))
    for axis, at, side in walls:
        ov = r - side * (pos[:, axis] - at)
        worst = max(worst, float(ov.max()))
        worst_rel = max(worst_rel, float((ov / r).max()))
    return max(worst, 0.0), max(worst_rel, 0.0)


def _segment_area(r, h):
    """Area of the part of a disc of radius r below a chord at signed height h from its centre
    (h in [-r, r])."""
    h = np.clip(h, -r, r)
    return r * r * np.arccos(-h / r) + h * np.sqrt(np.maximum(r * r - h * h, 0.0))


def area_fraction(cols, x0, x1, y0, y1):
    """2d packing fraction in the window [x0, x1] x [y0, y1]: area of the discs (radius r) inside
    the horizontal strip y0..y1 (exact circle segments), over the window's area. Discs are
    assumed inside [x0, x1] (a box with side walls)."""
    y, r = cols["y"], cols["radius"]
    a = _segment_area(r, y1 - y) - _segment_area(r, y0 - y)
    return float(a.sum()) / ((x1 - x0) * (y1 - y0))


def bed_height(cols, quantile=0.98):
    """Height of a settled bed: the given quantile of the tops y + r (ignores a few loose
    discs on top)."""
    return float(np.quantile(cols["y"] + cols["radius"], quantile))


def root():
    return os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
