# Sourced by scripts/build-deb.sh and scripts/check-deb.sh: `--paraview X` runs the script inside
# the Debian system that ships ParaView X (scripts/in-system.sh --throwaway: the cached system is
# left exactly as it was, only its build directory is kept), unless this Debian ships X itself.
# The checkout is /psi/src in there; paths are given and printed relative to it.
source "$root/scripts/lib/paraview-versions.sh"

# psi_deb_in_system SUITE SCRIPT [ARG...]: runs scripts/SCRIPT in SUITE's throwaway system, with
# the maintainer's name, the build date and whether lintian has run, when given, passed on.
psi_deb_in_system() {
  local suite=$1 script=$2 v pass=()
  shift 2
  for v in DEBFULLNAME DEBEMAIL PSI_DEB_MAINTAINER SOURCE_DATE_EPOCH PSI_DEB_LINTED; do
    [ -z "${!v:-}" ] || pass+=("$v=${!v}")
  done
  bash "$root/scripts/in-system.sh" --throwaway "$suite" env "${pass[@]}" bash "scripts/$script" "$@"
}

# psi_deb_relative PATH: PATH relative to the checkout (the system sees only the checkout).
psi_deb_relative() {
  local rel
  rel=$(realpath --relative-to="$root" "$1")
  case "$rel" in
    ../*|/*) echo "$1 is outside the checkout, which is all a Debian system sees" >&2; return 1 ;;
  esac
  echo "$rel"
}
