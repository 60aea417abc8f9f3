#!/usr/bin/env bash
# Configure and build hardcontact into ./build (or $HARDCONTACT_BUILD_DIR), 2 jobs (or
# $HARDCONTACT_JOBS). Extra arguments go to the cmake configure step, e.g.
#   bash .ci/build.sh -DCMAKE_BUILD_TYPE=Debug
# Quiet-ish: prints the configuration summary and compiler diagnostics (no progress lines);
# full logs in <build>/configure.log and <build>/build.log.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD_DIR="${HARDCONTACT_BUILD_DIR:-$ROOT/build}"
JOBS="${HARDCONTACT_JOBS:-2}"
mkdir -p "$BUILD_DIR"

if ! cmake -S "$ROOT" -B "$BUILD_DIR" "$@" >"$BUILD_DIR/configure.log" 2>&1; then
  cat "$BUILD_DIR/configure.log" >&2
  echo "build: cmake configure FAILED (log: $BUILD_DIR/configure.log)" >&2
  exit 1
fi
summary='^-- (LAMMPS fix API|LAMMPS headers|No liblammps|No tests|Modern LAMMPS host|LIGGGHTS host|Micro-benchmarks)'
grep -E "$summary" "$BUILD_DIR/configure.log" \
  | sed 's/^-- /build: /' || true

t0=$SECONDS
status=0
cmake --build "$BUILD_DIR" --parallel "$JOBS" >"$BUILD_DIR/build.log" 2>&1 || status=$?
# compiler/linker diagnostics only: drop make's progress and bookkeeping lines
grep -vE '^\[ *[0-9]+%\]|^(gmake|make)(\[[0-9]+\])?: (Entering|Leaving)|^Consolidate compiler generated dependencies' \
  "$BUILD_DIR/build.log" || true
if [ "$status" -ne 0 ]; then
  echo "build: FAILED (log: $BUILD_DIR/build.log)" >&2
  exit "$status"
fi
echo "build: ok in $((SECONDS - t0)) s -> $BUILD_DIR"
