#!/usr/bin/env bash
# Prepare a Debian (bookworm) machine to build and test hardcontact.
#
#  1. makes sure a deb-src entry for the distribution exists (needed for the LAMMPS headers),
#  2. installs the build/test packages that are missing (apt-get update only if needed),
#     LIGGGHTS 3.8 among them (the LIGGGHTS host),
#  3. caches the full LAMMPS header set of the INSTALLED liblammps-dev version in
#     .cache/lammps-headers/<version>/ (Debian's liblammps-dev ships only 34 headers and
#     lacks e.g. neigh_request.h, lammpsplugin.h and the bundled fmt/ headers).
#
# Idempotent and silent when everything is already in place. Run it as yourself: the steps
# that need root (apt-get, the apt sources) go through sudo (as_root in .ci/lib.sh); as root it
# runs them directly. Debian only (it says so and changes nothing elsewhere).
# Set HARDCONTACT_SETUP_VERBOSE=1 to see what it checks.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
CACHE_DIR="${HARDCONTACT_CACHE_DIR:-$ROOT/.cache}"
# liggghts + libliggghts-dev: LIGGGHTS 3.8 with its full headers, for build/liggghts_hardcontact
# (the LIGGGHTS host; CMake builds it when it finds them)
PACKAGES=(lammps liblammps-dev libeigen3-dev libopenmpi-dev openmpi-bin libgtest-dev cmake g++
          make python3 python3-numpy python3-matplotlib dpkg-dev xz-utils liggghts libliggghts-dev
          libbenchmark-dev)
SRC_LIST=/etc/apt/sources.list.d/debian-src.sources
export DEBIAN_FRONTEND=noninteractive

say() { printf 'setup: %s\n' "$*"; }
verbose() { if [ "${HARDCONTACT_SETUP_VERBOSE:-0}" = 1 ]; then say "$@"; fi; }
die() { printf 'setup: ERROR: %s\n' "$*" >&2; exit 1; }

# shellcheck source=lib.sh
. "$ROOT/.ci/lib.sh"
check_debian

codename() {
  local c=""
  if [ -r /etc/os-release ]; then c="$(. /etc/os-release && echo "${VERSION_CODENAME:-}")"; fi
  [ -n "$c" ] || c=bookworm
  echo "$c"
}
CODENAME="$(codename)"

APT_UPDATED=0
apt_update() {
  [ "$APT_UPDATED" = 1 ] && return 0
  say "apt-get update"
  as_root apt-get update -qq >/dev/null || die "apt-get update failed (no network access to the Debian archive?)"
  APT_UPDATED=1
}

# ---------------------------------------------------------------- 1. deb-src entry
have_debsrc() {
  # all Sources targets apt is configured for (downloaded or not): "suite component"
  # output captured first: under pipefail, grep -q closing the pipe early fails the pipeline
  local t
  t="$(apt-get indextargets --no-release-info --format '$(RELEASE) $(COMPONENT)' \
       'Created-By: Sources' 2>/dev/null || true)"
  grep -qx "$CODENAME main" <<<"$t"
}
if ! have_debsrc; then
  say "adding deb-src entry $SRC_LIST"
  as_root tee "$SRC_LIST" >/dev/null <<EOF
Types: deb-src
URIs: http://deb.debian.org/debian
Suites: $CODENAME
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
EOF
  have_debsrc || die "added $SRC_LIST but apt does not see a deb-src entry for '$CODENAME main'"
fi

# ---------------------------------------------------------------- 2. packages
# one dpkg-query call: "<package> <status>" for the packages dpkg knows about
status="$(dpkg-query -W -f='${Package} ${db:Status-Status}\n' "${PACKAGES[@]}" 2>/dev/null || true)"
missing=()
for p in "${PACKAGES[@]}"; do
  grep -qx "$p installed" <<<"$status" || missing+=("$p")
done
if [ "${#missing[@]}" -gt 0 ]; then
  apt_update
  say "installing ${missing[*]}"
  as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null \
    || die "apt-get install ${missing[*]} failed"
fi
verbose "packages present: ${PACKAGES[*]}"

# ---------------------------------------------------------------- 3. LAMMPS headers
# Installed version of liblammps-dev and of its source package (without binNMU suffix +bN).
PKG_VERSION="$(dpkg-query -W -f='${Version}' liblammps-dev)"
SRC_PKG="$(dpkg-query -W -f='${source:Package}' liblammps-dev 2>/dev/null || true)"
[ -n "$SRC_PKG" ] || SRC_PKG=lammps
SRC_VERSION="$(printf '%s' "$PKG_VERSION" | sed -E 's/\+b[0-9]+$//')"
DIR_VERSION="${SRC_VERSION#*:}"            # no epoch in directory names
HDR_DIR="$CACHE_DIR/lammps-headers/$DIR_VERSION"
STAMP="$HDR_DIR/.hardcontact-complete"

# "29 Sep 2021" -> 20210929
date_to_num() {
  local d m y
  read -r d m y <<<"$1"
  m="$(case "$m" in Jan) echo 01;; Feb) echo 02;; Mar) echo 03;; Apr) echo 04;; May) echo 05;;
       Jun) echo 06;; Jul) echo 07;; Aug) echo 08;; Sep) echo 09;; Oct) echo 10;;
       Nov) echo 11;; Dec) echo 12;; *) echo XX;; esac)"
  printf '%04d%s%02d' "$y" "$m" "$((10#$d))"
}

# Version of the installed library: LAMMPSConfigVersion.cmake, else pkg-config's liblammps.pc.
installed_lib_version() {
  local f v=""
  f="$(dpkg -L liblammps-dev 2>/dev/null | grep '/LAMMPSConfigVersion.cmake$' | head -n1 || true)"
  if [ -n "$f" ] && [ -r "$f" ]; then
    v="$(sed -nE 's/^set\(PACKAGE_VERSION "([0-9]+)"\)/\1/p' "$f" | head -n1)"
  fi
  if [ -z "$v" ]; then
    f="$(dpkg -L liblammps-dev 2>/dev/null | grep '/liblammps.pc$' | head -n1 || true)"
    [ -n "$f" ] && v="$(sed -nE 's/^Version: *([0-9]+).*/\1/p' "$f" | head -n1)"
  fi
  echo "$v"
}

header_version() {  # prints "20210929 Update 2" style info from version.h: "<num>|<date>|<update>"
  local vh="$1/version.h" date upd
  date="$(sed -nE 's/^#define LAMMPS_VERSION "(.*)"/\1/p' "$vh")"
  upd="$(sed -nE 's/^#define LAMMPS_UPDATE "(.*)"/\1/p' "$vh")"
  printf '%s|%s|%s' "$(date_to_num "$date")" "$date" "$upd"
}

# Header set and installed library must be the same LAMMPS: version.h vs the library's
# version and, for every header liblammps-dev installs, byte-identical content.
check_headers() {
  local dir="$1" hv lib_v
  [ -r "$dir/version.h" ] || die "header set in $dir has no version.h"
  hv="$(header_version "$dir")"
  lib_v="$(installed_lib_version)"
  if [ -n "$lib_v" ] && [ "${hv%%|*}" != "$lib_v" ]; then
    die "the installed liblammps ($PKG_VERSION, LAMMPS version $lib_v) and the header set in $dir (LAMMPS $(echo "$hv" | cut -d'|' -f2) $(echo "$hv" | cut -d'|' -f3), version $(echo "${hv%%|*}")) are different versions."
  fi
  local h base bad=()
  while IFS= read -r h; do
    base="$(basename "$h")"
    [ -f "$dir/$base" ] || { bad+=("$base (missing)"); continue; }
    cmp -s "$h" "$dir/$base" || bad+=("$base")
  done < <(dpkg -L liblammps-dev | grep -E '^/usr/include/lammps/[^/]+\.h$')
  if [ "${#bad[@]}" -gt 0 ]; then
    die "the installed liblammps ($PKG_VERSION) and the header set in $dir are different versions: installed headers differ: ${bad[*]}"
  fi
}

if [ -f "$STAMP" ] && [ -r "$HDR_DIR/version.h" ]; then
  check_headers "$HDR_DIR"
  verbose "LAMMPS headers cached in $HDR_DIR"
else
  say "caching the LAMMPS $SRC_VERSION headers in ${HDR_DIR#$ROOT/}"
  # captured first: with several source stanzas (trixie's too) grep -q would close the pipe
  # early and pipefail would report apt-cache's SIGPIPE as "no such version"
  have_src() { local t; t="$(apt-cache showsrc "$SRC_PKG" 2>/dev/null || true)";
               grep -qxF "Version: $SRC_VERSION" <<<"$t"; }
  if ! have_src; then
    apt_update
    have_src || die "the installed liblammps-dev is $PKG_VERSION but apt offers no source package $SRC_PKG=$SRC_VERSION (available: $(apt-cache showsrc "$SRC_PKG" 2>/dev/null | sed -n 's/^Version: //p' | tr '\n' ' ')); the installed liblammps and the header set would be different versions."
  fi
  mkdir -p "$CACHE_DIR/lammps-headers"
  TMP="$(mktemp -d "$CACHE_DIR/lammps-headers/.tmp.XXXXXX")"
  trap 'rm -rf "$TMP"' EXIT
  ( cd "$TMP" && apt-get source -qq --download-only -o APT::Sandbox::User=root \
        "$SRC_PKG=$SRC_VERSION" >/dev/null ) \
    || die "apt-get source --download-only $SRC_PKG=$SRC_VERSION failed"
  shopt -s nullglob
  tarballs=("$TMP"/*.orig.tar.*)
  shopt -u nullglob
  [ "${#tarballs[@]}" -ge 1 ] || die "no *.orig.tar.* in the downloaded source package"
  mkdir -p "$TMP/hdr"
  # top-level src/*.h, the bundled fmt/ headers (pointers.h includes fmt/format.h) and PLUGIN/
  tar -xf "${tarballs[0]}" -C "$TMP/hdr" --strip-components=2 --wildcards \
      --no-wildcards-match-slash '*/src/*.h' '*/src/fmt/*.h' '*/src/PLUGIN/*.h' \
    || die "extracting the headers from ${tarballs[0]##*/} failed"
  check_headers "$TMP/hdr"
  touch "$TMP/hdr/.hardcontact-complete"
  rm -rf "$HDR_DIR"
  mv "$TMP/hdr" "$HDR_DIR"
  rm -rf "$TMP"      # the tarballs
  trap - EXIT
  say "LAMMPS $(header_version "$HDR_DIR" | cut -d'|' -f2,3 | tr '|' ' ') headers: $(find "$HDR_DIR" -name '*.h' | wc -l) files"
fi
