#!/usr/bin/env python3
"""Accuracy versus time of fix hardcontact: drives every LAMMPS run of the benchmark and
writes the CSV files of bench/results/. Called by bench/run.sh accuracy (see there)."""

import argparse
import csv
import math
import os
import resource
import shutil
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
sys.path.insert(0, str(HERE.parent.parent / "python"))
import decks  # noqa: E402
import hctools as hc  # noqa: E402
import scenes  # noqa: E402

SOLVERS = ["cg", "apgd", "pgs", "uzawa"]
# the default family (the fix's default without friction): the soft twins match its overlaps
DEFAULT = "cg"
WARMS = ["yes", "no"]


def config(quick):
    """Scenes and run lengths. Windows are in steps of the scene's h; caps in seconds of
    wall time per run (fix halt)."""
    if quick:
        return dict(
            tols=[1e-2, 1e-4, 1e-6],
            scenes=[
                dict(make=lambda: scenes.pile(10), settle=(300, 100, 10), lead=5, window=20),
                dict(make=lambda: scenes.pile(30), settle=(400, 150, 10), lead=5, window=20),
                dict(make=lambda: scenes.pile3d(4, 6), settle=(300, 100, 10), lead=5, window=20),
                dict(make=lambda: scenes.crystal(16, 16), settle=(0, 0, 10), lead=5, window=20),
                dict(make=lambda: scenes.cluster(0.25), probe=3, lead=0, window=12),
                dict(make=lambda: scenes.pour(150, width_d=12), probe=110, lead=0, window=200),
            ],
            cap=6.0, exact_cap=120.0, soft_levels=[1e-2, 1e-4], soft_cap=30.0,
            soft_settle_per_layer=40, soft_window=1000, pour_full_max_steps=4e5,
            pour_window_steps=20000, slide_h=[3e-4, 1e-3, 3e-3], slide_steps=100)
    return dict(
        tols=[1e-2, 1e-4, 1e-6, 1e-8, 1e-10],
        scenes=[
            dict(make=lambda: scenes.pile(10), settle=(460, 150, 20), lead=10, window=100),
            dict(make=lambda: scenes.pile(30), settle=(580, 200, 20), lead=10, window=80),
            dict(make=lambda: scenes.pile(100), settle=(1000, 300, 20), lead=10, window=40),
            dict(make=lambda: scenes.pile3d(10), settle=(700, 300, 20), lead=10, window=60),
            dict(make=lambda: scenes.crystal(30, 30), settle=(0, 0, 20), lead=10, window=60),
            dict(make=lambda: scenes.cluster(0.4), probe=3, lead=0, window=12),
            dict(make=lambda: scenes.pour(400), probe=170, lead=0, window=300),
        ],
        cap=40.0, exact_cap=300.0, soft_levels=[1e-2, 1e-4, 1e-6, 1e-8], soft_cap=120.0,
        soft_settle_per_layer=90, soft_window=2500, pour_full_max_steps=4e5,
        pour_window_steps=60000, slide_h=[1e-4, 3e-4, 1e-3, 3e-3, 1e-2], slide_steps=200)


def load_factor():
    """How much slower than alone a serial run is now: 1-minute load / processors, >= 1,
    at most 3 (the time caps of the runs are stretched by it)."""
    try:
        load = float(open("/proc/loadavg").read().split()[0])
    except (OSError, ValueError):
        return 1.0
    return min(max(load / (os.cpu_count() or 1), 1.0), 3.0)


class Runner:
    def __init__(self, args):
        self.args = args
        self.quick = args.quick
        self.cfg = config(args.quick)
        self.work = Path(args.work).resolve()
        self.results = Path(args.results)
        self.results.mkdir(parents=True, exist_ok=True)
        self.lmp_hard = args.lmp
        self.lmp_soft = args.soft_lmp
        only = "_".join(filter(None, args.only.split(",")))
        self.log = open(str(self.results / ("run_log_%s.txt" % only if only else "run_log.txt")), "w")

    def say(self, msg):
        line = "[%s] %s" % (time.strftime("%H:%M:%S"), msg)
        print(line, flush=True)
        self.log.write(line + "\n")
        self.log.flush()

    def lammps(self, exe, deck, workdir, timeout=1800):
        """Run a deck; returns (log text, wall seconds, cpu seconds of the child)."""
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        r = hc.run_deck(exe, deck, workdir=workdir, timeout=timeout, args=["-screen", "none"])
        text, secs = r.log, r.seconds
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
        return text, secs, cpu


# --------------------------------------------------------------------------- analysis helpers

def window_stats(text):
    """Statistics of the last thermo block (the measured window) and its timing."""
    blocks = hc.parse_thermo(text)
    tims = hc.loop_times(text)
    th, tm = blocks[-1], tims[-1]
    rows = slice(1, None)    # row 0 is the setup of the run (no solve)
    it = th["f_hc[1]"][rows]
    n = len(it)
    hits = th["f_hc[6]"][-1] - th["f_hc[6]"][0]
    steps = tm["steps"]
    work = tm["loop"] - tm.get("Output", 0.0)
    cpu_frac = tm.get("cpu_frac", float("nan"))
    return dict(steps=steps, cpu_frac=cpu_frac, t_step_cpu=work / max(steps, 1) * min(cpu_frac, 1.0),
                iter_mean=float(it.mean()) if n else float("nan"),
                iter_max=int(it.max()) if n else 0,
                overlap_rel_max=float(th["f_hc[7]"][rows].max()) if n else float("nan"),
                overlap_abs_max=float(th["f_hc[2]"][rows].max()) if n else float("nan"),
                residual_max=float(th["f_hc[5]"][rows].max()) if n else float("nan"),
                rows_mean=float(th["f_hc[3]"][rows].mean()) if n else float("nan"),
                active_mean=float(th["f_hc[4]"][rows].mean()) if n else float("nan"),
                maxiter_hits=int(hits), vmax_max=float(th["c_vmax"][rows].max()) if n else 0.0,
                t_modify=tm.get("Modify", float("nan")) / max(steps, 1),
                t_step=work / max(steps, 1), t_neigh=tm.get("Neigh", 0.0) / max(steps, 1),
                row_iter_rate=float((th["f_hc[1]"][rows] * th["f_hc[3]"][rows]).sum()) / max(tm.get("Modify", 1e-30), 1e-30))


def radii_of(frame):
    return frame["radius"]


def coords(frame):
    """Positions of a dumped frame: x, y and, when dumped, z (0 in the 2d scenes)."""
    cols = [frame["x"], frame["y"]] + ([frame["z"]] if "z" in frame else [])
    return np.column_stack(cols)


def velocities(frame):
    cols = [frame["vx"], frame["vy"]] + ([frame["vz"]] if "vz" in frame else [])
    return np.column_stack(cols)


def pair_gaps(frame_atoms, frame_local):
    """Relative gaps D/(r_i + r_j) of the active pair contacts (force > 0) of one step."""
    ids = frame_atoms["id"].astype(int)
    index = np.full(ids.max() + 1, -1)
    index[ids] = np.arange(len(ids))
    x, r = coords(frame_atoms), frame_atoms["radius"]
    i = frame_local["f_hc[1]"].astype(int)
    j = frame_local["f_hc[2]"].astype(int)
    f = frame_local["f_hc[3]"]
    keep = (j > 0) & (f > 0)
    a, b = index[i[keep]], index[j[keep]]
    d = np.linalg.norm(x[b] - x[a], axis=1)
    size = r[a] + r[b]
    return (d - size) / size


def all_overlaps(frame, wall_list):
    """Largest relative overlap over all pairs (D/(r_i+r_j)) and walls (D/r_i) of a frame."""
    from scipy.spatial import cKDTree
    x = coords(frame)
    r = frame["radius"]
    worst = 0.0
    pairs = cKDTree(x).query_pairs(2.0 * r.max(), output_type="ndarray")
    if len(pairs):
        a, b = pairs[:, 0], pairs[:, 1]
        s = r[a] + r[b]
        ov = (s - np.linalg.norm(x[b] - x[a], axis=1)) / s
        worst = max(worst, float(ov.max()))
    for dim, coord, side in wall_list:
        gap = side * (x[:, dim] - coord) - r
        worst = max(worst, float((-gap / r).max()))
    return worst


# --------------------------------------------------------------------------- the benchmark

def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--lmp", required=True)
    ap.add_argument("--soft-lmp", default="/usr/bin/lmp")
    ap.add_argument("--work", required=True)
    ap.add_argument("--results", required=True)
    ap.add_argument("--only", default="", help="comma-separated scene names (debugging)")
    ap.add_argument("--skip-matrix", action="store_true")
    ap.add_argument("--skip-soft", action="store_true")
    args = ap.parse_args()
    R = Runner(args)
    cfg = R.cfg
    R.work.mkdir(parents=True, exist_ok=True)
    only = set(filter(None, args.only.split(",")))

    # --only: the rows of the other scenes stay in the CSV files (a scene rerun or added on its
    # own; the report names the runs, machine_<scenes>.json)
    kept = {}
    for f in ("matrix.csv", "scenes.csv", "soft.csv"):
        kept[f] = []
        if only and (R.results / f).exists():
            with open(str(R.results / f)) as fh:
                kept[f] = [r for r in csv.DictReader(fh) if r.get("scene") not in only]
    matrix_rows, probe_rows, soft_rows, scene_rows = [], [], [], []
    t_start = time.time()
    for spec in cfg["scenes"]:
        sc = spec["make"]()
        name = sc["name"]
        if only and name not in only:
            continue
        wd = R.work / name
        if wd.exists():
            shutil.rmtree(str(wd))
        wd.mkdir(parents=True)
        scenes.write_data(wd / "scene.data", sc)
        n = len(sc["diameter"])
        lf = load_factor()
        cap = cfg["cap"] * lf
        R.say("scene %s: %d discs, h = %g s (time cap per run %.0f s, load factor %.2f)" % (name, n, sc["h"], cap, lf))
        info = dict(scene=name, dim=sc.get("dim", 2), load_factor=lf, discs=n, h=sc["h"], layers=sc["layers"] or "", gravity=sc["gravity"],
                    window=spec["window"], lead=spec["lead"], desc=sc.get("desc", ""))

        # ---- start state (window start) and probe state (velocity error against exact)
        if "settle" in spec:
            n_fall, n_relax, n_hold = spec["settle"]
            visc = 100.0 * float(scenes.mass(sc).mean())    # drag rate 100 /s: 10 steps of 1 ms
            deck = decks.settle(sc, "../scene.data", n_fall, 2.5e-4, 1.0e-3, 1e-3, n_relax, 1e-4,
                                visc, n_hold, 1e-6)
            text, secs, cpu = R.lammps(R.lmp_hard, deck, wd / "settle")
            R.say("  settled in %.1f s (cpu %.1f)" % (secs, cpu))
            start = ("restart", str(wd / "settle" / "start.restart"))
            probe_restart = str(wd / "settle" / "start.restart")
            check = "yes"
            info.update(settle_steps="%d x 0.25 ms (tol 1e-3) + %d x %g ms with drag (tol 1e-4) + %d x %g ms (tol 1e-6)" % (
                n_fall, n_relax, sc["h"] * 1e3, n_hold, sc["h"] * 1e3))
        else:
            start = ("data", str(wd / "scene.data"))
            check = "yes"
            deck = decks.hard(sc, start, "apgd", 1e-8, "yes", 0, spec["window"], 3600, check=check,
                              write_restart_at=spec["probe"], write_data_at=True,
                              gapdump_every=0)
            text, secs, cpu = R.lammps(R.lmp_hard, deck, wd / "reference")
            probe_restart = str(wd / "reference" / "probe.restart")
            R.say("  reference run (apgd 1e-8) in %.1f s, probe state at step %d" % (secs, spec["probe"]))
            ref = hc.parse_thermo(text)
            info.update(probe_step=spec["probe"],
                        vmax_ref=float(max(b["c_vmax"].max() for b in ref)))
        info["check"] = check

        # ---- exact reference of the probe step
        exact_v = None
        try:
            deck = decks.probe(sc, probe_restart, "exact", 1e-10, "no", check=check, maxiter=1000000)
            text, secs, cpu = R.lammps(R.lmp_hard, deck, wd / "exact", timeout=cfg["exact_cap"])
            fr = hc.read_dump(wd / "exact" / "probe.dump")
            v0 = velocities(fr[0].columns)
            exact_v = velocities(fr[-1].columns)
            m = scenes.mass(sc)  # noqa: F841 (documentation: gravity is the only force)
            ufree = v0.copy()
            ufree[:, 1] -= sc["gravity"] * sc["h"]
            vscale = float(np.linalg.norm(ufree, axis=1).max())
            tm = hc.loop_times(text)[-1]
            th = hc.parse_thermo(text)[-1]
            info.update(exact_seconds=tm["loop"], exact_seconds_cpu=tm["loop"] * min(tm.get("cpu_frac", 1.0), 1.0), exact_iterations=int(th["f_hc[1]"][-1]),
                        exact_rows=int(th["f_hc[3]"][-1]), exact_residual=float(th["f_hc[5]"][-1]),
                        vscale=vscale)
            R.say("  exact: %.2f s, %d rows, residual %.2g" % (tm["loop"], th["f_hc[3]"][-1], th["f_hc[5]"][-1]))
        except Exception as e:  # noqa: BLE001
            R.say("  exact FAILED or too slow: %s" % str(e).splitlines()[0])
            info.update(exact_seconds="failed")

        # ---- the matrix
        if not args.skip_matrix:
            for solver in SOLVERS:
                for warm in WARMS:
                    stop_reason = ""
                    for tol in cfg["tols"]:
                        row = dict(scene=name, solver=solver, tol=tol, warmstart=warm)
                        if stop_reason:
                            row.update(status="skipped: " + stop_reason)
                            matrix_rows.append(row)
                            continue
                        tag = "%s_%s_%g" % (solver, warm, tol)
                        gap_every = max(spec["window"] // 4, 1)
                        deck = decks.hard(sc, start, solver, tol, warm, spec["lead"], spec["window"],
                                          cap, check=check, gapdump_every=gap_every,
                                          lead_cap=cap / 4)
                        try:
                            text, secs, cpu = R.lammps(R.lmp_hard, deck, wd / tag,
                                                       timeout=3 * cap + 120)
                        except Exception as e:  # noqa: BLE001
                            row.update(status="failed: " + str(e).splitlines()[0][:200])
                            R.say("  %s FAILED: %s" % (tag, str(e)[:300]))
                            matrix_rows.append(row)
                            stop_reason = "a looser tolerance failed"
                            continue
                        st = window_stats(text)
                        row.update(st)
                        row.update(status="ok", wall=round(secs, 2), cpu=round(cpu, 2))
                        row["t_phys"] = st["t_step"] / sc["h"]
                        row["t_phys_cpu"] = st["t_step_cpu"] / sc["h"]
                        # spurious gaps of the active contacts (dumped 4 times in the window)
                        try:
                            fa = hc.read_dump(wd / tag / "gap.dump")
                            fl = {fr.timestep: fr.columns for fr in hc.read_dump_local(wd / tag / "gap.local")}
                            gaps = np.concatenate([pair_gaps(f, fl[s]) for s, f, _ in fa if s in fl and s > fa[0].timestep] or [np.zeros(0)])
                            if len(gaps):
                                row.update(gap_pos_mean=float(np.maximum(gaps, 0).mean()),
                                           gap_mean=float(gaps.mean()), gap_max=float(gaps.max()),
                                           gap_contacts=len(gaps))
                        except FileNotFoundError:
                            pass    # window cut before the first dump
                        except Exception as e:  # noqa: BLE001
                            R.say("  gap analysis failed: %s" % e)
                        if st["steps"] < spec["window"]:
                            row["status"] = "ok (window cut to %d steps by the %.0f s cap)" % (st["steps"], cap)
                            stop_reason = "%s at tol %g took longer than the %.0f s cap per run" % (solver, tol, cap)
                        elif st["maxiter_hits"] >= 0.5 * st["steps"]:
                            stop_reason = "%s at tol %g already stopped at maxiter in most steps" % (solver, tol)
                        # velocity error of one step from the probe state
                        if exact_v is not None:
                            try:
                                deck = decks.probe(sc, probe_restart, solver, tol, warm, check=check)
                                ptext, psecs, pcpu = R.lammps(R.lmp_hard, deck, wd / tag / "probe",
                                                              timeout=2 * cap + 120)
                                fr = hc.read_dump(wd / tag / "probe" / "probe.dump")
                                v = velocities(fr[-1].columns)
                                err = np.linalg.norm(v - exact_v, axis=1)
                                pth = hc.parse_thermo(ptext)[-1]
                                ptm = hc.loop_times(ptext)[-1]
                                row.update(vel_err=float(err.max()) / info["vscale"],
                                           vel_err_rms=float(np.sqrt((err ** 2).mean())) / info["vscale"],
                                           probe_iter=int(pth["f_hc[1]"][-1]),
                                           probe_t=ptm.get("Modify", float("nan")),
                                           probe_t_cpu=ptm.get("Modify", float("nan")) * min(ptm.get("cpu_frac", float("nan")), 1.0))
                            except Exception as e:  # noqa: BLE001
                                R.say("  probe %s failed: %s" % (tag, str(e)[:200]))
                        matrix_rows.append(row)
                        R.say("  %-22s %-8s steps %3d  it %8.1f  ov %.2e  verr %.2e  %.4f s/step  hits %d" % (
                            tag, row["status"][:8], st["steps"], st["iter_mean"], st["overlap_rel_max"],
                            row.get("vel_err", float("nan")), st["t_step"], st["maxiter_hits"]))
                write_csv(R.results / "matrix.csv", kept["matrix.csv"] + matrix_rows)
        scene_rows.append(info)
        write_csv(R.results / "scenes.csv", kept["scenes.csv"] + scene_rows)

        # ---- soft-sphere twin
        if not args.skip_soft and name.startswith("pile"):
            soft_rows += soft_pile(R, sc, spec, wd, matrix_rows)
            write_csv(R.results / "soft.csv", kept["soft.csv"] + soft_rows)
        if not args.skip_soft and name == "pour":
            soft_rows += soft_pour(R, sc, spec, wd, matrix_rows, info)
            write_csv(R.results / "soft.csv", kept["soft.csv"] + soft_rows)
        R.say("  elapsed %.0f s" % (time.time() - t_start))

    if not only or "slide" in only:
        write_csv(R.results / "slide.csv", slide_runs(R))
    R.say("done in %.0f s" % (time.time() - t_start))


def hard_overlap_at(matrix_rows, scene, tol):
    """The achieved largest relative overlap of the default family (DEFAULT, warm start) at tol."""
    for r in matrix_rows:
        if r["scene"] == scene and r["solver"] == DEFAULT and r["warmstart"] == "yes" and r["tol"] == tol \
                and r.get("status", "").startswith("ok"):
            ov = r.get("overlap_rel_max")
            if isinstance(ov, float) and math.isfinite(ov) and ov > 0:
                return ov, r
    return None, None


def soft_overlap(wd, sc, ids_radius):
    """Largest relative overlap of a soft run: all pairs and walls of the dumped frames, and
    the pair carrying the largest force at every tracked step (track.txt)."""
    worst = 0.0
    frames = hc.read_dump(wd / "soft.dump")
    for fr in frames[1:]:
        worst = max(worst, all_overlaps(fr.columns, sc["wall_list"]))
    tr = np.loadtxt(str(wd / "track.txt"), comments="#", ndmin=2)
    if len(tr):
        ok = tr[:, 1] > 0    # the reduction of no pair at all gives -1e20
        if ok.any():
            dist, i, j = tr[ok, 2], tr[ok, 3].astype(int), tr[ok, 4].astype(int)
            s = ids_radius[i] + ids_radius[j]
            worst = max(worst, float(((s - dist) / s).max()))
        worst = max(worst, float(-tr[:, 5:].min()))    # the walls' smallest gaps
    return worst


def hertz_tc(kn, m_eff, r_eff, delta):
    """Contact time of the Hertz contact linearised at overlap delta: pi sqrt(m/k'),
    k' = dF/ddelta = 1.5 kn sqrt(R delta)."""
    k = 1.5 * kn * math.sqrt(r_eff * delta)
    return math.pi * math.sqrt(m_eff / k)


def soft_pile(R, sc, spec, wd, matrix_rows):
    """Soft twin of a settled pile: kn from the hard contact forces (Hertz: F = kn sqrt(R)
    delta^1.5), one correction at the default tolerance's overlap, then one run per level."""
    cfg = R.cfg
    rows = []
    name = sc["name"]
    L = sc["layers"]
    loc = hc.read_dump_local(wd / "settle" / "start.local")[-1].columns
    data = (wd / "settle" / "start.data")
    r = 0.5 * sc["diameter"]
    ids_radius = np.zeros(len(r) + 1)
    ids_radius[1:] = r
    i = loc["f_hc[1]"].astype(int)
    j = loc["f_hc[2]"].astype(int)
    F = loc["f_hc[3]"]
    ri = ids_radius[i]
    rj = ids_radius[np.maximum(j, 0)]
    pair = j > 0
    reff = np.where(pair, ri * rj / np.where(pair, ri + rj, 1.0), ri)
    size = np.where(pair, ri + rj, ri)
    m = scenes.mass(sc)
    m_eff = 0.5 * m.min()
    r_eff = 0.25 * sc["diameter"].min()
    ratio = 1.0    # correction of the Hertz estimate after the calibration run
    levels = cfg["soft_levels"]
    calib = 1e-4 if 1e-4 in levels else levels[0]
    order = [calib] + [l for l in levels if l != calib]
    for k, tol in enumerate(order):
        target, hrow = hard_overlap_at(matrix_rows, name, tol)
        if not target:
            target = tol
        tries = 3 if k == 0 else 1
        for t in range(tries):
            kn = ratio * float(np.max(F / (np.sqrt(reff) * (target * size) ** 1.5)))
            delta = target * sc["diameter"].mean()
            tc = hertz_tc(kn, m_eff, r_eff, delta)
            dt = tc / 50.0
            zeta = 0.5
            gn = 2 * zeta * math.sqrt(kn / m_eff) * (r_eff * delta) ** -0.25
            omega_m = math.sqrt(1.5 * kn * math.sqrt(r_eff * delta) / m.mean())
            omega_1 = 0.5 * math.pi * omega_m / L
            visc = 2.0 * omega_1 * m.mean()
            n_settle = max(int(cfg["soft_settle_per_layer"] * L), 1000)
            n_window = cfg["soft_window"]
            run_dir = wd / ("soft_%g_%d" % (tol, t))
            deck = decks.soft(sc, "../settle/start.data", kn, gn, dt, n_settle, visc, n_window,
                              10, max(n_window // 5, 1), cfg["soft_cap"])
            text, secs, cpu = R.lammps(R.lmp_soft, deck, run_dir)
            tm = hc.loop_times(text)[-1]
            meas = soft_overlap(run_dir, sc, ids_radius)
            steps = tm["steps"]
            t_step = (tm["loop"] - tm.get("Output", 0.0)) / max(steps, 1)
            cf = min(tm.get("cpu_frac", float("nan")), 1.0)
            row = dict(cpu_frac=cf, t_step_cpu=t_step * cf, t_phys_cpu=t_step * cf / dt, scene=name, matched_tol=tol, target_overlap=target, kn=kn, gamma_n=gn,
                       t_c=tc, dt=dt, steps=steps, overlap_rel_max=meas, t_step=t_step,
                       t_phys=t_step / dt, t_pair=tm.get("Pair", 0.0) / max(steps, 1), wall=round(secs, 2),
                       cpu=round(cpu, 2), note="settled %d steps with fix viscous, window %d steps%s" % (
                           n_settle, n_window, "" if hrow else "; no hard run at this tol: target = tol"),
                       hard_t_phys=hrow["t_phys"] if hrow else "", hard_t_step=hrow["t_step"] if hrow else "",
                       hard_t_phys_cpu=hrow["t_phys_cpu"] if hrow else "")
            if steps < n_window:
                row["note"] += "; window cut to %d steps by the cap" % steps
            for old in rows:
                if old["matched_tol"] == tol:
                    old["final"] = 0
            row["final"] = 1
            rows.append(row)
            R.say("  soft %s tol %g try %d: kn %.3g dt %.3g -> overlap %.3g (target %.3g), %.2e s/step, %.3g s per s" % (
                name, tol, t, kn, dt, meas, target, t_step, t_step / dt))
            if meas > 0:
                ratio *= (meas / target) ** 1.5    # static Hertz: delta ~ kn^(-2/3)
            if k == 0 and abs(meas / target - 1) < 0.15:
                break
    return rows


def soft_pour(R, sc, spec, wd, matrix_rows, info):
    """Soft twin of the pour: kn from the Hertz impact estimate at the largest speed of the
    hard pour (delta = (5 m v^2 / (4 kn sqrt(R)))^(2/5)), corrected once on a full pour at
    the loosest level; tighter levels run a window of the pour from the probe state (mid
    pour) when a full pour would take too long."""
    cfg = R.cfg
    rows = []
    name = sc["name"]
    r = 0.5 * sc["diameter"]
    ids_radius = np.zeros(len(r) + 1)
    ids_radius[1:] = r
    m = scenes.mass(sc)
    m_eff = 0.5 * m.mean()
    r_eff = 0.25 * sc["diameter"].mean()
    v = info.get("vmax_ref", 1.0)
    T = spec["window"] * sc["h"]
    ratio = 1.0
    t_step_full = None
    for tol in cfg["soft_levels"]:
        target, hrow = hard_overlap_at(matrix_rows, name, tol)
        if not target:
            target = tol
        delta = target * sc["diameter"].mean()
        for t in range(2):
            kn = ratio * 5 * m_eff * v * v / (4 * math.sqrt(r_eff) * delta ** 2.5)
            # Hertz impact duration 2.87 (m^2 / (R E*^2 v))^(1/5), E* = 3/4 kn
            tc = 2.87 * (m_eff ** 2 / (r_eff * (0.75 * kn) ** 2 * v)) ** 0.2
            dt = tc / 50.0
            gn = 2 * 0.5 * math.sqrt(kn / m_eff) * (r_eff * delta) ** -0.25
            nfull = int(math.ceil(T / dt))
            full = nfull <= cfg["pour_full_max_steps"]
            if full:
                nsteps, data, note = nfull, "../scene.data", "full pour (%.3g s)" % T
            else:
                nsteps = cfg["pour_window_steps"]
                data = "../reference/probe.data"
                note = "window of %d steps (%.3g s) from the mid-pour state (step %d of the hard pour); kn from the Hertz law corrected at the loosest level" % (
                    nsteps, nsteps * dt, spec["probe"])
            run_dir = wd / ("soft_%g_%d" % (tol, t))
            deck = decks.soft(sc, data, kn, gn, dt, 0, 0.0, nsteps, 10, max(nsteps // 50, 1),
                              cfg["soft_cap"] * (3 if full else 1), zero_velocity=False)
            text, secs, cpu = R.lammps(R.lmp_soft, deck, run_dir)
            tm = hc.loop_times(text)[-1]
            steps = tm["steps"]
            meas = soft_overlap(run_dir, sc, ids_radius)
            t_step = (tm["loop"] - tm.get("Output", 0.0)) / max(steps, 1)
            cf = min(tm.get("cpu_frac", float("nan")), 1.0)
            if steps < nsteps:
                note += "; cut to %d steps by the cap" % steps
            for old in rows:
                if old["matched_tol"] == tol:
                    old["final"] = 0
            if not hrow:
                note += "; no hard run at this tol: target = tol"
            rows.append(dict(cpu_frac=cf, t_step_cpu=t_step * cf, t_phys_cpu=t_step * cf / dt,
                             scene=name, matched_tol=tol, target_overlap=target, kn=kn, gamma_n=gn,
                             t_c=tc, dt=dt, steps=steps, overlap_rel_max=meas, t_step=t_step,
                             t_phys=t_step / dt, t_pair=tm.get("Pair", 0.0) / max(steps, 1),
                             wall=round(secs, 2), cpu=round(cpu, 2), note=note,
                             hard_t_phys=hrow["t_phys"] if hrow else "",
                             hard_t_step=hrow["t_step"] if hrow else "",
                             hard_t_phys_cpu=hrow["t_phys_cpu"] if hrow else "", final=1))
            R.say("  soft pour tol %g try %d (%s): kn %.3g dt %.3g -> overlap %.3g (target %.3g), %.2e s/step, %.3g s per s" % (
                tol, t, "full" if full else "window", kn, dt, meas, target, t_step, t_step / dt))
            if not full or steps < nsteps:
                break
            if meas > 0:
                ratio *= (meas / target) ** 2.5    # impacts: delta ~ kn^(-2/5)
            if abs(meas / target - 1) < 0.15:
                break
    return rows


def slide_runs(R):
    rows = []
    for h in R.cfg["slide_h"]:
        sc = scenes.slide(h)
        wd = R.work / "slide" / ("h%g" % h)
        wd.mkdir(parents=True, exist_ok=True)
        scenes.write_data(wd / "slide.data", sc)
        text, secs, cpu = R.lammps(R.lmp_hard, decks.slide(sc, nsteps=R.cfg["slide_steps"]), wd)
        th = hc.parse_thermo(text)[-1]
        act = th["f_hc[4]"][1:] > 0
        gap = th["v_gap"][1:][act]
        vt = th["v_vt"][1:][act]
        d = float(sc["diameter"][0])
        pred = (h * vt) ** 2 / (2 * d)
        rows.append(dict(h=h, vt=float(vt.mean()), d=d, steps_active=int(act.sum()),
                         gap_mean=float(gap.mean()), gap_rel=float(gap.mean()) / d,
                         predicted=float(pred.mean()), ratio=float(gap.mean() / pred.mean()),
                         exact_chord=float((np.sqrt(d * d + (h * vt) ** 2) - d).mean())))
        R.say("slide h %g: gap %.3e (predicted (h vt)^2/(2d) = %.3e, ratio %.3f)" % (
            h, gap.mean(), pred.mean(), gap.mean() / pred.mean()))
    return rows


FRONT = ["scene", "solver", "tol", "warmstart", "matched_tol", "status", "steps"]


def write_csv(path, rows):
    keys = [k for k in FRONT if any(k in r for r in rows)]
    for r in rows:
        for k in r:
            if k not in keys:
                keys.append(k)
    with open(str(path), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        for r in rows:
            w.writerow({k: (("%.6g" % v) if isinstance(v, float) else v) for k, v in r.items()})


if __name__ == "__main__":
    main()
