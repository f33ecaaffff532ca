# The summary line of scripts/test.sh, the one place it is written and read (sourced by
# scripts/test.sh, scripts/test-paraview.sh and .ci/run):
#   N passed, M failed, K skipped, R passed only on a retry[: NAME...]
# A test that passed only on a retry counts as passed and is named, so that a flaky test is seen.

# test_summary PASSED FAILED SKIPPED [RETRIED_NAME...]: prints the line.
test_summary() {
  local passed=$1 failed=$2 skipped=$3
  shift 3
  echo "$passed passed, $failed failed, $skipped skipped, $# passed only on a retry${1:+: $*}"
}

# test_summary_of FILE: the last summary line of a log; empty when it has none.
test_summary_of() {
  grep -E '^[0-9]+ passed, [0-9]+ failed, [0-9]+ skipped, [0-9]+ passed only on a retry' "$1" |
    tail -n 1 || true
}

# test_summary_add LINE: adds a summary line's counts to the totals SUMMARY_PASSED,
# SUMMARY_FAILED, SUMMARY_SKIPPED and its names to the array SUMMARY_RETRIED; returns 1 for an
# empty LINE (no summary: the run did not reach its tests).
SUMMARY_PASSED=0
SUMMARY_FAILED=0
SUMMARY_SKIPPED=0
SUMMARY_RETRIED=()
test_summary_add() {
  local line=$1 names
  [ -n "$line" ] || return 1
  set -- $(printf '%s\n' "$line" | tr -d ',')
  SUMMARY_PASSED=$((SUMMARY_PASSED + $1))
  SUMMARY_FAILED=$((SUMMARY_FAILED + $3))
  SUMMARY_SKIPPED=$((SUMMARY_SKIPPED + $5))
  names=$(printf '%s\n' "$line" | sed -n 's/.* passed only on a retry: //p')
  [ -z "$names" ] || SUMMARY_RETRIED+=($names)
}
