#!/usr/bin/env bash
# The set-up scripts as a user meets them (.ci/setup.sh, .ci/setup_modern_lammps.sh, .ci/lib.sh):
#  1. on a system that is not Debian (an Ubuntu os-release) both stop with an ERROR that says
#     what to do instead, and write no apt source;
#  2. the modern host takes any revision of trixie's LAMMPS 4 Feb 2025 source, the newest;
#  3. as a user who is not root, with everything installed, setup.sh checks and writes nothing;
#     with a package missing it asks sudo for apt-get (a recording sudo stands in for it) and
#     leaves nothing of root's in the checkout; without sudo it says how to get root;
#  4. run under sudo, what was written is given back to the calling user.
# Needs root (to act as another user) and the set-up done once (packages, .cache/).
# Usage: test_setup_scripts.sh <source dir>
set -euo pipefail
SRC="$(cd "${1:?source dir}" && pwd)"
pass=0 fail=0
ok() { echo "ok: $*"; pass=$((pass + 1)); }
bad() { echo "FAIL: $*"; fail=$((fail + 1)); }
check() { local what="$1"; shift; if "$@"; then ok "$what"; else bad "$what"; fi; }

[ "$(id -u)" = 0 ] || { echo "this test needs root (it acts as another user)"; exit 1; }
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
chmod 755 "$TMP"

# ------------------------------------------------------------------ 1. not Debian
cat >"$TMP/ubuntu-os-release" <<'EOF'
NAME="Ubuntu"
PRETTY_NAME="Ubuntu 24.04.1 LTS"
ID=ubuntu
ID_LIKE=debian
VERSION_CODENAME=noble
EOF
sources_before="$(ls -l /etc/apt/sources.list.d/)"
for script in setup.sh setup_modern_lammps.sh; do
  rc=0
  out="$(HARDCONTACT_OS_RELEASE="$TMP/ubuntu-os-release" HARDCONTACT_CACHE_DIR="$TMP/nocache" \
         bash "$SRC/.ci/$script" 2>&1)" || rc=$?
  check "$script on Ubuntu exits non-zero ($rc)" [ "$rc" -ne 0 ]
  check "$script on Ubuntu: one ERROR naming the system and the way to build elsewhere" \
    grep -q "ERROR: this set-up installs Debian's packages and supports Debian (bookworm) only; this system is 'Ubuntu 24.04.1 LTS'.*-DLAMMPS_SOURCE_DIR" <<<"$out"
done
check "no apt source was written on Ubuntu" [ "$sources_before" = "$(ls -l /etc/apt/sources.list.d/)" ]
check "no cache was made on Ubuntu" [ ! -e "$TMP/nocache" ]

# ------------------------------------------------------------------ 2. trixie's revision
pick() { bash -c 'die() { echo "die: $*"; exit 1; }; . "$1/.ci/lib.sh"; newest_version_of "$2"' _ "$SRC" "$1"; }
check "the newest revision of 20250204 is taken" \
  [ "$(printf 'Version: 20220106.git7586adbb6a+ds1-2\nVersion: 20250204+dfsg.1-2\nVersion: 20250204+dfsg.1-3\n' | pick 20250204)" = "20250204+dfsg.1-3" ]
check "a stable update (+deb13u1) is newer than its revision" \
  [ "$(printf '20250204+dfsg.1-2+deb13u1\n20250204+dfsg.1-2\n' | pick 20250204)" = "20250204+dfsg.1-2+deb13u1" ]
check "another release is not taken" \
  [ -z "$(printf '20220106.git7586adbb6a+ds1-2\n20250722+dfsg-1\n' | pick 20250204 || true)" ]
if [ -f /etc/apt/sources.list.d/debian-trixie-src.sources ]; then    # the modern host's set-up ran
  avail="$(apt-cache showsrc lammps 2>/dev/null | sed -n 's/^Version: //p' | pick 20250204 || true)"
  check "apt offers a 4 Feb 2025 source here ($avail)" [ -n "$avail" ]
fi

# ------------------------------------------------------------------ 3. as a user
# a copy of the checkout's scripts and cached headers, owned by the user
USER_NAME=nobody
CO="$TMP/checkout"
mkdir -p "$CO/.ci"
cp "$SRC"/.ci/*.sh "$CO/.ci/"
cp -a "$SRC/.cache/lammps-headers" "$TMP/headers-copy"
mkdir -p "$CO/.cache"
mv "$TMP/headers-copy" "$CO/.cache/lammps-headers"
chown -R "$USER_NAME" "$CO"
as_user() { runuser -u "$USER_NAME" -- env PATH="$1" HOME="$TMP" bash "$CO/.ci/setup.sh" 2>&1; }
rc=0
out="$(as_user "/usr/bin:/bin")" || rc=$?
check "as a user, everything installed: setup.sh exits 0 ($rc)" [ "$rc" = 0 ]
check "as a user, everything installed: nothing to say" [ -z "$out" ]

# a package reported missing: a dpkg-query that hides python3-numpy; a sudo that records
mkdir -p "$TMP/bin-nosudo" "$TMP/bin-sudo"
cat >"$TMP/bin-nosudo/dpkg-query" <<'EOF'
#!/bin/sh
/usr/bin/dpkg-query "$@" | grep -v '^python3-numpy '
EOF
cp "$TMP/bin-nosudo/dpkg-query" "$TMP/bin-sudo/dpkg-query"
cat >"$TMP/bin-sudo/sudo" <<EOF
#!/bin/sh
echo "sudo \$*" >>"$TMP/sudo.log"
EOF
chmod 755 "$TMP"/bin-*/*
touch "$TMP/sudo.log" && chown "$USER_NAME" "$TMP/sudo.log"
rc=0
out="$(as_user "$TMP/bin-nosudo:/usr/bin:/bin")" || rc=$?
check "as a user without sudo, a package missing: exits non-zero ($rc)" [ "$rc" -ne 0 ]
check "as a user without sudo: the ERROR says how to get root" \
  grep -q "ERROR: 'apt-get update -qq' needs root and there is no sudo: run it as root once" <<<"$out"
rc=0
out="$(as_user "$TMP/bin-sudo:/usr/bin:/bin")" || rc=$?
check "as a user with sudo, a package missing: exits 0 ($rc)" [ "$rc" = 0 ]
check "apt-get update went through sudo" grep -q "^sudo apt-get update" "$TMP/sudo.log"
check "apt-get install of the missing package went through sudo" \
  grep -q "^sudo env DEBIAN_FRONTEND=noninteractive apt-get install .*python3-numpy" "$TMP/sudo.log"
check "nothing else went through sudo" [ "$(wc -l <"$TMP/sudo.log")" = 2 ]
check "nothing in the user's checkout belongs to root" [ -z "$(find "$CO" -user root)" ]

# ------------------------------------------------------------------ 4. under sudo
mkdir -p "$TMP/given/build/sub" && touch "$TMP/given/build/sub/f" "$TMP/given/out"
uid="$(id -u "$USER_NAME")" gid="$(id -g "$USER_NAME")"
SUDO_UID="$uid" SUDO_GID="$gid" bash -c \
  'die() { exit 1; }; . "$1/.ci/lib.sh"; give_back_to_sudo_user "$2/build" "$2/out" "$2/absent"' \
  _ "$SRC" "$TMP/given"
check "under sudo, build/ and out/ go back to the calling user" \
  [ -z "$(find "$TMP/given/build" "$TMP/given/out" ! -user "$USER_NAME")" ]
mkdir -p "$TMP/given/root-build"
env -u SUDO_UID bash -c 'die() { exit 1; }; . "$1/.ci/lib.sh"; give_back_to_sudo_user "$2"' \
  _ "$SRC" "$TMP/given/root-build"
check "as plain root (CI) nothing is given away" [ "$(stat -c %U "$TMP/given/root-build")" = root ]
for f in examples/quickstart.sh tests/run_all.sh; do
  check "$f gives its outputs back on exit" grep -q "trap 'give_back_to_sudo_user" "$SRC/$f"
done

echo "$pass passed, $fail failed"
[ "$fail" = 0 ]
