"""Table and plot of bench/results/friction/<host>/friction_front.csv (front.py): per run the observable (mean
height at t = T), the time it took to come to rest, overlaps, iterations and the loop time, with
the ratios against the soft twins of the same run; the plot draws the mean height against the
loop time (soft twins as squares, the fix's default circled (grey: the default before)).

  python3 bench/friction/report.py CSV
"""

import csv
import math
import sys
from pathlib import Path

DEFAULT = ("hybrid", 1e-2, 0.02)    # the fix's default with friction (solver, tol, cone lagged) at the deck's h
OLD_DEFAULT = ("apgd", 1e-4, 0.02)    # before 2026-12-04


def load(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        for k, v in r.items():
            try:
                r[k] = float(v)
            except (TypeError, ValueError):
                pass
    return rows


def twin_time_at(twins, overlap):
    """Issue 36's target 2 compares with soft twins at largest overlaps of 1e-2 and 1e-3 of the
    contact size, interpolated as issue 15 did: the twins' loop time against their sampled
    largest overlap (twins: (overlap, loop time) pairs), linear in log-log between the two
    twins that bracket `overlap` (beyond them, the nearest two extended: marked extrapolated).
    None with fewer than two twins."""
    pts = sorted(((o, t) for o, t in twins if o > 0), reverse=True)
    if len(pts) < 2:
        return None, False
    pair, outside = None, True
    for a, b in zip(pts, pts[1:]):
        if b[0] <= overlap <= a[0]:
            pair, outside = (a, b), False
            break
    if pair is None:
        pair = (pts[0], pts[1]) if overlap > pts[0][0] else (pts[-2], pts[-1])
    (o1, t1), (o2, t2) = pair
    p = math.log(t2 / t1) / math.log(o1 / o2)
    return t1 * (o1 / overlap) ** p, outside


def main():
    if len(sys.argv) != 2:
        raise SystemExit(__doc__)
    path = Path(sys.argv[1])
    rows = load(path)
    soft = {r["tol"]: r for r in rows if r["kind"] == "soft"}
    hard = [r for r in rows if r["kind"] == "hard"]
    s2, s3 = soft.get(1e-2), soft.get(1e-3)
    at = {x: twin_time_at([(r["overlap_max"], r["loop_s"]) for r in soft.values()], x)
          for x in (1e-2, 1e-3)}
    out = ["| run | tol | h | mean height at T | at rest from t | largest overlap (end) | it/step (max) | maxiter stops | loop (s) | / soft 1e-2 | / soft 1e-3 | soft / hard at largest overlaps 1e-2; 1e-3 |",
           "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in hard + list(soft.values()):
        is_soft = r["kind"] == "soft"
        it = "-" if is_soft else "%.0f (%.0f)" % (r["it_mean"], r["it_max"])
        stops = "-" if is_soft else "%d" % r["maxiter_stops"]
        ratio = lambda s: ("%.2f" % (r["loop_s"] / s["loop_s"])) if s else "-"
        rest = "%.1f" % r["t_rest"] if r["t_rest"] == r["t_rest"] else "not by %.0f" % r["T"]
        target = "-" if is_soft else "; ".join(
            "-" if t is None else "%.2f%s" % (t / r["loop_s"], " (extrapolated)" if far else "")
            for t, far in (at[1e-2], at[1e-3]))
        out.append("| %s | %s | %s | %.4f | %s | %.2g (%.2g) | %s | %s | %.1f | %s | %s | %s |" % (
            r["run"], "%g" % r["tol"] if not is_soft else "static overlap %g" % r["tol"],
            "%.3g" % r["h"], r["zavg"], rest, r["overlap_max"], r["overlap_end"], it, stops,
            r["loop_s"], ratio(s2), ratio(s3), target))
    for x in (1e-2, 1e-3):
        t, far = at[x]
        if t is not None:
            out.append("")
            out.append("Twins' loop time at a largest overlap of %g (interpolated%s): %.1f s" % (
                x, ", extrapolated" if far else "", t))
    md = path.with_suffix(".md")
    md.write_text("\n".join(out) + "\n")
    print("\n".join(out))
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for r in hard:
        mk = {"apgd": "o", "nsgs": "^", "hybrid": "D"}.get(r["solver"].split("/")[0], "s")
        ax.plot(r["loop_s"], r["zavg"], mk, color="C%d" % [0.02, 0.04, 0.08].index(r["h"]) if r["h"] in (0.02, 0.04, 0.08) else "k")
        ax.annotate("%s %g h %g" % (r["solver"], r["tol"], r["h"]), (r["loop_s"], r["zavg"]),
                    fontsize=7, xytext=(3, 3), textcoords="offset points")
        if (r["solver"], r["tol"], r["h"]) == DEFAULT:
            ax.plot(r["loop_s"], r["zavg"], "o", ms=14, mfc="none", color="k", label="default")
        if (r["solver"], r["tol"], r["h"]) == OLD_DEFAULT:
            ax.plot(r["loop_s"], r["zavg"], "o", ms=14, mfc="none", color="0.6", ls="none",
                    label="default before 2026-12-04")
    for r in soft.values():
        ax.plot(r["loop_s"], r["zavg"], "s", color="C3")
        ax.annotate("soft, static overlap %g" % r["tol"], (r["loop_s"], r["zavg"]), fontsize=7,
                    xytext=(3, -9), textcoords="offset points", color="C3")
    ax.legend(fontsize=7, loc="lower right")
    ax.set_xscale("log")
    ax.set_xlabel("loop time (s, one core)")
    ax.set_ylabel("mean height of the spheres at t = %g" % hard[0]["T"])
    ax.set_title("Frictional settle (mu 0.5), hard (colour: h 0.02 / 0.04 / 0.08) and soft twins")
    fig.tight_layout()
    png = path.with_suffix(".png")
    fig.savefig(png, dpi=110)
    print("wrote", md, png)


if __name__ == "__main__":
    main()
