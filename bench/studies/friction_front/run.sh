#!/usr/bin/env bash
# The frictional front (README.md here): the 10-layer settle at every (tol, h) with its twins,
# the heap over three seeds, then the table and the plot; --quick checks the scripts (a small
# settle, one heap seed, about 5 minutes).
#   bench/studies/friction_front/run.sh [--quick]
# The 8000-sphere settle is separate: python3 front.py --scene settle20 (about 4 minutes).
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
/usr/bin/python3 "$HERE/front.py" --jobs 2 "$@"
bash "$HERE/heap_front.sh" "$@"
if [ "${1:-}" = "--quick" ]; then
  /usr/bin/python3 "$HERE/report.py" "$HERE/../../results/friction_front_quick.csv"
else
  /usr/bin/python3 "$HERE/report.py"
fi
