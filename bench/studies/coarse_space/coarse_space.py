"""Is there a small coarse space for cg on a frictionless pile at rest? (bench/studies/coarse_space/README.md,
section 10.13; issue 15, target 1.)

Section 10.1 found that a two-level preconditioner whose coarse space holds the six uniform
stresses of each aggregate cuts Jacobi-PCG's iterations on the 20-layer pile from about 200 to
34-35, but with aggregates of about 9 rows: a coarse problem of 56 % of the rows, and symmetric
Gauss-Seidel smoothing, each costing about a product. A coarse space pays only if it is small
and the smoother cheap. This script asks, for dumped problems (HARDCONTACT_DUMP_PROBLEMS), on
their exact pushing rows (analyze.reference), from the fix's warm start, to its stopping test:
  * Jacobi-PCG, the iterations `cg` needs there (analyze.pcg);
  * with coarse spaces on aggregates of growing size - the bodies within `radius` contacts of
    a seed (a greedy cover of the contact graph), a row in its first body's aggregate - holding
    either the six uniform stresses (the forces n_c.E.n_c) or the constant, three ways of
    adding them to Jacobi at the cost of one coarse solve per iteration: additive
    (D^-1 + Q), balancing ((I - QA) D^-1 (I - AQ) + Q) and A-DEF2 ((I - QA) D^-1 + Q from a
    coarse-corrected start), Q = P (P^T A P)^-1 P^T;
  * what the slow modes look like: the smallest eigenpairs of D^-1/2 A D^-1/2, their
    participation ratio ((sum v^2)^2 / sum v^4 / n: 1 for a mode spread evenly, 1/n for one
    row) and their weight on wall rows, and how many eigenvalues lie below 0.002 ... 0.1 (the
    count a deflation would have to remove).
Usage: coarse_space.py --csv OUT.csv LABEL=FILE ...  (prints a markdown summary)"""

import argparse
import csv
import sys
from pathlib import Path

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spl

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "spectrum"))    # problem, analyze
import problem  # noqa: E402
from analyze import pcg, reference, tentative  # noqa: E402

RADII = (1, 2, 3, 4, 6)
THRESHOLDS = (2e-3, 5e-3, 1e-2, 2e-2, 5e-2, 1e-1)


def aggregates(bi, bj, n_bodies, radius):
    """Aggregate per body: seeds in index order, each taking the bodies not yet taken within
    `radius` contacts of it (breadth first over the rows' pairs). -1: a body in no row."""
    pair = bj >= 0
    adj = sp.csr_matrix((np.ones(2 * pair.sum()), (np.r_[bi[pair], bj[pair]],
                                                   np.r_[bj[pair], bi[pair]])),
                        shape=(n_bodies, n_bodies))
    in_rows = np.zeros(n_bodies, bool)
    in_rows[bi] = True
    in_rows[bj[pair]] = True
    agg = -np.ones(n_bodies, int)
    count = 0
    for seed in np.flatnonzero(in_rows):
        if agg[seed] >= 0:
            continue
        agg[seed] = count
        front = [seed]
        for _ in range(radius):
            nxt = []
            for b in front:
                for o in adj.indices[adj.indptr[b]:adj.indptr[b + 1]]:
                    if agg[o] < 0:
                        agg[o] = count
                        nxt.append(o)
            front = nxt
        count += 1
    return agg, count


def prolongator(P, free, radius, kind):
    """P: per aggregate, an orthonormal basis of the candidates' values on its rows
    (analyze.tentative); the aggregates that hold no row are dropped."""
    bi, bj, n = P["bi"][free], P["bj"][free], P["normal"][free]
    agg, count = aggregates(bi, bj, P["n_bodies"], radius)
    _, row_agg = np.unique(agg[bi], return_inverse=True)
    T = sp.csr_matrix((np.ones(len(bi)), (np.arange(len(bi)), row_agg)),
                      shape=(len(bi), row_agg.max() + 1))
    if kind == "stress":
        cand = np.column_stack([n[:, 0] ** 2, n[:, 1] ** 2, n[:, 2] ** 2,
                                n[:, 0] * n[:, 1], n[:, 0] * n[:, 2], n[:, 1] * n[:, 2]])
    else:
        cand = np.ones((len(bi), 1))
    return tentative(T, cand), count


def study(label, path, out):
    P = problem.load(path)
    _, free, _ = reference(P)
    A = P["A"][free][:, free].tocsr()
    d = A.diagonal()
    rhs, x0, scale, tol = -P["b"][free], P["mu0"][free], P["scale"][free], P["tol"]
    n = A.shape[0]
    jac = pcg(A, rhs, x0, scale, tol, lambda r: r / d)
    rows = []
    for kind in ("stress", "const"):
        for radius in RADII:
            T, count = prolongator(P, free, radius, kind)
            E = (T.T @ A @ T).tocsc()
            Ef = spl.splu(E + 1e-12 * abs(E).max() * sp.identity(E.shape[0], format="csc"))

            def Q(r, T=T, Ef=Ef):
                return T @ Ef.solve(T.T @ r)

            def balancing(r):
                z = (r - A @ Q(r)) / d
                return z - Q(A @ z) + Q(r)

            def adef2(r):
                z = r / d
                return z - Q(A @ z) + Q(r)

            rows.append(dict(label=label, rows=n, kind=kind, radius=radius, aggregates=count,
                             coarse=T.shape[1], jacobi=jac,
                             additive=pcg(A, rhs, x0, scale, tol, lambda r: r / d + Q(r)),
                             balancing=pcg(A, rhs, x0, scale, tol, balancing),
                             adef2=pcg(A, rhs, x0 + Q(rhs - A @ x0), scale, tol, adef2)))
    # the slow modes
    Dm = sp.diags(1.0 / np.sqrt(d))
    S = (Dm @ A @ Dm).tocsc()
    lam, V = spl.eigsh(S, k=12, sigma=-1e-9, which="LM")
    wall = P["bj"][free] < 0
    modes = []
    for k in np.argsort(lam):
        v = V[:, k]
        modes.append((lam[k], (v ** 2).sum() ** 2 / (v ** 4).sum() / n, (v[wall] ** 2).sum()))
    every = np.linalg.eigvalsh(S.toarray())
    below = [int((every < t).sum()) for t in THRESHOLDS]
    with open(out, "a", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        if f.tell() == 0:
            w.writeheader()
        w.writerows(rows)
    return rows, modes, below, wall.mean()


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--csv", required=True)
    ap.add_argument("problems", nargs="+", help="LABEL=FILE")
    a = ap.parse_args()
    open(a.csv, "w").close()
    for item in a.problems:
        label, path = item.split("=", 1)
        rows, modes, below, wall_share = study(label, path, a.csv)
        print("### %s (%s): %d pushing rows, Jacobi-PCG %d iterations\n" % (
            label, path.rsplit("/", 1)[-1], rows[0]["rows"], rows[0]["jacobi"]))
        print("| coarse space | radius | aggregates | coarse rows (share) | additive | balancing | A-DEF2 |")
        print("|---|---|---|---|---|---|---|")
        for r in rows:
            print("| %s | %d | %d | %d (%.1f %%) | %d | %d | %d |" % (
                r["kind"], r["radius"], r["aggregates"], r["coarse"], 100.0 * r["coarse"] / r["rows"],
                r["additive"], r["balancing"], r["adef2"]))
        print("\nThe 12 slowest modes of D^-1/2 A D^-1/2 (wall rows are %.0f %% of the rows):\n" % (
            100 * wall_share))
        print("| eigenvalue | participation | weight on wall rows |")
        print("|---|---|---|")
        for lam, pr, wl in modes:
            print("| %.2e | %.3f | %.2f |" % (lam, pr, wl))
        print("\nEigenvalues below %s: %s (of %d)\n" % (
            ", ".join("%g" % t for t in THRESHOLDS), ", ".join(map(str, below)), rows[0]["rows"]))


if __name__ == "__main__":
    main()
