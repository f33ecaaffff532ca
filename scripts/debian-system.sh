#!/usr/bin/env bash
# Makes (once) and prints the directory of a minimal Debian system of SUITE (trixie: ParaView
# 5.13; sid: ParaView 6.1), with git, in which scripts/in-system.sh runs the project's commands.
# The archive is the one this machine's apt uses. Systems are cached under $PSI_SYSTEMS_DIR
# (default /var/cache/psivolume/systems) and reused; delete a directory there to make it anew.
#   bash scripts/debian-system.sh trixie
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
suite=${1:?usage: debian-system.sh SUITE}
base=${PSI_SYSTEMS_DIR:-/var/cache/psivolume/systems}
dir="$base/$suite"
if [ -x "$dir/usr/bin/git" ]; then
  echo "$dir"
  exit 0
fi
[ "$(id -u)" -eq 0 ] || { echo "debian-system: making a system needs root (debootstrap, chroot)" >&2; exit 1; }
if ! command -v debootstrap >/dev/null; then
  echo "[system] installing debootstrap" >&2
  source "$here/lib/apt.sh"
  psi_apt "" update -qq >&2 && DEBIAN_FRONTEND=noninteractive psi_apt "" install -y -qq debootstrap >&2
fi
mirror=$(bash "$here/lib/debian-mirror.sh")
mkdir -p "$base"
rm -rf "$dir.partial"
echo "[system] debootstrap --variant=minbase --include=git $suite (from this machine's apt archive)" >&2
start=$SECONDS
if ! debootstrap --variant=minbase --include=git,ca-certificates "$suite" "$dir.partial" "$mirror" \
    >"$base/$suite.debootstrap.log" 2>&1; then
  tail -n 20 "$base/$suite.debootstrap.log" >&2
  echo "debian-system: debootstrap of $suite failed (log: $base/$suite.debootstrap.log)" >&2
  exit 1
fi
mv "$dir.partial" "$dir"
echo "[system] $suite ready in $((SECONDS - start)) s: $dir" >&2
echo "$dir"
