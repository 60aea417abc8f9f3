#!/usr/bin/env bash
# Heap: 800 spheres poured through an inlet onto a rough floor, with fix hardcontact for
# three frictions (mu 0.2; mu 0.5; mu 0.5 with rolling 0.1) and the soft-sphere twin of the
# last two (pair_style granular), then the angle of repose of each heap.
#   examples/heap/run.sh [OUTDIR] [hard|soft|both] [extra LAMMPS arguments, e.g. -var npour 800]
# default OUTDIR out/heap, both. Each run dir OUTDIR/<hard|soft>_<case>: log.lammps, heap.dump;
# OUTDIR: angles.txt (one line per run), heap.png (profiles and side views).
set -euo pipefail
# shellcheck source=../common/run_common.sh
source "$(dirname "${BASH_SOURCE[0]}")/../common/run_common.sh"
hc_twin_args heap "$@"

HARD_CASES=("mu0.2:-var mu 0.2" "mu0.5:-var mu 0.5" "mu0.5_mur0.1:-var mu 0.5 -var mur 0.1")
SOFT_CASES=("mu0.5:-var mu 0.5" "mu0.5_mur0.1:-var mu 0.5 -var mur 0.1")
runs=()
run_case() {    # run_case hard|soft CASE:ARGS
  local kind="$1" name="${2%%:*}" args="${2#*:}" launcher deck
  if [ "$kind" = hard ]; then launcher="$LMP" deck=in.heap; else launcher="$LMP_SOFT" deck=in.heap.soft; fi
  # shellcheck disable=SC2086   # ARGS are words
  hc_lmp "$OUT/${kind}_$name" "" "heap: $deck ($name)" "$launcher" "$deck" $args "${LMP_ARGS[@]}"
  hc_loop_time "$OUT/${kind}_$name/log.lammps" "heap %-17s: %d steps, loop time %.1f s\n" "${kind}_$name"
  runs+=("${kind} ${name}=$OUT/${kind}_$name/heap.dump")
}
if [ "$WHICH" != soft ]; then for c in "${HARD_CASES[@]}"; do run_case hard "$c"; done; fi
if [ "$WHICH" != hard ]; then for c in "${SOFT_CASES[@]}"; do run_case soft "$c"; done; fi

: > "$OUT/angles.txt"
for r in "${runs[@]}"; do
  printf "%-18s " "${r%%=*}" >> "$OUT/angles.txt"
  "$PY" "$HERE/heap_angle.py" --floor 1.0 "${r#*=}" >> "$OUT/angles.txt"
done
cat "$OUT/angles.txt"
(cd "$HERE" && "$PY" heap_plot.py "$OUT/heap.png" "${runs[@]}")
echo "heap: output in $OUT"
