#!/usr/bin/env bash
# The micro-benchmarks of two build directories, run alternately, one binary at a time (A B,
# then B A, ...: seconds on a shared 2-core machine drift and jump by +-30 %, and alternating
# spreads that over both builds), then one table: per benchmark the median CPU time of each
# build over the rounds, the rounds' spread, B/A and B's contact-iterations per second.
#   bench/micro/compare.sh BUILD_A BUILD_B [FILTER]
# FILTER: a --benchmark_filter regex (default: all). Environment: MICRO_ROUNDS (3),
# MICRO_MIN_TIME (seconds per benchmark and round, 0.2), MICRO_SPHERES (3000). JSON reports
# and the table go to $BENCH_WORKDIR/micro (default bench/work/micro); nothing else is written.
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
[ $# -ge 2 ] || { echo "usage: $0 BUILD_A BUILD_B [FILTER]" >&2; exit 2; }
A="$(realpath "$1")/bench/micro/hardcontact_micro"
B="$(realpath "$2")/bench/micro/hardcontact_micro"
FILTER="${3:-.}"
for exe in "$A" "$B"; do
  [ -x "$exe" ] || { echo "compare: no $exe (cmake --build <dir> --target hardcontact_micro)" >&2; exit 1; }
done
ROUNDS="${MICRO_ROUNDS:-3}"
WORK="${BENCH_WORKDIR:-$ROOT/bench/work}/micro"
mkdir -p "$WORK"
rm -f "$WORK"/[ab].*.json "$WORK"/[ab].*.log
PY=/usr/bin/python3; [ -x "$PY" ] || PY=python3

machine() {
  echo "cpu:     $(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -n1) ($(nproc) cores)"
  echo "load:    $(cut -d' ' -f1-3 /proc/loadavg) (1, 5, 15 min) $1"
}
{
  echo "micro-benchmarks, $(date -u '+%Y-%m-%d %H:%M UTC') on $(hostname)"
  machine "before"
  echo "A:       $A"
  echo "B:       $B"
  echo "filter:  $FILTER; $ROUNDS rounds of ${MICRO_MIN_TIME:-0.2} s per benchmark, ${MICRO_SPHERES:-3000} spheres"
} | tee "$WORK/table.txt"

run() {    # run <a|b> <round>
  local exe=$A; [ "$1" = b ] && exe=$B
  "$exe" --spheres="${MICRO_SPHERES:-3000}" --benchmark_filter="$FILTER" \
    --benchmark_min_time="${MICRO_MIN_TIME:-0.2}" \
    --benchmark_out="$WORK/$1.$2.json" --benchmark_out_format=json >/dev/null 2>"$WORK/$1.$2.log" \
    || { cat "$WORK/$1.$2.log" >&2; echo "compare: $exe failed" >&2; exit 1; }
}
for r in $(seq 1 "$ROUNDS"); do
  printf 'round %s/%s\n' "$r" "$ROUNDS" >&2
  if [ $((r % 2)) = 1 ]; then run a "$r"; run b "$r"; else run b "$r"; run a "$r"; fi
done

{
  machine "after"
  echo
  "$PY" "$HERE/compare_runs.py" --a "$WORK"/a.*.json --b "$WORK"/b.*.json
} | tee -a "$WORK/table.txt"
