#!/usr/bin/env bash
# Runs one benchmark and records its output as docs/benchmarks/NAME.md, with the command, the
# date, the machine, the ParaView and the OpenGL driver it ran on; then regenerates
# docs/benchmarks.md from all the records (scripts/benchmarks-page.py). Runs with an X server
# (scripts/lib/with-xvfb.sh: DISPLAY's, else Xvfb). The record's "title" is TITLE (default: the
# command).
#   bash scripts/bench-record.sh NAME [--title TITLE] -- pvpython Benchmarks/bench_scale.py --sizes 20
# Notes on a record (what the figures say) go below its output by hand; the page is never edited.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
. "$root/scripts/lib/python-path.sh"
. "$root/scripts/lib/paraview-versions.sh"
x=(bash "$root/scripts/lib/with-xvfb.sh")
name=${1:?usage: bench-record.sh NAME [--title TITLE] -- COMMAND...}
shift
title=""
while [ $# -gt 0 ] && [ "$1" != "--" ]; do
  case "$1" in
    --title) title=${2:?--title takes a title}; shift 2 ;;
    *) echo "bench-record: unknown option $1" >&2; exit 2 ;;
  esac
done
[ "${1:-}" = "--" ] && shift
[ $# -gt 0 ] || { echo "bench-record: no command given" >&2; exit 2; }
cmd="" # the command as one can paste it: arguments with blanks in double quotes
for arg in "$@"; do
  case "$arg" in
    *[[:space:]]*) cmd+=" \"$arg\"" ;;
    *) cmd+=" $arg" ;;
  esac
done
cmd=${cmd# }
out=$(mktemp)
trap 'rm -f "$out"' EXIT
glx=$("${x[@]}" glxinfo -B 2>/dev/null || true)
renderer=$(printf '%s\n' "$glx" | sed -n 's/^ *OpenGL renderer string: //p' | head -n1)
mesa=$(printf '%s\n' "$glx" | sed -n 's/^ *OpenGL core profile version string: //p' | head -n1)
start=$SECONDS
(cd "$root" && "${x[@]}" "$@") | tee "$out"
seconds=$((SECONDS - start))
cpu=$(sed -n 's/^model name\s*: //p' /proc/cpuinfo | head -n1)
os=$(. /etc/os-release && echo "$PRETTY_NAME")
pv=$(installed_paraview_version)  # 5.11.0+dfsg-1 -> ParaView 5.11.0 (Debian package 5.11.0+dfsg-1)
[ -z "$pv" ] || pv="ParaView $(printf '%s\n' "$pv" | sed -E 's/^[0-9]+://; s/[+~-].*//') (Debian package $pv)"
# the benchmark's file: a module of the package run with -m, else the first file the command names
benchmark=$(echo "$cmd" | sed -nE 's#.*-m (psivolume[A-Za-z0-9_.]*).*#Python/\1.py#p' | sed 's#\.#/#g; s#/py$#.py#')
[ -n "$benchmark" ] || benchmark=$(echo "$cmd" | grep -oE '(Benchmarks|Python|scripts|build/bin)/[A-Za-z0-9_./-]+' | head -n1)
{
  echo "benchmark: $benchmark"
  echo "title: ${title:-$cmd}"
  echo "date: $(date -u +%Y-%m-%d)"
  echo "machine: $os; $cpu; $(nproc) cores; $(free -g | awk '/^Mem:/ {print $2}') GB"
  echo "paraview: ${pv:-unknown}"
  echo "opengl: ${renderer:-unknown}${mesa:+; $mesa}"
  echo "command: $cmd"
  echo "seconds: $seconds"
  echo "---"
  echo '```'
  cat "$out"
  echo '```'
} > "$root/docs/benchmarks/$name.md"
python3 "$root/scripts/benchmarks-page.py"
echo "[bench-record] docs/benchmarks/$name.md written, docs/benchmarks.md regenerated"
