#!/usr/bin/env bash
# Quick start on a fresh Debian bookworm machine (as root): install what is needed, build,
# and run the flagship example (a cluster of spheres hitting a wall) into out/flagship/.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"

bash .ci/setup.sh
bash .ci/build.sh

EXAMPLE=examples/cluster_impact/run.sh
if [ ! -f "$EXAMPLE" ]; then
  echo "quickstart: $EXAMPLE does not exist, so there is no flagship example to run." >&2
  echo "quickstart: the build itself succeeded: build/lmp_hardcontact, build/hardcontactplugin.so" >&2
  exit 1
fi

export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export HARDCONTACT_LMP="$ROOT/build/lmp_hardcontact"
OUT=out/flagship
mkdir -p "$OUT"
bash "$EXAMPLE" "$OUT"
echo "quickstart: done; the flagship example's output is in $ROOT/$OUT/"
