#!/usr/bin/env python3
"""Performance of fix hardcontact (issue 15): drives every LAMMPS run of the benchmark, one at
a time, and writes perf_runs.csv (one row per run), perf_steps.csv (per-step
solver output of the hard runs) and perf_machine.csv into --results (bench/results/perf/<host>/). Called by bench/run.sh perf."""

import argparse
import csv
import math
import os
import re
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

SETTLE_KE = 5e-3   # "settled": kinetic energy per sphere stays below this x mean m g d


def settle_time(ke, cpu):
    """Wall time (thermo cpu) from which the kinetic energy per sphere (in m g d) stays below
    SETTLE_KE; nan if it does not (the spheres start at rest, so the first crossing is not it)."""
    above = np.nonzero(ke >= SETTLE_KE)[0]
    if len(above) == 0 or above[-1] + 1 >= len(ke):
        return float("nan")
    return float(cpu[above[-1] + 1])


# The default frictionless solver (the fix's default without friction): the reference run of
# every series; apgd (the default before it, and with friction) runs beside it.
REF = "cg"


def config(quick):
    """Sizes, run lengths (steps of h = 0.02) and wall-time caps (s) per run (fix halt)."""
    if quick:
        return dict(
            footprint=6, layers=[5, 10], exact_layers=5, settle=lambda L: 150 + 20 * L,
            window=15, settle_cap=15.0, window_cap=8.0, long_cap=60.0,
            tray_ratios=[1, 1000], tray_settle=150, tray_window=20,
            tray_solvers=["apgd", "pgs"], throughput=[(10, 5), (16, 5)], thr_steps=150, thr_cap=20.0,
            ts_pile=(8, 8, 10), soft_overlaps=[1e-3, 1e-4], soft_cap=40.0, ts_soft_levels=2,
            ts_soft_cap_stiffest=40.0, mpi_tols=[1e-2],
            still_layers=[5], still_steps=2000, still_cap=30.0, steps_h=[0.05, 0.1],
            subspace_window=40, big_stiff_cap=60.0)
    return dict(
        footprint=10, layers=[5, 10, 20, 40], exact_layers=5, settle=lambda L: 200 + 20 * L,
        window=40, settle_cap=20.0, window_cap=12.0, long_cap=200.0,
        tray_ratios=[1, 10, 100, 1000], tray_settle=200, tray_window=50,
        tray_solvers=["apgd", "pgs", "uzawa"], throughput=[(10, 10), (20, 10), (32, 10), (45, 10)],
        thr_steps=250, thr_cap=45.0,
        ts_pile=(20, 20, 20), soft_overlaps=[1e-3, 1e-4, 1e-5, 1e-6], soft_cap=120.0,
        # the issue's pile gets a third, stiffer twin, so that its soft runs' largest overlaps
        # bracket 1e-3 (target 3; the static 1e-3 twin overlaps about 9e-3 in the fall): it
        # needs about 8 minutes to cover the whole settle
        ts_soft_levels=3, ts_soft_cap_stiffest=700.0,
        mpi_tols=[1e-4, 1e-2],
        still_layers=[5, 10, 20], still_steps=6000, still_cap=300.0, steps_h=[0.05, 0.1, 0.2],
        subspace_window=100, big_stiff_cap=3600.0)


# The parts of a run (--only) and the groups of rows each writes
DEFAULT_PARTS = "heights,still,tray,throughput,tts,steps"
PART_OF_GROUP = dict(heights="heights", tray="tray", throughput="throughput", tts="tts", mpi="tts",
                     still="still", steps="steps")
# "At rest" for the part still: kinetic energy per sphere below this x m g d (the windows of
# the part heights start where the settle ends, at 1e-3 m g d: the piles still creep there)
STILL_KE = 1e-10
# cg's subspace start: the fix's default without friction is `subspace 10` (a run without the
# keyword records the value it ran with); the scenes at rest (parts still and tray) also run the
# same window with `subspace 0`, the start before it became the default (2026-12-01)
DEFAULT_SUBSPACE = {"cg": 10}
PLAIN = 0


def loadavg():
    return open("/proc/loadavg").read().split()[0]


def cpu_ticks():
    """The machine's CPU time so far (/proc/stat, all cores): busy and stolen ticks, total."""
    v = [int(x) for x in open("/proc/stat").readline().split()[1:9]]
    user, nice, system, idle, iowait, irq, softirq, steal = v
    return user + nice + system + irq + softirq, steal, sum(v)


def cpu_share(before, after):
    """Percent of all cores busy and stolen by the hypervisor between two cpu_ticks(): a
    serial run on this 2-core machine keeps about 50 % busy alone; more means something else
    ran beside it, steal means the host took the cores away (load average says neither)."""
    busy, steal, total = (a - b for a, b in zip(after, before))
    return (100.0 * busy / total, 100.0 * steal / total) if total > 0 else (float("nan"),) * 2


# The fix's report of its solver's communication at the end of each run (HARDCONTACT_COMM_TIMES,
# src/lammps/fix_hardcontact.cpp), one line per run of a deck
COMM_LINE = re.compile(r"Fix hardcontact communication in this run, per process: (\d+) forwards "
                       r"(\S+) s \(mean, max (\S+) s\), (\d+) reductions (\S+) s \(mean, max "
                       r"(\S+) s\)")


def solver_comm(text):
    """Per run of the deck: forwards, their mean and max seconds, reductions, the same."""
    return [dict(forwards=int(m[0]), forward_s=float(m[1]), forward_max_s=float(m[2]),
                 reductions=int(m[3]), reduce_s=float(m[4]), reduce_max_s=float(m[5]))
            for m in COMM_LINE.findall(text)]


class Bench:
    def __init__(self, args):
        self.a = args
        self.cfg = config(args.quick)
        self.work = Path(args.work).resolve()
        self.results = Path(args.results)
        self.work.mkdir(parents=True, exist_ok=True)
        self.results.mkdir(parents=True, exist_ok=True)
        self.runs = []
        self.steps = []
        self.t0 = time.time()
        self.data = {}
        self.part = ""
        self.cpu = (float("nan"), float("nan"))    # the last launch's cpu_share()
        # every hard run reports its solver's communication (forwards, reductions, seconds)
        os.environ["HARDCONTACT_COMM_TIMES"] = "1"
        # A run keeps the rows of the parts it does not run from the last runs, so the report
        # covers every part: a partial run (--only) the other parts, a full run the part big
        # (run only when named; a full run of b43485a dropped its rows). A row's part is its
        # own column or, in files written before it existed, follows from its group.
        self.keep_other_parts(args.only.split(","))

    def keep_other_parts(self, only):
        for fname, rows in (("perf_runs.csv", self.runs), ("perf_steps.csv", self.steps)):
            path = self.results / fname
            if not path.exists():
                continue
            for r in csv.DictReader(open(str(path))):
                part = r.get("part") or PART_OF_GROUP.get(r.get("group", ""), "")
                if fname == "perf_steps.csv":
                    part = r.get("part") or ""
                    if not part:
                        run = next((x for x in self.runs if x["id"] == r["id"]), None)
                        part = run["part"] if run else ""
                if part and part not in only:
                    r["part"] = part
                    rows.append(r)

    def note(self, msg):
        print("[%5.0f s, load %s] %s" % (time.time() - self.t0, loadavg(), msg), flush=True)

    # ---- running

    def datafile(self, scene, name):
        path = self.work / (name + ".data")
        if name not in self.data:
            scenes.write(scene, path)
            self.data[name] = scene
        return path

    def pile(self, nx, ny, layers):
        """The pile scene nx x ny x layers (bench/perf/scenes.py), its name and data file."""
        sc = scenes.pile(nx, ny, layers)
        name = "pile%dx%dx%d" % (nx, ny, layers)
        return sc, name, self.datafile(sc, name)

    def launch(self, exe, deck, rundir, ranks=1, timeout=1800):
        """Run a deck (serial, or mpirun -np ranks); return (log text, wall s, load before,
        load after)."""
        before = loadavg()
        ticks = cpu_ticks()
        # ranks up to the core count: MPI busy-polls as a plain mpirun does (hctools' default is
        # to yield, for ranks beyond the cores); beyond, it yields
        env = {"OMPI_MCA_mpi_yield_when_idle": "0"} if ranks <= (os.cpu_count() or 1) else None
        t = time.time()
        text = hc.run_deck(exe, deck, np=ranks, workdir=rundir, timeout=timeout,
                           args=["-screen", "none"], env=env).log
        wall = time.time() - t
        self.cpu = cpu_share(ticks, cpu_ticks())
        return text, wall, before, loadavg()

    def hard(self, rid, group, scene, data, solver, tol, phases, names, extra=None,
             start=None, restart_out=None, ranks=1, h=0.02, skin=0.3, subspace=None):
        """One hardcontact run with the given phases [(steps, cap[, until])] (until: the phase
        ends once the kinetic energy per sphere is below until x m g d), thermo every step; one
        row per phase in perf_runs.csv."""
        rundir = self.work / rid
        start = start or ("data", str(data))
        # None: the fix's default (no keyword); recorded as the value the fix runs with
        fix_extra = "subspace %d" % subspace if subspace is not None else ""
        if subspace is None:
            subspace = DEFAULT_SUBSPACE.get(solver, 0)
        deck = decks.hard(scene, start, solver, tol, [(p[0], 1) + tuple(p[1:]) for p in phases],
                          h=h, skin=skin, fix_extra=fix_extra,
                          ranks_2d=ranks > 1 or (extra or {}).get("mpi_ref", False),
                          restart_out=restart_out and str(rundir / restart_out))
        self.note("%s: %s tol %g, %d spheres, %s ranks %d" % (rid, solver, tol, scene["n"],
                                                             "+".join(str(p[0]) for p in phases), ranks))
        try:
            text, wall, lb, la = self.launch(self.a.lmp, deck, rundir, ranks)
        except hc.LammpsRunError as e:
            self.note("FAILED: %s" % str(e).splitlines()[0])
            self.runs.append(dict(id=rid, group=group, solver=solver, tol=tol, n=scene["n"],
                                  ranks=ranks, status="failed", part=self.part))
            return []
        blocks, times, comms = hc.parse_thermo(text), hc.loop_times(text), solver_comm(text)
        mgd = scene["mean_mass"] * scene["mean_d"]
        rows = []
        for k, (phase, name) in enumerate(zip(phases, names)):
            nreq, cap = phase[:2]
            until = phase[2] if len(phase) > 2 else None
            if k >= len(blocks):
                break
            b, t = blocks[k], times[k]
            sl = slice(1, None)  # the first row is the state before the run
            it, cand, act = b["f_hc[1]"][sl], b["f_hc[3]"][sl], b["f_hc[4]"][sl]
            done = len(it)
            ke = b["KinEng"] / scene["n"] / mgd
            row = dict(id=rid, group=group, phase=name, solver=solver, tol=tol, n=scene["n"],
                       layers=scene.get("layers", ""), ratio=scene.get("mass_ratio", ""),
                       ranks=ranks, h=h, skin=skin, subspace=subspace,
                       # a phase with `until` is done when the pile came to rest, not at nreq steps
                       status=("ok" if ke[-1] < until else "capped") if until is not None
                       else ("ok" if done >= nreq else "capped"),
                       steps=done, steps_asked=nreq, cap_s=cap,
                       it_mean=float(it.mean()) if done else float("nan"),
                       it_median=float(np.median(it)) if done else float("nan"),
                       it_max=float(it.max()) if done else float("nan"),
                       # the second half of the phase (subspace N builds up in the first steps)
                       it_mean_2nd_half=float(it[done // 2:].mean()) if done >= 2 else float("nan"),
                       cand_mean=float(cand.mean()) if done else float("nan"),
                       active_mean=float(act.mean()) if done else float("nan"),
                       solves_mean=float(b["f_hc[9]"][sl].mean()) if done else float("nan"),
                       maxiter_stops=int(b["f_hc[6]"][-1]),
                       overlap_max=float(b["f_hc[7]"].max()),
                       ke_end=float(ke[-1]), ke_start=float(ke[0]),
                       ke_max=float(ke[1:].max()) if done else float("nan"),
                       z_end=float(b["c_zavg"][-1]) if "c_zavg" in b else float("nan"),
                       settle_wall_s=settle_time(ke, b["CPU"]),
                       loop_s=t["loop"], modify_s=t.get("Modify", float("nan")),
                       neigh_s=t.get("Neigh", float("nan")), comm_s=t.get("Comm", float("nan")),
                       ci_cand=float((it * cand).sum()), ci_active=float((it * act).sum()),
                       iterations=int(it.sum()),
                       load_before=lb, load_after=la, wall_s=wall,
                       cpu_busy_pct=self.cpu[0], cpu_steal_pct=self.cpu[1])
            if k < len(comms):
                row.update({"solver_" + key: v for key, v in comms[k].items()})
            row["ci_per_s_cand"] = row["ci_cand"] / row["modify_s"] if row["modify_s"] > 0 else float("nan")
            row["ci_per_s_active"] = row["ci_active"] / row["modify_s"] if row["modify_s"] > 0 else float("nan")
            row["ms_per_step"] = 1e3 * t["loop"] / max(done, 1)
            row.update(extra or {})
            row["part"] = self.part
            rows.append(row)
            for s, a, c, ac, e, o in zip(b["Step"][sl], it, cand, act, ke[1:], b["f_hc[7]"][sl]):
                self.steps.append(dict(id=rid, part=self.part, phase=name, step=int(s), iterations=int(a),
                                       candidates=int(c), active=int(ac), ke_per_mgd=float(e),
                                       overlap=float(o)))
        self.runs.extend(rows)
        self.note("  -> " + "; ".join("%s: %d steps, %.0f it/step, %.1f ms/step%s" % (
            r["phase"], r["steps"], r["it_mean"], r["ms_per_step"],
            " (capped)" if r["status"] == "capped" else "") for r in rows))
        self.save()
        return rows

    def soft(self, rid, group, scene, data, overlap, duration, extra=None, cap=None):
        """Soft twin: kn for a static overlap `overlap` x d under the load of a column of the
        pile, restitution 0.1, dt = t_c / 20 at the top layer's impact speed (the convention of
        potentials/glass_beads.params); runs `duration` time units, at most `cap` seconds
        (default soft_cap)."""
        layers = scene.get("layers", 10)
        d, m = scene["mean_d"], scene["mean_mass"]
        v = max(1.0, math.sqrt(2.0 * (scenes.SPACING - scenes.D_MIN) * layers))
        p = decks.hertz_params(d, v, overlap, layers * m, 0.1, 20)
        nsteps = int(round(duration / p["dt"]))
        every = max(nsteps // 200, 1)
        rundir = self.work / rid
        deck = decks.soft(scene, str(data), p, [(nsteps, every, cap or self.cfg["soft_cap"])])
        self.note("%s: soft, static overlap target %g, kn %.3g, dt %.3g, %d steps, %d spheres" % (
            rid, overlap, p["kn"], p["dt"], nsteps, scene["n"]))
        try:
            text, wall, lb, la = self.launch(self.a.soft_lmp, deck, rundir)
        except hc.LammpsRunError as e:
            self.note("FAILED: %s" % str(e).splitlines()[0])
            return None
        b, t = hc.parse_thermo(text)[0], hc.loop_times(text)[0]
        radius = 0.5 * np.asarray(scene["d"])
        pair = []
        for f, dist, i, j in zip(b["c_red[1]"], b["c_red[2]"], b["c_red[3]"], b["c_red[4]"]):
            if f > 0 and i >= 1 and j >= 1:
                rs = radius[int(i) - 1] + radius[int(j) - 1]
                pair.append((rs - dist) / rs)
        pair = np.array(pair) if pair else np.zeros(1)
        wall_ov = np.maximum(b["c_wmax"], 0.0)
        ke = b["KinEng"] / scene["n"] / (m * d)
        tail = max(len(pair) // 10, 1)
        row = dict(id=rid, group=group, phase="settle", solver="soft", tol=overlap, n=scene["n"],
                   layers=layers, ranks=1, status="ok" if t["steps"] >= nsteps else "capped",
                   steps=t["steps"], steps_asked=nsteps, cap_s=cap or self.cfg["soft_cap"],
                   kn=p["kn"], dt=p["dt"], t_c=p["t_c"], simulated=t["steps"] * p["dt"],
                   overlap_max=float(max(pair.max(), wall_ov.max())),
                   overlap_pair_max=float(pair.max()), overlap_wall_max=float(wall_ov.max()),
                   overlap_rest=float(max(pair[-tail:].max(), wall_ov[-tail:].max())),
                   ke_end=float(ke[-1]),
                   settle_wall_s=settle_time(ke, b["CPU"]),
                   loop_s=t["loop"], modify_s=t.get("Modify", float("nan")),
                   projected_s=t["loop"] * nsteps / max(t["steps"], 1),
                   pair_s=t.get("Pair", float("nan")), neigh_s=t.get("Neigh", float("nan")),
                   ms_per_step=1e3 * t["loop"] / max(t["steps"], 1),
                   load_before=lb, load_after=la, wall_s=wall,
                   cpu_busy_pct=self.cpu[0], cpu_steal_pct=self.cpu[1])
        row.update(extra or {})
        row["part"] = self.part
        self.runs.append(row)
        self.note("  -> %d steps, %.1f s, largest overlap %.2g (at rest %.2g), KE end %.2g" % (
            row["steps"], row["loop_s"], row["overlap_max"], row["overlap_rest"], row["ke_end"]))
        self.save()
        return row

    # ---- the five measurements

    def heights(self):
        c = self.cfg
        fp = c["footprint"]
        for L in c["layers"]:
            sc, name, data = self.pile(fp, fp, L)
            settle, win = c["settle"](L), c["window"]
            rid = "heights_%s_%s" % (name, REF)
            self.hard(rid, "heights", sc, data, REF, 1e-4,
                      [(settle, c["long_cap"]), (win, c["long_cap"])], ["settle", "rest"],
                      restart_out="settled.restart")
            restart = self.work / rid / "settled.restart"
            others = ["apgd", "pgs", "uzawa"] + (["exact"] if L <= c["exact_layers"] else [])
            for solver in others:
                cap = c["long_cap"] if solver == "apgd" else c["settle_cap"] * (2 if solver == "exact" else 1)
                self.hard("heights_%s_%s_settle" % (name, solver), "heights", sc, data, solver, 1e-4,
                          [(settle, cap)], ["settle"])
                if restart.exists():
                    self.hard("heights_%s_%s_rest" % (name, solver), "heights", sc, data, solver,
                              1e-4, [(win, c["long_cap"] if solver == "apgd" else c["window_cap"])], ["rest"],
                              start=("restart", str(restart)))

    def still(self):
        """The piles of the part heights (its settled restarts) run on with the default solver
        until they are at rest (kinetic energy per sphere below STILL_KE m g d; a frictionless
        pile creeps for thousands of steps after the settle), then a window there."""
        c = self.cfg
        fp = c["footprint"]
        for L in c["still_layers"]:
            sc, name, data = self.pile(fp, fp, L)
            restart = self.work / ("heights_%s_%s" % (name, REF)) / "settled.restart"
            if not restart.exists():
                self.note("still_%s: no restart from the part heights (%s); skipped" % (name, restart))
                continue
            rid = "still_%s_%s" % (name, REF)
            # the window as long as the subspace-0 one below: their means compare step for step
            # (a 40-step window against a 100-step one had read as 1.4 x the time on identical
            # iterations, the later steps of a longer window being cheaper)
            self.hard(rid, "still", sc, data, REF, 1e-4,
                      [(c["still_steps"], c["still_cap"], STILL_KE), (c["subspace_window"], c["long_cap"])],
                      ["calm", "still"], start=("restart", str(restart)), restart_out="calm.restart")
            calm = self.work / rid / "calm.restart"
            if calm.exists():    # the same window from the same state, without the subspace start
                self.hard("still_%s_%s_subspace%d" % (name, REF, PLAIN), "still", sc, data, REF,
                          1e-4, [(c["subspace_window"], c["long_cap"])], ["still"],
                          start=("restart", str(calm)), subspace=PLAIN)

    def tray(self):
        c = self.cfg
        for ratio in c["tray_ratios"]:
            sc = scenes.tray(ratio)
            name = "tray_m%d" % ratio
            data = self.datafile(sc, name)
            rid = "tray_%s_%s" % (name, REF)
            self.hard(rid, "tray", sc, data, REF, 1e-4,
                      [(c["tray_settle"], 60.0), (c["tray_window"], 60.0)], ["settle", "rest"],
                      restart_out="settled.restart")
            restart = self.work / rid / "settled.restart"
            if restart.exists():
                self.hard("tray_%s_%s_subspace%d_rest" % (name, REF, PLAIN), "tray", sc, data, REF,
                          1e-4, [(c["subspace_window"], c["window_cap"])], ["rest"],
                          start=("restart", str(restart)), subspace=PLAIN)
            for solver in c["tray_solvers"]:
                if solver != REF and restart.exists():
                    self.hard("tray_%s_%s_rest" % (name, solver), "tray", sc, data, solver, 1e-4,
                              [(c["tray_window"], c["window_cap"])], ["rest"],
                              start=("restart", str(restart)))

    def throughput(self):
        c = self.cfg
        for fp, L in c["throughput"]:
            sc, name, data = self.pile(fp, fp, L)
            self.hard("throughput_%s_%s" % (name, REF), "throughput", sc, data, REF, 1e-4,
                      [(c["thr_steps"], c["thr_cap"])], ["settle"])

    def hard_vs_soft_and_mpi(self):
        """The issue's pile (20 x 20 x 20 in full mode): hard at tol 1e-4 and 1e-2 (serial runs
        with `processors * * 1`, the 1-rank references of the MPI runs), its soft twin at static
        overlaps 1e-3.. and the 10 x 10 x 20 pile's twin, then 2 ranks."""
        c = self.cfg
        nx, ny, L = c["ts_pile"]
        sc, name, data = self.pile(nx, ny, L)
        steps = c["settle"](L)
        duration = steps * 0.02
        for tol in (1e-4, 1e-2):
            self.hard("tts_%s_%s_tol%g" % (name, REF, tol), "tts", sc, data, REF, tol,
                      [(steps, 400.0)], ["settle"], extra=dict(mpi_ref=True))
        # the default before cg, same pile, same run of the benchmark
        self.hard("tts_%s_apgd_tol0.0001" % name, "tts", sc, data, "apgd", 1e-4,
                  [(steps, 400.0)], ["settle"], extra=dict(mpi_ref=True))
        for k, ov in enumerate(c["soft_overlaps"][:c["ts_soft_levels"]]):
            self.soft("tts_%s_soft_%g" % (name, ov), "tts", sc, data, ov, duration,
                      cap=c["ts_soft_cap_stiffest"] if k == 2 else None)
        # the stiffness sweep on the smaller pile of the heights series (same duration)
        fp = c["footprint"]
        L2 = max(l for l in c["layers"] if l <= L)
        sc2, name2, data2 = self.pile(fp, fp, L2)
        steps2 = c["settle"](L2)
        self.hard("tts_%s_%s_tol0.01" % (name2, REF), "tts", sc2, data2, REF, 1e-2, [(steps2, 200.0)],
                  ["settle"])
        for ov in c["soft_overlaps"]:
            self.soft("tts_%s_soft_%g" % (name2, ov), "tts", sc2, data2, ov, steps2 * 0.02)
        for tol in c["mpi_tols"]:
            self.hard("mpi2_%s_%s_tol%g" % (name, REF, tol), "mpi", sc, data, REF, tol,
                      [(steps, 400.0)], ["settle"], ranks=2)

    def larger_step(self):
        """Time to solution with a larger step: the pile of the part tts settled for the same
        simulated time with h = 0.02 (the issue's scene) and the larger steps steps_h (skin
        9 h, at least 0.3: a step may move a sphere further), and its soft twin at a static
        overlap of 1e-3, all in this part so that the ratios come from one run."""
        c = self.cfg
        nx, ny, L = c["ts_pile"]
        sc, name, data = self.pile(nx, ny, L)
        duration = c["settle"](L) * 0.02
        for h in [0.02] + c["steps_h"]:
            n = int(round(duration / h))
            self.hard("steps_%s_%s_h%g" % (name, REF, h), "steps", sc, data, REF, 1e-4,
                      [(n, 400.0)], ["settle"], h=h, skin=max(0.3, round(9.0 * h, 3)))
        self.soft("steps_%s_soft_0.001" % name, "steps", sc, data, 1e-3, duration)

    def big(self):
        """Issue 15's 64,000 spheres (targets 3 and 4): an 80 x 80 x 10 pile (the 10-layer pile
        of section 1 on a footprint 64 x larger), its settle hard at tol 1e-4 on 1 and 2 ranks
        and its soft twin at a static overlap of 1e-3."""
        c = self.cfg
        nx, L = (20, 10) if self.a.quick else (80, 10)
        sc, name, data = self.pile(nx, nx, L)
        steps = c["settle"](L)
        self.hard("tts_%s_%s_tol0.0001" % (name, REF), "tts", sc, data, REF, 1e-4,
                  [(steps, 1200.0)], ["settle"], extra=dict(mpi_ref=True))
        self.hard("mpi2_%s_%s_tol0.0001" % (name, REF), "mpi", sc, data, REF, 1e-4,
                  [(steps, 1200.0)], ["settle"], ranks=2)
        self.soft("tts_%s_soft_0.001" % name, "tts", sc, data, 1e-3, steps * 0.02)

    def big_stiff(self):
        """Target 3 at 64,000 spheres: the pile of part big gets two stiffer soft twins (static
        overlaps 1e-4 and 1e-5), so that the soft runs' largest overlaps bracket 1e-3 as for
        the piles of part tts. Not in the default set: about 30 minutes on one core (the runs
        must cover the whole fall: its impacts make the largest overlap)."""
        c = self.cfg
        nx, L = (20, 10) if self.a.quick else (80, 10)
        sc, name, data = self.pile(nx, nx, L)
        steps = c["settle"](L)
        for ov in (1e-4, 1e-5):
            self.soft("tts_%s_soft_%g" % (name, ov), "tts", sc, data, ov, steps * 0.02,
                      cap=c["big_stiff_cap"])

    # ---- output

    def save(self):
        for fname, rows in (("perf_runs.csv", self.runs), ("perf_steps.csv", self.steps)):
            keys = []
            for r in rows:
                keys += [k for k in r if k not in keys]
            with open(str(self.results / fname), "w", newline="") as f:
                w = csv.DictWriter(f, fieldnames=keys, restval="")
                w.writeheader()
                for r in rows:
                    w.writerow({k: ("%.6g" % v if isinstance(v, float) else v) for k, v in r.items()})


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--lmp", required=True)
    ap.add_argument("--soft-lmp", required=True)
    ap.add_argument("--work", required=True)
    ap.add_argument("--results", required=True)
    ap.add_argument("--only", default=DEFAULT_PARTS,
                    help="comma-separated subset of heights,still,tray,throughput,tts,steps,big,big_stiff "
                         "(still needs the restarts of a heights run; big: the 64,000-sphere "
                         "pile, hard 1 and 2 ranks and its soft twin; big_stiff: two stiffer "
                         "twins of that pile (target 3 at 64,000); neither in the default set: "
                         "about 15 and 30 minutes more)")
    a = ap.parse_args()
    b = Bench(a)
    only = a.only.split(",")
    for part, fn in (("heights", b.heights), ("still", b.still), ("tray", b.tray),
                     ("throughput", b.throughput), ("tts", b.hard_vs_soft_and_mpi),
                     ("steps", b.larger_step), ("big", b.big), ("big_stiff", b.big_stiff)):
        if part in only:
            b.part = part
            fn()
    b.save()
    b.note("done")


if __name__ == "__main__":
    main()
