#!/usr/bin/env python3
"""Writes report.md and figures/perf_*.png beside the perf_*.csv of a results folder,
bench/results/perf/<host>/ (the output of bench/perf/run.py). Called by bench/run.sh perf; can be
rerun alone on a folder. The user guide, doc/performance.md, quotes its headline numbers."""

import argparse
import csv
import math
from pathlib import Path

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402
import numpy as np  # noqa: E402

# REF: the default frictionless solver, the reference of every series (bench/perf/run.py)
REF = "cg"
SOLVERS = ["cg", "apgd", "pgs", "uzawa", "exact"]
COLORS = dict(cg="C6", apgd="C0", pgs="C1", uzawa="C2", exact="C3", soft="C4")
STILL_KE = 1e-10    # bench/perf/run.py: "at rest" of the part still, x m g d per sphere


# Target 3's soft twin "at about 1e-3 overlap": the largest overlap measured in the soft run (as
# the twin was described: "kn giving a largest overlap of 2.4e-3"), not the static
# overlap its stiffness was chosen for (the impacts of the fall overlap about 10 x more).
TARGET3_OVERLAP = 1e-3


def soft_time_at(soft_rows, overlap):
    """The wall time of a soft twin whose largest overlap would be `overlap`: log-log between
    the two soft runs whose largest overlaps bracket it, else along the line through the two
    nearest (extrapolated). (time, lower overlap, higher overlap, bracketed), or None with fewer
    than two runs."""
    pts = sorted((num(r["overlap_max"]), num(r["projected_s"])) for r in soft_rows)
    pts = [p for p in pts if p[0] > 0 and p[1] > 0]
    if len(pts) < 2:
        return None
    k = next((i for i in range(len(pts) - 1) if pts[i][0] <= overlap <= pts[i + 1][0]), None)
    inside = k is not None
    if not inside:
        k = 0 if overlap < pts[0][0] else len(pts) - 2
    (o1, t1), (o2, t2) = pts[k], pts[k + 1]
    slope = math.log(t2 / t1) / math.log(o2 / o1) if o2 != o1 else 0.0
    return t1 * (overlap / o1) ** slope, o1, o2, inside


def num(x):
    try:
        return float(x)
    except (TypeError, ValueError):
        return float("nan")


def fmt(x, digits=3):
    x = num(x)
    if math.isnan(x):
        return "-"
    if x == 0:
        return "0"
    if abs(x) >= 1e5 or abs(x) < 1e-2:
        return "%.*e" % (max(digits - 2, 0), x)
    return "%.*g" % (digits, x)


def subspace_of(r):
    """cg's subspace N of a run (0: off; rows written before the column existed: 0)."""
    v = num(r.get("subspace"))
    return 0 if math.isnan(v) else int(v)


# the fix's default subspace N per solver (cg: 10 since 2026-12-01)
DEFAULT_SUBSPACE = {"cg": 10}


def is_variant(r):
    """A run whose subspace N is not its solver's default (the parts still and tray run the
    default and `subspace 0` from the same states)."""
    return subspace_of(r) != DEFAULT_SUBSPACE.get(r["solver"], 0)


def products(r):
    """' + 1 product' for a run with the subspace start (its one product per step is not in
    the iterations), else ''."""
    return " + 1 product" if subspace_of(r) else ""


def table(head, rows):
    out = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    out += ["| " + " | ".join(str(c) for c in r) + " |" for r in rows]
    return "\n".join(out)


def cpu_range(rows, key, ranks):
    """The range of a cpu_share column (run.py) over the runs on `ranks` that recorded it."""
    v = [num(r.get(key, "")) for r in rows if str(r.get("ranks")) == str(ranks)]
    v = [x for x in v if not math.isnan(x)]
    return (min(v), max(v), len(v)) if v else None


def load_range(rows):
    loads = [num(r["load_before"]) for r in rows] + [num(r["load_after"]) for r in rows]
    loads = [x for x in loads if not math.isnan(x)]
    return (min(loads), max(loads)) if loads else (float("nan"), float("nan"))


def solver_comm_cell(r):
    f, d = num(r.get("solver_forward_max_s", "")), num(r.get("solver_reduce_max_s", ""))
    return "-" if math.isnan(f) else "%s + %s" % (fmt(f), fmt(d))


def per_iteration_cell(r):
    f, d, it = (num(r.get(k, "")) for k in ("solver_forwards", "solver_reductions", "iterations"))
    return "-" if math.isnan(f) or not it > 0 else "%.2f, %.2f" % (f / it, d / it)


def cpu_cell(one, two):
    def cell(r):
        b, st = num(r.get("cpu_busy_pct", "")), num(r.get("cpu_steal_pct", ""))
        return "-" if math.isnan(b) else "%.0f %%, %.1f %%" % (b, st)
    return "%s / %s" % (cell(one), cell(two))


class Report:
    def __init__(self, results, figures):
        self.runs = list(csv.DictReader(open(str(results / "perf_runs.csv"))))
        self.runs = [r for r in self.runs if r.get("status") != "failed"]
        self.machine = {r["key"]: r["value"] for r in csv.DictReader(open(str(results / "perf_machine.csv")))}
        # parts run on their own (PERF_ONLY=...): perf_machine_<parts>.csv each
        self.parts = []
        for path in sorted(results.glob("perf_machine_*.csv")):
            self.parts.append({r["key"]: r["value"] for r in csv.DictReader(open(str(path)))})
        self.figures = figures
        self.results = results
        figures.mkdir(parents=True, exist_ok=True)
        self.lines = []
        self.targets = []

    def find(self, **kw):
        return [r for r in self.runs if all(str(r.get(k)) == str(v) for k, v in kw.items())]

    def one(self, **kw):
        f = self.find(**kw)
        return f[0] if f else None

    def save(self, fig, ax, xlabel, ylabel, title, name, legend=7, loglog=False):
        """Axes, labels, legend and the PNG under the report's figures/."""
        if loglog:
            ax.set_xscale("log")
            ax.set_yscale("log")
        ax.set_xlabel(xlabel)
        ax.set_ylabel(ylabel)
        ax.set_title(title)
        ax.legend(fontsize=legend)
        fig.tight_layout()
        fig.savefig(str(self.figures / name), dpi=110)
        plt.close(fig)

    def w(self, *text):
        self.lines.extend(text)

    # ---- 1. iterations against pile height

    def heights(self):
        rows = self.find(group="heights")
        if not rows:
            return
        layers = sorted({int(num(r["layers"])) for r in rows})
        tab = []
        fig, ax = plt.subplots(figsize=(6.4, 4.2))
        for solver in SOLVERS:
            xs, settle, rest = [], [], []
            for L in layers:
                s = [r for r in rows if r["solver"] == solver and int(num(r["layers"])) == L]
                st = next((r for r in s if r["phase"] == "settle"), None)
                rs = next((r for r in s if r["phase"] == "rest"), None)
                if not st and not rs:
                    continue
                xs.append(L)
                settle.append(num(st["it_mean"]) if st else float("nan"))
                rest.append(num(rs["it_mean"]) if rs else float("nan"))
                ref = st or rs
                tab.append([L, ref["n"], solver,
                            "%s / %s%s" % (st["steps"], st["steps_asked"], " (capped)" if st["status"] == "capped" else "") if st else "-",
                            fmt(st["it_mean"]) if st else "-", fmt(st["it_max"]) if st else "-",
                            fmt(rs["it_mean"]) if rs else "-", fmt(rs["it_max"]) if rs else "-",
                            fmt(rs["cand_mean"], 4) if rs else "-", fmt(rs["active_mean"], 4) if rs else "-",
                            fmt(rs["ms_per_step"]) if rs else "-",
                            "%s / %s" % (st["maxiter_stops"] if st else "-", rs["maxiter_stops"] if rs else "-"),
                            fmt(rs["ke_end"] if rs else st["ke_end"], 2)])
            if xs:
                ax.plot(xs, settle, "o--", color=COLORS[solver], label="%s, settle" % solver)
                ax.plot(xs, rest, "s-", color=COLORS[solver], label="%s, at rest" % solver)
        ax.axhline(30, color="k", lw=0.8, ls=":")
        ax.axhline(60, color="k", lw=0.8, ls="-.")
        ax.text(layers[0], 32, "target at rest (30)", fontsize=7)
        ax.text(layers[0], 64, "target settle (60)", fontsize=7)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xticks(layers)
        ax.set_xticklabels([str(L) for L in layers])
        ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
        ax.set_xlabel("pile height (layers)")
        ax.set_ylabel("solver iterations per step (mean)")
        ax.set_title("Iterations per step, tol 1e-4, warm start")
        ax.legend(fontsize=7, ncol=2)
        fig.tight_layout()
        fig.savefig(str(self.figures / "perf_iterations_vs_height.png"), dpi=110)
        plt.close(fig)
        self.along_settle(results=self.results)
        nx, ny, _ = rows[0]["id"].split("_")[1].replace("pile", "").split("x")
        fp = "%s x %s" % (nx, ny)
        self.w("## 1. Iterations per step against pile height", "",
               "Polydisperse spheres (d 0.8-1.0, density 1, LJ units, g = 1) on a simple-cubic lattice "
               "of spacing 1.1 with random horizontal offsets (up to 0.04), falling into a box walled in "
               "x and y onto a floor (`wall xplane/yplane/zplane`), h = 0.02, skin 0.3, `pair_style none`, "
               "tol 1e-4 (default), warm start. Footprint: %s columns. *Settle*: the whole fall "
               "from the lattice (200 + 20 x layers steps; the runs of `pgs`/`uzawa`/`exact` have a wall-time "
               "cap (`fix halt` on the run's elapsed time, checked every step) and cover the first steps only when marked capped). *At rest*: a window at the end, "
               "every solver started from the restart `%s` (the default) wrote at the end of its settle (with its "
               "warm-start forces). Iterations = `f_ID[1]`, candidates = `f_ID[3]`, active = `f_ID[4]`; "
               "KE end = kinetic energy per sphere at the end, in units of m g d." % (fp, REF), "",
               table(["layers", "N", "solver", "settle steps", "it/step settle (mean)", "(max)",
                      "it/step at rest (mean)", "(max)", "candidates at rest", "active at rest",
                      "ms/step at rest", "maxiter stops settle / rest", "KE end"], tab), "",
               "![iterations against pile height](figures/perf_iterations_vs_height.png)", "",
               "Iterations of `%s` along the fall and at rest (per step, candidate rows on the "
               "right axis):" % REF, "",
               "![iterations along the settle](figures/perf_iterations_along_settle.png)", "")
        r20s = self.one(group="heights", solver=REF, layers=20, phase="settle")
        r20r = self.one(group="heights", solver=REF, layers=20, phase="rest")
        if r20r:
            self.targets.append(("1. resting 20-layer pile, %s, tol 1e-4" % REF, "<= 30 it/step",
                                 "%s it/step" % fmt(r20r["it_mean"]), num(r20r["it_mean"]) / 30.0))
        if r20s:
            self.targets.append(("1. 20-layer pile during the settle", "<= 60 it/step",
                                 "%s it/step (max %s)" % (fmt(r20s["it_mean"]), fmt(r20s["it_max"])),
                                 num(r20s["it_mean"]) / 60.0))
        for solver in (REF, "apgd"):
            ap = [(int(num(r["layers"])), num(r["it_mean"])) for r in rows
                  if r["solver"] == solver and r["phase"] == "rest"]
            if len(ap) >= 2:
                ap.sort()
                slope = np.polyfit(np.log([a for a, _ in ap]), np.log([b for _, b in ap]), 1)[0]
                self.findings.append("Iterations of `%s` at rest grow like layers^%.2f (%s)." % (
                    solver, slope, ", ".join("%d layers: %.0f" % (a, b) for a, b in ap)))
        # the default against apgd, same scenes, same run of the benchmark
        for phase in ("settle", "rest"):
            pairs = []
            for r in rows:
                if r["solver"] != REF or r["phase"] != phase:
                    continue
                a = self.one(group="heights", solver="apgd", layers=int(num(r["layers"])), phase=phase)
                if a and r["status"] != "capped" and a["status"] != "capped":
                    pairs.append("%s layers %s / %s it/step, %s / %s ms/step (%.2fx the time)" % (
                        r["layers"], fmt(r["it_mean"]), fmt(a["it_mean"]), fmt(r["ms_per_step"]),
                        fmt(a["ms_per_step"]), num(r["ms_per_step"]) / num(a["ms_per_step"])))
            if pairs:
                self.findings.append("`%s` against `apgd` (%s): %s." % (REF, phase, "; ".join(pairs)))

    def along_settle(self, results):
        path = results / "perf_steps.csv"
        if not path.exists():
            return
        series = {}
        for r in csv.DictReader(open(str(path))):
            if r["id"].startswith("heights_") and r["id"].endswith("_" + REF):
                series.setdefault(r["id"].split("_")[1], []).append(
                    (int(r["step"]), int(r["iterations"]), int(r["candidates"])))
        if not series:
            return
        fig, ax = plt.subplots(figsize=(7.0, 4.2))
        ax2 = ax.twinx()
        for k, (pile, s) in enumerate(sorted(series.items(), key=lambda kv: len(kv[1]))):
            s = np.array(sorted(s))
            ax.plot(s[:, 0], s[:, 1], lw=0.7, color="C%d" % k, label=pile)
            ax2.plot(s[:, 0], s[:, 2], lw=1.5, ls=":", color="C%d" % k)
        ax.set_xlabel("step (h = 0.02)")
        ax.set_ylabel("%s iterations per step (solid)" % REF)
        ax2.set_ylabel("candidate rows (dotted)")
        ax.legend(fontsize=7, loc="upper left")
        fig.tight_layout()
        fig.savefig(str(self.figures / "perf_iterations_along_settle.png"), dpi=110)
        plt.close(fig)

    # ---- 2. a scene at rest with a mass ratio

    # ---- 1.1 at rest for real

    def still(self):
        rows = self.find(group="still", phase="still")
        if not rows:
            return
        tab = []
        for r in sorted(rows, key=lambda r: (num(r["layers"]), is_variant(r))):
            calm = self.one(group="still", phase="calm", id=r["id"].split("_subspace")[0])
            win = self.one(group="heights", solver=REF, phase="rest", layers=r["layers"])
            tab.append([r["layers"], r["n"], "%s subspace %d" % (REF, subspace_of(r)) if is_variant(r) else REF,
                        "%s%s" % (calm["steps"], "" if num(calm["ke_end"]) < STILL_KE else " (not reached)") if calm else "-",
                        fmt(calm["ke_start"], 2) if calm else "-", fmt(r["ke_start"], 2), fmt(r["ke_max"], 2),
                        r["steps"],
                        fmt(r["it_mean"]), fmt(r.get("it_mean_2nd_half")), fmt(r["it_max"]), fmt(r["active_mean"], 4),
                        fmt(r["ms_per_step"]), fmt(r["overlap_max"], 2),
                        "%s (%s)" % (fmt(win["it_mean"]), fmt(num(r["it_mean"]) / num(win["it_mean"]), 2)) if win else "-"])
        self.w("### 1.1 A pile at rest for real", "",
               "The windows *at rest* above start where the settle ends, with a kinetic energy of "
               "about 1e-3 m g d per sphere: the frictionless piles still creep there (a few spheres "
               "at 0.1-0.4, about 10 x g h, which also loosens the tolerance, whose scale is h times "
               "the fastest approach). Here the restart of each `%s` settle runs on until the kinetic "
               "energy per sphere is below %s m g d (`calm`, checked every 10 steps) or for %s steps "
               "(`not reached`: a few spheres slide without friction along the floor or a wall at a "
               "constant speed, while the pile itself no longer moves), then the same window "
               "(`still`), once with the default (`%s`, `subspace %d`) and once with `subspace 0` "
               "(the default before 2026-12-01). Last column: the window of section 1, and this "
               "window's iterations over it." % (REF, fmt(STILL_KE), max((r["steps_asked"] for r in self.find(group="still", phase="calm")), key=num, default="-"),
                                             REF, DEFAULT_SUBSPACE[REF]), "",
               table(["layers", "N", "solver", "steps to rest", "KE at the start (m g d per sphere)",
                      "KE in the window (start)", "(max)", "steps", "it/step at rest (mean)", "(2nd half)", "(max)",
                      "active rows", "ms/step", "largest overlap",
                      "it/step, window of section 1 (ratio)"], tab), "",
               "At rest the scale of the tolerance is g h^2 (the free approach of one step), so "
               "tol 1e-4 asks for gaps to 4e-8 d on these piles, and every step starts about 4 x "
               "tol away however tightly the last one was solved: the warm start repeats the last "
               "forces, and a gap error r_n left by step n returns in step n + 1 as "
               "3 r_n - 3 r_(n-1) + r_(n-2) (the gap, the velocity it left and the change of that "
               "velocity; measured on dumped problems of the 5-layer pile: 3-5 x tol at tol 1e-4 "
               "and at tol 1e-10 alike). Removing a factor of 4 from a residual spread over the "
               "slow modes of the pile costs about as many iterations as the conditioning allows "
               "(bench/studies/spectrum, section 10.1).", "")
        r20 = next((r for r in rows if int(num(r["layers"])) == 20 and not is_variant(r)), None)
        s20 = next((r for r in rows if int(num(r["layers"])) == 20 and is_variant(r)), None)
        for r in rows:
            dflt = next((x for x in rows if x["layers"] == r["layers"] and not is_variant(x)), None)
            if is_variant(r) and dflt:
                self.findings.append(
                    "At rest for real (section 1.1), %s layers: the default (`subspace %d`) %s it/step (%s in "
                    "the second half of its %s steps) and %s ms/step against %s (%s) and %s with `subspace %d` "
                    "(%.2fx the time)." % (
                        r["layers"], subspace_of(dflt), fmt(dflt["it_mean"]), fmt(dflt.get("it_mean_2nd_half")),
                        dflt["steps"], fmt(dflt["ms_per_step"]),
                        fmt(r["it_mean"]), fmt(r.get("it_mean_2nd_half")), fmt(r["ms_per_step"]), subspace_of(r),
                        num(dflt["ms_per_step"]) / num(r["ms_per_step"])))
        if r20:
            self.targets.append(("1. 20-layer pile at rest (section 1.1: KE %s m g d per sphere), %s, tol 1e-4" % (fmt(r20["ke_start"], 1), REF),
                                 "<= 30 it/step", "%s it/step%s (%s in the second half of %s steps)" % (
                                     fmt(r20["it_mean"]), products(r20), fmt(r20.get("it_mean_2nd_half")), r20["steps"]),
                                 (num(r20["it_mean"]) + (1.0 if subspace_of(r20) else 0.0)) / 30.0))
        if s20:
            self.targets.append(("1. the same, %s subspace %d (bench/studies/spectrum, section 10.2)" % (REF, subspace_of(s20)),
                                 "<= 30 it/step", "%s it/step%s (%s in the second half of %s steps)" % (
                                     fmt(s20["it_mean"]), products(s20), fmt(s20.get("it_mean_2nd_half")), s20["steps"]),
                                 (num(s20["it_mean"]) + (1.0 if subspace_of(s20) else 0.0)) / 30.0))

    def tray(self):
        rows = self.find(group="tray")
        if not rows:
            return
        ratios = sorted({int(num(r["ratio"])) for r in rows})
        tab = []
        worst = None
        worst_sub = None
        for ratio in ratios:
            for solver in SOLVERS + ["%s subspace" % REF]:
                sub = solver.endswith("subspace")
                r = [x for x in rows if x["solver"] == solver.split()[0] and int(num(x["ratio"])) == ratio
                     and x["phase"] == "rest" and is_variant(x) == sub]
                if not r:
                    continue
                r = r[0]
                tab.append([ratio, "%s %d" % (solver, subspace_of(r)) if sub else solver, r["steps"],
                            fmt(r["it_mean"]), fmt(r.get("it_mean_2nd_half")), fmt(r["it_median"]), fmt(r["it_max"]),
                            fmt(r["cand_mean"], 4), fmt(r["active_mean"], 4), fmt(r["ms_per_step"]),
                            r["maxiter_stops"], fmt(r["ke_end"], 2)])
                if solver == REF and (worst is None or num(r["it_mean"]) > num(worst["it_mean"])):
                    worst = r
                if sub and (worst_sub is None or num(r["it_mean"]) > num(worst_sub["it_mean"])):
                    worst_sub = r
        self.w("## 2. A scene at rest with a mass ratio", "",
               "A heavy sphere (d = 10, at (7, 7, 6.2), mass 1, 10, 100 or 1000 x a small one through "
               "its density) on a walled 14 x 14 tray of spheres of d = 1 touching each other and the "
               "floor (lattice sc 1.0, origin 0.5 0.5 0.5); `%s` settles it, then each solver runs a "
               "window from that state (tol 1e-4, warm start). `%s` runs with its default subspace "
               "start (`subspace %d` since 2026-12-01, bench/studies/spectrum, section 10.2), whose one product per step (the "
               "product of the newest correction) is not in the iterations; `%s subspace 0`: the same "
               "window without it (the default before)." % (REF, REF, DEFAULT_SUBSPACE[REF], REF), "",
               table(["mass ratio", "solver", "steps", "it/step (mean)", "(2nd half)", "(median)", "(max)", "candidates",
                      "active", "ms/step", "maxiter stops", "KE end"], tab), "")
        for r, label in ((worst, REF), (worst_sub, "%s subspace %d, bench/studies/spectrum, section 10.2" % (REF, subspace_of(worst_sub or {})))):
            if r:
                self.targets.append(("1. scene at rest, mass ratio 1..1000 (%s)" % label, "<= 10 it/step",
                                     "%s it/step%s (worst: ratio %s)" % (fmt(r["it_mean"]), products(r), r["ratio"]),
                                     (num(r["it_mean"]) + (1.0 if subspace_of(r) else 0.0)) / 10.0))

    # ---- 3. throughput

    def throughput(self):
        rows = [r for r in self.runs if r["solver"] not in ("soft",) and r.get("ci_per_s_cand")
                and int(num(r["ranks"])) == 1 and num(r["steps"]) >= 10 and r["group"] in ("heights", "throughput", "tts")]
        if not rows:
            return
        fig, ax = plt.subplots(figsize=(6.4, 4.2))
        tab = []
        for solver in SOLVERS:
            s = sorted([r for r in rows if r["solver"] == solver], key=lambda r: num(r["n"]))
            if not s:
                continue
            ax.plot([num(r["n"]) for r in s], [num(r["ci_per_s_cand"]) for r in s], "o", color=COLORS[solver],
                    label="%s (candidate rows)" % solver, alpha=0.8)
            if solver == REF:
                ax.plot([num(r["n"]) for r in s], [num(r["ci_per_s_active"]) for r in s], "x", color=COLORS[solver],
                        label="%s (active rows)" % REF, alpha=0.8)
        for r in sorted(rows, key=lambda r: (r["solver"], num(r["n"]), r["id"])):
            if r["solver"] != REF and r["group"] != "heights":
                continue
            tab.append([r["id"].split("_")[1], r["n"], r["solver"], fmt(r["tol"]), r["phase"], r["steps"],
                        fmt(r["it_mean"]), fmt(r["cand_mean"], 4), fmt(r["ci_per_s_cand"]), fmt(r["ci_per_s_active"]),
                        fmt(r["ms_per_step"]), "%.0f" % (100 * num(r["modify_s"]) / max(num(r["loop_s"]), 1e-12))])
        ax.axhline(1.5e8, color="k", lw=0.8, ls=":")
        ax.text(min(num(r["n"]) for r in rows), 1.6e8, "target 1.5e8 (20-layer pile)", fontsize=7)
        self.save(fig, ax, "spheres N", "contact-iterations per second of the fix", "Throughput, one rank (iterations x rows / Modify time)", "perf_throughput.png", legend=7, loglog=True)
        self.w("## 3. Throughput: contact-iterations per second", "",
               "Contact-iterations per second = sum over the steps of (rows x iterations) / the `Modify` time "
               "of LAMMPS's timing breakdown (the fix's whole step: candidates, solve, update; the loop "
               "time is within a few %% of it, see the last column). Rows are counted two ways: the "
               "candidate rows `f_ID[3]` (the rows of the problem; the headline figure, as in the "
               "accuracy report) and the active rows `f_ID[4]` (force > 0). `%s` on the piles of "
               "every series, one rank; also `apgd`, `pgs` and `uzawa` on the height series (their per-iteration "
               "cost differs)." % REF, "",
               table(["pile", "N", "solver", "tol", "phase", "steps", "it/step", "candidates", "ci/s (candidate rows)",
                      "ci/s (active rows)", "ms/step", "Modify % of loop"], tab), "",
               "![contact-iterations per second against N](figures/perf_throughput.png)", "")
        r20 = self.one(group="heights", solver=REF, layers=20, phase="settle")
        if r20:
            self.targets.append(("2. throughput, 20-layer pile, one core", ">= 1.5e8 ci/s",
                                 "%s ci/s (candidate rows; %s active)" % (fmt(r20["ci_per_s_cand"]), fmt(r20["ci_per_s_active"])),
                                 1.5e8 / num(r20["ci_per_s_cand"])))

    # ---- 4. hard vs soft

    def hard_vs_soft(self):
        rows = self.find(group="tts")
        if not rows:
            return
        piles = []
        for r in rows:
            p = r["id"].split("_")[1]
            if p not in piles:
                piles.append(p)
        tab = []
        fig, ax = plt.subplots(figsize=(6.4, 4.2))
        for k, pile in enumerate(piles):
            hs = [r for r in rows if r["id"].split("_")[1] == pile and r["solver"] != "soft"]
            # the 1e-4 hard run of a height-series pile is that series' settle
            if not any(num(r["tol"]) == 1e-4 and r["solver"] == REF for r in hs):
                h = self.one(group="heights", solver=REF, phase="settle", id="heights_%s_%s" % (pile, REF))
                if h:
                    hs.append(h)
            ss = sorted([r for r in rows if r["id"].split("_")[1] == pile and r["solver"] == "soft"],
                        key=lambda r: -num(r["tol"]))
            ref = next((r for r in hs if num(r["tol"]) == 1e-4 and r["solver"] == REF), None)
            for r in sorted(hs, key=lambda r: -num(r["tol"])) + ss:
                soft = r["solver"] == "soft"
                t = num(r["projected_s"]) if soft else num(r["loop_s"])
                tab.append([pile, r["n"], "soft, static overlap %s" % fmt(r["tol"]) if soft else "hard %s tol %s" % (r["solver"], fmt(r["tol"])),
                            "%s%s" % (r["steps"], " of %s (capped; time projected)" % r["steps_asked"] if r["status"] == "capped" else ""),
                            fmt(r.get("dt")) if soft else "0.02",
                            fmt(t), fmt(r["overlap_max"], 2), fmt(r.get("overlap_rest"), 2) if soft else "-",
                            fmt(r["ke_end"], 2), fmt(r["settle_wall_s"]),
                            fmt(t / num(ref["loop_s"]), 2) if ref else "-"])
            mk = "os^"[k % 3]
            ax.plot([num(r["overlap_max"]) for r in ss], [num(r["projected_s"]) for r in ss], mk + "-",
                    color=COLORS["soft"], label="soft, %s" % pile)
            for r in hs:
                ax.plot([num(r["overlap_max"])], [num(r["loop_s"])], mk, color=COLORS.get(r["solver"], "C5") if num(r["tol"]) == 1e-4 else "C5",
                        label="hard %s tol %s, %s" % (r["solver"], fmt(r["tol"]), pile))
            if ref and len(ss) >= 2:
                ov = np.log([num(r["overlap_max"]) for r in ss])
                tt = np.log([num(r["projected_s"]) for r in ss])
                slope, icpt = np.polyfit(ov, tt, 1)
                target_ov = num(ref["overlap_max"])
                t_eq = math.exp(icpt + slope * math.log(target_ov))
                self.equal[pile] = (t_eq, target_ov, slope, num(ref["loop_s"]), min(num(r["overlap_max"]) for r in ss))
            s1 = next((r for r in ss if num(r["tol"]) == 1e-3), None)
            soft_at = soft_time_at(ss, TARGET3_OVERLAP)
            if ref and s1:
                self.at1e3[pile] = dict(t=soft_at[0] if soft_at else None, th=num(ref["loop_s"]), n=ref["n"],
                                        static_t=num(s1["projected_s"]), static_ov=num(s1["overlap_max"]),
                                        static_ovr=num(s1["overlap_rest"]))
                if soft_at:
                    self.at1e3[pile].update(lo=soft_at[1], hi=soft_at[2], inside=soft_at[3])
        self.save(fig, ax, "largest overlap during the settle / contact size", "wall time of the settle (s)", "Time to solution: hard vs soft (same simulated time)", "perf_hard_vs_soft.png", legend=6, loglog=True)
        self.w("## 4. Time to solution: hard against soft spheres", "",
               "The same data file and the same simulated time (the settle of section 1: 200 + 20 x layers "
               "steps of 0.02) with the soft-sphere twin: `pair_style gran/hertz/history` frictionless "
               "(xmu = 0), `fix wall/gran hertz/history` for the floor and sides, `fix nve/sphere`, Debian's "
               "`/usr/bin/lmp`. kn is chosen so that the static load of a column of the pile (layers x m g) "
               "overlaps a pair by the given fraction of d (`static overlap`), gamma_n for a restitution of "
               "0.1 at the top layer's impact speed, dt = t_c / 20 (Hertz contact time at that speed; the "
               "convention of `potentials/glass_beads.params`, t_c/50 would cost 2.5x more). The impacts of "
               "the fall overlap about 10x more than the static load does: the *measured* largest "
               "overlap (pair with the largest force, and the floor; sampled about 200 times per run) is "
               "what the comparison uses; sampled, it misses the peak of most impacts (a contact lasts "
               "20 steps), so the soft overlaps are lower bounds and the soft/hard ratios at equal "
               "overlap below are conservative. Hard: `f_ID[7]`, every step. Wall time = LAMMPS loop time (a "
               "capped soft run is projected to the full run from its steps). *Time to settle*: wall time "
               "from which the kinetic energy per sphere stays below 5e-3 m g d (`-`: not within the run). "
               "*Target 3* (\"its soft twin at about 1e-3 overlap\") takes the twin whose *largest* "
               "overlap is %s, as the issue described its own twin by its largest overlap: its time is "
               "interpolated log-log between the two soft runs whose largest overlaps bracket it "
               "(extrapolated, and said so, where none do). The twin calibrated to a static overlap of "
               "1e-3 overlaps 8-16 x more in the fall (4-11 x at rest), and is compared too." % fmt(TARGET3_OVERLAP), "",
               table(["pile", "N", "run", "steps", "dt", "wall s", "largest overlap (settle)", "soft overlap at rest",
                      "KE end", "time to settle (s)", "wall / hard tol 1e-4"], tab), "",
               "![wall time against largest overlap](figures/perf_hard_vs_soft.png)", "")
        for pile, a in self.at1e3.items():
            if a["t"] is None:
                # one soft run (the 64,000-sphere pile: part big): no twin at a largest overlap of 1e-3
                self.targets.append(("3. settle of %s (N %s) vs soft at a largest overlap of %s" % (pile, a["n"], fmt(TARGET3_OVERLAP)),
                                     ">= 5x faster",
                                     "not measured: one soft twin, at a static overlap of 1e-3, which overlaps %s in the fall "
                                     "and %s at rest (soft/hard = %.2fx against it)" % (
                                         fmt(a["static_ov"], 2), fmt(a["static_ovr"], 2), a["static_t"] / a["th"]),
                                     float("nan")))
                continue
            how = ("interpolated between the soft runs at %s and %s" if a["inside"] else
                   "extrapolated from the soft runs at %s and %s") % (fmt(a["lo"], 2), fmt(a["hi"], 2))
            self.targets.append(("3. settle of %s (N %s) vs soft at a largest overlap of %s" % (pile, a["n"], fmt(TARGET3_OVERLAP)),
                                 ">= 5x faster",
                                 "soft/hard = %.2fx (soft time %s s, %s, log-log; the twin calibrated to a static overlap of "
                                 "1e-3 overlaps %s in the fall and %s at rest: %.2fx)" % (
                                     a["t"] / a["th"], fmt(a["t"]), how, fmt(a["static_ov"], 2), fmt(a["static_ovr"], 2),
                                     a["static_t"] / a["th"]),
                                 5.0 / (a["t"] / a["th"])))
        for pile, (teq, ov, slope, th, lo) in self.equal.items():
            extra = "" if ov >= lo else ", extrapolated below the stiffest soft run (%s)" % fmt(lo, 2)
            self.targets.append(("3. %s vs soft at equal overlap (%s)" % (pile, fmt(ov, 2)), ">= 20x faster",
                                 "soft/hard = %.2gx (power-law fit, time ~ overlap^%.2f%s)" % (teq / th, slope, extra),
                                 20.0 / (teq / th)))

    # ---- 4.1 a larger step

    def larger_step(self):
        rows = self.find(group="steps")
        if not rows:
            return
        hard = sorted([r for r in rows if r["solver"] != "soft"], key=lambda r: num(r["h"]))
        soft = next((r for r in rows if r["solver"] == "soft"), None)
        if not hard:
            return
        ref = hard[0]
        pile = ref["id"].split("_")[1]
        tab = []
        for r in hard:
            tab.append([pile, r["n"], "hard %s tol %s" % (r["solver"], fmt(r["tol"])), fmt(r["h"]), fmt(r["skin"]),
                        "%s%s" % (r["steps"], " (capped)" if r["status"] == "capped" else ""),
                        fmt(r["it_mean"]), fmt(r["loop_s"]), fmt(r["overlap_max"], 2), fmt(r["z_end"], 4),
                        fmt(r["ke_end"], 2), fmt(r["settle_wall_s"]),
                        fmt(num(soft["projected_s"]) / num(r["loop_s"]), 2) if soft else "-"])
        if soft:
            tab.append([pile, soft["n"], "soft, static overlap %s" % fmt(soft["tol"]), fmt(soft["dt"]), "0.1",
                        "%s%s" % (soft["steps"], " of %s (capped; time projected)" % soft["steps_asked"] if soft["status"] == "capped" else ""),
                        "-", fmt(soft["projected_s"]), fmt(soft["overlap_max"], 2), "-", fmt(soft["ke_end"], 2),
                        fmt(soft["settle_wall_s"]), "1"])
        self.w("### 4.1 The same settle with a larger step", "",
               "The scheme is stable for any step; the settle of section 4 used h = 0.02 because "
               "the issue's scene did. Here the same pile (`%s`) settles for the same simulated time "
               "with larger steps (tol 1e-4, `%s`; skin 9 h, at least 0.3), and its soft twin at a "
               "static overlap of 1e-3 runs in the same part of the benchmark. *Mean height at the "
               "end*: `c_zavg`, the mean z of the spheres (how far the settle got; the lattice "
               "starts much higher). Last column: soft time / hard time." % (pile, REF), "",
               table(["pile", "N", "run", "h or dt", "skin", "steps", "it/step", "wall s",
                      "largest overlap", "mean height at the end", "KE end", "time to settle (s)",
                      "soft / hard"], tab), "")
        if soft:
            best = min(hard, key=lambda r: num(r["loop_s"]))
            z0 = num(ref["z_end"])
            self.findings.append(
                "A larger step (section 4.1): the %s settle takes %s s at h = %s and %s s at h = %s "
                "(%.2fx), its mean height at the end %s against %s (%.1f %% of it); iterations per "
                "step %s against %s." % (
                    pile, fmt(ref["loop_s"]), fmt(ref["h"]), fmt(best["loop_s"]), fmt(best["h"]),
                    num(ref["loop_s"]) / num(best["loop_s"]), fmt(best["z_end"], 4), fmt(z0, 4),
                    100.0 * abs(num(best["z_end"]) - z0) / z0, fmt(best["it_mean"]), fmt(ref["it_mean"])))
            # this part's soft twin has a static overlap of 1e-3; section 4 measured what a twin
            # whose largest overlap is TARGET3_OVERLAP takes against it (a ratio of two soft runs
            # of one part, like every ratio here)
            a = self.at1e3.get(pile)
            if a and a["t"] is not None:
                stiffer = a["t"] / a["static_t"]
                ratio = num(soft["projected_s"]) * stiffer / num(best["loop_s"])
                self.targets.append((
                    "3. settle of %s vs soft at a largest overlap of %s, hard at h = %s (same simulated time, section 4.1)" % (
                        pile, fmt(TARGET3_OVERLAP), fmt(best["h"])), ">= 5x faster",
                    "soft/hard = %.2fx (this part's twin at a static overlap of 1e-3, %.2fx the hard run's time, "
                    "times %.2f, what a twin at a largest overlap of %s takes against it in section 4; h = 0.02 "
                    "in the same part: %.2fx)" % (
                        ratio, num(soft["projected_s"]) / num(best["loop_s"]), stiffer, fmt(TARGET3_OVERLAP),
                        num(soft["projected_s"]) * stiffer / num(ref["loop_s"])),
                    5.0 / ratio))

    # ---- 5. MPI

    def mpi(self):
        rows = self.find(group="mpi")
        if not rows:
            return
        tab = []
        for r in rows:
            pile = r["id"].split("_")[1]
            one = next((x for x in self.find(group="tts") if x["id"].split("_")[1] == pile and x["solver"] == r["solver"]
                        and num(x["tol"]) == num(r["tol"])), None)
            if not one:
                continue
            sp = num(one["loop_s"]) / num(r["loop_s"])
            tab.append([pile, r["n"], r["solver"], fmt(r["tol"]), "%s / %s" % (one["steps"], r["steps"]),
                        fmt(one["loop_s"]), fmt(r["loop_s"]), "%.2f" % sp,
                        "%s / %s" % (fmt(one["it_mean"]), fmt(r["it_mean"])),
                        "%s / %s" % (fmt(one["ke_end"], 3), fmt(r["ke_end"], 3)),
                        "%s / %s" % (fmt(one["overlap_max"], 2), fmt(r["overlap_max"], 2)),
                        solver_comm_cell(r), fmt(r["comm_s"]), per_iteration_cell(r),
                        "%s / %s" % (r["load_before"], r["load_after"]), cpu_cell(one, r)])
            self.targets.append(("4. MPI, 2 ranks vs 1 (%s, N %s, %s, tol %s; target on 64,000)" % (pile, r["n"], r["solver"], fmt(r["tol"])),
                                 ">= 1.7x", "%.2fx" % sp, 1.7 / sp))
        self.w("## 5. MPI: 1 against 2 ranks", "",
               "The pile of section 4, `processors * * 1`, `mpirun --oversubscribe -np 2` against the "
               "serial run of the same deck. On this 2-core machine shared with another engineer's builds "
               "and tests, a 2-rank run competes with them for the cores: look at the load column.", "",
               table(["pile", "N", "solver", "tol", "steps 1 / 2 ranks", "loop s, 1 rank", "loop s, 2 ranks", "speed-up",
                      "it/step 1 / 2", "KE end 1 / 2", "largest overlap 1 / 2",
                      "solver's communication, 2 ranks: forwards + reductions, s (largest rank)",
                      "LAMMPS Comm s (2 ranks)", "per iteration: forwards, reductions",
                      "load before / after (2 ranks)", "cores busy, stolen: 1 / 2 ranks"], tab), "",
               "The solver's communication is what the fix reports at the end of a run under "
               "`HARDCONTACT_COMM_TIMES` (src/lammps/fix_hardcontact.cpp): the seconds each rank spent "
               "in the forward communications of ghost velocities and in reductions, including the "
               "wait for the other rank. It is inside LAMMPS's Modify time; LAMMPS's own Comm column "
               "counts only its exchanges of positions and neighbor lists. Per iteration: the calls "
               "divided by the iterations of the run (the setup's and the steps' own calls included). "
               "Cores busy, stolen: the share of the machine's cores busy and taken by the hypervisor "
               "during the run (/proc/stat); a serial run alone keeps 50 % busy.", "")

    def write(self, out):
        m = self.machine
        self.findings = []
        self.equal, self.at1e3 = {}, {}
        body_start = len(self.lines)
        self.heights()
        self.still()
        self.tray()
        self.throughput()
        self.hard_vs_soft()
        self.larger_step()
        self.mpi()
        body = self.lines[body_start:]
        lo, hi = load_range(self.runs)
        capped = [r["id"] + (" (" + r["phase"] + ")") for r in self.runs if r.get("status") == "capped"]
        head = ["# Performance of fix hardcontact: the perf suite's report (issue 15)", "",
                "Generated by `bench/run.sh perf` (%s mode) on %s; do not edit by hand: edit "
                "`bench/perf/report.py` and rerun (`bench/perf/report.py` alone redraws from the "
                "`perf_*.csv` beside this file). Scripts: `bench/perf/` (scenes, decks, runs, this report). "
                "What these numbers mean for a user: doc/performance.md." % (
                    m.get("mode"), m.get("date")), "",
                "**Machine and load.** Timings were taken on a shared %s-core virtual machine (%s), "
                "whose speed varies: identical runs of one deck were seen to differ by up to 40 %% "
                "within an hour (2026-12-01), so compare ratios of runs of one part rather than "
                "times across parts or reports; every run but the 2-rank ones is a "
                "single process (`OMP_NUM_THREADS=1`), run one at a time. Load average (1, 5, 15 min) "
                "%s before the whole benchmark and %s after; the 1-minute load seen before/after each "
                "run ranged over %.2f-%.2f (per run in `perf_runs.csv`, columns "
                "`load_before`, `load_after`). A load above 1 means a run may have shared its core: "
                "absolute times are upper bounds; ratios of runs taken at similar load are more "
                "trustworthy. Binary: hardcontact %s, `%s`; soft twin and LAMMPS: %s (Debian). "
                "The benchmark took %s min." % (
                    m.get("nproc"), m.get("cpu"), m.get("load_before"), m.get("load_after"), lo, hi,
                    m.get("hardcontact"), m.get("launcher"), m.get("lammps"), m.get("minutes")), ""]
        c1, c2 = cpu_range(self.runs, "cpu_busy_pct", 1), cpu_range(self.runs, "cpu_busy_pct", 2)
        st = cpu_range(self.runs, "cpu_steal_pct", 1), cpu_range(self.runs, "cpu_steal_pct", 2)
        if c1 or c2:
            head += ["Runs since 2026-12-02 also record the share of the machine's cores busy and "
                     "stolen by the hypervisor while they ran (/proc/stat; columns `cpu_busy_pct`, "
                     "`cpu_steal_pct`), which the load average does not tell: %s%s%s." % (
                         "serial runs kept %.0f-%.0f %% of the cores busy (50 %% is the run alone; %d "
                         "runs)" % c1 if c1 else "",
                         "; 2-rank runs %.0f-%.0f %% (%d runs)" % c2 if c2 else "",
                         "; at most %.1f %% was stolen" % max(x[1] for x in st if x)
                         if any(st) else ""), ""]
        for pm in self.parts:
            other = pm.get("cpu") and pm.get("cpu") != m.get("cpu")
            head += ["Part `%s` was run on its own (`PERF_ONLY=%s bench/run.sh perf`) on %s: load %s "
                     "before and %s after, %s min, hardcontact %s%s." % (
                         pm.get("only"), pm.get("only"), pm.get("date"), pm.get("load_before"),
                         pm.get("load_after"), pm.get("minutes"), pm.get("hardcontact"),
                         "; on another host (%s): compare its times with its own part's only"
                         % pm.get("cpu") if other else ""), ""]
        tg = [[a, b, c, ("%.2g" % d if not math.isnan(d) else "-"),
               ("yes" + (" (extrapolated)" if "extrapolated" in c else "")) if d <= 1 else "no"]
              for a, b, c, d in self.targets]
        head += ["## The issue's targets against the measurements", "",
                 "Factor = how far the measurement is from the target (measured / target for counts, "
                 "target / measured for speeds and speed-ups): <= 1 meets the target.", "",
                 table(["target (issue 15)", "wanted", "measured", "factor to go", "met"], tg), "",
                 "Measured elsewhere: the 64,000-sphere pile (targets 3 and 4) is the parts `big` and "
                 "`big_stiff` (its stiffer soft twins) of this benchmark, run on their own (below when); "
                 "the 1,000,000-sphere run, memory per sphere (target 5) and the messages and reductions "
                 "per iteration (target 4, counted) are in bench/scale/README.md (`bench/run.sh scale`) and "
                 "bench/studies/mpi_calls/README.md; section 5 gives them as measured in its 2-rank runs); "
                 "SCoPI's box_spheres_3d scene (target 3) is in bench/scopi/README.md (`bench/run.sh scopi`).", ""]
        head += self.then_and_now()
        head += ["## What the numbers say", ""] + ["- " + f for f in self.findings + self.say()] + [""]
        if capped:
            head += ["Runs stopped by their wall-time cap (the numbers cover the steps done): " +
                     ", ".join(capped) + ".", ""]
        Path(out).write_text("\n".join(head + body) + "\n")

    def then_and_now(self):
        """The issue's own measurements (filed with an older binary) next to this run's."""
        rows = []
        big = [r for r in self.find(group="tts", solver=REF) if r["id"].split("_")[1] == "pile20x20x20"]
        h4 = next((r for r in big if num(r["tol"]) == 1e-4), None)
        h2 = next((r for r in big if num(r["tol"]) == 1e-2), None)
        soft = self.one(group="tts", solver="soft", id="tts_pile20x20x20_soft_0.001")
        m2 = self.one(group="mpi", id="mpi2_pile20x20x20_%s_tol0.01" % REF)
        tray = self.one(group="tray", solver=REF, ratio=1000, phase="rest")
        if h4:
            rows.append(["8000-sphere settle, tol 1e-4 (wall s / 600 steps; issue: apgd, now: %s)" % REF, "104 s",
                         "%s s / %s steps" % (fmt(h4["loop_s"]), h4["steps"])])
            rows.append(["  iterations per step near the end of the settle", "about 540",
                         "%s (mean over the settle), %s (max)" % (fmt(h4["it_mean"]), fmt(h4["it_max"]))])
            rows.append(["  contact-iterations per second", "about 4e7", fmt(h4["ci_per_s_cand"])])
        if h2:
            rows.append(["8000-sphere settle, tol 1e-2 (issue: apgd, now: %s)" % REF, "23 s", "%s s" % fmt(h2["loop_s"])])
        if soft:
            rows.append(["8000-sphere soft twin (issue: overlap 2.4e-3, dt = t_c/50)", "54 s",
                         "%s s (overlap %s in the fall, %s at rest; dt = t_c/20)" % (
                             fmt(soft["projected_s"]), fmt(soft["overlap_max"], 2), fmt(soft["overlap_rest"], 2))])
        if m2 and h2:
            rows.append(["2 ranks vs 1, tol 1e-2", "1.5x", "%.2fx" % (num(h2["loop_s"]) / num(m2["loop_s"]))])
        if tray:
            rows.append(["heavy sphere (mass 1000x) on the tray at rest, it/step", "about 880", fmt(tray["it_mean"])])
        if not rows:
            return []
        return ["## The issue's measurements (older binary) against this run", "",
                "Issue 15 was filed with an older build of the fix; the solvers changed since, so its "
                "numbers are not this binary's. Same scenes, same machine type.", "",
                table(["quantity", "issue 15", "this run"], rows), ""]

    def say(self):
        out = []
        for a, b, c, d in self.targets:
            if not math.isnan(d) and d > 1:
                out.append("%s: %s, target %s (%.2gx to go)." % (a, c, b, d))
            elif not math.isnan(d):
                out.append("%s: met (%s, target %s)." % (a, c, b))
        st = [r for r in self.find(group="heights", phase="settle") if r["solver"] in ("pgs", "uzawa")]
        ap = {r["layers"]: r for r in self.find(group="heights", phase="settle", solver=REF)}
        worse = []
        for r in st:
            if r["layers"] in ap:
                worse.append("%s %s layers: %s vs %s %s" % (r["solver"], r["layers"], fmt(r["it_mean"]), REF,
                                                            fmt(ap[r["layers"]]["it_mean"])))
        if worse:
            out.append("Iterations per step during the settle against %s (tol 1e-4; pgs/uzawa " % REF +
                       "over the steps their cap allowed, mostly the early, cheaper part of the fall): "
                       + "; ".join(worse) + ".")
        return out


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--results", required=True)
    ap.add_argument("--out", required=True, help="the report (bench/results/perf/<host>/report.md)")
    ap.add_argument("--figures", required=True)
    a = ap.parse_args()
    Report(Path(a.results), Path(a.figures)).write(a.out)


if __name__ == "__main__":
    main()
