"""The frictional rows of doc/performance.md from the suite's results: per scene the hard run at
the fix's defaults (and with adaptive steps where it was run), its soft twins, the observable
and the loop time of each, and soft / hard - at the twins as run, and at largest overlaps of
1e-2 and 1e-3 of the contact size (issue 36's target 2, interpolated between the twins that
bracket them: report.twin_time_at) where the twins' overlaps were sampled. Writes
friction_summary.md and friction_summary.png (observable against loop time, one panel per
scene, the default circled, twins as squares) next to the first CSV given (or into --out).

  python3 bench/friction/summary.py [--results DIR] [--settle10 CSV] [--settle20 CSV]
                                    [--cones CSV] [--collapse CSV]

Each CSV defaults to the name the suite writes into DIR (bench/run.sh friction: front.py's
friction_front.csv and friction_front_settle20.csv, cones.sh's friction_cones.csv with its
--stiff rows, collapse.sh's friction_collapse.csv); a missing one leaves its scenes out.
"""

import argparse
import csv
import math
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import report  # noqa: E402

DEFAULT_RUN = "hybrid_tol0.01_h0.02"      # front.py's run at the fix's defaults
ADAPTIVE_RUN = "hybrid_tol0.01_dtreset0.08"


def rows_of(path):
    if path is None or not Path(path).is_file():
        return []
    with open(path) as f:
        return list(csv.DictReader(f))


def num(v):
    try:
        return float(v)
    except (TypeError, ValueError):
        return float("nan")


def mean_sd(xs):
    xs = [x for x in xs if x == x]
    if not xs:
        return float("nan"), float("nan")
    m = sum(xs) / len(xs)
    sd = math.sqrt(sum((x - m) ** 2 for x in xs) / (len(xs) - 1)) if len(xs) > 1 else 0.0
    return m, sd


def geo_mean(xs):
    xs = [x for x in xs if x > 0]
    return math.exp(sum(math.log(x) for x in xs) / len(xs)) if xs else float("nan")


def fmt_obs(m, sd, digits=3):
    return ("%.*f" % (digits, m)) + ("" if sd != sd or sd == 0.0 else " +- %.*f" % (digits, sd))


class Scene:
    """One scene: hard runs and twins, each {label, loop, obs (mean, sd), overlap}."""

    def __init__(self, name, observable):
        self.name, self.observable = name, observable
        self.hard, self.soft = [], []

    def ratios(self, hard):
        """soft / hard at each twin as run, and at 1e-2, 1e-3 where the twins' overlaps are known."""
        as_run = ["%.2f" % (s["loop"] / hard["loop"]) for s in self.soft]
        known = [(s["overlap"], s["loop"]) for s in self.soft if s["overlap"] == s["overlap"]]
        at = []
        for x in (1e-2, 1e-3):
            t, far = report.twin_time_at(known, x)
            at.append("-" if t is None else "%.2f%s" % (t / hard["loop"], "*" if far else ""))
        return "; ".join(as_run), "; ".join(at)


def settle(name, rows):
    sc = Scene(name, "mean height at the end")
    for r in rows:
        run = r["run"]
        entry = dict(loop=num(r["loop_s"]), obs=(num(r["zavg"]), float("nan")),
                     overlap=num(r["overlap_max"]))
        if r["kind"] == "soft":
            sc.soft.append(dict(entry, label="soft, static overlap %s of r" % r["tol"]))
        elif run == DEFAULT_RUN:
            sc.hard.append(dict(entry, label="hard, tol %s, h 0.02" % r["tol"], default=num(r["tol"]) == 1e-2))
        elif run == ADAPTIVE_RUN:
            sc.hard.append(dict(entry, label="hard, tol %s, fix dt/reset to 0.08" % r["tol"], default=False))
    sc.soft.sort(key=lambda s: -s["overlap"])
    return sc if sc.hard and sc.soft else None


def cones(rows):
    out = []
    for scene, observable in (("drum", "dynamic angle (deg)"), ("heap", "flank angle (deg), 3 seeds"),
                              ("hopper3d", "discharge rate at D 10 mm (beads/s)")):
        sc = Scene(scene, observable)
        for run, label in (("lagged", "hard, the defaults"), ("soft", "soft, the deck's kn"),
                           ("soft10", "soft, 10 x the deck's kn")):
            rs = [r for r in rows if r["scene"] == scene and r["run"] == run]
            if not rs:
                continue
            vals = [num(r["value"].split("+-")[0].split("/")[0]) for r in rs]
            m, sd = mean_sd(vals)
            if scene == "drum" and "+-" in rs[0]["value"]:
                sd = num(rs[0]["value"].split("+-")[1])
            entry = dict(label=label, loop=mean_sd([num(r["loop_s"]) for r in rs])[0], obs=(m, sd),
                         overlap=num(rs[0]["overlap_max"]) if run == "lagged" else float("nan"))
            (sc.hard if run == "lagged" else sc.soft).append(dict(entry, default=run == "lagged"))
        if sc.hard and sc.soft:
            out.append(sc)
    return out


def collapse(rows):
    sc = Scene("column collapse", "runout (L_inf - L0) / L0, 3 seeds")
    for run in sorted({r["run"] for r in rows}):
        rs = [r for r in rows if r["run"] == run]
        m, sd = mean_sd([num(r["runout"]) for r in rs])
        loop = mean_sd([num(r["loop_s"]) for r in rs])[0]
        if run.startswith("soft_kn"):
            sc.soft.append(dict(label="soft, kn %s" % run[len("soft_kn"):], loop=loop, obs=(m, sd),
                                overlap=geo_mean([num(r["overlap_max"]) for r in rs])))
        elif run == "hard" or run.startswith("hard_hmax"):
            label = "hard, the defaults" if run == "hard" else "hard, fix dt/reset to %s" % run[len("hard_hmax"):]
            sc.hard.append(dict(label=label, loop=loop, obs=(m, sd), default=run == "hard",
                                overlap=max(num(r["overlap_max"]) for r in rs)))
    sc.soft.sort(key=lambda s: -s["overlap"])
    return sc if sc.hard and sc.soft else None


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--results", default=".")
    ap.add_argument("--settle10")
    ap.add_argument("--settle20")
    ap.add_argument("--cones")
    ap.add_argument("--collapse")
    ap.add_argument("--out", help="folder of friction_summary.md and .png (default: the first CSV's)")
    a = ap.parse_args()
    d = Path(a.results)
    paths = dict(settle10=a.settle10 or d / "friction_front.csv",
                 settle20=a.settle20 or d / "friction_front_settle20.csv",
                 cones=a.cones or d / "friction_cones.csv",
                 collapse=a.collapse or d / "friction_collapse.csv")
    quick = "quick" in Path(paths["settle10"]).name    # front.py --quick: 6 layers, t = 10
    scenes = [settle("settle, 6 layers (front.py --quick), t = 10" if quick else
                     "settle, 1210 spheres, t = 30", rows_of(paths["settle10"])),
              settle("settle, 8000 spheres, t = 12", rows_of(paths["settle20"]))]
    scenes += cones(rows_of(paths["cones"]))
    scenes.append(collapse(rows_of(paths["collapse"])))
    scenes = [s for s in scenes if s is not None]
    if not scenes:
        raise SystemExit("summary.py: none of the suite's CSVs found: %s" % ", ".join(map(str, paths.values())))
    out = ["| scene | run | observable | loop (s) | largest overlap | soft / hard at the twins as run | at largest overlaps 1e-2; 1e-3 (* extrapolated) |",
           "|---|---|---|---|---|---|---|"]
    for sc in scenes:
        digits = 1 if "rate" in sc.observable or "angle" in sc.observable else 3
        for h in sc.hard:
            as_run, at = sc.ratios(h)
            out.append("| %s | %s | %s | %.1f | %.2g | %s | %s |" % (
                sc.name, h["label"], fmt_obs(*h["obs"], digits), h["loop"], h["overlap"], as_run, at))
        for s in sc.soft:
            ov = "not sampled" if s["overlap"] != s["overlap"] else "%.2g" % s["overlap"]
            out.append("| %s | %s | %s | %.1f | %s | - | - |" % (
                sc.name, s["label"], fmt_obs(*s["obs"], digits), s["loop"], ov))
    out += ["", "Observables: " + "; ".join("%s: %s" % (s.name, s.observable) for s in scenes) + ".",
            "Sources: " + ", ".join("%s %s" % (k, v) for k, v in paths.items() if Path(v).is_file()) + "."]
    first = next(Path(v) for v in paths.values() if Path(v).is_file())
    md = (Path(a.out) if a.out else first.parent) / "friction_summary.md"
    md.write_text("\n".join(out) + "\n")
    print("\n".join(out))
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    cols = 3
    rows = (len(scenes) + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(4.2 * cols, 3.3 * rows), squeeze=False)
    for ax, sc in zip(axes.flat, scenes):
        for h in sc.hard:
            ax.errorbar(h["loop"], h["obs"][0], yerr=h["obs"][1] if h["obs"][1] == h["obs"][1] else None,
                        fmt="o", color="C0")
            ax.annotate(h["label"].replace("hard, ", ""), (h["loop"], h["obs"][0]), fontsize=6,
                        xytext=(3, 3), textcoords="offset points")
            if h.get("default"):
                ax.plot(h["loop"], h["obs"][0], "o", ms=13, mfc="none", color="k")
        for s in sc.soft:
            ax.errorbar(s["loop"], s["obs"][0], yerr=s["obs"][1] if s["obs"][1] == s["obs"][1] else None,
                        fmt="s", color="C3")
            ax.annotate(s["label"].replace("soft, ", ""), (s["loop"], s["obs"][0]), fontsize=6,
                        xytext=(3, -9), textcoords="offset points", color="C3")
        ax.set_xscale("log")
        ax.set_title(sc.name, fontsize=8)
        ax.set_xlabel("loop time (s, one core)", fontsize=7)
        ax.set_ylabel(sc.observable, fontsize=7)
        ax.tick_params(which="both", labelsize=6)
    for ax in list(axes.flat)[len(scenes):]:
        ax.axis("off")
    fig.suptitle("Frictional scenes: hard (circles; the fix's defaults ringed) and soft twins (squares)",
                 fontsize=9)
    fig.tight_layout()
    png = md.with_suffix(".png")
    fig.savefig(png, dpi=110)
    print("wrote", md, png)


if __name__ == "__main__":
    main()
