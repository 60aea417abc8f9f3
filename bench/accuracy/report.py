#!/usr/bin/env python3
"""Figures and doc/accuracy-vs-time.md from the CSV files of bench/results/accuracy/<host>/."""

import argparse
import csv
import json
import math
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

SOLVERS = ["cg", "apgd", "pgs", "uzawa"]
# the fix's default without friction, warm, tol 1e-4: "the default" of every finding
DEFAULT = "cg"
STUDY_FRICTION_TOL = Path(__file__).resolve().parents[1] / "studies" / "friction_tol" / "results" / "friction_tol.csv"
CPU = [""]    # "_cpu" when the timings are CPU times (machine under load), see main()


def T(key):
    """The timing column in use: wall clock, or CPU time of the run when the machine was
    loaded (set in main)."""
    return key + CPU[0]
COLOR = {"cg": "tab:red", "apgd": "tab:blue", "pgs": "tab:green", "uzawa": "tab:orange"}
MARK = {"cg": "D", "apgd": "o", "pgs": "s", "uzawa": "^"}
ORDER = ["pile10", "pile30", "pile100", "pile3d", "crystal", "cluster", "pour"]
TITLE = {"pile10": "pile, 10 layers", "pile30": "pile, 30 layers", "pile100": "pile, 100 layers",
         "pile3d": "3D pile",    # main() adds its layers
         "crystal": "hexagonal crystal", "cluster": "cluster impact (6.3)", "pour": "pour into a box"}


def read(path):
    if not Path(path).exists():
        return []
    with open(str(path)) as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        for k, v in list(r.items()):
            try:
                r[k] = float(v)
            except (TypeError, ValueError):
                pass
    return rows


def ok(r):
    return str(r.get("status", "")).startswith("ok")


def num(r, k):
    v = r.get(k, "")
    return v if isinstance(v, float) and not math.isnan(v) else None


def fmt(v, spec="%.2g"):
    if v is None or v == "":
        return "-"
    if isinstance(v, str):
        return v
    return spec % v


def ms(v):
    if v is None:
        return "-"
    if v >= 100e-3:
        return "%.0f" % (v * 1e3)
    if v >= 1e-3:
        return "%.3g" % (v * 1e3)
    return "%.2g" % (v * 1e3)


def pareto(points):
    """Indices of the points (x, y) not dominated (smaller x and smaller y are better)."""
    idx = sorted(range(len(points)), key=lambda i: (points[i][0], points[i][1]))
    front, best = [], float("inf")
    for i in idx:
        if points[i][1] < best:
            front.append(i)
            best = points[i][1]
    return front


# ------------------------------------------------------------------------------------ figures

def fig_overlap(matrix, soft, scenes, out):
    present = [s for s in ORDER if any(r["scene"] == s for r in matrix)]
    n = len(present)
    cols = 3
    rws = int(math.ceil(n / cols))
    fig, axes = plt.subplots(rws, cols, figsize=(12, 3.6 * rws), squeeze=False)
    for ax, s in zip(axes.flat, present):
        h = scenes[s]["h"]
        pts = []
        for r in matrix:
            if r["scene"] != s or not ok(r):
                continue
            x, y = num(r, "overlap_rel_max"), num(r, T("t_step"))
            if x is None or y is None or x <= 0:
                continue
            y = y / h
            pts.append((x, y))
            ax.loglog([x], [y], MARK[r["solver"]], color=COLOR[r["solver"]], ms=6,
                      mfc=COLOR[r["solver"]] if r["warmstart"] == "yes" else "none")
            if r["solver"] == DEFAULT and r["warmstart"] == "yes" and r["tol"] == 1e-4:
                ax.loglog([x], [y], "*", color="k", ms=13, mfc="none")
        if pts:
            fr = pareto(pts)
            ax.loglog([pts[i][0] for i in fr], [pts[i][1] for i in fr], "k--", lw=1, zorder=0)
        sp = [r for r in soft if r["scene"] == s and r.get("final", 1) == 1 and r["overlap_rel_max"] > 0]
        if sp:
            sp = sorted(sp, key=lambda r: r["overlap_rel_max"])
            full = [r for r in sp if not str(r.get("note", "")).startswith("window")]
            win = [r for r in sp if str(r.get("note", "")).startswith("window")]
            ax.loglog([r["overlap_rel_max"] for r in full], [r[T("t_phys")] for r in full], "x-",
                      color="tab:red", ms=8, lw=1)
            if win:
                ax.loglog([r["target_overlap"] for r in win], [r[T("t_phys")] for r in win], "D",
                          color="tab:red", mfc="none", ms=6)
        ax.set_title(TITLE.get(s, s) + " (h = %g s)" % h, fontsize=10)
        ax.set_xlabel("largest overlap / contact size (max over the window)", fontsize=8)
        ax.set_ylabel("wall s per simulated s", fontsize=8)
        ax.tick_params(labelsize=8)
        ax.grid(True, which="major", alpha=0.3)
    for ax in list(axes.flat)[n:]:
        ax.axis("off")
    handles = [plt.Line2D([], [], marker=MARK[s], color=COLOR[s], ls="none", label=s) for s in SOLVERS]
    handles += [plt.Line2D([], [], marker="o", color="gray", mfc="none", ls="none", label="warmstart no"),
                plt.Line2D([], [], marker="*", color="k", mfc="none", ms=12, ls="none", label="default (%s 1e-4 warm)" % DEFAULT),
                plt.Line2D([], [], color="k", ls="--", label="Pareto front (hardcontact)"),
                plt.Line2D([], [], color="tab:red", marker="x", label="soft spheres (gran/hertz/history, dt = t_c/50)"),
                plt.Line2D([], [], color="tab:red", marker="D", mfc="none", ls="none",
                           label="soft, timed on a window, at its target overlap")]
    fig.legend(handles=handles, loc="lower center", ncol=4, fontsize=8, frameon=False)
    fig.tight_layout(rect=(0, 0.06, 1, 1))
    fig.savefig(str(out), dpi=72)
    plt.close(fig)


def fig_velocity(matrix, scenes, out):
    present = [s for s in ORDER if any(r["scene"] == s and num(r, "vel_err") is not None for r in matrix)]
    n = len(present)
    if not n:
        return False
    cols = 3
    rws = int(math.ceil(n / cols))
    fig, axes = plt.subplots(rws, cols, figsize=(12, 3.5 * rws), squeeze=False)
    for ax, s in zip(axes.flat, present):
        pts = []
        for r in matrix:
            if r["scene"] != s or not ok(r):
                continue
            x, y = num(r, "vel_err"), num(r, T("probe_t"))
            if x is None or y is None:
                continue
            x = max(x, 1e-16)
            pts.append((x, y))
            ax.loglog([x], [y], MARK[r["solver"]], color=COLOR[r["solver"]], ms=6,
                      mfc=COLOR[r["solver"]] if r["warmstart"] == "yes" else "none")
            if r["solver"] == DEFAULT and r["warmstart"] == "yes" and r["tol"] == 1e-4:
                ax.loglog([x], [y], "*", color="k", ms=13, mfc="none")
        if pts:
            fr = pareto(pts)
            ax.loglog([pts[i][0] for i in fr], [pts[i][1] for i in fr], "k--", lw=1, zorder=0)
        ex = scenes[s].get(T("exact_seconds"))
        if isinstance(ex, float):
            ax.axhline(ex, color="tab:purple", ls=":", lw=1.2)
            ax.text(ax.get_xlim()[0] if pts else 1e-12, ex, " exact", color="tab:purple", fontsize=8, va="bottom")
        ax.set_title(TITLE.get(s, s), fontsize=10)
        ax.set_xlabel("max |v - v_exact| / max |u_free| after one step", fontsize=8)
        ax.set_ylabel("wall s of that step (fix)", fontsize=8)
        ax.tick_params(labelsize=8)
        ax.grid(True, which="major", alpha=0.3)
    for ax in list(axes.flat)[n:]:
        ax.axis("off")
    handles = [plt.Line2D([], [], marker=MARK[s], color=COLOR[s], ls="none", label=s) for s in SOLVERS]
    handles += [plt.Line2D([], [], marker="o", color="gray", mfc="none", ls="none", label="warmstart no"),
                plt.Line2D([], [], marker="*", color="k", mfc="none", ms=12, ls="none", label="default"),
                plt.Line2D([], [], color="tab:purple", ls=":", label="solver exact (same step)")]
    fig.legend(handles=handles, loc="lower center", ncol=6, fontsize=8, frameon=False)
    fig.tight_layout(rect=(0, 0.06, 1, 1))
    fig.savefig(str(out), dpi=72)
    plt.close(fig)
    return True


def is_2d_pile(scene):
    """pile10, pile30, pile100 (the height series); pile3d is not one of them."""
    return scene.startswith("pile") and scene[4:].isdigit()


def iteration_table(matrix, tol):
    """{(solver, warm): [(layers, mean iterations, hit fraction)]} for the 2d piles."""
    out = {}
    for r in matrix:
        if not is_2d_pile(r["scene"]) or r["tol"] != tol or not ok(r):
            continue
        L = float(r["scene"][4:])
        out.setdefault((r["solver"], r["warmstart"]), []).append(
            (L, r["iter_mean"], r["maxiter_hits"] / max(r["steps"], 1)))
    for k in out:
        out[k].sort()
    return out


def slope(points):
    pts = [(L, it) for L, it, hit in points if it > 0 and hit == 0]
    if len(pts) < 2:
        return None
    x = np.log([p[0] for p in pts])
    y = np.log([p[1] for p in pts])
    return float(np.polyfit(x, y, 1)[0])


def fig_iterations(matrix, tols, out):
    tols = [t for t in tols if iteration_table(matrix, t)]
    if not tols:
        return False
    fig, axes = plt.subplots(1, len(tols), figsize=(4 * len(tols), 3.4), squeeze=False)
    for ax, tol in zip(axes.flat, tols):
        tab = iteration_table(matrix, tol)
        for (solver, warm), pts in sorted(tab.items()):
            L = [p[0] for p in pts]
            it = [max(p[1], 0.3) for p in pts]
            ax.loglog(L, it, MARK[solver] + ("-" if warm == "no" else ":"), color=COLOR[solver],
                      mfc=COLOR[solver] if warm == "yes" else "none", label="%s, warm %s" % (solver, warm))
            for p in pts:
                if p[2] > 0:
                    ax.annotate("maxiter", (p[0], max(p[1], 0.3)), fontsize=6, color=COLOR[solver])
        Ls = np.array([10.0, 100.0])
        ax.loglog(Ls, 3 * Ls, color="gray", lw=0.8)
        ax.loglog(Ls, 3 * Ls ** 2, color="gray", lw=0.8, ls="--")
        ax.text(100, 300, "~L", fontsize=7, color="gray")
        ax.text(100, 3e4, "~L^2", fontsize=7, color="gray")
        ax.set_title("tol %g" % tol, fontsize=10)
        ax.set_xlabel("pile height (layers)", fontsize=8)
        ax.set_ylabel("mean solver iterations per step", fontsize=8)
        ax.tick_params(labelsize=8)
        ax.grid(True, alpha=0.3)
    axes.flat[0].legend(fontsize=6)
    fig.tight_layout()
    fig.savefig(str(out), dpi=72)
    plt.close(fig)
    return True


def fig_slide(slide, out):
    if not slide:
        return False
    fig, ax = plt.subplots(figsize=(4.5, 3.3))
    h = np.array([r["h"] for r in slide])
    ax.loglog(h, [r["gap_mean"] for r in slide], "o", label="measured (mean gap, active contact)")
    ax.loglog(h, [r["predicted"] for r in slide], "-", label="(h v_t)^2 / (2 d)")
    ax.set_xlabel("time step h (s)", fontsize=8)
    ax.set_ylabel("gap after the step (m)", fontsize=8)
    ax.set_title("sliding contact, v_t = %.2g m/s, d = %g m" % (slide[0]["vt"], slide[0]["d"]), fontsize=9)
    ax.legend(fontsize=7)
    ax.tick_params(labelsize=8)
    ax.grid(True, alpha=0.3)
    fig.tight_layout()
    fig.savefig(str(out), dpi=72)
    plt.close(fig)
    return True


# ------------------------------------------------------------------------------------ text

def find(matrix, scene, solver, warm, tol):
    for r in matrix:
        if r["scene"] == scene and r["solver"] == solver and r["warmstart"] == warm and r["tol"] == tol:
            return r
    return None


def scene_table(matrix, scene, tols):
    head = "| solver | warm | " + " | ".join("tol %g" % t for t in tols) + " |"
    lines = [head, "|" + "---|" * (len(tols) + 2)]
    for solver in SOLVERS:
        for warm in ("yes", "no"):
            cells = []
            for t in tols:
                r = find(matrix, scene, solver, warm, t)
                if r is None:
                    cells.append("")
                elif not ok(r):
                    cells.append("skipped" if str(r.get("status", "")).startswith("skipped") else "failed")
                else:
                    c = "%s ms, %s it, ov %s, dv %s" % (ms(num(r, T("t_step"))), fmt(num(r, "iter_mean"), "%.0f") if num(r, "iter_mean") and num(r, "iter_mean") >= 10 else fmt(num(r, "iter_mean"), "%.2g"),
                                                     fmt(num(r, "overlap_rel_max"), "%.1e"), fmt(num(r, "vel_err"), "%.0e"))
                    if r["maxiter_hits"] > 0:
                        c += ", **maxiter %d/%d**" % (r["maxiter_hits"], r["steps"])
                    if "cut" in str(r.get("status", "")):
                        c += ", (%d steps)" % r["steps"]
                    cells.append(c)
            lines.append("| %s | %s | %s |" % (solver, warm, " | ".join(cells)))
    return "\n".join(lines)


def best_at(matrix, scene, limit, key="overlap_rel_max"):
    """Fastest run (time per step) whose `key` is <= limit and which never hit maxiter."""
    cands = [r for r in matrix if r["scene"] == scene and ok(r) and num(r, key) is not None
             and r[key] <= limit and r["maxiter_hits"] == 0]
    return min(cands, key=lambda r: r[T("t_step")]) if cands else None


def label(r):
    return "%s tol %g warm %s" % (r["solver"], r["tol"], r["warmstart"])


def build_doc(res, figdir_rel, meta, matrix, soft, scenes, slide, figs):
    tols = sorted({r["tol"] for r in matrix}, reverse=True)
    present = [s for s in ORDER if s in scenes]
    L = []
    w = L.append
    w("# Accuracy versus time: what a tighter tolerance costs in fix hardcontact")
    w("")
    w("Generated by `bench/run.sh accuracy%s` (%s mode) on %s; do not edit by hand, edit "
      "`bench/accuracy/report.py` and rerun. Data: the CSV files of `bench/results/accuracy/<host>/`." % (
          " --quick" if meta.get("mode") == "quick" else "", meta.get("mode", "?"), meta.get("date", "?")))
    w("")
    machine_at = len(L)
    w("**Machine.** %s processors (`nproc`), %s; load average %s before the run and %s after; "
      "LAMMPS %s (Debian); hardcontact %s; the whole benchmark took %s min. Every LAMMPS run "
      "is serial (one process, `OMP_NUM_THREADS=1`) and runs alone: times are single-core "
      "times. Other users' processes disturb wall-clock times on this shared machine; the "
      "CPU time of every run is in the CSV files too (`cpu`) for comparison." % (
          meta.get("nproc", "?"), meta.get("cpu", "?"), meta.get("load_before", "?"),
          meta.get("load_after", "?"), meta.get("lammps", "?"), meta.get("git", "?"),
          fmt(meta.get("minutes"), "%.0f")))
    w("")
    for part in meta.get("parts", []):
        w("Run on its own (`ACCURACY_ONLY=%s bench/run.sh accuracy`): %s, on %s: %s, load %s "
          "before and %s after, hardcontact %s, %s min; its rows replaced those scenes' rows of "
          "the run above (ratios within a scene come from one run; times of different runs "
          "compare only where the processor is the same)." % (
              part["only"], part["only"], part.get("date", "?"), part.get("cpu", "?"),
              part.get("load_before", "?"), part.get("load_after", "?"), part.get("git", "?"),
              fmt(part.get("minutes"), "%.0f")))
        w("")
    # ---------------------------------------------------------------- summary (filled later)
    summary_at = len(L)
    w("")
    w("## What was measured")
    w("")
    w("Scenes (2d discs, and spheres in the 3D pile; `units si`, grains of about 1 mm, density "
      "2500 kg/m^3, g = 9.81 m/s^2 along -y; all data files written by "
      "`bench/accuracy/scenes.py` from fixed seeds):")
    w("")
    w("| scene | what | h (s) | start of every run | window (steps) | probe state | exact solve of the probe step |")
    w("|---|---|---|---|---|---|---|")
    for s in present:
        sc = scenes[s]
        nwin = int(sc.get("window", 0) or 0)
        if sc.get("settle_steps"):
            if s.startswith("pile"):
                start = "settled: %s; then %d lead-in steps" % (sc["settle_steps"], sc.get("lead", 0))
            else:
                start = "held %s steps, then %d lead-in steps" % (str(sc["settle_steps"]).split("+")[-1].strip(), sc.get("lead", 0))
            probe = "the start state"
        else:
            start = "the data file (t = 0)"
            probe = "step %d of an apgd 1e-8 run" % sc["probe_step"] if sc.get("probe_step") != "" else "-"
        ex = sc.get(T("exact_seconds"))
        exs = ("%.2g s, %d rows" % (ex, sc["exact_rows"])) if isinstance(ex, float) else str(ex)
        w("| %s | %s | %g | %s | %d | %s | %s |" % (TITLE.get(s, s), sc.get("desc", ""), sc["h"], start, nwin, probe, exs))
    w("")
    w("- Piles settle with h = 0.25 ms (list rebuilt every step), then are held with the "
      "benchmark's h = 1 ms at tol 1e-6; the cluster impact (h = 0.1 s, the paper's step) and "
      "the pour (h = 0.5 ms, impact speeds up to about 1 m/s) are measured over the whole "
      "event from t = 0.")
    w("- Every combination solver (cg, apgd, pgs, uzawa) x tol x warmstart (yes, no) runs the same "
      "window from the same start (a restart file, which carries the warm-start forces), "
      "default `maxiter` 10000. Tolerances are run from loose to tight; once a solver needs "
      "more than the time cap of one run (fix halt) or stops at maxiter in most steps, the "
      "tighter tolerances are skipped for that solver and warm-start setting (marked "
      "\"skipped\").")
    w("- **time per step**: loop time minus output time, divided by the steps of the window "
      "(`t_step`; the `Modify` line of the LAMMPS timing breakdown, i.e. the fix alone, is "
      "`t_modify` in the CSV: the fix is more than 90 % of the loop). Per unit of physical "
      "time: `t_step / h`. Neighbour lists: `neigh_modify delay 0 every 1 check yes` (and the "
      "rebuilds the fix forces); their cost is included.")
    if meta.get("timing") == "cpu":
        w("- **Timings in this document are CPU times**: the machine was loaded (load average %s "
          "at the start), so each LAMMPS process got only part of a core; its wall-clock times "
          "(`t_step`, `t_phys`, `probe_t` in the CSV) include the waiting. The tables and plots "
          "use them multiplied by the \"CPU use\" fraction LAMMPS prints for the loop "
          "(`t_step_cpu`, ...), which is what the run takes alone on a core, up to cache and "
          "memory-bandwidth sharing with the other processes." % meta.get("load_before", "?"))
    else:
        w("- Timings in this document are wall-clock times (the load average was below 1 at the "
          "start); CPU-time equivalents are in the CSV (`*_cpu`).")
    w("- **iterations**: mean of `f_ID[1]` over the window. **overlap**: max of `f_ID[7]` "
      "(largest overlap relative to the contact size) over the window.")
    w("- **velocity error dv**: from the probe state, one step with the combination and one "
      "step with `solver exact` (Lawson-Hanson active set, to machine precision): "
      "max_i |v_i - v_exact,i| / max_i |u_free,i| (u_free = v + h g: the velocity scale of the "
      "step; for a pile at rest it is g h). With warm start the first solve starts from the "
      "forces stored in the restart file (those of the previous step, solved by apgd at "
      "tol 1e-6 for piles and crystal, 1e-8 for the cluster and the pour).")
    w("- **spurious gap**: the gap D = |x_j - x_i| - r_i - r_j, after the step, of contacts "
      "that carry a force (local array, 4 times per window): `gap_pos_mean` (mean of "
      "max(0, D)/(r_i + r_j)) and `gap_mean` in matrix.csv; and a dedicated scene (below).")
    w("")
    # ---------------------------------------------------------------- per scene
    results_at = len(L)
    w("## Results per scene")
    w("")
    w("Each cell: time per step (ms), mean iterations per step, largest overlap / contact size "
      "over the window, velocity error of one step against exact. Bold: solves that stopped at "
      "`maxiter` (count / steps).")
    w("")
    for s in present:
        w("### %s" % TITLE.get(s, s))
        w("")
        w(scene_table(matrix, s, tols))
        w("")
    front_at = len(L)
    if figs.get("overlap"):
        w("![Pareto fronts, overlap](%s/accuracy_overlap.png)" % figdir_rel)
        w("")
        w("*Wall time per simulated second against the largest overlap reached, one panel per "
          "scene. Filled markers: warm start; hollow: cold start; star: the default; dashed: "
          "Pareto front of hardcontact; red: soft spheres at the stiffness that gives that "
          "overlap.*")
        w("")
    if figs.get("velocity"):
        w("![Pareto fronts, velocity](%s/accuracy_velocity.png)" % figdir_rel)
        w("")
        w("*Time of one step from the probe state against the velocity error of that step "
          "(dotted: the same step with `solver exact`).*")
        w("")
    front_end = len(L)
    # ---------------------------------------------------------------- soft spheres
    if soft:
        w("## Against soft spheres (gran/hertz/history)")
        w("")
        w("The same scenes with Debian's `lmp`: `pair_style gran/hertz/history kn NULL gn NULL "
          "0.0 1` (frictionless, like hardcontact), `fix wall/gran` with the same parameters, "
          "`fix nve/sphere`. The stiffness kn is chosen so that the largest overlap matches "
          "what hardcontact (%s, warm start) reached at the tolerance of the row: for the " % DEFAULT +
          "piles, from the contact forces of the settled hard pile (Hertz: delta = (F / (kn "
          "sqrt(R)))^(2/3)), corrected after a first run (up to 3 runs at the default "
          "tolerance's overlap, the correction then used for every level); for the pour, from "
          "the Hertz impact estimate at the largest speed of the hard pour, corrected once on "
          "a full pour. Normal damping: 0.5 of critical at that overlap. Time step dt = t_c / 50, "
          "t_c the contact time (piles: pi sqrt(m_eff / k'), k' the Hertz stiffness at the target "
          "overlap, m_eff of the two smallest grains; pour: Hertz impact duration at the largest "
          "speed). Soft piles start from the settled hard pile, settle with `fix viscous` "
          "(critical for the slowest mode), then the window is measured. The overlap of a "
          "soft run is the largest of: every pair and wall in dumped frames, and, every 10 "
          "steps, the pair carrying the largest force (compute pair/local + reduce).")
        w("")
        w("| scene | matched tol | hard overlap | soft overlap | kn | dt (s) | soft s/step | soft wall s per sim. s | hard wall s per sim. s | soft / hard | note |")
        w("|---|---|---|---|---|---|---|---|---|---|---|")
        for r in soft:
            hp = r.get(T("hard_t_phys"))
            ratio = (r[T("t_phys")] / hp) if isinstance(hp, float) and hp > 0 else None
            if r.get("final", 1) != 1:
                r = dict(r, note="calibration run (kn corrected after it); " + str(r.get("note", "")))
            w("| %s | %g | %s | %s | %.3g | %.2g | %s | %s | %s | %s | %s |" % (
                TITLE.get(r["scene"], r["scene"]), r["matched_tol"], fmt(r["target_overlap"], "%.2e"),
                fmt(r["overlap_rel_max"], "%.2e"), r["kn"], r["dt"], fmt(r[T("t_step")], "%.2e"),
                fmt(r[T("t_phys")], "%.3g"), fmt(hp, "%.3g"), fmt(ratio, "%.2g"), r.get("note", "")))
        w("")
    # ---------------------------------------------------------------- iterations vs height
    w("## Iterations against pile height")
    w("")
    piles = [s for s in present if is_2d_pile(s)]
    if len(piles) >= 2:
        w("Mean iterations per step in the held piles (h = 1 ms), and the exponent of a power "
          "law fitted through them (runs that stopped at maxiter are left out of the fit):")
        w("")
        w("| tol | solver | warm | " + " | ".join("%s" % p for p in piles) + " | exponent |")
        w("|---|---|---|" + "---|" * (len(piles) + 1))
        for tol in tols:
            tab = iteration_table(matrix, tol)
            for solver in SOLVERS:
                for warm in ("no", "yes"):
                    pts = tab.get((solver, warm), [])
                    if not pts:
                        continue
                    byL = {int(p[0]): p for p in pts}
                    cells = []
                    for p in piles:
                        q = byL.get(int(p[4:]))
                        cells.append("-" if q is None or q[1] != q[1] else ("%.0f%s" % (q[1], " (maxiter)" if q[2] > 0 else "")))
                    sl = slope(pts)
                    w("| %g | %s | %s | %s | %s |" % (tol, solver, warm, " | ".join(cells), fmt(sl, "%.2f")))
        w("")
        if figs.get("iterations"):
            w("![iterations against height](%s/accuracy_iterations.png)" % figdir_rel)
            w("")
    # ---------------------------------------------------------------- spurious gap
    w("## Spurious gap of sliding contacts")
    w("")
    if slide:
        w("Dedicated scene (`scenes.slide`): a disc (d = 1 mm) touching a fixed disc, moving "
          "tangentially at v_t = 0.1 m/s and pulled towards its centre by a constant "
          "acceleration of 100 m/s^2 (fix addforce), so the contact stays active every step; "
          "gap = centre distance - d after each step, averaged over the steps (apgd, tol "
          "1e-10). SCHEME.md predicts (h v_t)^2 / (2 d), d = distance of the centres.")
        w("")
        w("| h (s) | h v_t / d | measured gap (m) | gap / d | (h v_t)^2/(2d) (m) | measured / predicted |")
        w("|---|---|---|---|---|---|")
        for r in slide:
            w("| %g | %.2g | %.3e | %.2e | %.3e | %.3f |" % (r["h"], r["h"] * r["vt"] / r["d"], r["gap_mean"],
                                                          r["gap_rel"], r["predicted"], r["ratio"]))
        w("")
        if figs.get("slide"):
            w("![spurious gap](%s/accuracy_slide_gap.png)" % figdir_rel)
            w("")
    gl = []
    for s in present:
        r = find(matrix, s, "apgd", "yes", 1e-8) or find(matrix, s, "apgd", "yes", 1e-6)
        if r and num(r, "gap_pos_mean") is not None:
            gl.append("%s %.1e (%d contacts, at tol %g)" % (TITLE.get(s, s), r["gap_pos_mean"], r["gap_contacts"], r["tol"]))
    if gl:
        w("In the scenes, the mean positive gap of force-carrying pair contacts relative to the "
          "contact size (apgd, warm start, tight tolerance): " + "; ".join(gl) + ". Resting "
          "piles and the crystal do not slide, so only the tolerance shows there; in the cluster "
          "impact grains slide several diameters per step and the gap is of the order of the "
          "grain size.")
        w("")
    friction_section(res, w)
    # Findings (main() inserts them at machine_at) and the front first, the method and the
    # machine after the results
    front = L[front_at:front_end]
    if front:
        front = ["## The front: time against accuracy", ""] + front
    method = L[summary_at + 1:results_at]
    machine = L[machine_at:summary_at]
    L = (L[:machine_at] + front + L[results_at:front_at] + L[front_end:] + [""] + method
         + ["### Machine", ""] + machine)
    return L, machine_at


def friction_section(res, w):
    """Friction and rolling resistance on a 3D pile, from bench/studies/friction_tol/run.sh (a run of
    its own: friction_tol.csv beside the other CSV files, else the study's results), when present."""
    rows = read(res / "friction_tol.csv") or read(STUDY_FRICTION_TOL)
    if not rows:
        return
    base = {r["tol"]: r["loop_s"] for r in rows if r["case"] == "frictionless"}
    spheres, steps = rows[0]["spheres"], rows[0]["steps"]
    w("## Friction and rolling resistance: what accuracy costs on a 3D pile")
    w("")
    w("`bench/studies/friction_tol/run.sh` (a run of its own, not part of the matrix above): the settling "
      "3D pile of `bench/compare/in.pile3d` (%d polydisperse spheres, d 0.8-1.0, h = 0.02, %d steps, "
      "walled box), warm start: frictionless with apgd and with cg (`frictionless cg`, the default "
      "without friction), `friction 0.5` and `friction 0.5 rolling 0.1` with apgd (the default "
      "with friction), each tolerance against the same case at tol 1e-8. Time / frictionless: "
      "against the frictionless apgd run at that tolerance. Position error: distance of each "
      "sphere's final position to the reference's, in mean diameters (a settling pile amplifies "
      "any difference, so this is an upper bound on what the tolerance alone does). Loop times "
      "on one core, the 1-minute load at the end of each run in the last column."
      % (spheres, steps))
    w("")
    w("| case | tol | loop (s) | time / frictionless | iterations per step (max) | overlap / size at the end | position error RMS (max), d | load |")
    w("|---|---|---|---|---|---|---|---|")
    for r in rows:
        ratio = r["loop_s"] / base[r["tol"]] if base.get(r["tol"]) else float("nan")
        w("| %s | %g | %.2f | %.1f | %.1f (%d) | %.2g | %.2g (%.2g) | %s |" % (
            r["case"].replace("_", " "), r["tol"], r["loop_s"], ratio, r["iterations_per_step"],
            r["max_iterations"], r["end_overlap"], r["rms_error_d"], r["max_error_d"], r["load1"]))
    w("")
    sel = [r for r in rows if r["case"] == "frictionless_cg" and base.get(r["tol"])]
    if sel:
        w("- cg (the default without friction) takes %.2f-%.2f x apgd's time on the frictionless "
          "pile over tol %g..%g (%.0f-%.0f iterations per step)." % (
              min(r["loop_s"] / base[r["tol"]] for r in sel), max(r["loop_s"] / base[r["tol"]] for r in sel),
              max(r["tol"] for r in sel), min(r["tol"] for r in sel),
              min(r["iterations_per_step"] for r in sel), max(r["iterations_per_step"] for r in sel)))
    for case in ("friction_0.5", "friction_0.5_rolling_0.1"):
        sel = [r for r in rows if r["case"] == case and base.get(r["tol"])]
        if not sel:
            continue
        ratios = [r["loop_s"] / base[r["tol"]] for r in sel]
        w("- %s costs %.1f-%.1f x the frictionless time over tol %g..%g (%.0f-%.0f iterations "
          "per step); the position error falls with the tolerance as without friction." % (
              case.replace("_", " "), min(ratios), max(ratios), max(r["tol"] for r in sel),
              min(r["tol"] for r in sel), min(r["iterations_per_step"] for r in sel),
              max(r["iterations_per_step"] for r in sel)))
    w("")


def summary(matrix, soft, scenes, tols):
    """Data-driven findings, placed at the top of the document."""
    S = []
    w = S.append
    present = [s for s in ORDER if s in scenes]
    w("## Findings")
    w("")
    # fastest per target accuracy
    for limit in (1.01e-2, 1.01e-4, 1.01e-6):
        parts = []
        for s in present:
            b = best_at(matrix, s, limit)
            d = find(matrix, s, DEFAULT, "yes", 1e-4)
            if b is None:
                parts.append("%s: none" % s)
                continue
            parts.append("%s: %s (%s ms/step)" % (s, label(b), ms(b[T("t_step")])))
        w("- Fastest combination reaching an overlap <= %.0e (no maxiter stop): %s." % (limit / 1.01, "; ".join(parts)))
    # default vs best at its own accuracy
    parts = []
    for s in present:
        d = find(matrix, s, DEFAULT, "yes", 1e-4)
        if d is None or not ok(d):
            continue
        b = best_at(matrix, s, max(d["overlap_rel_max"], 1e-4) * 1.01)
        if b:
            parts.append("%s %.1fx" % (s, d[T("t_step")] / b[T("t_step")]))
    if parts:
        w("- The default (%s, tol 1e-4, warm start) against the fastest combination reaching " % DEFAULT +
          "the same overlap (time ratio, 1.0x = the default is the fastest): %s." % ", ".join(parts))
    # warm start effect
    parts = []
    for s in present:
        for t in (1e-4,):
            a, b = find(matrix, s, DEFAULT, "yes", t), find(matrix, s, DEFAULT, "no", t)
            if a and b and ok(a) and ok(b):
                parts.append("%s %.0f -> %.0f it (%.2gx time)" % (s, b["iter_mean"], a["iter_mean"], a[T("t_step")] / b[T("t_step")]))
    if parts:
        w("- Warm start, %s at tol 1e-4 (iterations per step cold -> warm): %s." % (DEFAULT, "; ".join(parts)))
    # uzawa
    parts = []
    for s in present:
        hits = [r for r in matrix if r["scene"] == s and r["solver"] == "uzawa" and ok(r) and r["maxiter_hits"] > 0]
        sk = [r for r in matrix if r["scene"] == s and r["solver"] == "uzawa" and str(r.get("status", "")).startswith("skipped")]
        if hits or sk:
            t = min([r["tol"] for r in hits] or [1])
            parts.append("%s (maxiter from tol %g)" % (s, t) if hits else "%s (skipped from tol %g)" % (s, max(r["tol"] for r in sk)))
    if parts:
        w("- uzawa stops at maxiter = 10000 (or was skipped after doing so) on: %s." % ", ".join(parts))
    # velocity error of one step at the default, piles
    parts = []
    for s in present:
        r = find(matrix, s, DEFAULT, "yes", 1e-4)
        c = find(matrix, s, DEFAULT, "no", 1e-4)
        if r and num(r, "vel_err") is not None and c and num(c, "vel_err") is not None:
            parts.append("%s %.1e (cold start %.1e)" % (s, r["vel_err"], c["vel_err"]))
    if parts:
        w("- Velocity error of one step at the default (%s, tol 1e-4, warm start; max |v - v_exact| " % DEFAULT +
          "/ max |u_free|): %s." % "; ".join(parts))
    # unconverged solves: overlap far beyond the residual
    bad = [r for r in matrix if ok(r) and r["maxiter_hits"] > 0 and num(r, "overlap_rel_max") is not None
           and num(r, "residual_max") is not None and r["overlap_rel_max"] > 100 * max(r["tol"], r["residual_max"])]
    if bad:
        b = max(bad, key=lambda r: r["overlap_rel_max"])
        w("- Runs whose solves stopped at maxiter can show overlaps far beyond the residual: %d runs, "
          "worst %s on %s (overlap %.2g of the contact size with the final residual at most %.2g; "
          "see the remarks)." % (len(bad), label(b), b["scene"], b["overlap_rel_max"], b["residual_max"]))
    # throughput
    rates = [r for r in matrix if ok(r) and num(r, "row_iter_rate") and r["iter_mean"] >= 50
             and (r["scene"].startswith("pile") or r["scene"] == "crystal")]
    if rates:
        for solver in SOLVERS:
            rs = [r for r in rates if r["solver"] == solver]
            if rs:
                b = max(rs, key=lambda r: r["row_iter_rate"])
                w("- Throughput of %s: up to %.2g contact-iterations per second of the fix "
                  "(%s, %d candidate contacts, tol %g; iterations x candidate contacts / `Modify` time, piles and crystal only, where nearly every candidate is active)." % (
                      solver, b["row_iter_rate"], b["scene"], b["rows_mean"], b["tol"]))
        fr = [r["t_modify"] / r["t_step"] for r in matrix if ok(r) and num(r, "t_modify") and num(r, "t_step")]
        if fr:
            w("- The fix (`Modify`) takes %.0f-%.0f %% of the loop time (median %.0f %%); the rest "
              "is mostly neighbour-list building." % (100 * min(fr), 100 * max(fr), 100 * float(np.median(fr))))
    # soft
    parts = []
    for r in soft:
        if r.get("final", 1) != 1:
            continue
        hp = r.get(T("hard_t_phys"))
        if isinstance(hp, float) and hp > 0:
            reached = 0.5 <= r["overlap_rel_max"] / r["target_overlap"] <= 2.0
            win = str(r.get("note", "")).startswith("window")
            parts.append("%s at %.0e: %.2gx%s" % (r["scene"], r["target_overlap"], r[T("t_phys")] / hp,
                                                  " (window)" if win else ("" if reached else " (soft overlap %.1e: not matched)" % r["overlap_rel_max"])))
    if parts:
        w("- Soft spheres at the same largest overlap need this many times the wall time of "
          "hardcontact (%s, warm start) per simulated second: %s (see the soft-sphere table "
          "for which runs are full runs and which are windows)." % (DEFAULT, "; ".join(parts)))
    w("")
    return S


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--results", required=True)
    ap.add_argument("--doc", required=True)
    ap.add_argument("--figures", required=True)
    args = ap.parse_args()
    res = Path(args.results)
    figdir = Path(args.figures)
    figdir.mkdir(parents=True, exist_ok=True)
    matrix = read(res / "matrix.csv")
    soft = read(res / "soft.csv")
    slide = read(res / "slide.csv")
    scenes = {r["scene"]: r for r in read(res / "scenes.csv")}
    if isinstance(scenes.get("pile3d", {}).get("layers"), float):
        TITLE["pile3d"] = "3D pile, %d layers" % scenes["pile3d"]["layers"]
    meta = json.loads((res / "machine.json").read_text()) if (res / "machine.json").exists() else {}
    meta["parts"] = [json.loads(f.read_text()) for f in sorted(res.glob("machine_*.json"))]
    try:
        load = float(str(meta.get("load_before", "0")).split()[0])
    except ValueError:
        load = 0.0
    if load >= 1.0 and matrix and "t_step_cpu" in matrix[0]:
        CPU[0] = "_cpu"
    meta["timing"] = "cpu" if CPU[0] else "wall"
    figs = {}
    if matrix:
        fig_overlap(matrix, soft, scenes, figdir / "accuracy_overlap.png")
        figs["overlap"] = True
        figs["velocity"] = fig_velocity(matrix, scenes, figdir / "accuracy_velocity.png")
        figs["iterations"] = fig_iterations(matrix, [1e-2, 1e-4, 1e-6], figdir / "accuracy_iterations.png")
    figs["slide"] = fig_slide(slide, figdir / "accuracy_slide_gap.png")
    doc = Path(args.doc)
    rel = Path(*([".."] * 0)) / figdir.resolve().relative_to(doc.resolve().parent)
    L, at = build_doc(res, str(rel), meta, matrix, soft, scenes, slide, figs)
    tols = sorted({r["tol"] for r in matrix}, reverse=True)
    S = summary(matrix, soft, scenes, tols)
    notes = Path(__file__).with_name("discussion.md")
    extra = notes.read_text().splitlines() if notes.exists() else []
    L = L[:at] + S + extra + [""] + L[at:]
    doc.write_text("\n".join(L).rstrip() + "\n")
    print("wrote", doc, "and figures in", figdir)


if __name__ == "__main__":
    main()
