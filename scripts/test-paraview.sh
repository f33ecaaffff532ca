#!/usr/bin/env bash
# scripts/test.sh --paraview VERSION: the suite against another ParaView, inside a Debian system
# that ships it (made with debootstrap once, then reused: scripts/debian-system.sh), from this
# checkout as it is. VERSION: 5.11 (Debian 12), 5.13 (Debian 13), 6.1 (Debian unstable), or all.
# On a Debian that ships VERSION itself, the suite runs here. Prints one line per ParaView with its
# counts and wall time; fails when any fails.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
want=${1:?usage: test-paraview.sh VERSION|all [--only REGEX] [ctest args]}
shift
source "$root/scripts/lib/paraview-versions.sh"
here_series=$(installed_paraview_series)
versions=("$want")
[ "$want" = all ] && versions=(5.11 5.13 6.1)
summary=()
status=0
for v in "${versions[@]}"; do
  suite=$(suite_of "$v")
  log=$(mktemp)
  start=$SECONDS
  echo "=== ParaView $v (Debian $suite) ==="
  if [ "$v" = "$here_series" ]; then
    cmd=(bash "$root/scripts/test.sh" "$@")
  else
    cmd=(bash "$root/scripts/in-system.sh" "$suite" bash scripts/test.sh "$@")
  fi
  if "${cmd[@]}" 2>&1 | tee "$log"; then rc=0; else rc=1; status=1; fi
  counts=$(grep -E '^[0-9]+ passed, [0-9]+ failed' "$log" | tail -n1 || true)
  summary+=("ParaView $v (Debian $suite): ${counts:-did not reach the tests}, $((SECONDS - start)) s$([ $rc = 0 ] || echo ', FAILED')")
  rm -f "$log"
done
echo
printf '%s\n' "${summary[@]}"
exit "$status"
