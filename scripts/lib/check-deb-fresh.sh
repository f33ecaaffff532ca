#!/usr/bin/env bash
# scripts/check-deb.sh --fresh [--paraview X] DEB: the check of check-deb.sh on a brand-new
# Debian system of the suite that ships ParaView X (default: this machine's), as a ParaView site
# installs it: debootstrap --variant=minbase into a temporary directory (scripts/debian-system.sh
# with PSI_SYSTEMS_DIR there), the check's own tools installed (xvfb, xauth: only those), then
# check-deb.sh inside it (scripts/in-system.sh), whose `apt-get install ./DEB` fetches ParaView
# and all it depends on from the archive. The system is deleted at the end, also on failure or
# when killed. The archives are kept in /var/cache/psivolume/debs/SUITE for the next run:
# debootstrap's --cache-dir, linked into the system's apt cache and back.
# Takes 4 to 7 minutes on two busy cores (debootstrap 1, the check 3 to 5½), the archives cached
# or not (the first run of a suite downloads 450 to 650 MiB).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
source "$root/scripts/lib/deb-elsewhere.sh"  # psi_deb_relative, suite_of (paraview-versions.sh)
series=$(system_paraview_series)
if [ "${1:-}" = --paraview ]; then
  series=${2:?--paraview takes 5.11, 5.13 or 6.1}
  shift 2
fi
suite=$(suite_of "$series")
rel=$(psi_deb_relative "${1:?usage: check-deb.sh --fresh [--paraview X] DEB}")
[ "$(id -u)" -eq 0 ] || { echo "check-deb --fresh: needs root (debootstrap, chroot)" >&2; exit 1; }
tools=(xvfb xauth)
cache=/var/cache/psivolume/debs/$suite
# lintian has run on this machine (check-deb.sh --fresh): the system gets only the check's tools.
in_system() { bash "$root/scripts/in-system.sh" "$suite" env DEBIAN_FRONTEND=noninteractive \
  PSI_DEB_LINTED=1 "$@"; }
# The installed packages, as their archives are named, with their installed sizes (KiB).
packages() {
  local f='${db:Status-Abbrev}|${Package}_${Version}_${Architecture}.deb ${Installed-Size}\n'
  dpkg-query --admindir="$sys/var/lib/dpkg" -W -f="$f" | sed -n 's/^ii *|//p' | sed 's/:/%3a/' |
    sort
}
# link FROM TO: the archives of one directory into another, hard links (the cache and the
# temporary directory on one disk; otherwise nothing is cached).
link() { find "$1" -maxdepth 1 -name '*.deb' -exec cp -l -n -t "$2" {} + 2>/dev/null || true; }
cached() { du -sb "$cache" | cut -f1; }
mib() { echo $((($1 + 524288) / 1048576)); }

archives=""
tmp=$(mktemp -d "${TMPDIR:-/var/tmp}/psi-fresh.XXXXXX")
# The archives fetched are kept, also on failure. in-system.sh's mounts are private to its
# namespace; --one-file-system leaves alone any that a killed debootstrap left behind.
trap '[ -z "$archives" ] || link "$archives" "$cache"; rm -rf --one-file-system "$tmp"' EXIT
trap 'exit 130' INT TERM HUP
export PSI_SYSTEMS_DIR=$tmp
start=$SECONDS
mkdir -p "$cache"
cache_before=$(cached)
sys=$(bash "$root/scripts/debian-system.sh" --include "" --cache-dir "$cache" "$suite")
archives=$sys/var/cache/apt/archives
packages > "$tmp/minbase.txt"
echo "fresh   Debian $suite, minbase: $(wc -l < "$tmp/minbase.txt") packages, $((SECONDS - start)) s"
link "$cache" "$archives"
in_system apt-get install -y -qq --no-install-recommends "${tools[@]}" >/dev/null
packages > "$tmp/tools.txt"
echo "fresh   the check's own tools first: ${tools[*]} ($(($(wc -l < "$tmp/tools.txt") -
  $(wc -l < "$tmp/minbase.txt"))) packages with what they need)"
check=$SECONDS
in_system bash scripts/check-deb.sh "$rel"
link "$archives" "$cache"  # now, for the figure below
# What the installation brought: all but the package itself stays after its removal.
comm -13 "$tmp/tools.txt" <(packages) > "$tmp/new.txt"
size=$(cut -d' ' -f1 "$tmp/new.txt" | (cd "$archives" && xargs stat -c %s) |
  awk '{s += $1} END {print s}')
installed=$(awk '{s += $2} END {print int(s / 1024)}' "$tmp/new.txt")
paraview=$(dpkg-query --admindir="$sys/var/lib/dpkg" -W -f='${Version}' paraview)
echo "fresh   the installation brought $(($(wc -l < "$tmp/new.txt") + 1)) packages, paraview" \
  "$paraview among them: $(mib "$size") MiB of archives, $installed MiB installed;" \
  "check $((SECONDS - check)) s, in all $((SECONDS - start)) s; archives downloaded now" \
  "(minbase and tools too): $(mib $(($(cached) - cache_before))) MiB, the rest from $cache"
