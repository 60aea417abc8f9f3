#!/usr/bin/python3
"""Table of two builds' micro-benchmark runs (Google Benchmark JSON, several rounds each):
per benchmark the median CPU time of each build, the spread of its rounds (max / min - 1: the
noise to read the ratio against), the B/A ratio of the medians and B's contact-iterations per
second. Used by compare.sh; standard library only.

    compare_runs.py --a A1.json A2.json ... --b B1.json B2.json ...
"""
import argparse
import json
import statistics
import sys

UNIT_NS = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}


def read_rounds(paths):
    """{name: [cpu time in ns per round]}, {name: [contact_its per round]}, names in run order."""
    times, rates, order = {}, {}, []
    for path in paths:
        with open(path) as f:
            report = json.load(f)
        for b in report["benchmarks"]:
            if b.get("run_type", "iteration") != "iteration":
                continue  # aggregates of --benchmark_repetitions: the rounds are ours
            name = b["name"]
            if name not in times:
                order.append(name)
                times[name], rates[name] = [], []
            times[name].append(b["cpu_time"] * UNIT_NS[b.get("time_unit", "ns")])
            if "contact_its" in b:
                rates[name].append(b["contact_its"])
    return times, rates, order


def show_time(ns):
    for unit, scale in (("s", 1e9), ("ms", 1e6), ("us", 1e3)):
        if ns >= scale:
            return f"{ns / scale:.3g} {unit}"
    return f"{ns:.3g} ns"


def spread(values):
    return max(values) / min(values) - 1.0 if min(values) > 0 else float("nan")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--a", nargs="+", required=True, help="build A's JSON reports, one per round")
    ap.add_argument("--b", nargs="+", required=True, help="build B's JSON reports, one per round")
    args = ap.parse_args()
    ta, _, order = read_rounds(args.a)
    tb, rb, order_b = read_rounds(args.b)
    order += [n for n in order_b if n not in ta]
    rows = [("benchmark", "A (median)", "A spread", "B (median)", "B spread", "B/A",
             "B contact-its/s")]
    for name in order:
        a, b = ta.get(name), tb.get(name)
        ma = statistics.median(a) if a else None
        mb = statistics.median(b) if b else None
        rows.append((
            name,
            show_time(ma) if a else "-",
            f"{100 * spread(a):.0f} %" if a else "-",
            show_time(mb) if b else "-",
            f"{100 * spread(b):.0f} %" if b else "-",
            f"{mb / ma:.3f}" if a and b and ma > 0 else "-",
            f"{statistics.median(rb[name]):.3g}" if rb.get(name) else "-",
        ))
    widths = [max(len(r[k]) for r in rows) for k in range(len(rows[0]))]
    for r in rows:
        print("  ".join(r[k].ljust(widths[k]) if k == 0 else r[k].rjust(widths[k])
                        for k in range(len(r))))
    return 0


if __name__ == "__main__":
    sys.exit(main())
