"""Writes, for dumped problems (HARDCONTACT_DUMP_PROBLEMS), the linear system of their exact
pushing rows (analyze.reference) as text for amg_pcg (bench/studies/amg/README.md, section 10.15):
    n nnz tol / n+1 row pointers / nnz lines "column value" / n lines "rhs x0 scale"
the system A_FF x = -b_F that cg solves once its free rows are the right ones, from the fix's
warm start, with the fix's row scales and tolerance.
Usage: amg.py OUT_PREFIX LABEL=FILE ...   (writes OUT_PREFIX.LABEL.txt, prints the paths)"""

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "spectrum"))    # problem, analyze

import problem  # noqa: E402
from analyze import reference  # noqa: E402


def main():
    prefix = sys.argv[1]
    for item in sys.argv[2:]:
        label, path = item.split("=", 1)
        P = problem.load(path)
        _, free, _ = reference(P)
        A = P["A"][free][:, free].tocsr()
        A.sort_indices()
        rhs, x0, scale = -P["b"][free], P["mu0"][free], P["scale"][free]
        out = "%s.%s.txt" % (prefix, label)
        with open(out, "w") as f:
            f.write("%d %d %.17g\n" % (A.shape[0], A.nnz, P["tol"]))
            f.write(" ".join(map(str, A.indptr)) + "\n")
            for c, v in zip(A.indices, A.data):
                f.write("%d %.17g\n" % (c, v))
            for r, x, s in zip(rhs, x0, scale):
                f.write("%.17g %.17g %.17g\n" % (r, x, s))
        print(label, out)


if __name__ == "__main__":
    main()
