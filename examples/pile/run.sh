#!/usr/bin/env bash
# Pile: 750 glass discs settle in a box, with fix hardcontact (OUTDIR/hard) and with the
# soft-sphere twin (OUTDIR/soft; pair_style gran/hertz/history), then compares them.
#   examples/pile/run.sh [OUTDIR] [hard|soft|both] [extra LAMMPS arguments, e.g. -var tend 0.2]
# default OUTDIR out/pile, both. Each run dir: log.lammps, pile.dump (atoms), contacts.dump
# (contact forces), pile.<step>.png; OUTDIR: compare.png (kinetic energy), chains.png.
set -euo pipefail
# shellcheck source=../common/run_common.sh
source "$(dirname "${BASH_SOURCE[0]}")/../common/run_common.sh"
hc_twin_args pile "$@"
"$PY" "$HERE/make_data.py" "$OUT/data.pile" > /dev/null
hc_twins pile pile -var data "$OUT/data.pile" "${LMP_ARGS[@]}"
echo "pile: output in $OUT"
