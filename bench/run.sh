#!/usr/bin/env bash
# The benchmark suites of fix hardcontact, LAMMPS bench/ style:
#   bench/run.sh SUITE [--quick]      one suite; results in bench/results/SUITE/<host>/
#   bench/run.sh [--help]             the suites and the studies, one line each
# Each suite's README.md says what it measures, how long it takes, what it needs and which
# section of doc/performance.md it feeds; bench/README.md says the rest.
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
SUITES=(perf accuracy friction scale scopi)

# the first line of a README (its title), for the listings
title() { sed -n '1s/^# *//p' "$1"; }

usage() {
  echo "usage: bench/run.sh SUITE [--quick]"
  echo
  echo "suites (full run / --quick, on the 2-core test machine):"
  for s in "${SUITES[@]}"; do
    printf '  %-10s %s (%s)\n' "$s" "$(title "$HERE/$s/README.md")" \
      "$(sed -n 's/^Time: //p' "$HERE/$s/README.md" | head -1)"
  done
  echo
  echo "studies (one question each, dated answers; run with bench/studies/<topic>/run.sh):"
  for d in "$HERE"/studies/*/; do
    printf '  %-18s %s\n' "$(basename "$d")" "$(title "$d/README.md")"
  done
  echo
  echo "tools: bench/compare/compare_builds.sh OLD_LMP NEW_LMP [STEPS] (callgrind, two builds)"
}

case "${1:-}" in
  "" | -h | --help) usage; exit 0 ;;
esac
suite="$1"
shift
for s in "${SUITES[@]}"; do
  [ "$s" = "$suite" ] && exec bash "$HERE/$suite/run.sh" "$@"
done
echo "no suite '$suite'" >&2
usage >&2
exit 2
