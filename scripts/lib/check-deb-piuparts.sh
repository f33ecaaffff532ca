#!/usr/bin/env bash
# scripts/check-deb.sh --piuparts [--paraview X] DEB: Debian's own installation test, piuparts,
# on a copy of the cached Debian system of the suite that ships ParaView X (scripts/debian-system.sh,
# with ParaView installed there by scripts/setup-deps.sh): piuparts copies it (hard links; the
# cached system is left as it was), records its files, installs DEB with apt, runs the installed
# plugin in pvpython and pvbatch (Testing/Python/test_installed.py --by-name, a custom script of
# piuparts after the installation), removes and purges it, and fails on any file left, added or
# changed, and on anything else piuparts checks (broken symlinks among them). Root.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
source "$root/scripts/lib/paraview-versions.sh"
series=$(system_paraview_series)
if [ "${1:-}" = --paraview ]; then
  series=${2:?--paraview takes 5.11, 5.13 or 6.1}
  shift 2
fi
suite=$(suite_of "$series")
deb=$(realpath "${1:?usage: check-deb.sh --piuparts [--paraview X] DEB}")
[ "$(id -u)" -eq 0 ] || { echo "check-deb --piuparts: needs root (piuparts, chroot)" >&2; exit 1; }
command -v piuparts >/dev/null || { echo "FAILED: piuparts is not installed (apt-get install piuparts)"; exit 1; }
sys=$(bash "$root/scripts/debian-system.sh" "$suite")
[ -x "$sys/usr/bin/pvpython" ] && [ -x "$sys/usr/bin/xvfb-run" ] || {
  echo "FAILED: the $suite system has no ParaView or Xvfb: bash scripts/in-system.sh $suite bash scripts/setup-deps.sh"
  exit 1; }
work=$(mktemp -d "${TMPDIR:-/var/tmp}/psi-piuparts.XXXXXX")
trap 'rm -rf --one-file-system "$work"' EXIT
mkdir "$work/scripts" "$work/tmp"
# Custom scripts run in the chroot as root; piuparts copies only the scripts themselves, so the
# test comes inside this one.
{
  cat <<'EOF'
#!/bin/sh
set -e
export PYTHONUNBUFFERED=1 HOME=/tmp/psi-home
mkdir -p "$HOME" && cd "$HOME"
cat > test_installed.py <<'PSI_TEST_INSTALLED_END'
EOF
  cat "$root/Testing/Python/test_installed.py"
  cat <<'EOF'
PSI_TEST_INSTALLED_END
for exe in pvpython pvbatch; do
  xvfb-run -a -s "-noreset -screen 0 1280x1024x24" \
    $exe --force-offscreen-rendering test_installed.py --by-name --prefix /usr
done
cd / && rm -rf "$HOME"
EOF
} > "$work/scripts/post_install_psivolume"
chmod 755 "$work/scripts/post_install_psivolume"
mirror=$(bash "$root/scripts/lib/debian-mirror.sh")
start=$SECONDS
# The cached system's own build trees and byte code are not the package's business.
piuparts --existing-chroot="$sys" --hard-link --distribution="$suite" --mirror="$mirror" \
  --tmpdir="$work/tmp" --scriptsdir="$work/scripts" --no-upgrade-test --no-adequate \
  --keep-sources-list --ignore-regex='^/root/psi-build/.*' --ignore-regex='^/psi/.*' \
  --ignore-regex='.*/__pycache__/.*' --ignore-regex='.*\.pyc$' \
  --log-file="$work/piuparts.log" "$deb" > /dev/null 2>&1 || {
    tail -n 60 "$work/piuparts.log"; echo "FAILED: piuparts (log above)"; exit 1; }
grep -E 'PASS:|test_installed: passed' "$work/piuparts.log" | sed 's/^[0-9m:. ]*//' || true
echo "check-deb --piuparts: passed on $suite (ParaView $series), $((SECONDS - start)) s"
