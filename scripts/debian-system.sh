#!/usr/bin/env bash
# Makes (once) and prints the directory of a minimal Debian system of SUITE (bookworm: ParaView
# 5.11; trixie: 5.13; sid: 6.1), with git, in which scripts/in-system.sh runs the project's
# commands.
# The archive is the one this machine's apt uses. Systems are cached under $PSI_SYSTEMS_DIR
# (default /var/cache/psivolume/systems) and reused; delete a directory there to make it anew.
#   bash scripts/debian-system.sh [--include PACKAGES] [--cache-dir DIR] trixie
# --include: the packages added to minbase, comma-separated (default git,ca-certificates; empty:
# the bare minbase, as scripts/check-deb.sh --fresh makes it). --cache-dir: a directory
# debootstrap takes the packages from and keeps those it downloads in (its --cache-dir).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
include=git,ca-certificates
deb_cache=""
while [ "$#" -gt 1 ]; do
  case "$1" in
    --include) include=$2; shift 2 ;;
    --cache-dir) deb_cache=$2; shift 2 ;;
    *) break ;;
  esac
done
suite=${1:?usage: debian-system.sh [--include PACKAGES] [--cache-dir DIR] SUITE}
base=${PSI_SYSTEMS_DIR:-/var/cache/psivolume/systems}
dir="$base/$suite"
# Made in $dir.partial and renamed when complete.
if [ -d "$dir" ]; then
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
options=(--variant=minbase ${include:+--include="$include"})
if [ -n "$deb_cache" ]; then
  mkdir -p "$deb_cache"
  options+=(--cache-dir="$deb_cache")
fi
echo "[system] debootstrap ${options[*]} $suite (from this machine's apt archive)" >&2
start=$SECONDS
if ! debootstrap "${options[@]}" "$suite" "$dir.partial" "$mirror" \
    >"$base/$suite.debootstrap.log" 2>&1; then
  tail -n 20 "$base/$suite.debootstrap.log" >&2
  echo "debian-system: debootstrap of $suite failed (log: $base/$suite.debootstrap.log)" >&2
  exit 1
fi
mv "$dir.partial" "$dir"
echo "[system] $suite ready in $((SECONDS - start)) s: $dir" >&2
echo "$dir"
