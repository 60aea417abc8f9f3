"""Reads a problem written by fix hardcontact under HARDCONTACT_DUMP_PROBLEMS (format in
src/core/problem_dump.h) and rebuilds the frictionless dual of eq. 15:
    min 1/2 mu.A mu + b.mu over mu >= 0,  A = h^2 G M^-1 G^T,  b = gap + h G u_free,
the gap of row c after the step being g_c = (A mu + b)_c."""

import numpy as np
import scipy.sparse as sp


def load(path):
    with open(path) as f:
        head = f.readline().split()
        if head[:2] != ["hardcontact-problem", "1"]:
            raise ValueError("%s: not a hardcontact problem file" % path)
        nb, n_owned, nr = (int(v) for v in head[2:5])
        h, tol = float(head[5]), float(head[6])
        bodies = np.loadtxt(f, max_rows=nb, ndmin=2)
        rows = np.loadtxt(f, max_rows=nr, ndmin=2)
    inv_mass, u_free = bodies[:, 0], bodies[:, 1:4]
    bi, bj = rows[:, 0].astype(int), rows[:, 1].astype(int)
    normal, gap, size, scale, mu0 = rows[:, 2:5], rows[:, 5], rows[:, 6], rows[:, 7], rows[:, 8]
    # G: row c is -n_c on body i, +n_c on body j (a wall, j < 0, does not move)
    r, c, v = [], [], []
    pair = bj >= 0
    for k in range(3):
        r += [np.arange(nr), np.arange(nr)[pair]]
        c += [3 * bi + k, 3 * bj[pair] + k]
        v += [-normal[:, k], normal[pair, k]]
    G = sp.csr_matrix((np.concatenate(v), (np.concatenate(r), np.concatenate(c))), shape=(nr, 3 * nb))
    A = (h * h * (G @ sp.diags(np.repeat(inv_mass, 3)) @ G.T)).tocsr()
    b = gap + h * (G @ u_free.ravel())
    # a row is identified across steps by its bodies (the wall's index for a wall row); valid
    # while the neighbour lists are not rebuilt (body indices are LAMMPS's local indices)
    keys = list(zip(bi.tolist(), bj.tolist()))
    return dict(A=A, b=b, mu0=mu0, scale=scale, tol=tol, h=h, n_bodies=nb, bi=bi, bj=bj,
                normal=normal, size=size, keys=keys)
