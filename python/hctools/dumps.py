"""Reading LAMMPS text dumps (dump custom / atom / local; gzipped or one file per step)."""

import glob
import gzip
from collections import namedtuple

import numpy as np

from .logs import is_int_token


# (timestep, {column: numpy array}, box bounds: array (3,2) or (3,3) for triclinic)
DumpFrame = namedtuple("DumpFrame", ["timestep", "columns", "box"])


def _open_text(path):
    path = str(path)
    if path.endswith(".gz"):
        return gzip.open(path, "rt")
    return open(path, "r")


def _convert_column(tokens):
    try:
        if all(is_int_token(t) for t in tokens):
            return np.array(tokens, dtype=np.int64)
        return np.array(tokens, dtype=np.float64)
    except ValueError:
        return np.array(tokens, dtype=object)    # e.g. element names


def _read_frames(path, item):
    """Generic reader of LAMMPS text dumps whose per-frame table is 'ITEM: <item> cols...'."""
    paths = sorted(glob.glob(str(path))) if any(c in str(path) for c in "*?[") else [path]
    if not paths:
        raise FileNotFoundError(path)
    frames = []
    for p in paths:
        with _open_text(p) as f:
            lines = f.read().splitlines()
        i, n = 0, len(lines)
        while i < n:
            if not lines[i].startswith("ITEM: TIMESTEP"):
                i += 1
                continue
            timestep = int(lines[i + 1].split()[0])
            i += 2
            count, box, names = None, None, None
            while i < n:
                line = lines[i]
                if line.startswith("ITEM: NUMBER OF"):
                    count = int(lines[i + 1].split()[0])
                    i += 2
                elif line.startswith("ITEM: BOX BOUNDS"):
                    box = np.array([[float(x) for x in lines[i + k].split()] for k in (1, 2, 3)])
                    i += 4
                elif line.startswith("ITEM: " + item):
                    names = line.split()[2:]
                    i += 1
                    break
                elif line.startswith("ITEM: TIMESTEP"):
                    raise ValueError("%s: frame at step %d has no 'ITEM: %s' table" % (p, timestep, item))
                else:
                    i += 1
            if names is None or count is None:
                raise ValueError("%s: truncated frame at step %d" % (p, timestep))
            rows = lines[i:i + count]
            if len(rows) < count:
                raise ValueError("%s: frame at step %d has %d of %d rows" % (p, timestep, len(rows), count))
            i += count
            toks = [r.split() for r in rows]
            cols = {}
            for j, name in enumerate(names):
                cols[name] = _convert_column([t[j] for t in toks])
            frames.append(DumpFrame(timestep, cols, box))
    frames.sort(key=lambda fr: fr.timestep)
    return frames


def read_dump(path, sort_by_id=True):
    """Frames of a text 'dump custom' (or atom) file: a list of DumpFrame(timestep,
    {column: numpy array}, box), box as an array [[xlo, xhi(, xy)], [ylo, yhi(, xz)],
    [zlo, zhi(, yz)]]. Rows are sorted by the 'id' column when there is one (the order in the
    file depends on the processors). path may be gzipped (.gz) or a glob pattern (one file per
    step, 'dump.*.txt')."""
    frames = _read_frames(path, "ATOMS")
    if sort_by_id:
        for fr in frames:
            if "id" in fr.columns and len(fr.columns["id"]):
                order = np.argsort(fr.columns["id"], kind="stable")
                for k in fr.columns:
                    fr.columns[k] = fr.columns[k][order]
    return frames


def read_dump_local(path):
    """Frames of a text 'dump local' file: same shape as read_dump, with the columns of
    'ITEM: ENTRIES ...' (in file order)."""
    return _read_frames(path, "ENTRIES")
