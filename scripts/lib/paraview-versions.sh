# The ParaView versions the plugin supports and the Debian suite that ships each, and the one
# way the scripts tell which ParaView is installed (the paraview package's version); sourced by
# every script that asks (setup-deps.sh, test-paraview.sh, readme-images.sh, bench-record.sh,
# build-deb.sh and check-deb.sh through lib/deb-elsewhere.sh, .ci/run).

# The series (X.Y) of a Debian package version: 5.11.2+dfsg-6 -> 5.11, 1:6.1.1-3 -> 6.1.
paraview_series_of() {
  printf '%s\n' "$1" | sed -E 's/^([0-9]+:)?([0-9]+\.[0-9]+).*/\2/'
}

# The version of the installed paraview package (5.11.0+dfsg-1); empty when none is installed.
installed_paraview_version() {
  local v
  v=$(dpkg-query -W -f='${Version}' paraview 2>/dev/null || true)
  [ -z "$v" ] || echo "$v"
}

# The series of the installed paraview package; empty when none is installed.
installed_paraview_series() {
  local v
  v=$(installed_paraview_version)
  [ -z "$v" ] || paraview_series_of "$v"
}

# The supported series and the Debian suite that ships each, one pair a line.
PSI_PARAVIEW_SUITES="5.11 bookworm
5.13 trixie
6.1 sid"

# The series this Debian ships: the installed paraview package's, else the one its suite
# carries (the codename of /etc/os-release; unstable names its next release's codename and says
# "sid" in its pretty name); empty when unknown.
system_paraview_series() {
  local v suite
  v=$(installed_paraview_series)
  if [ -z "$v" ] && [ -r /etc/os-release ]; then
    suite=$(. /etc/os-release && case "${PRETTY_NAME:-}" in *sid*) echo sid ;;
                                  *) echo "${VERSION_CODENAME:-}" ;; esac)
    v=$(printf '%s\n' "$PSI_PARAVIEW_SUITES" | awk -v s="$suite" '$2 == s {print $1}')
  fi
  echo "$v"
}

# The Debian suite that ships ParaView series $1.
suite_of() {
  local suite
  suite=$(printf '%s\n' "$PSI_PARAVIEW_SUITES" | awk -v v="$1" '$1 == v {print $2}')
  [ -n "$suite" ] || { echo "ParaView $1 is not one of 5.11, 5.13, 6.1" >&2; return 1; }
  echo "$suite"
}

# The suite to run in for ParaView series $1: empty when this Debian ships it (run here), else the
# Debian suite that does (run inside its system, scripts/in-system.sh). The one `--paraview X`
# dispatch of the scripts (test.sh through test-paraview.sh, build-deb.sh, check-deb.sh).
suite_elsewhere() {
  if [ "$1" = "$(system_paraview_series)" ]; then
    return 0
  fi
  suite_of "$1"
}
