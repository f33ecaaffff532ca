# The ParaView versions the plugin supports and the Debian suite that ships each; sourced by
# scripts/setup-deps.sh, scripts/test-paraview.sh and .ci/run.

# The series (X.Y) of a Debian package version: 5.11.2+dfsg-6 -> 5.11, 1:6.1.1-3 -> 6.1.
paraview_series_of() {
  printf '%s\n' "$1" | sed -E 's/^([0-9]+:)?([0-9]+\.[0-9]+).*/\2/'
}

# The series of the installed paraview package; empty when none is installed.
installed_paraview_series() {
  local v
  v=$(dpkg-query -W -f='${Version}' paraview 2>/dev/null || true)
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
