#!/usr/bin/env bash
# The cone (fix hardcontact `cone lagged|exact|convex`, doc/fix_hardcontact.md) on the example
# scenes, the fix's other settings at their defaults with friction (hybrid, tol 1e-2), beside each
# scene's soft twin: the drum's dynamic angle (examples/drum, R 7, 1.25 revolutions), the heap's
# flank and cone angles (examples/heap, 3 seeds of fix pour) and hopper3d's discharge rate
# (examples/hopper3d, outlet 10 mm, its deck's step). Loop time, iterations per step, largest
# overlap and solves at maxiter of each run, one process per run, two runs at a time (load 2).
# Writes friction_cones.csv into bench/results/friction/<host>/ (bench/common.sh).
#   bench/friction/cones.sh [--quick] [--stiff]   (--quick: drum 0.25 revolutions, heap 400
#                                           spheres and one seed, no hopper; --stiff: only the
#                                           soft twins at 10 x their kn, rows soft10, appended)
set -euo pipefail
STIFF=no; ARGS=()
for arg in "$@"; do if [ "$arg" = --stiff ]; then STIFF=yes; else ARGS+=("$arg"); fi; done
# shellcheck source=../common.sh
source "$(dirname "${BASH_SOURCE[0]}")/../common.sh" friction_cones_ "${ARGS[@]}"
EX="$ROOT/examples"
SEEDS=(4767548 1234567 7654321); DRUM=(); HEAP=(); HOPPER=yes
[ "$MODE" = quick ] && { SEEDS=(4767548); DRUM=(-var nrev 0.25); HEAP=(-var npour 400 -var tend 30); HOPPER=no; }
CSV="$RESULTS/friction_cones.csv"
[ "$MODE" = quick ] && CSV="$RESULTS/friction_cones_quick.csv"
[ "$STIFF" = yes ] && [ -f "$CSV" ] ||
  echo "scene,run,seed,observable,value,loop_s,steps,it_mean,overlap_max,maxiter_stops,load1" > "$CSV"

# hard DIR: iterations (mean over the thermo rows after the first), largest overlap, maxiter stops
hard_stats() {
  local it ov stops
  it=$(bench_thermo "$1/log.lammps" mean:f_hc[1])
  IFS=, read -r ov stops < <(bench_thermo --keep-first "$1/log.lammps" max:f_hc[7] last:f_hc[6])
  echo "$it,$ov,$stops"
}

# the twins' springs: each deck's default kn, and 10 x it (soft10)
KN_DRUM=6000; KN_HEAP=6000; KN_HOPPER=2000
drum() {    # drum CONE|soft|soft10
  local d="$WORK/drum_$1" angle loop steps stats=",,"
  if [ "${1#soft}" != "$1" ]; then
    local kn=$KN_DRUM; [ "$1" = soft10 ] && kn=$((10 * KN_DRUM))
    (cd "$EX/drum" && LMP_SOFT="$SOFT_LMP" HARDCONTACT_LMP="$LMP" bash run.sh "$d" soft "${DRUM[@]}" -var kn "$kn" > "$d.out" 2>&1)
    d="$d/soft"
  else
    (cd "$EX/drum" && HARDCONTACT_LMP="$LMP" bash run.sh "$d" hard -var solver "cone $1" "${DRUM[@]}" > "$d.out" 2>&1)
    d="$d/hard"
    stats=$(hard_stats "$d")
  fi
  angle=$("$PY" "$EX/drum/drum_angle.py" "$d/drum.dump" "$d/log.lammps" | sed -n 's/.*dynamic angle \([0-9.]*\) +- \([0-9.]*\).*/\1 +- \2/p')
  # the rotation is the deck's last run: its loop time and steps
  IFS=, read -r loop steps < <(bench_thermo "$d/log.lammps" loop steps)
  echo "drum,$1,,dynamic angle (deg),$angle,$loop,$steps,$stats,$(bench_load1)" >> "$CSV"
}

heap() {    # heap CONE|soft|soft10 SEED
  local d="$WORK/heap_$1_$2" angle flank loop steps stats=",,"
  mkdir -p "$d"
  if [ "${1#soft}" != "$1" ]; then
    local kn=$KN_HEAP; [ "$1" = soft10 ] && kn=$((10 * KN_HEAP))
    (cd "$d" && "$SOFT_LMP" -in "$EX/heap/in.heap.soft" -var mu 0.5 -var seed "$2" -var kn "$kn" "${HEAP[@]}" \
       -log log.lammps -echo none -screen none > /dev/null)
  else
    (cd "$d" && "$LMP" -in "$EX/heap/in.heap" -var mu 0.5 -var seed "$2" -var fix_extra "cone $1" \
       "${HEAP[@]}" -log log.lammps -echo none -screen none > /dev/null)
    stats=$(hard_stats "$d")
  fi
  angle=$("$PY" "$EX/heap/heap_angle.py" --floor 1.0 "$d/heap.dump")
  flank=$(sed -n 's/.*flank \([0-9.]*\) deg.*/\1/p' <<< "$angle")
  angle="${flank:-nan} / $(sed -n 's/.*cone \([0-9.]*\) deg.*/\1/p' <<< "$angle")"
  IFS=, read -r loop steps < <(bench_thermo "$d/log.lammps" loop steps)
  echo "heap,$1,$2,flank / cone angle (deg),$angle,$loop,$steps,$stats,$(bench_load1)" >> "$CSV"
}

hopper() {    # hopper CONE|soft|soft10: outlet 10 mm, from the settled bed of the same model
  local d="$WORK/hopper_$1" rate loop steps stats=",,"
  if [ "${1#soft}" != "$1" ]; then
    local kn=$KN_HOPPER; [ "$1" = soft10 ] && kn=$((10 * KN_HOPPER))
    (cd "$EX/hopper3d" && LMP_SOFT="$SOFT_LMP" HARDCONTACT_LMP="$LMP" bash run.sh "$d" soft 10 -var kn "$kn" > "$d.out" 2>&1)
    d="$d/soft_D10"
  else
    (cd "$EX/hopper3d" && HARDCONTACT_LMP="$LMP" bash run.sh "$d" hard 10 -var solver "hybrid cone $1" \
       -var tol 1e-2 > "$d.out" 2>&1)
    d="$d/hard_D10"
    stats=$(hard_stats "$d")
  fi
  rate=$("$PY" "$EX/hopper3d/beverloo3d.py" "$(dirname "$d")" 10 2>/dev/null | awk '$1 == "10.0" {print $3; exit}')
  IFS=, read -r loop steps < <(bench_thermo "$d/log.lammps" loop steps)
  echo "hopper3d,$1,,discharge rate (beads/s) at D 10 mm,${rate:-nan},$loop,$steps,$stats,$(bench_load1)" >> "$CSV"
}

if [ "$STIFF" = yes ]; then    # two runs at a time, as the rows beside them were measured
  drum soft10 &
  if [ "$HOPPER" = yes ]; then hopper soft10; fi
  wait
  for ((k = 0; k < ${#SEEDS[@]}; k += 2)); do
    heap soft10 "${SEEDS[k]}" &
    if [ $((k + 1)) -lt ${#SEEDS[@]} ]; then heap soft10 "${SEEDS[k + 1]}"; fi
    wait
  done
  column -t -s, "$CSV"
  exit 0
fi
for pair in "lagged exact" "convex soft"; do
  read -r a b <<< "$pair"
  drum "$a" & drum "$b" & wait
  for seed in "${SEEDS[@]}"; do heap "$a" "$seed" & heap "$b" "$seed" & wait; done
  if [ "$HOPPER" = yes ]; then hopper "$a" & hopper "$b" & wait; fi
done
column -t -s, "$CSV"
