# The start every bench entry script shares (sourced, not run):
#   source "$(dirname "${BASH_SOURCE[0]}")/common.sh" <work-prefix> "$@"
# reads the optional --quick argument and sets ROOT, PY, MODE (full|quick), QUICK (the flag to
# pass on), LMP (HARDCONTACT_LMP, default build/lmp_hardcontact), SOFT_LMP (default
# /usr/bin/lmp, Debian's LAMMPS), WORK (BENCH_WORKDIR or bench/work, then <work-prefix><MODE>)
# and RESULTS (bench/results), and makes the two folders.
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
PY=/usr/bin/python3
_bench_prefix="$1"
shift
MODE=full
QUICK=()
if [ "${1:-}" = "--quick" ]; then MODE=quick; QUICK=(--quick); shift; fi
[ $# -eq 0 ] || { echo "usage: $0 [--quick]" >&2; exit 2; }
LMP="${HARDCONTACT_LMP:-$ROOT/build/lmp_hardcontact}"
SOFT_LMP="${SOFT_LMP:-/usr/bin/lmp}"
[ -x "$LMP" ] || { echo "no $LMP: build first (bash .ci/build.sh) or set HARDCONTACT_LMP" >&2; exit 1; }
[ -x "$SOFT_LMP" ] || { echo "no $SOFT_LMP (Debian package lammps): set SOFT_LMP" >&2; exit 1; }
WORK="${BENCH_WORKDIR:-$ROOT/bench/work}/$_bench_prefix$MODE"
RESULTS="$ROOT/bench/results"
mkdir -p "$WORK" "$RESULTS"
