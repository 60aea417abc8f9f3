#!/usr/bin/env bash
# Set up (packages with LIGGGHTS, LAMMPS headers, a modern LAMMPS), build, and run every test
# except "soak". Run it as yourself (apt-get goes through sudo) or as root; run with sudo, it
# gives the build and .cache/ back to you when it ends.
#   bash tests/run_all.sh             # all of it
#   bash tests/run_all.sh -L unit     # extra arguments go to ctest
# MPI tests carry the ctest PROCESSORS property (min(np, 2)): with -j2 an mpirun test never
# shares this 2-core machine with another test.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD_DIR="${HARDCONTACT_BUILD_DIR:-$ROOT/build}"
die() { printf 'run_all: ERROR: %s\n' "$*" >&2; exit 1; }
# shellcheck source=../.ci/lib.sh
. "$ROOT/.ci/lib.sh"
trap 'give_back_to_sudo_user "$BUILD_DIR" "$ROOT/.cache"' EXIT

bash "$ROOT/.ci/setup.sh"
bash "$ROOT/.ci/setup_modern_lammps.sh"     # the modern host: LAMMPS 4 Feb 2025 + PLUGIN
bash "$ROOT/.ci/build.sh"

export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
ctest --test-dir "$BUILD_DIR" --output-on-failure -LE soak -j "${HARDCONTACT_JOBS:-2}" "$@"
