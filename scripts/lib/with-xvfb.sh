#!/usr/bin/env bash
# Runs a command with an X display: the one DISPLAY names when it accepts connections, else a
# virtual X server (Xvfb) of its own, started for the command and ended with it. Every script of
# the project that needs X goes through this file; none starts Xvfb itself.
#   bash scripts/lib/with-xvfb.sh [--new] [--screen WxHxD] [--fbdir DIR] [--] COMMAND [ARG...]
#   --new            a server of its own even when DISPLAY is usable (scripts/test.sh: each test
#                    in a fresh server)
#   --screen WxHxD   the screen's size and depth (default 1280x1024x24)
#   --fbdir DIR      the screen also kept in DIR/Xvfb_screen0 (xwd format; implies --new)
# Exit status: COMMAND's; 1 when no server could be started.
#
# The server runs with -noreset: by default Xvfb resets whenever its last client disconnects and
# refuses connections meanwhile, which made a pvpython/pvbatch process (most often a rank of the
# 2-rank MPI test) fail with "bad X server connection" now and then (measured: two processes
# opening and closing the display 3,000 times failed 13-17% of the time by default, 0% with
# -noreset).
#
# The display number is the server's own choice (-displayfd): it takes the first number whose
# lock file and socket are both free. So servers started at the same time never take the same
# number, nor do those of the Debian systems of scripts/in-system.sh, which have a /tmp (lock
# files) of their own but share X's abstract sockets with the host; there are no number ranges
# to keep apart. Only local clients may connect (-nolisten tcp, no TCP port).
set -euo pipefail
new=0
screen=1280x1024x24
fbdir=""
usage="usage: with-xvfb.sh [--new] [--screen WxHxD] [--fbdir DIR] [--] COMMAND [ARG...]"
while [ "$#" -gt 0 ]; do
  case "$1" in
    --new) new=1; shift ;;
    --screen) screen=${2:?--screen takes WxHxD}; shift 2 ;;
    --fbdir) fbdir=${2:?--fbdir takes a directory}; new=1; shift 2 ;;
    --) shift; break ;;
    -*) echo "with-xvfb: unknown option $1 ($usage)" >&2; exit 2 ;;
    *) break ;;
  esac
done
[ "$#" -gt 0 ] || { echo "$usage" >&2; exit 2; }

# DISPLAY accepts a connection (Xlib's own test: XOpenDisplay; libX11 comes with ParaView).
usable() {
  [ -n "${DISPLAY:-}" ] && python3 -c '
import ctypes, ctypes.util, sys
x = ctypes.CDLL(ctypes.util.find_library("X11") or "libX11.so.6")
x.XOpenDisplay.restype = ctypes.c_void_p
sys.exit(0 if x.XOpenDisplay(None) else 1)' 2>/dev/null
}
if [ "$new" = 0 ] && usable; then
  exec "$@"
fi

command -v Xvfb >/dev/null || { echo "with-xvfb: Xvfb is not installed (Debian: xvfb)" >&2; exit 1; }
work=$(mktemp -d "${TMPDIR:-/tmp}/with-xvfb.XXXXXX")
server=""
stop() {
  if [ -n "$server" ]; then
    kill "$server" 2>/dev/null || true
    wait "$server" 2>/dev/null || true
  fi
  rm -rf "$work"
}
trap stop EXIT
trap 'exit 129' HUP
trap 'exit 130' INT
trap 'exit 143' TERM
Xvfb -displayfd 3 -noreset -nolisten tcp -screen 0 "$screen" ${fbdir:+-fbdir "$fbdir"} \
  3>"$work/display" </dev/null >"$work/log" 2>&1 &
server=$!
# The number is written once the server accepts connections.
for _ in $(seq 300); do
  [ -s "$work/display" ] && break
  kill -0 "$server" 2>/dev/null || break
  sleep 0.1
done
display=$(tr -dc 0-9 < "$work/display")
if [ -z "$display" ]; then
  tail -n 20 "$work/log" >&2
  echo "with-xvfb: Xvfb did not start" >&2
  exit 1
fi
set +e
DISPLAY=":$display" "$@"
status=$?
set -e
exit "$status"
