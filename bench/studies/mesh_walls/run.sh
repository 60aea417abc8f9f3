#!/usr/bin/env bash
# What a triangle-mesh wall costs (issue 40): the settling pile of bench/compare/in.pile3d (1210
# spheres, 10 layers, h 0.02, 150 steps) in its box of plane walls, of a region block, and of
# STL meshes of the same box with 10 to 61,000 triangles; frictionless (the default solver) and
# with friction 0.5. One process, one run at a time. About 2 minutes. Results:
# bench/studies/mesh_walls/results/mesh_walls.csv; the table goes into bench/studies/mesh_walls/README.md.
# HARDCONTACT_LMP: the launcher (default build/lmp_hardcontact; any build with `wall stl`).
#   bench/studies/mesh_walls/run.sh [--quick]     (--quick: 30 steps, into results-quick/)
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
# shellcheck source=../../common.sh
source "$HERE/../../common.sh" mesh_walls_ "$@"
STEPS=150
[ "$MODE" = quick ] && STEPS=30
RES="$RESULTS/mesh_walls.csv"
sed -e 's/hardcontact solver ${solver} wall xplane 0 11 wall yplane 0 11 wall zplane 0 NULL/hardcontact ${extra} ${walls}/' \
  -e "s/^pair_style .*/region          walls block 0 11 0 11 0 100 side in units box\n&/" "$ROOT/bench/compare/in.pile3d" > "$WORK/in.pile"
declare -A TRIS
for cell in 40 1 0.5 0.2; do TRIS[$cell]=$("$PY" "$HERE/make_box.py" "$cell" "$WORK/box_$cell.stl"); done
{
  echo "# $(date -u +%F) $(uname -n), $(nproc) cores, $(git -C "$ROOT" rev-parse --short HEAD); one run at a time"
  echo "walls,triangles,law,loop_s,modify_s,iterations_per_step,ke_end,load1"
} > "$RES"
run() {    # run NAME TRIANGLES LAW WALLS EXTRA
  local log="$WORK/log.$1.$3"
  (cd "$WORK" && "$LMP" -in in.pile -var nz 10 -var n "$STEPS" -var walls "$4" -var extra "$5" \
     -log "$log" -echo none -screen none)
  # every thermo row, the first (step 0: no solve) too
  bench_thermo --keep-first "$log" loop time:Modify mean:f_hc[1] last:KinEng load \
    | sed "s/^/$1,$2,$3,/" >> "$RES"
}
for law in frictionless friction; do
  extra=""; [ $law = friction ] && extra="friction 0.5"
  run planes 0 $law "wall xplane 0 11 wall yplane 0 11 wall zplane 0 NULL" "$extra"
  run region 0 $law "wall region walls" "$extra"
  for cell in 40 1 0.5 0.2; do
    run "stl_$cell" "${TRIS[$cell]}" $law "wall stl box_$cell.stl" "$extra"
  done
done
cat "$RES"
