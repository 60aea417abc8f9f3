"""Running LAMMPS decks and reading their logs (standard library + numpy)."""

import os
import re
import subprocess
import time
from pathlib import Path

import numpy as np


class LammpsError(RuntimeError):
    pass


def run(lmp, deck, workdir, name="in.deck", timeout=3600, log="log.lammps"):
    """Write deck to workdir/name and run it serially; return (log text, wall seconds)."""
    workdir = Path(workdir)
    workdir.mkdir(parents=True, exist_ok=True)
    (workdir / name).write_text(deck)
    t0 = time.time()
    env = dict(os.environ, OMP_NUM_THREADS="1")
    try:
        p = subprocess.run([str(lmp), "-in", name, "-log", log, "-screen", "none"], cwd=str(workdir),
                           stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                           timeout=timeout, env=env)
    except subprocess.TimeoutExpired:
        raise LammpsError("%s in %s: no end after %.0f s (killed; a hang inside a step?)" % (
            lmp, workdir, timeout))
    secs = time.time() - t0
    text = (workdir / log).read_text() if (workdir / log).exists() else ""
    errs = [l for l in (text + p.stdout + p.stderr).splitlines() if "ERROR" in l]
    if p.returncode != 0 or errs:
        raise LammpsError("%s in %s failed (rc %d): %s\n%s" % (lmp, workdir, p.returncode,
                          "\n".join(errs[:5]), "\n".join(text.splitlines()[-15:])))
    return text, secs


def thermo_blocks(text):
    """One dict (column -> numpy array) per run's thermo block."""
    blocks = []
    lines = text.splitlines()
    k = 0
    while k < len(lines):
        words = lines[k].split()
        if words and words[0] == "Step":
            cols = words
            rows = []
            k += 1
            while k < len(lines):
                if lines[k].startswith("WARNING"):
                    k += 1
                    continue
                w = lines[k].split()
                if len(w) != len(cols):
                    break
                try:
                    rows.append([float(x) for x in w])
                except ValueError:
                    break
                k += 1
            arr = np.array(rows).reshape(-1, len(cols))
            blocks.append({c: arr[:, i] for i, c in enumerate(cols)})
        else:
            k += 1
    return blocks


_LOOP = re.compile(r"^Loop time of ([0-9.eE+-]+) on (\d+) procs for (\d+) steps with (\d+) atoms")


def timings(text):
    """One dict per run: loop (s), steps, atoms and the timing breakdown (avg seconds per
    section: Pair, Neigh, Comm, Output, Modify, Other)."""
    out = []
    lines = text.splitlines()
    for k, line in enumerate(lines):
        m = _LOOP.match(line)
        if not m:
            continue
        t = dict(loop=float(m.group(1)), procs=int(m.group(2)), steps=int(m.group(3)),
                 atoms=int(m.group(4)), cpu_frac=float("nan"))
        for l in lines[k + 1:k + 30]:
            c = re.match(r"^([0-9.]+)% CPU use", l)
            if c:
                t["cpu_frac"] = float(c.group(1)) / 100.0
            w = [x.strip() for x in l.split("|")]
            if len(w) >= 6 and w[0] in ("Pair", "Bond", "Kspace", "Neigh", "Comm", "Output", "Modify", "Other"):
                try:
                    t[w[0]] = float(w[2])
                except ValueError:
                    pass
            if l.startswith("Nlocal") or l.startswith("Total # of neighbors"):
                break
        out.append(t)
    return out


def read_dump(path):
    """Frames of a dump custom file: list of (timestep, dict column -> array)."""
    frames = []
    with open(str(path)) as f:
        lines = f.read().splitlines()
    k = 0
    while k < len(lines):
        if lines[k].startswith("ITEM: TIMESTEP"):
            step = int(lines[k + 1])
            n = int(lines[k + 3])
            k += 4
            while not lines[k].startswith("ITEM: ATOMS") and not lines[k].startswith("ITEM: ENTRIES"):
                k += 1
            cols = lines[k].split()[2:]
            data = np.array([[float(x) for x in l.split()] for l in lines[k + 1:k + 1 + n]]).reshape(n, len(cols))
            frames.append((step, {c: data[:, i] for i, c in enumerate(cols)}))
            k += 1 + n
        else:
            k += 1
    return frames
