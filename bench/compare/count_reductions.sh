#!/usr/bin/env bash
# Collective reductions per step of a build (issue 37 item 5): the 1210-sphere pile of
# in.pile3d (COMPARE_EXTRA: fix keywords, e.g. "friction 0.5"; SOLVER, default the fix's)
# run for N and 2N steps under mpirun -np 2 with a counting MPI_Allreduce/MPI_Reduce
# (count_reductions.c, LD_PRELOAD); the difference over N is the count per step, and the
# iterations per step (thermo f_hc[1] summed) say how many of those the solver's iterations make.
#   bench/compare/count_reductions.sh LMP [N]
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
[ $# -ge 1 ] || { echo "usage: $0 LMP [N]" >&2; exit 2; }
LMP="$(realpath "$1")"; N="${2:-20}"
WORK="${BENCH_WORKDIR:-$ROOT/bench/work}/count_reductions"
mkdir -p "$WORK"; cd "$WORK"
mpicc -shared -fPIC -O2 -o libcount_reductions.so "$HERE/count_reductions.c"
EXTRA="${COMPARE_EXTRA:-}"
SOLVER="${SOLVER:-}"
if [ -n "$SOLVER" ]; then
  sed "s/hardcontact solver \${solver} wall/hardcontact solver \${solver} $EXTRA wall/" "$HERE/in.pile3d" > in.pile3d
else
  sed "s/hardcontact solver \${solver} wall/hardcontact $EXTRA wall/" "$HERE/in.pile3d" > in.pile3d
fi
ROOT_FLAG=""; [ "$(id -u)" = 0 ] && ROOT_FLAG="--allow-run-as-root"
count() {    # steps
  mpirun $ROOT_FLAG -np 2 --oversubscribe -x LD_PRELOAD="$WORK/libcount_reductions.so" "$LMP" \
    -in in.pile3d -var solver "${SOLVER:-apgd}" -var nz 10 -var n "$1" -log "log.$1" \
    > /dev/null 2> "err.$1"
  sed -n 's/^reductions: allreduce \([0-9]*\) reduce \([0-9]*\)/\1 \2/p' "err.$1"
}
read -r a1 r1 < <(count "$N")
read -r a2 r2 < <(count $((2 * N)))
iters() { awk '/^ *Step/{f=1;for(i=1;i<=NF;i++) if($i=="f_hc[1]") c=i; next} /^Loop/{f=0} f && c {s+=$c} END{print s+0}' "$1"; }
i1=$(iters "log.$N"); i2=$(iters "log.$((2 * N))")
awk -v a1="$a1" -v a2="$a2" -v r1="$r1" -v r2="$r2" -v i1="$i1" -v i2="$i2" -v n="$N" \
  'BEGIN{printf "per step over steps %d..%d: allreduce %.2f, reduce %.2f, solver iterations %.2f\n", n, 2*n, (a2-a1)/n, (r2-r1)/n, (i2-i1)/n}'
