#!/usr/bin/env bash
# Quick start on a fresh Debian bookworm machine: install what is needed, build, and run the
# flagship example (a cluster of spheres hitting a wall) into out/flagship/. Run it as yourself
# (apt-get goes through sudo) or as root; run with sudo, it gives build/, out/ and .cache/ back
# to you when it ends.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
die() { printf 'quickstart: ERROR: %s\n' "$*" >&2; exit 1; }
# shellcheck source=../.ci/lib.sh
. "$ROOT/.ci/lib.sh"
trap 'give_back_to_sudo_user "$ROOT/build" "$ROOT/out" "$ROOT/.cache"' EXIT

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
