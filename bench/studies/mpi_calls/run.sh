#!/usr/bin/env bash
# Messages and global reductions per solver iteration, counted (not read off the code):
# bench/studies/mpi_calls/count_mpi_calls.c, preloaded into the unchanged launcher through MPI's
# profiling interface, counts every process's MPI calls. Two scenes, the settling pile of
# bench/compare/in.pile3d (NZ layers of 121 spheres, tol 1e-4): frictionless with `cg` (the
# default without friction, STEPS steps) and with `friction 0.5` and `apgd` (the default with
# friction; NZF layers, STEPSF steps). Each runs on 1, 2 and 4 processes (4 with
# --oversubscribe on a 2-core machine). With HARDCONTACT_REF_LMP set (another build, e.g.
# before a change), both launchers run each case, alternated ROUNDS times, for counts and loop
# times side by side.
# Writes bench/studies/mpi_calls/results/mpi_calls.csv (one row per scene, launcher, rank count and round: steps,
# solver iterations, MPI_Allreduce calls and point-to-point messages per process, the same per
# iteration, loop time, 1-minute load before the run) and prints each row; bench/studies/mpi_calls/README.md
# quotes it.
#   bench/studies/mpi_calls/run.sh [--quick]
set -euo pipefail
# shellcheck source=../../common.sh
source "$(dirname "${BASH_SOURCE[0]}")/../../common.sh" mpi_calls_ "$@"
NZ=20; STEPS=300; NZF=10; STEPSF=100; ROUNDS=3
[ "$MODE" = quick ] && { NZ=5; STEPS=40; NZF=5; STEPSF=20; ROUNDS=1; }
CSV="$RESULTS/mpi_calls.csv"
[ "$MODE" = quick ] && CSV="$WORK/mpi_calls.csv"
command -v mpicc > /dev/null || { echo "no mpicc (Debian package libopenmpi-dev)" >&2; exit 1; }
mpicc -shared -fPIC -O2 -o "$WORK/libcount_mpi_calls.so" "$ROOT/bench/studies/mpi_calls/count_mpi_calls.c"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1
# processors * * 1: the box is tallest in z, and LAMMPS's default grid would cut it there, leaving
# every sphere of a low pile on one process
# and a slot ${extra} for more keywords of the fix
sed -e 's/^thermo_style .*/thermo_style    custom step ke f_hc[1] f_hc[3]/' \
  -e 's/^create_box /processors      * * 1\ncreate_box /' \
  -e 's/hardcontact solver ${solver} wall/hardcontact solver ${solver} ${extra} wall/' \
  "$ROOT/bench/compare/in.pile3d" > "$WORK/in.pile"
LAUNCHERS=("new:$LMP")
[ -n "${HARDCONTACT_REF_LMP:-}" ] && LAUNCHERS=("ref:$HARDCONTACT_REF_LMP" "${LAUNCHERS[@]}")
echo "scene,launcher,ranks,round,steps,iterations,allreduce,messages,allreduce_per_it,messages_per_it,loop_s,load1" > "$CSV"
# scene: name, solver, extra keywords, layers, steps
SCENES=("pile_cg:cg::$NZ:$STEPS" "pile_friction_apgd:apgd:friction 0.5:$NZF:$STEPSF")
for r in $(seq 1 "$ROUNDS"); do
  for scene in "${SCENES[@]}"; do
    IFS=: read -r sname solver extra nz steps <<< "$scene"
    for np in 1 2 4; do
      for entry in "${LAUNCHERS[@]}"; do
        name=${entry%%:*}; lmp=${entry#*:}
        tag="${sname}_${name}_np${np}_$r"
        rm -f "$WORK/counts.$tag"
        load=$(cut -d' ' -f1 /proc/loadavg)
        (cd "$WORK" && MPI_CALL_COUNTS="$WORK/counts.$tag" mpirun -np "$np" --oversubscribe \
           -x LD_PRELOAD="$WORK/libcount_mpi_calls.so" -x MPI_CALL_COUNTS "$lmp" -in in.pile \
           -var solver "$solver" -var extra "$extra" -var nz "$nz" -var n "$steps" \
           -log "log.$tag" -echo none > /dev/null)
        # iterations summed over the steps (the first line, step 0, has none); calls: rank 0's
        # line (every process takes part in each reduction)
        IFS=, read -r n it t < <(bench_thermo "$WORK/log.$tag" rows sum:f_hc[1] loop)
        read -r red msg < <(awk '$2 == "0" {print $4, $6 + $8 + $14}' "$WORK/counts.$tag" | tail -1)
        awk -v s="$sname" -v name="$name" -v np="$np" -v r="$r" -v load="$load" -v n="$n" \
            -v it="$it" -v t="$t" -v red="$red" -v msg="$msg" 'BEGIN{
          printf "%s,%s,%d,%d,%d,%d,%d,%d,%.3f,%.3f,%.3f,%s\n", s, name, np, r, n, it, red, msg,
                 red / it, msg / it, t, load }' >> "$CSV"
        tail -1 "$CSV"
      done
    done
  done
done
echo "mpi_calls ($MODE): $CSV"
