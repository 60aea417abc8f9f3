"""One thermo block of a log as numbers for a CSV row: the bench scripts' window summaries.

From a shell script (bench/common.sh wraps it as bench_thermo):

    python3 -m hctools thermo LOG rows mean:f_hc[1] max:f_hc[1] delta:f_hc[6] max:f_hc[7] loop
    -> 40,1203.5,2210,0,9.8e-05,12.34

    python3 -m hctools thermo --each LOG Step f_hc[1] f_hc[4] loop
    -> one line per row of the window

The window is the block's rows after its first (the state before the run's first step, no
solve), unless --keep-first. A field is
    rows          the number of rows in the window
    COL           (with --each) the column on that row
    mean:COL max:COL min:COL first:COL last:COL
    sum:COL       the sum over the window
    half:COL      the mean over the second half of the window (rows n//2 .. n-1)
    delta:COL     last value minus the value on the row before the window (a counter's growth,
                  such as the fix's maxiter stops f_hc[6], over the window)
    loop          the loop time of the block's run, in seconds
    steps         the number of steps of the block's run (from its Loop time line)
    time:SECTION  the average seconds of a section of the run's timing breakdown (Modify, Pair...)
    load          the 1-minute load average now
Integers print as integers, other numbers with 6 significant digits.
"""

import argparse
import os
import sys

import numpy as np

from .logs import loop_times, parse_thermo


def _fmt(value):
    if isinstance(value, (int, np.integer)):
        return str(int(value))
    return "%.6g" % float(value)


def _column(block, name):
    if name not in block:
        raise KeyError("no thermo column %r (the block has: %s)" % (name, " ".join(block)))
    return block[name]


def window_values(text, fields, block=-1, keep_first=False, each=False):
    """The fields (see the module's help) of one thermo block of a log's text: a list of
    values, or with each=True a list of such lists, one per row of the window."""
    blocks = parse_thermo(text)
    if not blocks:
        raise ValueError("no thermo block in the log")
    th = blocks[block]
    index = block if block >= 0 else len(blocks) + block
    times = loop_times(text)
    run = times[index] if index < len(times) else {}
    start = 0 if keep_first else 1
    nrows = len(next(iter(th.values()))) if th else 0

    def constant(field):
        if field == "loop":
            return run.get("loop", float("nan"))
        if field == "steps":
            return run.get("steps", 0)
        if field == "load":
            return os.getloadavg()[0]
        return None

    if each:
        out = []
        for r in range(start, nrows):
            row = []
            for f in fields:
                c = constant(f)
                row.append(c if c is not None else _column(th, f)[r])
            out.append(row)
        return out
    values = []
    for f in fields:
        c = constant(f)
        if c is not None:
            values.append(c)
            continue
        if f == "rows":
            values.append(max(nrows - start, 0))
            continue
        op, _, name = f.partition(":")
        if op == "time":
            values.append(run.get(name, float("nan")))
            continue
        col = _column(th, name)
        win = col[start:]
        if op == "delta":
            values.append(col[-1] - col[0])
        elif not len(win):
            values.append(float("nan"))
        elif op == "mean":
            values.append(float(np.mean(win)))
        elif op == "sum":
            values.append(win.sum())
        elif op == "half":
            values.append(float(np.mean(win[len(win) // 2:])))
        elif op in ("max", "min", "first", "last"):
            values.append({"max": np.max, "min": np.min, "first": lambda a: a[0],
                           "last": lambda a: a[-1]}[op](win))
        else:
            raise ValueError("unknown field %r (rows, loop, steps, load, or "
                             "mean|sum|half|max|min|first|last|delta:COLUMN, time:SECTION)" % f)
    return values


def main(argv=None):
    ap = argparse.ArgumentParser(prog="python3 -m hctools thermo", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("log")
    ap.add_argument("fields", nargs="+")
    ap.add_argument("--block", type=int, default=-1, help="which thermo block (default: the last)")
    ap.add_argument("--keep-first", action="store_true", help="the window includes the first row")
    ap.add_argument("--each", action="store_true", help="one line per row of the window")
    ap.add_argument("--sep", default=",")
    a = ap.parse_args(argv)
    with open(a.log, errors="replace") as f:
        text = f.read()
    try:
        got = window_values(text, a.fields, a.block, a.keep_first, a.each)
    except (KeyError, ValueError, IndexError) as e:
        sys.exit("hctools thermo: %s: %s" % (a.log, e.args[0] if e.args else e))
    for row in (got if a.each else [got]):
        print(a.sep.join(_fmt(v) for v in row))
    return 0
