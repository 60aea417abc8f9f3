# The start every bench entry script shares (sourced, not run): a suite's bench/<suite>/run.sh
# sources "$(dirname "${BASH_SOURCE[0]}")/../common.sh" <work-prefix> "$@", a study's
# bench/studies/<topic>/run.sh "$(dirname "${BASH_SOURCE[0]}")/../../common.sh" <work-prefix> "$@".
# Reads the optional --quick argument and sets ROOT, PY, MODE (full|quick), QUICK (the flag to
# pass on), LMP (HARDCONTACT_LMP, default build/lmp_hardcontact), SOFT_LMP (default
# /usr/bin/lmp, Debian's LAMMPS), WORK (BENCH_WORKDIR or bench/work, then <work-prefix><MODE>),
# HOST_TAG (BENCH_HOST_TAG, else the CPU model: amd-epyc, intel-xeon, ...) and RESULTS, and
# makes the two folders. RESULTS: a suite's bench/results/<suite>/<HOST_TAG>/, a study's
# bench/studies/<topic>/results/; a --quick run writes beside them, to <HOST_TAG>-quick/ or
# results-quick/ (not committed). machine.txt in RESULTS records the host of the last run.
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
_bench_cpu="$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -1)"
HOST_TAG="${BENCH_HOST_TAG:-$(printf '%s' "${_bench_cpu:-unknown}" | tr 'A-Z' 'a-z' |
  sed -e 's/([rR]\{1,2\})//g; s/(tm)//g; s/@.*//; s/\<\(processor\|cpu\)\>//g' \
      -e 's/[^a-z0-9]\{1,\}/-/g; s/^-//; s/-$//')}"
_bench_dir="$(cd "$(dirname "${BASH_SOURCE[1]}")" && pwd)"
case "$_bench_dir" in
  "$ROOT"/bench/studies/*) RESULTS="$_bench_dir/results" ;;
  *) RESULTS="$ROOT/bench/results/$(basename "$_bench_dir")/$HOST_TAG" ;;
esac
[ "$MODE" = quick ] && RESULTS="$RESULTS-quick"
mkdir -p "$WORK" "$RESULTS"
{
  echo "script: ${BASH_SOURCE[1]#"$ROOT"/} ($MODE)"
  echo "date: $(date -u '+%Y-%m-%d %H:%M UTC')"
  echo "cpu: ${_bench_cpu:-unknown}"
  echo "cores: $(nproc)"
  echo "load (1, 5, 15 min) at the start: $(cut -d' ' -f1-3 /proc/loadavg)"
  echo "commit: $(git -C "$ROOT" rev-parse --short HEAD 2>/dev/null || echo unknown)"
  echo "launcher: $LMP"
} > "$RESULTS/machine.txt"

# Scenes two studies share (friction_rest, subspace_default):
# the walls of bench/compare/in.pile3d
PILE_WALLS="wall xplane 0 11 wall yplane 0 11 wall zplane 0 NULL"
# bench_tray_1000 FILE: the tray of bench/perf's section 2 (196 small spheres under one of
# 1000 x their mass, bench/perf/scenes.py) written to FILE; prints its wall keywords
bench_tray_1000() {
  "$PY" - "$1" <<PYEOF
import sys
sys.path.insert(0, "$ROOT/bench/perf")
import scenes
tray = scenes.tray(1000)
scenes.write(tray, sys.argv[1])
print(tray["walls"])
PYEOF
}
# bench_thermo [--each] LOG FIELD...: numbers of LOG's last thermo block for a CSV row, one line
# (or one per row of the window with --each); fields such as rows, mean:f_hc[1], max:f_hc[7],
# delta:f_hc[6], loop, load (python3 -m hctools thermo -h: python/hctools/summary.py)
bench_thermo() { PYTHONPATH="$ROOT/python${PYTHONPATH:+:$PYTHONPATH}" "$PY" -m hctools thermo "$@"; }
# bench_load1: the 1-minute load average, recorded beside each timed run
bench_load1() { cut -d' ' -f1 /proc/loadavg; }
# bench_restart_deck OUT LINES: a deck that reads the restart ${R} and goes on under gravity
# with the fix (tol 1e-4, walls ${walls}), then LINES (thermo, computes, run ...)
bench_restart_deck() {
  {
    printf '%s\n' 'read_restart    ${R}' 'neighbor        0.3 bin' \
      'neigh_modify    delay 0 every 1 check yes' 'fix             grav all gravity 1.0 vector 0 0 -1' \
      'fix             hc all hardcontact tol 1e-4 ${extra} ${walls}' 'timestep        0.02'
    printf '%s\n' "$2"
  } > "$1"
}
# bench_pile_deck OUT SED: bench/compare/in.pile3d with a slot ${extra} for more keywords of the
# fix and a write_restart ${W} after its run, its thermo lines changed by the sed expression SED
bench_pile_deck() {
  sed -e 's/hardcontact solver ${solver} wall/hardcontact solver ${solver} ${extra} wall/' \
      -e "$2" \
      -e 's/^run .*/run             ${n}\nwrite_restart   ${W}/' \
      "$ROOT/bench/compare/in.pile3d" > "$1"
}
# bench_tray_settle_deck OUT KEYWORDS: the tray (tray_m1000.data in the run's folder) settled
# for 200 steps by the default solver with KEYWORDS, written to tray.restart; walls ${walls}
bench_tray_settle_deck() {
  cat > "$1" <<EOF
units           lj
dimension       3
atom_style      sphere
boundary        f f f
atom_modify     map array
read_data       tray_m1000.data
pair_style      none
neighbor        0.3 bin
neigh_modify    delay 0 every 1 check yes
fix             grav all gravity 1.0 vector 0 0 -1
fix             hc all hardcontact ${2:+$2 }\${walls}
timestep        0.02
thermo          50
run             200
write_restart   tray.restart
EOF
}

# bench_rest_problems NAME:SETTLE ...: the scenes of bench/studies/spectrum/scenes_run.py settled with
# the default solver and a window at rest dumped into $WORK (HARDCONTACT_DUMP_PROBLEMS); fills
# PROBLEMS with NAME@STEP=FILE for the two steps the spectrum study takes: the third step at
# rest and 9 later (studies coarse_space and amg)
bench_rest_problems() {
  "$PY" "$ROOT/bench/studies/spectrum/scenes_run.py" --lmp "$LMP" --work "$WORK" "${@%%:*}"
  PROBLEMS=()
  local entry name settle
  for entry in "$@"; do
    name=${entry%%:*}
    settle=${entry##*:}
    PROBLEMS+=("$name@$((settle + 3))=$WORK/$name/problem.$((settle + 3))"
               "$name@$((settle + 12))=$WORK/$name/problem.$((settle + 12))")
  done
}
