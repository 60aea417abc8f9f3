#!/usr/bin/env python3
"""The mixer of examples/mixer as an ASCII STL: a horizontal drum of radius R about the y axis
(72 flat facets) from y = -1 to L + 1 (beyond the periodic length L of the box), with LIFTERS
radial baffles of height H reaching in from its wall (each a flat rectangle: a mesh wall is
two-sided, a sheet is a baffle). LIFTERS 0: the bare drum.
    make_mixer.py OUT.stl R L LIFTERS H"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '../common'))
import granular as gr    # noqa: E402

out, R, L, lifters, H = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), int(sys.argv[4]), float(sys.argv[5])
N, y0, y1 = 72, -1.0, L + 1.0


def rim(a, r, y):
    return (r * math.cos(a), y, r * math.sin(a))


tris = []
for k in range(N):
    a0, a1 = 2 * math.pi * k / N, 2 * math.pi * ((k + 1) % N) / N
    tris.append((rim(a0, R, y0), rim(a1, R, y0), rim(a1, R, y1)))
    tris.append((rim(a0, R, y0), rim(a1, R, y1), rim(a0, R, y1)))
for j in range(lifters):
    a = 2 * math.pi * (j + 0.5) / lifters + math.pi / N    # between two facets' corners
    # the baffle starts just outside the facet it stands on, so that it meets the wall
    r_out = R
    tris.append((rim(a, r_out, y0), rim(a, R - H, y0), rim(a, R - H, y1)))
    tris.append((rim(a, r_out, y0), rim(a, R - H, y1), rim(a, r_out, y1)))
gr.write_stl(out, tris, name="mixer")
print("%s: %d triangles (drum R = %g, %d lifters of height %g)" % (out, len(tris), R, lifters, H))
