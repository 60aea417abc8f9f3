#!/usr/bin/env bash
# The heap of examples/heap (800 spheres poured onto a rough floor, mu 0.5, t = 45) by the fix
# at tol 1e-2, 1e-3, 1e-4 and by its soft twin (pair_style granular), each with three seeds of
# fix pour: flank and cone angles (examples/heap/heap_angle.py) and loop times, one process.
# Writes friction_front_heap.csv into bench/results/friction/<host>/ (bench/common.sh).
#   bench/friction/heap_front.sh [--quick]      (--quick: 400 spheres to t = 30, one seed)
set -euo pipefail
# shellcheck source=../common.sh
source "$(dirname "${BASH_SOURCE[0]}")/../common.sh" friction_front_heap_ "$@"
HEAP="$ROOT/examples/heap"
SEEDS=(4767548 1234567 7654321); EXTRA=()
[ "$MODE" = quick ] && { SEEDS=(4767548); EXTRA=(-var npour 400 -var tend 30); }
CSV="$RESULTS/friction_front_heap.csv"
[ "$MODE" = quick ] && CSV="$RESULTS/friction_front_heap_quick.csv"
echo "run,kind,tol,seed,flank_deg,cone_deg,peak,loop_s,steps,it_mean,overlap_max,maxiter_stops,load1" > "$CSV"
for seed in "${SEEDS[@]}"; do
  for tol in 1e-2 1e-3 1e-4 soft; do
    d="$WORK/${tol}_$seed"
    mkdir -p "$d"
    if [ "$tol" = soft ]; then exe="$SOFT_LMP"; deck="$HEAP/in.heap.soft"; args=(); else
      exe="$LMP"; deck="$HEAP/in.heap"; args=(-var tol "$tol"); fi
    (cd "$d" && "$exe" -in "$deck" -var mu 0.5 -var seed "$seed" "${args[@]}" "${EXTRA[@]}" \
       -log log.lammps -echo none -screen none > /dev/null)
    angle=$("$PY" "$HEAP/heap_angle.py" --floor 1.0 "$d/heap.dump")
    load=$(bench_load1)
    flank=$(sed -n 's/.*flank \([0-9.]*\) deg.*/\1/p' <<< "$angle"); flank=${flank:-nan}
    cone=$(sed -n 's/.*cone \([0-9.]*\) deg.*/\1/p' <<< "$angle")
    peak=$(sed -n 's/.*peak \([0-9.]*\).*/\1/p' <<< "$angle")
    if [ "$tol" = soft ]; then
      IFS=, read -r loop steps < <(bench_thermo "$d/log.lammps" loop steps)
      echo "soft,soft,soft,$seed,$flank,$cone,$peak,$loop,$steps,,,,$load" >> "$CSV"
    else
      # iterations: the mean over the rows after the first (step 0: no solve); overlap: the
      # largest of every row; maxiter stops: the counter at the end
      IFS=, read -r loop steps it < <(bench_thermo "$d/log.lammps" loop steps mean:f_hc[1])
      IFS=, read -r ov stops < <(bench_thermo --keep-first "$d/log.lammps" max:f_hc[7] last:f_hc[6])
      echo "hard_tol$tol,hard,$tol,$seed,$flank,$cone,$peak,$loop,$steps,$it,$ov,$stops,$load" >> "$CSV"
    fi
    tail -1 "$CSV"
  done
done
