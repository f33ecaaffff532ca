#!/usr/bin/env bash
# scripts/test.sh --paraview VERSION: the suite against another ParaView, inside a Debian system
# that ships it (made with debootstrap once, then reused: scripts/debian-system.sh), from this
# checkout as it is. VERSION: 5.11 (Debian 12), 5.13 (Debian 13), 6.1 (Debian unstable), or all.
# On a Debian that ships VERSION itself, the suite runs here. Prints one line per ParaView with its
# counts and wall time, then the summary line of all of them; fails when any fails.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
want=${1:?usage: test-paraview.sh VERSION|all [--only REGEX] [ctest args]}
shift
source "$root/scripts/lib/paraview-versions.sh"
source "$root/scripts/lib/test-summary.sh"
versions=("$want")
[ "$want" = all ] && versions=(5.11 5.13 6.1)
summary=()
status=0
log=$(mktemp)
trap 'rm -f "$log"' EXIT
for v in "${versions[@]}"; do
  suite=$(suite_of "$v")
  start=$SECONDS
  echo "=== ParaView $v (Debian $suite) ==="
  if [ -z "$(suite_elsewhere "$v")" ]; then
    cmd=(bash "$root/scripts/test.sh" "$@")
  else
    cmd=(bash "$root/scripts/in-system.sh" "$suite" bash scripts/test.sh "$@")
  fi
  if "${cmd[@]}" 2>&1 | tee "$log"; then rc=0; else rc=1; status=1; fi
  counts=$(test_summary_of "$log")
  test_summary_add "$counts" || true
  summary+=("ParaView $v (Debian $suite): ${counts:-did not reach the tests}, $((SECONDS - start)) s$([ $rc = 0 ] || echo ', FAILED')")
done
echo
printf '%s\n' "${summary[@]}"
test_summary "$SUMMARY_PASSED" "$SUMMARY_FAILED" "$SUMMARY_SKIPPED" "${SUMMARY_RETRIED[@]}"
exit "$status"
