#!/usr/bin/env bash
# Runs a command of this checkout inside the Debian system of SUITE (scripts/debian-system.sh),
# as root, in a private mount namespace: the checkout is seen at /psi/src, the shared datasets
# (../shared/data or $PSI_DATA_DIR, when present) read-only at /psi/shared/data (the checkout's
# ../shared/data in there), /proc and a fresh /dev/shm are mounted, and all of
# it is unmounted when the command ends. The build goes to /root/psi-build/<checkout> in that
# system, one directory per checkout (every checkout is seen at the same /psi/src, and make's time
# stamps cannot tell one checkout's older sources from another's: objects of a newer checkout
# were taken as up to date), kept between runs and never mixed with the host's build/.
#   bash scripts/in-system.sh trixie bash scripts/test.sh
#   bash scripts/in-system.sh --throwaway trixie bash scripts/check-deb.sh dist/...deb
# --throwaway: the system is seen through an overlay whose changes are discarded when the command
# ends (packages installed, files written), except /root/psi-build, which is the system's own:
# the cached system stays exactly as it was, the builds are kept.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
throwaway=0
if [ "${1:-}" = --throwaway ]; then throwaway=1; shift; fi
suite=${1:?usage: in-system.sh [--throwaway] SUITE COMMAND [ARG...]}
shift
[ "$#" -gt 0 ] || { echo "usage: in-system.sh [--throwaway] SUITE COMMAND [ARG...]" >&2; exit 2; }
sys=$(bash "$root/scripts/debian-system.sh" "$suite")
shared=${PSI_DATA_DIR:-$(cd "$root/.." && pwd)/shared/data}  # seen as ../shared/data
# The system's resolver and host names are the machine's: apt inside needs the resolver, and a
# chroot keeps the machine's host name, to which ParaView's test driver connects the client of a
# client/server test (a Debian installed on a machine lists its own name in /etc/hosts).
cp -L /etc/resolv.conf "$sys/etc/resolv.conf"
cp -L /etc/hosts "$sys/etc/hosts"
mkdir -p "$sys/psi/src" "$sys/psi/shared/data" "$sys/root/psi-build"
args=$(printf '%q ' "$@")
# (X servers started in there take a display number whose socket is free, scripts/lib/with-xvfb.sh:
# X's abstract sockets are shared with the host and the other systems, their lock files are not.)
checkout=$(printf '%s' "$root" | md5sum | cut -c1-12)
overlay=""
if [ "$throwaway" = 1 ]; then
  overlay=$(mktemp -d "${TMPDIR:-/var/tmp}/psi-overlay.XXXXXX")
  trap 'rm -rf "$overlay"' EXIT
fi
unshare --mount --propagation private -- bash -euo pipefail -c '
  sys=$1 root=$2 shared=$3 args=$4 checkout=$5 overlay=$6
  if [ -n "$overlay" ]; then
    mkdir "$overlay/upper" "$overlay/work" "$overlay/root"
    mount -t overlay overlay \
      -o "lowerdir=$sys,upperdir=$overlay/upper,workdir=$overlay/work" "$overlay/root"
    mount --bind "$sys/root/psi-build" "$overlay/root/root/psi-build"
    sys=$overlay/root
  fi
  mount -t proc proc "$sys/proc"
  mount -t tmpfs -o mode=1777 shm "$sys/dev/shm"
  mount --bind "$root" "$sys/psi/src"
  if [ -d "$shared" ]; then
    mount --bind "$shared" "$sys/psi/shared/data"
    mount -o remount,bind,ro "$sys/psi/shared/data"
  fi
  exec chroot "$sys" /usr/bin/env -i HOME=/root TERM="${TERM:-dumb}" LANG=C.UTF-8 \
    PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin CI="${CI:-}" \
    PSI_BUILD_DIR="/root/psi-build/$checkout" \
    bash -c "cd /psi/src && exec $args"
' in-system "$sys" "$root" "$shared" "$args" "$checkout" "$overlay"
