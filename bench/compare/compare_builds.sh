#!/usr/bin/env bash
# Two builds of lmp_hardcontact on the same decks: instructions counted by callgrind (repeatable
# whatever else the machine does, unlike seconds on a shared 2-core machine) and whether the
# thermo output (iterations, candidates, active rows, residuals, overlaps per step) is identical.
#   bench/compare/compare_builds.sh OLD_LMP NEW_LMP [STEPS]
# Scenes: a 3D polydisperse pile (1210 spheres, 10 layers, walled box) settling, with apgd, pgs
# and uzawa (COMPARE_SOLVERS="apgd ..." to choose), frictionless or with the fix keywords of
# COMPARE_EXTRA (e.g. "friction 0.5"). Prints one line per solver; writes nothing outside
# $BENCH_WORKDIR (default bench/work/compare).
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
[ $# -ge 2 ] || { echo "usage: $0 OLD_LMP NEW_LMP [STEPS]" >&2; exit 2; }
OLD="$(realpath "$1")"; NEW="$(realpath "$2")"; STEPS="${3:-60}"
command -v valgrind >/dev/null || { echo "valgrind is needed (apt-get install valgrind)" >&2; exit 1; }
WORK="${BENCH_WORKDIR:-$ROOT/bench/work}/compare"
mkdir -p "$WORK"; cd "$WORK"
EXTRA="${COMPARE_EXTRA:-}"
sed "s/hardcontact solver \${solver} wall/hardcontact solver \${solver} $EXTRA wall/" "$HERE/in.pile3d" > in.pile3d
# the thermo rows (warnings name source lines, which a change may move)
thermo() { awk '/^ *Step/{f=1;next} /^Loop/{f=0} f && !/^WARNING/' "$1"; }
count() { sed -n 's/.*Collected : \([0-9]*\).*/\1/p' "$1"; }
echo "solver  steps  old_instructions  new_instructions  new/old  thermo"
for solver in ${COMPARE_SOLVERS:-apgd pgs uzawa}; do
  for which in old new; do
    lmp=$OLD; [ "$which" = new ] && lmp=$NEW
    valgrind --tool=callgrind --callgrind-out-file="cg.$which.$solver" "$lmp" \
      -in in.pile3d -var solver "$solver" -var nz 10 -var n "$STEPS" \
      -log "log.$which.$solver" > /dev/null 2> "cg.$which.$solver.err"
  done
  o=$(count "cg.old.$solver.err"); n=$(count "cg.new.$solver.err")
  same=differs; cmp -s <(thermo "log.old.$solver") <(thermo "log.new.$solver") && same=identical
  awk -v s="$solver" -v t="$STEPS" -v o="$o" -v n="$n" -v m="$same" \
    'BEGIN{printf "%-7s %5d  %16.0f  %16.0f  %7.3f  %s\n", s, t, o, n, n/o, m}'
done
