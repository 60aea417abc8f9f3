#!/usr/bin/env bash
# Runs a scene with fix hardcontact and its soft-sphere twin, then prints them side by side
# (wall time, steps, wall time per unit of physical time, largest overlap, bed height,
# packing fraction, final kinetic energy) and plots kinetic energy against time:
#   examples/compare.sh SCENE [OUTDIR] [extra run.sh arguments]
# SCENE: pile, pour or disc_packing. Output in OUTDIR (default out/compare/SCENE): hard/, soft/,
# compare.png. The hardcontact run uses $HARDCONTACT_LMP (default build/lmp_hardcontact); the
# twin runs with the same launcher (Debian's LAMMPS, GRANULAR package included) or $LMP_SOFT.
set -euo pipefail
# shellcheck source=common/run_common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common/run_common.sh"
SCENE="${1:?usage: compare.sh SCENE [OUTDIR] (SCENE: pile, pour, disc_packing)}"
[ -x "$HERE/$SCENE/run.sh" ] || { echo "compare.sh: no scene $SCENE (examples/$SCENE/run.sh)" >&2; exit 1; }
hc_outdir "${2:-$ROOT/out/compare/$SCENE}"
shift $(( $# >= 2 ? 2 : 1 ))
# run.sh ... both runs the two decks, then compare.py (the table and compare.png)
bash "$HERE/$SCENE/run.sh" "$OUT" both "$@"
