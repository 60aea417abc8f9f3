"""Scenes of the performance benchmark: deterministic LAMMPS data files (atom_style sphere,
LJ units) written from numpy, so every solver, rank count and the soft twin start from the
same atoms."""

import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "python"))
import hctools as hc  # noqa: E402

SPACING = 1.1      # loose simple-cubic lattice of the piles
D_MIN, D_MAX = 0.8, 1.0
OFFSET = 0.04      # largest random horizontal offset; keeps every gap of the lattice > 0


def write_data(path, box, diameter, density, x, title):
    """A data file of atoms 1..N of type 1 at rest, every float exact (hctools.write_data)."""
    hc.write_data(path, box, diameter, density, x, title=title, velocities=False)


def pile(nx, ny, layers, seed=15):
    """Polydisperse spheres (d uniform in [0.8, 1.0], density 1) on a simple-cubic lattice of
    spacing 1.1 with random horizontal offsets, in a box walled on x and y with a floor at z = 0;
    they fall under g = 1 and settle into a pile of about `layers` layers."""
    rng = np.random.default_rng(seed)
    n = nx * ny * layers
    k, j, i = np.meshgrid(np.arange(layers), np.arange(ny), np.arange(nx), indexing="ij")
    x = np.column_stack([(i.ravel() + 0.5) * SPACING, (j.ravel() + 0.5) * SPACING,
                         (k.ravel() + 0.5) * SPACING])
    x[:, :2] += rng.uniform(-OFFSET, OFFSET, size=(n, 2))
    d = rng.uniform(D_MIN, D_MAX, size=n)
    width = (nx * SPACING, ny * SPACING)
    box = ((0.0, width[0]), (0.0, width[1]), (0.0, (layers + 1) * SPACING))
    return dict(kind="pile", n=n, nx=nx, ny=ny, layers=layers, box=box, x=x, d=d, density=1.0,
                walls="wall xplane 0.0 %r wall yplane 0.0 %r wall zplane 0.0 NULL" % width,
                mean_d=float(d.mean()), mean_mass=float((np.pi / 6 * d ** 3).mean()))


def tray(mass_ratio, side=14, heavy_d=10.0, heavy_z=6.2):
    """A heavy sphere (diameter 10, mass `mass_ratio` x a small one, through its density) on a
    walled tray of side x side small spheres (d 1, density 1) touching the floor and each other
    (lattice sc 1.0 with origin 0.5 0.5 0.5); the heavy one starts 0.2 above the small ones."""
    k, j = np.meshgrid(np.arange(side), np.arange(side), indexing="ij")
    small = np.column_stack([j.ravel() + 0.5, k.ravel() + 0.5, np.full(side * side, 0.5)])
    x = np.vstack([small, [[side / 2.0, side / 2.0, heavy_z]]])
    d = np.concatenate([np.ones(side * side), [heavy_d]])
    # mass = density pi d^3 / 6: the heavy one has heavy_d^3 times the volume
    rho_heavy = mass_ratio / heavy_d ** 3
    density = np.concatenate([np.ones(side * side), [rho_heavy]])
    box = ((0.0, float(side)), (0.0, float(side)), (0.0, heavy_z + heavy_d / 2 + 1.0))
    return dict(kind="tray", n=len(x), box=box, x=x, d=d, density=density, mass_ratio=mass_ratio,
                walls="wall xplane 0.0 %r wall yplane 0.0 %r wall zplane 0.0 NULL" % (
                    float(side), float(side)),
                mean_d=1.0, mean_mass=np.pi / 6)


def write(scene, path):
    write_data(path, scene["box"], scene["d"], scene["density"], scene["x"],
               "hardcontact performance benchmark: %s, %d spheres" % (scene["kind"], scene["n"]))
