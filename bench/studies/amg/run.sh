#!/usr/bin/env bash
# Does algebraic multigrid pay for cg's solves? (issue 15 names hypre's BoomerAMG as a route to
# target 1; bench/studies/amg/README.md, section 10.15): settles the piles of 10 and 20 layers of
# section 1 with the default solver and dumps a window at rest (bench/studies/spectrum/scenes_run.py),
# writes the linear systems of two steps' exact pushing rows (bench/studies/amg/amg.py), and runs
# PCG from the fix's warm start to its stopping test with Jacobi and with one BoomerAMG V-cycle
# per iteration (bench/studies/amg/amg_pcg.cpp, built here against Debian's libhypre-dev, which
# this script installs when missing: apt-get, as root). One process, OMP_NUM_THREADS=1.
# Writes bench/studies/amg/results/amg.txt. About a minute.
#   bench/studies/amg/run.sh [--quick]      (--quick: the 10-layer pile only)
set -euo pipefail
# shellcheck source=../../common.sh
source "$(dirname "${BASH_SOURCE[0]}")/../../common.sh" amg_ "$@"
if [ ! -e /usr/include/hypre/HYPRE_parcsr_ls.h ]; then
  echo "run_amg: installing libhypre-dev (Debian)"
  DEBIAN_FRONTEND=noninteractive apt-get install -y -q libhypre-dev >/dev/null
fi
NAMES=(pile10:400 pile20:600)    # scene:settle steps (bench/studies/spectrum/scenes_run.py)
[ "$MODE" = quick ] && NAMES=(pile10:400)
GIT="$(cd "$ROOT" && git rev-parse --short HEAD 2>/dev/null || echo unknown)"
LOAD_BEFORE="$(cut -d' ' -f1-3 /proc/loadavg)"
T0=$SECONDS
mpicxx -O2 -DNDEBUG -I/usr/include/hypre -I/usr/include/eigen3 \
  "$ROOT/bench/studies/amg/amg_pcg.cpp" -o "$WORK/amg_pcg" -lHYPRE
bench_rest_problems "${NAMES[@]}"
OUT="$RESULTS/amg.txt"
{
  echo "BoomerAMG against Jacobi as cg's preconditioner ($MODE), $(date -u '+%Y-%m-%d %H:%M UTC')," \
       "$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -1), hardcontact $GIT,"
  echo "hypre $(dpkg-query -W -f '${Version}' libhypre-dev 2>/dev/null), load before $LOAD_BEFORE;" \
       "linear PCG on the exact pushing rows from the fix's warm start to its test (tol 1e-4)"
  ("$PY" "$ROOT/bench/studies/amg/amg.py" "$WORK/system" "${PROBLEMS[@]}") |
    while read -r label path; do
      OMP_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
        "$WORK/amg_pcg" "$path" "$label"
    done
  echo "load after $(cut -d' ' -f1-3 /proc/loadavg), $(( SECONDS - T0 )) s"
} > "$OUT"
cat "$OUT"
