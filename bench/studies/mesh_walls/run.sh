#!/usr/bin/env bash
# What a triangle-mesh wall costs (issue 40): the settling pile of bench/compare/in.pile3d (1210
# spheres, 10 layers, h 0.02, 150 steps) in its box of plane walls, of a region block, and of
# STL meshes of the same box with 10 to 61,000 triangles; frictionless (the default solver) and
# with friction 0.5. One process, one run at a time. About 2 minutes. Results:
# bench/studies/mesh_walls/results/mesh_walls.csv; the table goes into bench/studies/mesh_walls/README.md.
# HARDCONTACT_LMP: the launcher (default build/lmp_hardcontact; any build with `wall stl`).
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/../../.." && pwd)"
PY=/usr/bin/python3; [ -x "$PY" ] || PY=python3
LMP="${HARDCONTACT_LMP:-$ROOT/build/lmp_hardcontact}"
WORK="${BENCH_WORKDIR:-$ROOT/bench/work}/mesh_walls"
RES="$ROOT/bench/studies/mesh_walls/results/mesh_walls.csv"
mkdir -p "$WORK" "$(dirname "$RES")"
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
  (cd "$WORK" && "$LMP" -in in.pile -var nz 10 -var n 150 -var walls "$4" -var extra "$5" \
     -log "$log" -echo none -screen none)
  awk -v w="$1" -v nt="$2" -v law="$3" -v load="$(cut -d' ' -f1 /proc/loadavg)" '
    /^ *Step/{f=1; next} /^Loop/{f=0; loop=$4}
    f && NF >= 9 {it += $4; k++; ke = $3}
    /^Modify/{mod=$5}
    END{printf "%s,%s,%s,%.3f,%.3f,%.1f,%.10g,%s\n", w, nt, law, loop, mod, it / k, ke, load}' \
    "$log" >> "$RES"
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
