#!/usr/bin/env bash
# Pour: 600 glass discs poured into a box, with fix hardcontact (OUTDIR/hard) and with the
# soft-sphere twin (OUTDIR/soft; pair_style gran/hertz/history), then compares them.
#   examples/pour/run.sh [OUTDIR] [hard|soft|both] [extra LAMMPS arguments, e.g. -var tend 0.3]
# default OUTDIR out/pour, both. Each run dir: log.lammps, pour.dump (atoms), contacts.dump
# (contact forces), pour.<step>.png; OUTDIR: compare.png (kinetic energy), chains.png.
set -euo pipefail
# shellcheck source=../common/run_common.sh
source "$(dirname "${BASH_SOURCE[0]}")/../common/run_common.sh"
hc_twin_args pour "$@"
hc_twins pour pour "${LMP_ARGS[@]}"
echo "pour: output in $OUT"
