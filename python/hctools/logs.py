"""Reading LAMMPS and LIGGGHTS logs: thermo blocks and the timing of each run."""

import re

import numpy as np


def _is_number(tok):
    try:
        float(tok)
        return True
    except ValueError:
        return False


def _columns_to_arrays(names, rows):
    out = {}
    for j, name in enumerate(names):
        col = [r[j] for r in rows]
        if all(is_int_token(t) for t in col):
            out[name] = np.array([int(t) for t in col], dtype=np.int64)
        else:
            out[name] = np.array([float(t) for t in col], dtype=np.float64)
    return out


def is_int_token(tok):
    t = tok[1:] if tok[:1] in "+-" else tok
    return t.isdigit()


def parse_thermo(text):
    """Thermo blocks of a LAMMPS log (or screen output): a list with one dict per run, column
    name -> numpy array. A block starts at the header line printed after 'Per MPI rank memory
    allocation' (thermo_style one/custom; 'Memory usage per processor' in LIGGGHTS) and ends at
    'Loop time' (or at an ERROR / the end of the text for a run that died). Lines inside a block
    that are not a full row of numbers (warnings, fix output) are skipped. LIGGGHTS heads its
    columns without the f_/c_/v_ prefixes ("hc[7]" for f_hc[7]): those are named after the
    words of the last echoed `thermo_style custom` line instead, so tests read the same names on
    every host."""
    blocks = []
    lines = text.splitlines()
    i, n = 0, len(lines)
    custom = None
    while i < n:
        words = lines[i].split()
        if len(words) > 2 and words[0] == "thermo_style" and words[1] == "custom":
            custom = [w for w in words[2:] if not w.startswith("#")]
        if not (lines[i].startswith("Per MPI rank memory allocation") or
                lines[i].startswith("Memory usage per processor")):
            i += 1
            continue
        i += 1
        while i < n and not lines[i].strip():
            i += 1
        if i >= n:
            break
        names = lines[i].split()
        if not names or any(_is_number(t) for t in names):
            continue
        if custom and len(custom) == len(names):
            names = [c if c.endswith("_" + m) else m for c, m in zip(custom, names)]
        rows = []
        i += 1
        while i < n:
            line = lines[i]
            if line.startswith("Loop time") or line.startswith("ERROR") or \
                    line.startswith("Per MPI rank memory allocation") or \
                    line.startswith("Memory usage per processor"):
                break
            toks = line.split()
            if len(toks) == len(names) and all(_is_number(t) for t in toks):
                rows.append(toks)
            i += 1
        blocks.append(_columns_to_arrays(names, rows))
    return blocks


def read_thermo(path):
    """parse_thermo of a log file."""
    with open(str(path), errors="replace") as f:
        return parse_thermo(f.read())


_LOOP = re.compile(r"^Loop time of ([0-9.eE+-]+) on (\d+) procs for (\d+) steps with (\d+) atoms")
_SECTIONS = ("Pair", "Bond", "Kspace", "Neigh", "Comm", "Output", "Modify", "Other")


def loop_times(text):
    """One dict per run of a log's text: loop (seconds), procs, steps, atoms, cpu_frac (the
    "% CPU use" line, nan when absent) and the average seconds of each section of LAMMPS's
    timing breakdown that the log prints (Pair, Neigh, Comm, Output, Modify, Other...)."""
    out = []
    lines = text.splitlines()
    for k, line in enumerate(lines):
        m = _LOOP.match(line)
        if not m:
            continue
        t = dict(loop=float(m.group(1)), procs=int(m.group(2)), steps=int(m.group(3)),
                 atoms=int(m.group(4)), cpu_frac=float("nan"))
        for follow in lines[k + 1:k + 30]:
            c = re.match(r"^([0-9.]+)% CPU use", follow)
            if c:
                t["cpu_frac"] = float(c.group(1)) / 100.0
            w = [x.strip() for x in follow.split("|")]
            if len(w) >= 6 and w[0] in _SECTIONS:
                try:
                    t[w[0]] = float(w[2])
                except ValueError:
                    pass
            if follow.startswith("Nlocal") or follow.startswith("Total # of neighbors"):
                break
        out.append(t)
    return out


def read_loop_times(path):
    """loop_times of a log file."""
    with open(str(path), errors="replace") as f:
        return loop_times(f.read())
