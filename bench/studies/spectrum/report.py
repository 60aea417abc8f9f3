"""Table and figure of the spectrum study (bench/studies/spectrum/run.sh) from bench/studies/spectrum/results/spectrum.csv:
prints a markdown table (pasted into bench/studies/spectrum/README.md, section 10) and draws
bench/studies/spectrum/results/spectrum.png (smallest eigenvalues against pile height; iterations per
preconditioner)."""

import argparse
import csv

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

COLUMNS = [("cg_solver", "cg (the solver)"), ("pcg_jacobi", "jacobi"),
           ("pcg_jacobi_extrapolated", "jacobi, extrapolated start"), ("pcg_sgs", "sgs"),
           ("pcg_two_level", "two-level"), ("pcg_multilevel", "multilevel"),
           ("pcg_stress", "stress two-level"), ("pcg_old_factor", "old factor")]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--csv", required=True)
    ap.add_argument("--figure", required=True)
    a = ap.parse_args()
    rows = list(csv.DictReader(open(a.csv)))
    print("| scene, step | pushing rows (new since base) | warm residual / tol (force error) | lambda_min | condition | "
          + " | ".join(name for _, name in COLUMNS) + " | coarse rows (two-level, stress) |")
    print("|---" * (6 + len(COLUMNS)) + "|")
    for r in rows:
        # 5000 = the cap of analyze.pcg: did not converge
        # -1: not measured (the extrapolation needs the step before)
        its = [r[k] if 0 <= int(r[k]) < 5000 else "no conv." if int(r[k]) >= 5000 else "-"
               for k, _ in COLUMNS]
        print("| %s, %s | %s (%s) | %.2g (%.0f %%) | %.2g | %.3g | %s | %s, %s |" % (
            r["label"], r["step"], r["pushing"], r["rows_new_since_base"],
            float(r["warm_residual_over_tol"]), 100 * float(r["warm_force_error"]),
            float(r["lambda_min"]), float(r["condition"]), " | ".join(its),
            r["two_level_sizes"].split("/")[-1], r["stress_sizes"].split("/")[-1]))

    fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
    piles = [r for r in rows if r["label"].startswith("pile")]
    layers = np.array([int(r["label"][4:]) for r in piles])
    for k in range(5):
        ev = np.array([float(r["smallest"].split()[k]) for r in piles])
        ax[0].loglog(layers, ev, "o", color="C%d" % k, ms=4, label="eigenvalue %d" % (k + 1))
    ref = np.array([5.0, 20.0])
    lam5 = np.mean([float(r["lambda_min"]) for r in piles if r["label"] == "pile5"])
    ax[0].loglog(ref, lam5 * (ref / 5.0) ** -2, "k--", label="layers^-2")
    ax[0].set_xlabel("pile height (layers)")
    ax[0].set_ylabel("smallest eigenvalues of D^-1/2 A D^-1/2 (pushing rows)")
    ax[0].legend(fontsize=8)
    labels = ["%s %s" % (r["label"], r["step"]) for r in rows]
    x = np.arange(len(rows))
    w = 0.8 / len(COLUMNS)
    for j, (k, name) in enumerate(COLUMNS):
        v = np.array([min(max(float(r[k]), 0.0), 1000.0) for r in rows])
        ax[1].bar(x + (j - len(COLUMNS) / 2 + 0.5) * w, v, w, label=name)
    ax[1].set_xticks(x)
    ax[1].set_xticklabels(labels, rotation=30, fontsize=7, ha="right")
    ax[1].set_ylabel("iterations to the fix's tolerance (tol 1e-4)")
    ax[1].set_yscale("log")
    ax[1].legend(fontsize=7, ncol=2)
    fig.suptitle("Frictionless solves at rest: spectrum and preconditioners (bench/studies/spectrum/run.sh)")
    fig.tight_layout()
    fig.savefig(a.figure, dpi=110)


if __name__ == "__main__":
    main()
