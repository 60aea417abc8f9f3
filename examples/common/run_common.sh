# shellcheck shell=bash
# What the examples' run scripts share (examples/*/run.sh, examples/compare.sh). Sourced, bash:
#   source "$(dirname "${BASH_SOURCE[0]}")/../common/run_common.sh"
#
# Sets (set -euo pipefail too):
#   HERE      the folder of the script that sources this file (its decks and python scripts)
#   ROOT      the repository
#   LMP       $HARDCONTACT_LMP, default build/lmp_hardcontact (a path, or a name on PATH; made
#             absolute, and it must be executable: the scripts run LAMMPS from the run folders)
#   LMP_SOFT  $LMP_SOFT, default $LMP: the LAMMPS of the soft-sphere twins
#   PY        /usr/bin/python3 (Debian's numpy and matplotlib), else python3 from PATH
#   HC_NP     1: the number of MPI ranks of hc_lmp (> 1: mpirun, allowed as root)
# and the functions hc_outdir, hc_lmp, hc_loop_time, hc_twin_args and hc_twins below.
#
# LAMMPS_PLUGIN_PATH passes through untouched: with a modern LAMMPS (PLUGIN package) as
# HARDCONTACT_LMP, LAMMPS_PLUGIN_PATH=<folder of hardcontactplugin.so> makes every LAMMPS process
# (serial or under mpirun, which hands the environment to its ranks) load the fix at start-up.
set -euo pipefail

HERE="$(cd "$(dirname "${BASH_SOURCE[1]}")" && pwd)"
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"

hc_executable() {    # hc_executable PATH|NAME: its absolute path if it is an executable file, else nothing
  case "$1" in
    */*) [ -f "$1" ] && [ -x "$1" ] && echo "$(cd "$(dirname "$1")" && pwd)/$(basename "$1")" ;;
    *) type -P -- "$1" ;;
  esac
}
LMP="${HARDCONTACT_LMP:-$ROOT/build/lmp_hardcontact}"
LMP="$(hc_executable "$LMP")" || { echo "no ${HARDCONTACT_LMP:-$ROOT/build/lmp_hardcontact}: build first (bash .ci/build.sh)" >&2; exit 1; }
LMP_SOFT="${LMP_SOFT:-$LMP}"
LMP_SOFT="$(hc_executable "$LMP_SOFT" || echo "$LMP_SOFT")"
PY=/usr/bin/python3; [ -x "$PY" ] || PY=python3
HC_NP=1

hc_outdir() {    # hc_outdir DIR: makes DIR and sets OUT to its absolute path
  mkdir -p "$1"
  OUT="$(cd "$1" && pwd)"
}

# hc_lmp DIR PICTURES WHAT LAUNCHER DECK [LAMMPS arguments...]
# In DIR (made; the old pictures, glob PICTURES, removed): LAUNCHER -in $HERE/DECK -log log.lammps
# [arguments] > screen.txt, serial or under mpirun with HC_NP ranks. If LAMMPS fails: the end of
# screen.txt and "WHAT failed (see DIR)" on stderr, and exit 1.
hc_lmp() {
  local dir="$1" pictures="$2" what="$3" launcher="$4" deck="$5"
  shift 5
  local cmd=("$launcher")
  if [ "$HC_NP" -gt 1 ]; then
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
    cmd=(mpirun --oversubscribe -np "$HC_NP" "$launcher")
  fi
  mkdir -p "$dir"
  # shellcheck disable=SC2086   # PICTURES is a glob
  [ -z "$pictures" ] || rm -f "$dir"/$pictures
  (cd "$dir" && "${cmd[@]}" -in "$HERE/$deck" -log log.lammps "$@" > screen.txt) || {
    tail -5 "$dir/screen.txt" >&2
    if grep -q "fix style 'hardcontact'" "$dir/screen.txt"; then
      echo "($launcher does not know fix hardcontact: use build/lmp_hardcontact, or with a LAMMPS" \
           "built with the PLUGIN package set LAMMPS_PLUGIN_PATH=<folder of hardcontactplugin.so>)" >&2
    fi
    echo "$what failed (see $dir)" >&2
    exit 1
  }
}

# hc_loop_time LOG FORMAT LABEL: prints printf FORMAT with LABEL, the steps and the loop time
# (seconds) summed over the runs of a LAMMPS log.
hc_loop_time() {
  awk -v fmt="$2" -v label="$3" '/^Loop time/{t += $4; n += $9} END{printf fmt, label, n, t}' "$1"
}

# The scenes with a soft-sphere twin (pile, pour, disc_packing), whose run.sh reads
#   run.sh [OUTDIR] [hard|soft|both] [extra LAMMPS arguments]
# hc_twin_args SCENE "$@": sets OUT (made; default out/SCENE), WHICH (default both) and the
# array LMP_ARGS (the extra LAMMPS arguments).
hc_twin_args() {
  local scene="$1"
  shift
  hc_outdir "${1:-$ROOT/out/$scene}"
  WHICH="${2:-both}"
  shift $(( $# >= 2 ? 2 : $# ))
  # shellcheck disable=SC2034   # LMP_ARGS is for the sourcing script
  LMP_ARGS=("$@")
  case "$WHICH" in
    hard|soft|both) ;;
    *) echo "$scene: second argument is hard, soft or both" >&2; exit 1 ;;
  esac
}

# hc_twins SCENE NAME [LAMMPS arguments...]: per WHICH, runs $HERE/in.NAME with LMP into OUT/hard
# and/or its twin $HERE/in.NAME.soft with LMP_SOFT into OUT/soft (-var potentials <repo>/potentials
# and the arguments; pictures NAME.<step>.png, dump NAME.dump), printing the steps and loop time
# of each; with both, then compare.py (OUT/compare.png and the table) and plot_bed.py
# (OUT/chains.png).
hc_twins() {
  local scene="$1" name="$2"
  shift 2
  local runs="$WHICH" d launcher deck
  [ "$WHICH" != both ] || runs="hard soft"
  for d in $runs; do
    if [ "$d" = hard ]; then launcher="$LMP" deck="in.$name"; else launcher="$LMP_SOFT" deck="in.$name.soft"; fi
    hc_lmp "$OUT/$d" "$name.*.png" "$scene: $deck" "$launcher" "$deck" -var potentials "$ROOT/potentials" "$@"
    hc_loop_time "$OUT/$d/log.lammps" "$scene %-4s: %d steps, loop time %.2f s\n" "$d"
  done
  if [ "$WHICH" = both ]; then
    "$PY" "$ROOT/examples/compare.py" "$scene" "$OUT/hard" "$OUT/soft" "$OUT/compare.png"
    "$PY" "$ROOT/examples/common/plot_bed.py" "$OUT/chains.png" \
      "$OUT/hard:$name.dump:contacts.dump:hard:fix hardcontact" \
      "$OUT/soft:$name.dump:contacts.dump:soft:soft spheres (gran/hertz/history)"
  fi
}
