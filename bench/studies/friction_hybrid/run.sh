#!/usr/bin/env bash
# The hybrid frictional solver against apgd and nsgs (bench/studies/friction_hybrid/README.md):
# the crystal beds of test_stab_friction.py at tol 1e-2 and 1e-4, then examples/heap (800
# spheres, t = 45, seed 1) and examples/drum (0.5 revolution) with apgd and hybrid side by side,
# one process each, two at a time. About 12 minutes on 2 cores. Results:
# bench/studies/friction_hybrid/results/friction_hybrid.csv (beds) and friction_hybrid_scenes.txt.
# HARDCONTACT_LMP: the launcher (default build/lmp_hardcontact, any build from the commit that
# added solver hybrid).
set -euo pipefail
# shellcheck source=../../common.sh
source "$(dirname "${BASH_SOURCE[0]}")/../../common.sh" friction_hybrid_ "$@"
export HARDCONTACT_LMP="$LMP" OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
RES="$RESULTS"
echo "# $(date -u +%F) $(uname -n) $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg); $(git -C "$ROOT" rev-parse --short HEAD)" > "$RES/friction_hybrid.csv"
echo "case,solver,tol,loop_s,it_mean,it_rest_mean,it_rest_max,maxiter_stops,ke_rel_rest_per_sphere" >> "$RES/friction_hybrid.csv"
for tol in 1e-2 1e-4; do
  for case in conveyor slide; do
    for pair in "apgd nsgs" "hybrid"; do
      for s in $pair; do
        "$PY" "$ROOT/bench/studies/friction_hybrid/beds.py" "$case" "$s" "$tol" "$WORK/${case}_${s}_$tol" \
          > "$WORK/${case}_${s}_$tol.csv" &
      done
      wait
    done
  done
done
cat "$WORK"/*.csv | sort >> "$RES/friction_hybrid.csv"

out="$RES/friction_hybrid_scenes.txt"
echo "# $(date -u +%F) load $(cut -d' ' -f1-3 /proc/loadavg); apgd and hybrid side by side, one process each" > "$out"
for s in apgd hybrid; do
  mkdir -p "$WORK/heap_$s"
  sed "s/hardcontact tol \${tol}/hardcontact solver $s tol \${tol}/" "$ROOT/examples/heap/in.heap" > "$WORK/heap_$s/in.heap"
  (cd "$WORK/heap_$s" && "$LMP" -in in.heap -var npour 800 -var tend 45 -var mu 0.5 -var mur 0.1 \
      -var thermo_every 50 -var dump_every 2250 -log log.lammps -screen none) &
done
wait
for s in apgd hybrid; do
  loop=$(bench_thermo "$WORK/heap_$s/log.lammps" loop)
  angle=$("$PY" -c "import sys; sys.path.insert(0, '$ROOT/examples/heap'); import heap_angle as h; r = h.heap_angle('$WORK/heap_$s/heap.dump', floor=1.0); print('cone %.2f deg, flank %.2f deg' % (r['cone_angle'], r['angle']))")
  echo "heap $s: loop $loop s, $angle" >> "$out"
done
for s in apgd hybrid; do
  bash "$ROOT/examples/drum/run.sh" "$WORK/drum_$s" hard -var solver "solver $s" -var nrev 0.5 \
    > "$WORK/drum_$s.log" 2>&1 &
done
wait
for s in apgd hybrid; do
  echo "drum $s: $(grep -E '^drum hard' "$WORK/drum_$s.log" | sed 's/^drum hard *: //'); $(grep -E 'dynamic angle' "$WORK/drum_$s.log" | sed 's/^hard *//')" >> "$out"
done
cat "$RES/friction_hybrid.csv" "$out"
