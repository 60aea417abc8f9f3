#!/usr/bin/env bash
# Build a modern LAMMPS (Debian trixie's source package, "4 Feb 2025") with the PLUGIN and
# GRANULAR packages into .cache/lammps-modern/<version>/, once; later calls only check it.
#
# Why: Debian bookworm's LAMMPS (29 Sep 2021) has no PLUGIN package, and most users run a
# modern LAMMPS and load the fix with `plugin load`. The tests run every deck through both.
#
#   .cache/lammps-modern/<version>/src/      the LAMMPS src/ tree (headers for the plugin build)
#   .cache/lammps-modern/<version>/bin/lmp   the binary (MPI, PLUGIN, GRANULAR, JPEG, PNG)
#
# Needs root only for apt (packages, the trixie deb-src entry), through sudo when run as a user
# (as_root, .ci/lib.sh). About 3 minutes on 2 cores.
# Any revision of trixie's LAMMPS 4 Feb 2025 source package (20250204+dfsg.1-2, a later -3 or
# +deb13u1) is taken, the newest apt offers; its version.h must say "4 Feb 2025".
# HARDCONTACT_MODERN_LAMMPS=0 skips it (the tests on the modern host are then not registered).
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
CACHE_DIR="${HARDCONTACT_CACHE_DIR:-$ROOT/.cache}"
JOBS="${HARDCONTACT_JOBS:-2}"
SRC_PKG=lammps
UPSTREAM=20250204                    # trixie's LAMMPS release: its source package's upstream version
LAMMPS_DATE="4 Feb 2025"             # what its version.h must say
DIR_VERSION=$UPSTREAM
DEST="$CACHE_DIR/lammps-modern/$DIR_VERSION"
STAMP="$DEST/.hardcontact-complete"
SRC_LIST=/etc/apt/sources.list.d/debian-trixie-src.sources
PACKAGES=(cmake g++ make libopenmpi-dev openmpi-bin libjpeg-dev libpng-dev zlib1g-dev xz-utils
          dpkg-dev)
export DEBIAN_FRONTEND=noninteractive

say() { printf 'setup-modern-lammps: %s\n' "$*"; }
die() { printf 'setup-modern-lammps: ERROR: %s\n' "$*" >&2; exit 1; }
# shellcheck source=lib.sh
. "$ROOT/.ci/lib.sh"

[ "${HARDCONTACT_MODERN_LAMMPS:-1}" = 0 ] && { say "skipped (HARDCONTACT_MODERN_LAMMPS=0)"; exit 0; }
check_debian

# The cached build is trusted only if its version.h says the expected release and the binary
# reports the packages the tests need.
check_build() {
  local d="$1"
  [ -x "$d/bin/lmp" ] || return 1
  grep -q "^#define LAMMPS_VERSION \"$LAMMPS_DATE\"" "$d/src/version.h" 2>/dev/null || return 1
  local h
  h="$("$d/bin/lmp" -h 2>/dev/null)" || return 1
  grep -q "Large-scale Atomic/Molecular Massively Parallel Simulator - $LAMMPS_DATE" <<<"$h" \
    || return 1
  local pk
  pk="$(sed -n '/^Installed packages:/,/^List of individual style options/p' <<<"$h")"
  for p in GRANULAR PLUGIN; do grep -qw "$p" <<<"$pk" || return 1; done
}

if [ -f "$STAMP" ]; then
  check_build "$DEST" || die "the cached modern LAMMPS in ${DEST#$ROOT/} is not LAMMPS $LAMMPS_DATE with PLUGIN and GRANULAR; delete that folder and run this script again."
  exit 0
fi

# ---------------------------------------------------------------- packages
status="$(dpkg-query -W -f='${Package} ${db:Status-Status}\n' "${PACKAGES[@]}" 2>/dev/null || true)"
missing=()
for p in "${PACKAGES[@]}"; do grep -qx "$p installed" <<<"$status" || missing+=("$p"); done
APT_UPDATED=0
if [ "${#missing[@]}" -gt 0 ]; then
  as_root apt-get update -qq >/dev/null || die "apt-get update failed"
  APT_UPDATED=1
  say "installing ${missing[*]}"
  as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null \
    || die "apt-get install ${missing[*]} failed"
fi

# ---------------------------------------------------------------- the trixie source package
# captured first: under pipefail, grep -q closing the pipe early would fail the pipeline
# The newest source version of that release apt offers (bookworm's own lammps is older).
src_version() { apt-cache showsrc "$SRC_PKG" 2>/dev/null | sed -n 's/^Version: //p' \
                  | newest_version_of "$UPSTREAM"; }
SRC_VERSION="$(src_version || true)"
if [ -z "$SRC_VERSION" ]; then
  if [ ! -f "$SRC_LIST" ]; then
    say "adding deb-src entry $SRC_LIST (source packages only; nothing is installed from trixie)"
    as_root tee "$SRC_LIST" >/dev/null <<EOF
Types: deb-src
URIs: http://deb.debian.org/debian
Suites: trixie
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
EOF
  fi
  as_root apt-get update -qq >/dev/null || die "apt-get update failed"
  SRC_VERSION="$(src_version || true)"
  [ -n "$SRC_VERSION" ] || die "apt offers no source package $SRC_PKG of LAMMPS $LAMMPS_DATE ($UPSTREAM*; available: $(apt-cache showsrc "$SRC_PKG" 2>/dev/null | sed -n 's/^Version: //p' | tr '\n' ' '))"
fi

mkdir -p "$CACHE_DIR/lammps-modern"
TMP="$(mktemp -d "$CACHE_DIR/lammps-modern/.tmp.XXXXXX")"
trap 'rm -rf "$TMP"' EXIT
say "fetching the $SRC_PKG $SRC_VERSION source package"
# apt may fail on the .dsc (seen: 404) after it fetched the tarball: judge by the tarball.
( cd "$TMP" && apt-get source -qq --download-only -o APT::Sandbox::User=root \
      "$SRC_PKG=$SRC_VERSION" >/dev/null 2>&1 ) || true
shopt -s nullglob
tarballs=("$TMP"/lammps_*.orig.tar.*)
shopt -u nullglob
[ "${#tarballs[@]}" -ge 1 ] || die "apt-get source $SRC_PKG=$SRC_VERSION brought no *.orig.tar.* (network or archive problem)"

# Only what a CMake build of the core + PLUGIN + GRANULAR reads (not examples, docs, tools).
mkdir -p "$TMP/lammps"
tar -xf "${tarballs[0]}" -C "$TMP/lammps" --strip-components=1 --wildcards \
    '*/cmake' '*/src' '*/lib/plugin' '*/LICENSE' 2>/dev/null \
  || tar -xf "${tarballs[0]}" -C "$TMP/lammps" --strip-components=1 --wildcards '*/cmake' '*/src' '*/LICENSE' \
  || die "extracting ${tarballs[0]##*/} failed"
rm -f "${tarballs[@]}"
grep -q "^#define LAMMPS_VERSION \"$LAMMPS_DATE\"" "$TMP/lammps/src/version.h" \
  || die "the source package is not LAMMPS $LAMMPS_DATE (version.h says: $(grep LAMMPS_VERSION "$TMP/lammps/src/version.h"))"

say "building LAMMPS $LAMMPS_DATE (PLUGIN, GRANULAR, MPI, JPEG, PNG) with $JOBS jobs; about 3 minutes on 2 cores (log: ${DEST#$ROOT/}.build.log)"
t0=$SECONDS
LOG="$CACHE_DIR/lammps-modern/$DIR_VERSION.build.log"
{
  cmake -S "$TMP/lammps/cmake" -B "$TMP/build" -DCMAKE_BUILD_TYPE=Release \
    -DBUILD_MPI=ON -DBUILD_OMP=OFF -DPKG_PLUGIN=ON -DPKG_GRANULAR=ON \
    -DWITH_JPEG=ON -DWITH_PNG=ON -DWITH_GZIP=ON -DWITH_FFMPEG=OFF -DBUILD_SHARED_LIBS=OFF \
    -DCMAKE_INSTALL_PREFIX="$TMP/install" \
  && cmake --build "$TMP/build" --parallel "$JOBS"
} >"$LOG" 2>&1 || { tail -n 40 "$LOG" >&2; die "building LAMMPS failed (log: $LOG)"; }

rm -rf "$DEST"
mkdir -p "$DEST/bin"
cp "$TMP/build/lmp" "$DEST/bin/lmp"
# the src/ tree stays: the plugin is compiled against these headers (LAMMPS_SOURCE_DIR)
mv "$TMP/lammps/src" "$DEST/src"
find "$DEST/src" -name '*.cpp' -delete
check_build "$DEST" || die "the new build in ${DEST#$ROOT/} does not report LAMMPS $LAMMPS_DATE with PLUGIN and GRANULAR"
touch "$STAMP"
rm -rf "$TMP"
trap - EXIT
say "LAMMPS $LAMMPS_DATE built in $((SECONDS - t0)) s -> ${DEST#$ROOT/}/bin/lmp"
