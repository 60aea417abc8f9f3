#!/usr/bin/env python3
"""The hopper of examples/liggghts_hopper as a binary STL in millimetres, as a CAD tool would
export it: a cone of half-angle 30 degrees from the vertical from the outlet (radius R_OUT at
z = 0) up to radius 35 mm, then a cylinder up to z = 120 mm; 48 facets around, the cone in 6
rings, the cylinder in 8. Open at both ends (the outlet and the top).
    make_hopper.py OUT.stl [R_OUT_mm]"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '../common'))
import granular as gr    # noqa: E402

out = sys.argv[1]
r_out = float(sys.argv[2]) if len(sys.argv) > 2 else 10.0
R_TOP, Z_TOP, N = 35.0, 120.0, 48
z_cone = (R_TOP - r_out) / math.tan(math.radians(30.0))
rings = [(r_out + (R_TOP - r_out) * k / 6, z_cone * k / 6) for k in range(7)]
rings += [(R_TOP, z_cone + (Z_TOP - z_cone) * k / 8) for k in range(1, 9)]


def at(r, z, j):
    a = 2 * math.pi * (j % N) / N
    return (r * math.cos(a), r * math.sin(a), z)


tris = []
for (r0, z0), (r1, z1) in zip(rings, rings[1:]):
    for j in range(N):
        tris.append((at(r0, z0, j), at(r0, z0, j + 1), at(r1, z1, j + 1)))
        tris.append((at(r0, z0, j), at(r1, z1, j + 1), at(r1, z1, j)))
gr.write_stl(out, tris, binary=True, name="hopper for examples/liggghts_hopper, mm")
print("%s: %d triangles, outlet radius %g mm, cone up to z = %.2f mm" % (out, len(tris), r_out, z_cone))
