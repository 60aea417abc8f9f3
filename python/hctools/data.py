"""Writing scenes for LAMMPS: data files of spheres (atom_style sphere) and STL walls.

Why data files rather than create_atoms: create_atoms numbers atoms differently with the number
of ranks and random() in atom-style variables is per rank; a scene written here is the same on
every host and rank count, and both decks of a scene (hard contacts and the soft twin) read the
same file. Floats are written exactly (repr) unless a format is asked for.
"""

import math
import struct

import numpy as np


def sphere_mass(diameter, density):
    """The mass LAMMPS gives an atom_style sphere atom of this diameter and density (read_data,
    `set density`): pi/6 d^3 rho, in 2d too (LIGGGHTS in 2d: see write_data's host)."""
    return math.pi / 6.0 * np.asarray(diameter, dtype=float) ** 3 * np.asarray(density, dtype=float)


def write_data(path, box, diameter, density, pos, vel=None, types=None, title="hardcontact scene",
               host=None, dimension=3, velocities=True, number=repr, omega=None):
    """A LAMMPS data file for atom_style sphere, atoms numbered 1..N in the given order.

    box        ((xlo, xhi), (ylo, yhi), (zlo, zhi))
    diameter, density   per atom or one value
    pos, vel   (N, 3); vel defaults to 0
    omega      (N, 3) angular velocities, default 0 (the one way to start a spin on LIGGGHTS
               3.8, whose set has no omega)
    types      per atom (default 1)
    host, dimension     the host that reads the file and the deck's dimension: in a 2d box
               LIGGGHTS gives a sphere the mass of a disc, pi r^2 rho, where LAMMPS gives
               4/3 pi r^3 rho; for LIGGGHTS the file then holds the density 2/3 d rho, so that
               both hosts simulate the same masses (sphere_mass)
    velocities False: no Velocities section
    number     how a float is written (default repr: the file holds exactly the doubles given)
    """
    pos = np.asarray(pos, dtype=float).reshape(-1, 3)
    n = len(pos)
    diameter = np.broadcast_to(np.asarray(diameter, dtype=float), (n,))
    density = np.broadcast_to(np.asarray(density, dtype=float), (n,))
    if dimension == 2 and getattr(host, "name", None) == "liggghts":
        density = density * (2.0 / 3.0) * diameter
    vel = np.zeros((n, 3)) if vel is None else np.asarray(vel, dtype=float).reshape(n, 3)
    omega = np.zeros((n, 3)) if omega is None else np.asarray(omega, dtype=float).reshape(n, 3)
    types = np.ones(n, dtype=int) if types is None else np.broadcast_to(np.asarray(types, dtype=int), (n,))
    f = lambda x: number(float(x))    # noqa: E731 - one spelling for every float below
    lines = [title, "", "%d atoms" % n, "%d atom types" % (int(types.max()) if n else 1), ""]
    for (lo, hi), name in zip(box, "xyz"):
        lines.append("%s %s %slo %shi" % (f(lo), f(hi), name, name))
    lines += ["", "Atoms # sphere", ""]
    for i in range(n):
        lines.append("%d %d %s %s %s %s %s" % (i + 1, types[i], f(diameter[i]), f(density[i]),
                                               f(pos[i, 0]), f(pos[i, 1]), f(pos[i, 2])))
    if velocities:
        lines += ["", "Velocities", ""]
        for i in range(n):
            lines.append("%d %s %s %s %s %s %s" % (i + 1, f(vel[i, 0]), f(vel[i, 1]), f(vel[i, 2]),
                                                   f(omega[i, 0]), f(omega[i, 1]), f(omega[i, 2])))
    with open(str(path), "w") as out:
        out.write("\n".join(lines) + "\n")


def write_stl(path, triangles, binary=False, name="part"):
    """An STL file of triangles ((N, 3, 3): three vertices each), ASCII with exact doubles or
    binary (floats, as the format holds). Normals are written as 0: readers (the fix's and
    LIGGGHTS's) take them from the vertices' order."""
    triangles = np.asarray(triangles, dtype=float).reshape(-1, 3, 3)
    if binary:
        with open(str(path), "wb") as f:
            f.write(name.encode()[:80].ljust(80, b" "))
            f.write(struct.pack("<I", len(triangles)))
            for t in triangles:
                f.write(struct.pack("<12fH", 0.0, 0.0, 0.0, *t.reshape(-1), 0))
        return
    with open(str(path), "w") as f:
        f.write("solid %s\n" % name)
        for t in triangles:
            f.write(" facet normal 0 0 0\n  outer loop\n")
            for v in t:
                f.write("   vertex %.17g %.17g %.17g\n" % tuple(v))
            f.write("  endloop\n endfacet\n")
        f.write("endsolid %s\n" % name)
