# What the set-up scripts share (sourced by .ci/setup.sh, .ci/setup_modern_lammps.sh,
# examples/quickstart.sh and tests/run_all.sh). Each script defines die() before sourcing it.
#
# Root is needed for apt-get and the apt sources only: as_root runs those (through sudo when
# the user is not root); everything written into the checkout (.cache/, build/, out/) belongs to
# the user who runs the scripts. Run under sudo, the checkout is given back to that user on exit.

# The set-up installs Debian's packages (LAMMPS, LIGGGHTS, their sources): it is for Debian
# (tested on bookworm). Elsewhere it stops before writing anything: an Ubuntu machine would get
# a Debian archive entry named after an Ubuntu release, and apt would fail on it.
# HARDCONTACT_OS_RELEASE: another os-release file (the set-up's tests use it).
check_debian() {
  local f="${HARDCONTACT_OS_RELEASE:-/etc/os-release}" id="" name=""
  if [ -r "$f" ]; then
    id="$(. "$f" && echo "${ID:-}")"
    name="$(. "$f" && echo "${PRETTY_NAME:-${NAME:-}}")"
  fi
  command -v dpkg-query >/dev/null && command -v apt-get >/dev/null || id="${id:-none}-without-apt"
  [ "$id" = debian ] && return 0
  die "this set-up installs Debian's packages and supports Debian (bookworm) only; this system is '${name:-unknown}' (ID=${id:-unknown}), so nothing was changed. On another system install LAMMPS (a version with the PLUGIN package), Eigen 3, MPI and CMake yourself and build the plugin against that LAMMPS: 'cmake -S . -B build-plugin -DLAMMPS_SOURCE_DIR=/path/to/lammps/src && cmake --build build-plugin' (README, 'Using the fix in your own LAMMPS')."
}

# Run one command as root: directly when root, else through sudo (which asks for the password).
as_root() {
  if [ "$(id -u)" = 0 ]; then
    "$@"
  elif command -v sudo >/dev/null; then
    sudo "$@"
  else
    die "'$*' needs root and there is no sudo: run it as root once (su -c '$*'), or install sudo; then run this script again as yourself."
  fi
}

# The newest version in a list of source versions (one per line, on stdin) whose upstream
# version starts with $1, e.g. 20250204: any Debian revision (-2, -3, +deb13u1) or repack of that
# LAMMPS release. Prints nothing and fails when none matches.
newest_version_of() {
  local want="$1" v best=""
  while IFS= read -r v; do
    v="${v#Version: }"
    case "${v#*:}" in
      "$want"*) ;;
      *) continue ;;
    esac
    if [ -z "$best" ] || dpkg --compare-versions "$v" gt "$best"; then best="$v"; fi
  done
  [ -n "$best" ] && printf '%s\n' "$best"
}

# When the script runs as root under sudo (SUDO_UID set), give what it wrote into the checkout
# back to the user who called sudo, so that the next build as that user works. Not under plain
# root (CI): nothing to give back.
give_back_to_sudo_user() {
  [ "$(id -u)" = 0 ] && [ -n "${SUDO_UID:-}" ] && [ "${SUDO_UID}" != 0 ] || return 0
  local p
  for p in "$@"; do
    [ -e "$p" ] && chown -R "${SUDO_UID}:${SUDO_GID:-$SUDO_UID}" "$p"
  done
  return 0
}
