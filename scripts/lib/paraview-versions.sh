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

# The series this Debian ships: the installed paraview package's, else the one its release
# carries (from /etc/os-release: 12 -> 5.11, 13 -> 5.13, unstable -> 6.1); empty when unknown.
system_paraview_series() {
  local v
  v=$(installed_paraview_series)
  if [ -z "$v" ] && [ -r /etc/os-release ]; then
    case "$(. /etc/os-release && echo "${VERSION_ID:-}:${VERSION_CODENAME:-}")" in
      12:*|*:bookworm) v=5.11 ;;
      13:*|*:trixie) v=5.13 ;;
      :sid|:forky) v=6.1 ;;
    esac
  fi
  echo "$v"
}

# The Debian suite that ships ParaView series $1.
suite_of() {
  case "$1" in
    5.11) echo bookworm ;;
    5.13) echo trixie ;;
    6.1) echo sid ;;
    *) echo "ParaView $1 is not one of 5.11, 5.13, 6.1" >&2; return 1 ;;
  esac
}
