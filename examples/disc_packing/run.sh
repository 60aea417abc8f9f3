#!/usr/bin/env bash
# Disc packing: 1000 bidisperse discs compressed by gravity, with fix hardcontact (OUTDIR/hard)
# and with the soft-sphere twin (OUTDIR/soft; pair_style gran/hertz/history), then compares them.
#   examples/disc_packing/run.sh [OUTDIR] [hard|soft|both] [extra LAMMPS arguments, e.g. -var tend 0.2]
# default OUTDIR out/disc_packing, both. Each run dir: log.lammps, packing.dump (atoms), contacts.dump
# (contact forces), packing.<step>.png; OUTDIR: compare.png (kinetic energy), chains.png,
# profile.png (area fraction against height) and the table of packing.py.
set -euo pipefail
# shellcheck source=../common/run_common.sh
source "$(dirname "${BASH_SOURCE[0]}")/../common/run_common.sh"
hc_twin_args disc_packing "$@"
"$PY" "$HERE/make_data.py" "$OUT/data.packing" > /dev/null
hc_twins disc_packing packing -var data "$OUT/data.packing" "${LMP_ARGS[@]}"
case "$WHICH" in
  hard) "$PY" "$HERE/packing.py" "$OUT/hard:hardcontact" ;;
  both) "$PY" "$HERE/packing.py" --png "$OUT/profile.png" "$OUT/hard:hardcontact" "$OUT/soft:soft spheres" ;;
esac
echo "disc_packing: output in $OUT"
