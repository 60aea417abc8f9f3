"""What limits the iterations of a frictionless solve (bench/studies/spectrum/README.md, section 10): for
problems dumped by fix hardcontact (HARDCONTACT_DUMP_PROBLEMS), the exact solution, the
spectrum of the Jacobi-scaled operator on its pushing rows, and how many iterations a linear
preconditioned CG needs on those rows - the solve `cg` does once its free rows are the right
ones - from the warm start to the fix's own stopping test (|g_c| <= tol x scale_c), with:
  jacobi     D^-1 (what `cg` uses); also from a start extrapolated from the last two steps
  sgs        symmetric Gauss-Seidel (one forward and one backward sweep)
  two-level  sgs + an exact coarse solve on aggregates of strongly coupled rows
  multilevel smoothed aggregation, V(1,1) cycle with sgs smoothing
  stress     two-level, smoothed, with 6 candidates per aggregate instead of the constant:
             the forces n_c.E.n_c of the 6 uniform stresses E (the near-null space of a
             packing seen as a continuum, as rigid-body modes are for elasticity)
  old factor the exact inverse of an earlier step's operator on its pushing rows (Jacobi on
             rows it does not have): what reusing a factorization over steps would give
Usage: analyze.py --out CSV --log LAMMPS_LOG --label NAME --base FILE FILE...
       (each FILE a dumped problem; --base: the earlier step whose factor is reused)"""

import argparse
import csv
import os
import re
import time

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spl
from scipy.optimize import minimize

import problem


def reference(P):
    """The exact solution: L-BFGS-B on the bound-constrained dual, then the linear system on
    its pushing rows, rows leaving or joining until the complementarity conditions hold."""
    A, b = P["A"], P["b"]
    obj = lambda x: (0.5 * x @ (A @ x) + b @ x, A @ x + b)
    r = minimize(obj, P["mu0"], jac=True, method="L-BFGS-B", bounds=[(0, None)] * len(b),
                 options=dict(maxiter=50000, ftol=1e-30, gtol=1e-16, maxcor=50))
    free = r.x > 1e-12 * max(r.x.max(), 1e-300)
    for _ in range(50):
        mu = np.zeros_like(b)
        AF = A[free][:, free].tocsc()
        mu[free] = spl.spsolve(AF, -b[free])
        g = A @ mu + b
        leave = free & (mu < 0)
        join = ~free & (g < -1e-3 * P["tol"] * P["scale"])
        if not leave.any() and not join.any():
            break
        free = (free & ~leave) | join
        mu = np.maximum(mu, 0)
    viol = np.where(free, np.abs(g), np.maximum(0, -g)) / P["scale"]
    return mu, free, float(viol.max())


def pcg(A, rhs, x0, scale, tol, precond, maxit=5000):
    """Preconditioned CG on A x = rhs from x0; iterations until max |rhs - A x| / scale <= tol."""
    x = x0.copy()
    r = rhs - A @ x
    z = precond(r)
    p = z.copy()
    rz = r @ z
    for k in range(maxit):
        if np.max(np.abs(r) / scale) <= tol:
            return k
        q = A @ p
        a = rz / (p @ q)
        x += a * p
        r -= a * q
        z = precond(r)
        rz_new = r @ z
        p = z + (rz_new / rz) * p
        rz = rz_new
    return maxit


def sgs(A):
    L = sp.tril(A, format="csr")
    U = sp.triu(A, format="csr")
    d = A.diagonal()
    return lambda r: spl.spsolve_triangular(U, d * spl.spsolve_triangular(L, r, lower=True), lower=False)


def aggregates(A, theta=0.08):
    """Plain aggregation on the graph of strong couplings |A_ij| >= theta sqrt(A_ii A_jj)."""
    n = A.shape[0]
    d = np.sqrt(np.abs(A.diagonal()))
    C = A.tocoo()
    keep = (C.row != C.col) & (np.abs(C.data) >= theta * d[C.row] * d[C.col])
    S = sp.csr_matrix((np.ones(keep.sum()), (C.row[keep], C.col[keep])), shape=A.shape)
    agg = -np.ones(n, dtype=int)
    na = 0
    for i in range(n):
        nb = S.indices[S.indptr[i]:S.indptr[i + 1]]
        if agg[i] < 0 and np.all(agg[nb] < 0):
            agg[nb] = na
            agg[i] = na
            na += 1
    for i in range(n):
        if agg[i] < 0:
            nb = S.indices[S.indptr[i]:S.indptr[i + 1]]
            nb = nb[agg[nb] >= 0]
            agg[i] = agg[nb[0]] if len(nb) else na
            na += 0 if len(nb) else 1
    return sp.csr_matrix((np.ones(n), (np.arange(n), agg)), shape=(n, na))


def tentative(T, B):
    """The tentative prolongator of aggregates T (n x aggregates, 0/1) for candidates B (n x
    k): per aggregate, an orthonormal basis of B's rows there (dependent columns dropped)."""
    agg = T.tocsr().indices
    r, c, v, col = [], [], [], 0
    for a in range(T.shape[1]):
        idx = np.where(agg == a)[0]
        Q, R = np.linalg.qr(B[idx])
        diag = np.abs(np.diag(R))
        Q = Q[:, diag > 1e-8 * max(diag.max(), 1e-300)]
        for j in range(Q.shape[1]):
            r += idx.tolist()
            c += [col] * len(idx)
            v += Q[:, j].tolist()
            col += 1
    return sp.csr_matrix((v, (r, c)), shape=(B.shape[0], col))


def multigrid(A, levels, smoothed, coarsest=200, candidates=None):
    hier, Ak = [], A
    for _ in range(levels):
        if Ak.shape[0] <= coarsest:
            break
        T = aggregates(Ak)
        if candidates is not None:
            T = tentative(T, candidates)
        if smoothed:
            dinv = sp.diags(1.0 / Ak.diagonal())
            lam = spl.eigsh(dinv @ Ak, k=1, which="LM", return_eigenvectors=False)[0]
            T = (T - (4.0 / 3.0 / lam) * (dinv @ Ak @ T)).tocsr()
        hier.append((Ak, T, sp.tril(Ak, format="csr"), sp.triu(Ak, format="csr")))
        Ak = (T.T @ Ak @ T).tocsr()
    n = Ak.shape[0]
    coarse = spl.splu((Ak + 1e-12 * abs(Ak).max() * sp.identity(n)).tocsc())

    def cycle(level, r):
        if level == len(hier):
            return coarse.solve(r)
        Ak, T, L, U = hier[level]
        x = spl.spsolve_triangular(L, r, lower=True)
        x += T @ cycle(level + 1, T.T @ (r - Ak @ x))
        x += spl.spsolve_triangular(U, r - Ak @ x, lower=False)
        return x

    sizes = [h[0].shape[0] for h in hier] + [n]
    return (lambda r: cycle(0, r)), sizes


def cg_iterations(log, step):
    """f_hc[1] (the fix's iterations) at `step` in a LAMMPS log with the thermo of decks.py."""
    cols = None
    for line in open(log):
        w = line.split()
        if w[:2] == ["Step", "Time"]:
            cols = w
        elif cols and len(w) == len(cols) and w[0] == str(step):
            return int(float(w[cols.index("f_hc[1]")]))
    return -1


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", required=True)
    ap.add_argument("--log", required=True)
    ap.add_argument("--label", required=True)
    ap.add_argument("--base", required=True)
    ap.add_argument("--eigs", type=int, default=40)
    ap.add_argument("files", nargs="+")
    a = ap.parse_args()

    B = problem.load(a.base)
    mu_b, free_b, _ = reference(B)
    AB = B["A"][free_b][:, free_b].tocsc()
    t0 = time.time()
    factor = spl.splu(AB + 1e-12 * abs(AB).max() * sp.identity(AB.shape[0], format="csc"))
    factor_s = time.time() - t0
    fill = (factor.L.nnz + factor.U.nnz) / AB.shape[0]
    base_pos = {k: i for i, k in enumerate(k for k, f in zip(B["keys"], free_b) if f)}
    base_step = int(re.findall(r"\.(\d+)$", a.base)[0])

    rows = []
    for f in a.files:
        step = int(re.findall(r"\.(\d+)$", f)[0])
        P = problem.load(f)
        mu, free, exact_viol = reference(P)
        A = P["A"][free][:, free].tocsr()
        d = A.diagonal()
        rhs, x0, scale, tol = -P["b"][free], P["mu0"][free], P["scale"][free], P["tol"]
        # the spectrum of D^-1/2 A_FF D^-1/2 (unit diagonal)
        Dm = sp.diags(1.0 / np.sqrt(d))
        S = (Dm @ A @ Dm).tocsc()
        small = np.sort(spl.eigsh(S, k=min(a.eigs, S.shape[0] - 2), sigma=-1e-9, which="LM",
                                  return_eigenvectors=False))
        large = spl.eigsh(S, k=1, which="LA", return_eigenvectors=False)[0]
        warm = np.max(np.abs(rhs - A @ x0) / scale) / tol    # the warm start's residual / tol
        keys = [k for k, f in zip(P["keys"], free) if f]
        pos = np.array([base_pos.get(k, -1) for k in keys])
        have = pos >= 0

        def old_factor(r):
            z = r / d
            v = np.zeros(AB.shape[0])
            v[pos[have]] = r[have]
            z[have] = factor.solve(v)[pos[have]]
            return z

        it = dict(jacobi=pcg(A, rhs, x0, scale, tol, lambda r: r / d),
                  sgs=pcg(A, rhs, x0, scale, tol, sgs(A)))
        two, sizes2 = multigrid(A, 1, False)
        it["two_level"] = pcg(A, rhs, x0, scale, tol, two)
        ml, sizes = multigrid(A, 8, True)
        it["multilevel"] = pcg(A, rhs, x0, scale, tol, ml)
        n = P["normal"][free]
        stress = np.column_stack([n[:, 0] ** 2, n[:, 1] ** 2, n[:, 2] ** 2, n[:, 0] * n[:, 1],
                                  n[:, 0] * n[:, 2], n[:, 1] * n[:, 2]])
        st, sizes_st = multigrid(A, 1, True, candidates=stress)
        it["stress"] = pcg(A, rhs, x0, scale, tol, st)
        # the warm start extrapolated from the two last steps' forces (the base's start is the
        # solution two steps back when the base is the step before)
        it["extrapolated"] = -1
        if step == base_step + 1:
            start_b = {k: m for k, m in zip(B["keys"], B["mu0"])}
            older = np.array([start_b.get(k, 0.0) for k in keys])
            ext = np.maximum(0.0, 2.0 * x0 - older)
            it["extrapolated"] = pcg(A, rhs, ext, scale, tol, lambda r: r / d)
        it["old_factor"] = pcg(A, rhs, x0, scale, tol, old_factor)
        row = dict(label=a.label, step=step, bodies=P["n_bodies"], rows=len(P["b"]),
                   pushing=int(free.sum()), rows_new_since_base=int((~have).sum()),
                   base_step=base_step, exact_violation=exact_viol, warm_residual_over_tol=warm,
                   warm_force_error=float(np.linalg.norm(P["mu0"] - mu) / np.linalg.norm(mu)),
                   lambda_min=small[0], lambda_10=small[min(9, len(small) - 1)],
                   lambda_max=large, condition=large / small[0],
                   eig_below_2x_min=int(np.sum(small < 2 * small[0])),
                   cg_solver=cg_iterations(a.log, step), pcg_jacobi=it["jacobi"],
                   pcg_jacobi_extrapolated=it["extrapolated"], pcg_sgs=it["sgs"], pcg_two_level=it["two_level"],
                   two_level_sizes="/".join(map(str, sizes2)), pcg_multilevel=it["multilevel"],
                   multilevel_sizes="/".join(map(str, sizes)), pcg_stress=it["stress"],
                   stress_sizes="/".join(map(str, sizes_st)), pcg_old_factor=it["old_factor"],
                   factor_fill_per_row=fill, factor_seconds=factor_s,
                   smallest=" ".join("%.4g" % v for v in small))
        print(" ".join("%s=%s" % (k, v) for k, v in row.items() if k != "smallest"), flush=True)
        rows.append(row)
    new = not os.path.exists(a.out)
    with open(a.out, "a", newline="") as out:
        w = csv.DictWriter(out, fieldnames=list(rows[0].keys()))
        if new:
            w.writeheader()
        w.writerows(rows)


if __name__ == "__main__":
    main()
