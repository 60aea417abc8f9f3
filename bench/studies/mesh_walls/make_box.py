#!/usr/bin/env python3
"""The walls of bench/compare/in.pile3d (floor z = 0, sides x, y = 0 and 11) as an ASCII STL,
open at the top (height 40): each face split into square cells of side `cell`, two triangles
each. Usage: make_box.py CELL OUT.stl; prints the number of triangles."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '../../../examples/common'))
import granular as gr    # noqa: E402

cell, out = float(sys.argv[1]), sys.argv[2]
L, H = 11.0, 40.0


def quad(o, u, v, nu, nv, tris):
    """the rectangle o + [0, nu] u + [0, nv] v in unit cells, vertices from integer indices"""
    def p(i, j):
        return tuple(o[k] + i * u[k] + j * v[k] for k in range(3))
    for i in range(nu):
        for j in range(nv):
            tris.append((p(i, j), p(i + 1, j), p(i + 1, j + 1)))
            tris.append((p(i, j), p(i + 1, j + 1), p(i, j + 1)))


n, m = max(1, round(L / cell)), max(1, round(H / cell))
a, b = L / n, H / m
tris = []
quad((0, 0, 0), (a, 0, 0), (0, a, 0), n, n, tris)            # floor
quad((0, 0, 0), (a, 0, 0), (0, 0, b), n, m, tris)            # y = 0
quad((0, L, 0), (a, 0, 0), (0, 0, b), n, m, tris)            # y = L
quad((0, 0, 0), (0, a, 0), (0, 0, b), n, m, tris)            # x = 0
quad((L, 0, 0), (0, a, 0), (0, 0, b), n, m, tris)            # x = L
gr.write_stl(out, tris, name="box")
print(len(tris))
