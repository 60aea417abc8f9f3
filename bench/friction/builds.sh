#!/usr/bin/env bash
# Two builds of the fix on issue 36's frictional scenes at the fix's defaults, same run: each
# scene runs under the old and the new build at once (two runs at a time, one process each), so
# their loop times share the machine's load and can be compared as ratios. Scenes: the settles
# of 1210 and 8000 spheres (front.py's decks: mean height), examples/drum (R 7, 1.25
# revolutions: dynamic angle), examples/heap (3 seeds: flank / cone angle), examples/hopper3d
# (outlet 10 mm: discharge rate) and examples/column_collapse (3 seeds: runout). Per run: the
# observable, loop time, steps, iterations per step (thermo mean), largest overlap / size and
# solves at maxiter. Writes friction_builds.csv into bench/results/friction/<host>/.
#   bench/friction/builds.sh OLD_LMP NEW_LMP [--quick]
#     (--quick: the 6-layer settle, a quarter revolution, one heap of 400, no hopper, the short
#      column; checks the script). OLD_KEYWORDS / NEW_KEYWORDS: more fix keywords for either
#      run (the same build twice with NEW_KEYWORDS="speed contact" measures an option);
#      OLD_ENV / NEW_ENV: environment settings for either build (an experimental build's
#      switch), passed through `env`.
set -euo pipefail
OLD="$(realpath "$1")"; NEW="$(realpath "$2")"; shift 2    # the runs cd into the examples
# shellcheck source=../common.sh
source "$(dirname "${BASH_SOURCE[0]}")/../common.sh" friction_builds_ "$@"
EX="$ROOT/examples"
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
SEEDS=(4767548 1234567 7654321); DRUM=(); HEAP=(); HOPPER=yes; SETTLES=(settle10 settle20)
COLLAPSE=()
if [ "$MODE" = quick ]; then
  SEEDS=(4767548); DRUM=(-var nrev 0.25); HEAP=(-var npour 400 -var tend 30); HOPPER=no
  SETTLES=(quick); COLLAPSE=(-var nz 14 -var L0 6 -var tsettle 15 -var tend 30)
fi
CSV="$RESULTS/friction_builds.csv"
[ "$MODE" = quick ] && CSV="$RESULTS/friction_builds_quick.csv"
echo "scene,build,seed,observable,value,loop_s,steps,it_mean,overlap_max,maxiter_stops,load1" > "$CSV"

# per run (old, new): the executable, its extra fix keywords, its environment
declare -A LMP_OF=([old]="$OLD" [new]="$NEW")
declare -A KW_OF=([old]="${OLD_KEYWORDS:-}" [new]="${NEW_KEYWORDS:-}")
declare -A ENV_OF=([old]="${OLD_ENV:-}" [new]="${NEW_ENV:-}")
lmp_of() { echo "${LMP_OF[$1]}"; }
kw_of() { echo "${KW_OF[$1]}"; }
# The drum's and the hopper's decks write `tol ${tol}` after the keywords they are given, so a
# `tol X` among a build's keywords goes to their tol variable (else the deck's 1e-2 would win).
tol_of() { sed -n 's/.*\btol \([^ ]*\).*/\1/p' <<< "${KW_OF[$1]}"; }
kw_but_tol() { sed 's/\btol [^ ]*//' <<< "${KW_OF[$1]}"; }
# run BUILD COMMAND...: the command with the build's environment and HARDCONTACT_LMP
run() { local b="$1"; shift; env ${ENV_OF[$b]} HARDCONTACT_LMP="${LMP_OF[$b]}" "$@"; }

# hard_stats LOG: iterations per step (mean over the thermo rows after the first), the
# largest overlap / size and the solves at maxiter
hard_stats() {
  local it ov stops
  it=$(bench_thermo "$1" mean:f_hc[1])
  IFS=, read -r ov stops < <(bench_thermo --keep-first "$1" max:f_hc[7] last:f_hc[6])
  echo "$it,$ov,$stops"
}
row() {    # row SCENE BUILD SEED OBSERVABLE VALUE LOG
  local loop steps
  IFS=, read -r loop steps < <(bench_thermo "$6" loop steps)
  echo "$1,$2,$3,$4,$5,$loop,$steps,$(hard_stats "$6"),$(bench_load1)" >> "$CSV"
}

settle() {    # settle BUILD SCENE: front.py's default hard run (hybrid, tol 1e-2, h 0.02)
  local d="$WORK/settle_$1_$2" args=()
  case "$2" in quick) args=(--quick) ;; settle20) args=(--scene settle20) ;; esac
  BENCH_WORKDIR="$d" run "$1" "$PY" "$HERE/front.py" "${args[@]}" --lmp "$(lmp_of "$1")" \
    --only hybrid_tol0.01_h0.02 --fix-extra "$(kw_of "$1")" --results "$d" > "$d.out" 2>&1
  local log zavg
  log=$(ls "$d"/friction_front_*/hybrid_tol0.01_h0.02/log.lammps)
  zavg=$(bench_thermo "$log" last:c_zavg)
  row "$2" "$1" "" "mean height" "$zavg" "$log"
}
drum() {
  local d="$WORK/drum_$1" angle
  local kw=(); [ -n "$(kw_but_tol "$1" | tr -d ' ')" ] && kw=(-var solver "$(kw_but_tol "$1")")
  [ -n "$(tol_of "$1")" ] && kw+=(-var tol "$(tol_of "$1")")
  (cd "$EX/drum" && run "$1" bash run.sh "$d" hard "${DRUM[@]}" "${kw[@]}" > "$d.out" 2>&1)
  angle=$("$PY" "$EX/drum/drum_angle.py" "$d/hard/drum.dump" "$d/hard/log.lammps" |
          sed -n 's/.*dynamic angle \([0-9.]*\) +- \([0-9.]*\).*/\1 +- \2/p')
  row drum "$1" "" "dynamic angle (deg)" "$angle" "$d/hard/log.lammps"
}
heap() {    # heap BUILD SEED
  local d="$WORK/heap_$1_$2" angle
  local kw=(); [ -n "$(kw_of "$1")" ] && kw=(-var fix_extra "$(kw_of "$1")")
  mkdir -p "$d"
  (cd "$d" && run "$1" "$(lmp_of "$1")" -in "$EX/heap/in.heap" -var mu 0.5 -var seed "$2" \
     "${kw[@]}" "${HEAP[@]}" -log log.lammps -echo none -screen none > /dev/null)
  angle=$("$PY" "$EX/heap/heap_angle.py" --floor 1.0 "$d/heap.dump")
  angle="$(sed -n 's/.*flank \([0-9.]*\) deg.*/\1/p' <<< "$angle") / $(sed -n 's/.*cone \([0-9.]*\) deg.*/\1/p' <<< "$angle")"
  row heap "$1" "$2" "flank / cone angle (deg)" "$angle" "$d/log.lammps"
}
hopper() {
  local d="$WORK/hopper_$1" rate
  local tol; tol=$(tol_of "$1")
  (cd "$EX/hopper3d" && run "$1" bash run.sh "$d" hard 10 -var solver "hybrid $(kw_but_tol "$1")" \
     -var tol "${tol:-1e-2}" > "$d.out" 2>&1)
  rate=$("$PY" "$EX/hopper3d/beverloo3d.py" "$d" 10 2>/dev/null | awk '$1 == "10.0" {print $3; exit}')
  row hopper3d "$1" "" "discharge rate (beads/s) at D 10 mm" "${rate:-nan}" "$d/hard_D10/log.lammps"
}
collapse() {    # collapse BUILD SEED
  local d="$WORK/collapse_$1_$2" res
  local kw=(); [ -n "$(kw_of "$1")" ] && kw=(-var fix_extra "$(kw_of "$1")")
  mkdir -p "$d"
  (cd "$d" && run "$1" "$(lmp_of "$1")" -in "$EX/column_collapse/in.collapse" -var seed "$2" \
     "${kw[@]}" "${COLLAPSE[@]}" -log log.lammps -echo none -screen none > /dev/null)
  res=$(PYTHONPATH="$EX/column_collapse:$EX/common" "$PY" -c "import sys, collapse_runout as c
r = c.runout(sys.argv[1] + '/collapse0.dump', sys.argv[1] + '/collapse1.dump')
print('%.4f' % r['runout'])" "$d")
  # the whole deck (the column settling behind the gate, then the collapse): both runs' loop
  # times and steps
  local loop steps
  read -r loop steps < <(awk '/^Loop time/{t += $4; n += $9} END{printf "%.2f %d\n", t, n}' "$d/log.lammps")
  echo "collapse,$1,$2,runout (L_inf - L0) / L0,${res:-nan},$loop,$steps,$(hard_stats "$d/log.lammps"),$(bench_load1)" >> "$CSV"
}

for s in "${SETTLES[@]}"; do settle old "$s" & settle new "$s" & wait; done
drum old & drum new & wait
for seed in "${SEEDS[@]}"; do heap old "$seed" & heap new "$seed" & wait; done
if [ "$HOPPER" = yes ]; then hopper old & hopper new & wait; fi
for seed in "${SEEDS[@]}"; do collapse old "$seed" & collapse new "$seed" & wait; done
column -t -s, "$CSV"
