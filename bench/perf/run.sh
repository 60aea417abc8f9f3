#!/usr/bin/env bash
# Performance of fix hardcontact (issue 15): iterations per step against pile height for every
# solver, a resting scene with mass ratios 1..1000, contact-iterations per second against N,
# time to solution hard vs soft (gran/hertz/history twin), 1 vs 2 MPI ranks, the piles brought
# to rest for real (still) and the settle with larger steps (steps). Writes
# bench/results/perf/<host>/ (bench/common.sh): perf_*.csv, report.md (the tables, the figures in
# figures/); doc/performance.md, the user guide, quotes its headline numbers.
#
#   bench/run.sh perf [--quick]
#
# --quick: small sizes (about 3 minutes; for development). The full run takes about 20 minutes
# on 2 cores. Runs are one at a time (serial except the 2-rank ones); every run has a wall-time
# cap (fix halt) so the total stays bounded on a loaded machine (capped runs are marked).
# Environment: HARDCONTACT_LMP (default build/lmp_hardcontact; build it once and do not rebuild
# it while measuring), HARDCONTACT_SOURCE_DESC (what that launcher was built from; default:
# this tree's commit), SOFT_LMP (default /usr/bin/lmp), BENCH_WORKDIR (scratch, default
# bench/work: data files, logs, restarts; not committed), PERF_ONLY (subset of
# heights,still,tray,throughput,tts,steps,big,big_stiff: only those parts run (still needs
# the restarts of a heights run), the others' rows of the last runs are kept; big, the
# 64,000-sphere pile, and big_stiff, its two stiffer soft twins (target 3 at 64,000), run only
# when named: about 15 and 30 minutes). Hard runs report their solver's communication
# (HARDCONTACT_COMM_TIMES); every run records the cores' busy and stolen share.
set -euo pipefail
# shellcheck source=../common.sh
source "$(dirname "${BASH_SOURCE[0]}")/../common.sh" "perf-" "$@"

# what the launcher was built from: HARDCONTACT_SOURCE_DESC, else this tree's commit
GIT="${HARDCONTACT_SOURCE_DESC:-}"
if [ -z "$GIT" ]; then
  GIT="$(cd "$ROOT" && git rev-parse --short HEAD 2>/dev/null || echo unknown)"
  if [ -n "$(cd "$ROOT" && git status --porcelain --untracked-files=no -- src cmake CMakeLists.txt 2>/dev/null)" ]; then
    GIT="$GIT + uncommitted changes in src/ or cmake/"
  fi
fi
T0=$SECONDS
LOAD_BEFORE="$(cut -d' ' -f1-3 /proc/loadavg)"
"$PY" "$ROOT/bench/perf/run.py" "${QUICK[@]}" --lmp "$LMP" --soft-lmp "$SOFT_LMP" \
  --work "$WORK" --results "$RESULTS" --only "${PERF_ONLY:-heights,still,tray,throughput,tts,steps}" \
  2>&1 | tee "$WORK/run_log.txt"
LOAD_AFTER="$(cut -d' ' -f1-3 /proc/loadavg)"
# a partial run's log goes beside the full run's, which it would otherwise replace
RUN_LOG="$RESULTS/perf_run_log.txt"
[ -n "${PERF_ONLY:-}" ] && RUN_LOG="$RESULTS/perf_run_log_${PERF_ONLY//,/_}.txt"
cp "$WORK/run_log.txt" "$RUN_LOG"

LAMMPS_VERSION="$(echo "info" | "$SOFT_LMP" 2>/dev/null | sed -n 's/^LAMMPS (\(.*\))$/\1/p' | head -1)"
CPU="$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -1)"
# a full run describes the machine for the whole report; a partial one (PERF_ONLY) its part
MACHINE="$RESULTS/perf_machine.csv"
[ -n "${PERF_ONLY:-}" ] && MACHINE="$RESULTS/perf_machine_${PERF_ONLY//,/_}.csv"
# a full run measured every part but big again: the notes of earlier partial runs go
if [ -z "${PERF_ONLY:-}" ]; then
  for f in "$RESULTS"/perf_machine_*.csv; do
    case "$f" in
      "$RESULTS/perf_machine_big.csv" | "$RESULTS/perf_machine_big_stiff.csv") ;;
      *) [ -e "$f" ] && rm -f "$f" ;;
    esac
  done
fi
{
  echo "key,value"
  echo "only,\"${PERF_ONLY:-all}\""
  echo "mode,$MODE"
  echo "date,$(date -u '+%Y-%m-%d %H:%M UTC')"
  echo "nproc,$(nproc)"
  echo "cpu,\"$CPU\""
  echo "load_before,$LOAD_BEFORE"
  echo "load_after,$LOAD_AFTER"
  echo "lammps,$LAMMPS_VERSION"
  echo "hardcontact,$GIT"
  echo "launcher,$LMP"
  echo "minutes,$(( (SECONDS - T0) / 60 ))"
} > "$MACHINE"
"$PY" "$ROOT/bench/perf/report.py" --results "$RESULTS" --out "$RESULTS/report.md" \
  --figures "$RESULTS/figures"
echo "performance benchmark ($MODE): $(( (SECONDS - T0) / 60 )) min; $RESULTS/report.md"
