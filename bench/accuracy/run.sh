#!/usr/bin/env bash
# Accuracy versus time of fix hardcontact: every solver x tolerance x warm start on piles of 10,
# 30 and 100 layers, a hexagonal crystal, the paper's 6.3 cluster impact and a pour, against
# solver exact and against soft spheres (gran/hertz/history). Writes the
# CSV files to bench/results/accuracy/<host>/ (bench/common.sh) and regenerates
# doc/accuracy-vs-time.md and doc/figures/accuracy_*.png from them; a --quick run writes its
# report and figures beside its CSV files instead, and leaves doc/ alone.
#
#   bench/run.sh accuracy [--quick]
#
# --quick: smaller scenes, tolerances 1e-2..1e-6, short windows (a few minutes; for
# development). The full run takes about 30-40 minutes on 2 cores when the machine is idle.
# Environment: HARDCONTACT_LMP (default build/lmp_hardcontact), HARDCONTACT_SOURCE_DESC (what
# that launcher was built from, for the report; default: this tree's commit), SOFT_LMP (default /usr/bin/lmp),
# BENCH_WORKDIR (scratch, default bench/work: data files, logs, dumps; not committed),
# BENCH_WAIT_LOAD=N: wait up to N seconds for the 1-minute load average to drop below 1.
# ACCURACY_ONLY=<scenes> (comma-separated, e.g. pile3d): run those scenes only; the other
# scenes' rows stay in the CSV files, the run is described in machine_<scenes>.json and the
# report names it beside the full run.
set -euo pipefail
# shellcheck source=../common.sh
source "$(dirname "${BASH_SOURCE[0]}")/../common.sh" "" "$@"

load1() { cut -d' ' -f1 /proc/loadavg; }
if [ -n "${BENCH_WAIT_LOAD:-}" ]; then
  waited=0
  while awk -v l="$(load1)" 'BEGIN{exit !(l >= 1.0)}' && [ "$waited" -lt "$BENCH_WAIT_LOAD" ]; do
    echo "load $(load1) >= 1: waiting ($waited s of $BENCH_WAIT_LOAD)"; sleep 30; waited=$((waited + 30))
  done
fi

T0=$SECONDS
LOAD_BEFORE="$(cut -d' ' -f1-3 /proc/loadavg)"
ONLY=()
MACHINE="$RESULTS/machine.json"
if [ -n "${ACCURACY_ONLY:-}" ]; then
  ONLY=(--only "$ACCURACY_ONLY")
  MACHINE="$RESULTS/machine_${ACCURACY_ONLY//,/_}.json"
else
  rm -f "$RESULTS"/machine_*.json    # every scene is run again: no part of an older run is left
fi
"$PY" "$ROOT/bench/accuracy/run.py" "${QUICK[@]}" "${ONLY[@]}" --lmp "$LMP" --soft-lmp "$SOFT_LMP" \
  --work "$WORK" --results "$RESULTS"
LOAD_AFTER="$(cut -d' ' -f1-3 /proc/loadavg)"

LAMMPS_VERSION="$(echo "info" | "$SOFT_LMP" 2>/dev/null | sed -n 's/^LAMMPS (\(.*\))$/\1/p' | head -1)"
# What the launcher was built from: HARDCONTACT_SOURCE_DESC if set (e.g. a build of an
# exported commit), else this tree's commit (+ a note when src/ or cmake/ have local changes).
GIT="${HARDCONTACT_SOURCE_DESC:-}"
if [ -z "$GIT" ]; then
  GIT="$(cd "$ROOT" && git rev-parse --short HEAD 2>/dev/null || echo unknown)"
  if [ -n "$(cd "$ROOT" && git status --porcelain --untracked-files=no -- src cmake CMakeLists.txt 2>/dev/null)" ]; then
    GIT="$GIT + uncommitted changes in src/ or cmake/"
  fi
fi
"$PY" - "$MACHINE" <<PYEOF
import json, os, sys, time
cpu = "?"
for line in open("/proc/cpuinfo"):
    if line.startswith("model name"):
        cpu = line.split(":", 1)[1].strip()
        break
json.dump(dict(mode="$MODE", only="${ACCURACY_ONLY:-}", date=time.strftime("%Y-%m-%d %H:%M %Z"), nproc=os.cpu_count(), cpu=cpu,
               load_before="$LOAD_BEFORE", load_after="$LOAD_AFTER", lammps="$LAMMPS_VERSION",
               git="$GIT", launcher="$LMP", minutes=($SECONDS - $T0) / 60.0),
          open(sys.argv[1], "w"), indent=1)
PYEOF
DOC="$ROOT/doc/accuracy-vs-time.md"; FIGURES="$ROOT/doc/figures"
[ "$MODE" = quick ] && { DOC="$RESULTS/accuracy-vs-time.md"; FIGURES="$RESULTS/figures"; }
"$PY" "$ROOT/bench/accuracy/report.py" --results "$RESULTS" --doc "$DOC" --figures "$FIGURES"
echo "accuracy benchmark ($MODE): $(( (SECONDS - T0) / 60 )) min; $DOC"
