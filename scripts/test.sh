#!/usr/bin/env bash
# The test command: installs what is missing, builds, and runs every test with CTest under a
# virtual X server (Mesa llvmpipe gives OpenGL 4.5 with geometry shaders).
#   bash scripts/test.sh                      the ParaView of this Debian (12: 5.11, 13: 5.13,
#                                             unstable: 6.1)
#   bash scripts/test.sh --paraview 6.1       the same suite inside a Debian system that ships
#                                             that ParaView (made once and cached, see
#                                             scripts/debian-system.sh); 5.11, 5.13, 6.1 or all
#   bash scripts/test.sh --only REGEX         only the tests whose names match REGEX
#   bash scripts/test.sh --tsan               the level of detail's and the interaction's tests
#                                             under ThreadSanitizer: the plugin built with
#                                             PSI_SANITIZE_THREAD=ON into build-tsan/ (only what
#                                             they need); any report fails its test
# Further arguments go to each ctest call (e.g. -V).
#
# Each test runs in its own fresh X server (scripts/lib/with-xvfb.sh, which says why it runs
# with -noreset), under `ctest --repeat until-pass:3`: up to two retries, in the same server, as a
# guard; a real failure fails every attempt and fails the run. A test that passes only on a retry
# is counted as passed and named on the summary line (scripts/lib/test-summary.sh), so that a
# flaky test is seen. Every process a test starts is ended when the test ends, also when test.sh
# is interrupted or killed (see the tag below and scripts/lib/end_tagged.py).
# The build: build/, or $PSI_BUILD_DIR (--tsan: the same name with -tsan appended).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
. "$root/scripts/lib/python-path.sh"
. "$root/scripts/lib/test-summary.sh"
paraview=""
only=""
tsan=""
ctest_args=()
while [ "$#" -gt 0 ]; do
  case "$1" in
    --paraview) paraview=${2:?--paraview takes 5.11, 5.13, 6.1 or all}; shift 2 ;;
    --only) only=${2:?--only takes a regular expression}; shift 2 ;;
    --tsan) tsan=1; shift ;;
    *) ctest_args+=("$1"); shift ;;
  esac
done

if [ -n "$paraview" ]; then
  exec bash "$root/scripts/test-paraview.sh" "$paraview" ${only:+--only "$only"} "${ctest_args[@]}"
fi

bash "$root/scripts/setup-deps.sh"
build=${PSI_BUILD_DIR:-$root/build}
if [ -n "$tsan" ]; then
  build=$build-tsan
  bash "$root/scripts/lib/configure.sh" "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DPSI_SANITIZE_THREAD=ON -DPSI_BUILD_BENCHMARKS=OFF
  cmake --build "$build" -j"$(nproc)" --target PsiVolume TestLODImage
  only=${only:-'^(PsiRepresentations\.LODImage|PsiPython\.(interaction|lod_inputs))$'}
else
  bash "$root/scripts/build.sh"
fi
# pvpython 5.13+ loses buffered output when a script leaves through os._exit into a pipe
# (psivolume.process): unbuffered, a failing test's check lines reach the log.
export PYTHONUNBUFFERED=1
cd "$build"
mapfile -t tests < <(ctest -N | sed -n 's/^ *Test *#[0-9]*: //p' | grep -E -- "${only:-.}" || true)
[ "${#tests[@]}" -gt 0 ] || { echo "[test.sh] no test matches '${only}'"; exit 1; }
passed=0
failed=0
skipped=0
failures=()
skips=()
retried=()
leaks=()
out=$(mktemp)
trap 'rm -f "$out"' EXIT

# Each test runs with PSI_TEST_RUN=<run>:<n> in its environment, which every process it starts
# inherits, also one in a session or process group of its own (each MPI rank, test_pvserver.py's
# server) or orphaned (a pvserver rank whose smTestDriver was killed waits for its client forever,
# one rank busy-waiting in MPI at a full core). What is still running when the test ends is
# ended and named; on INT, TERM or HUP test.sh ends the test's processes before it exits; a
# sentinel in its own session ends them when test.sh itself is killed (SIGKILL reaches no trap).
run="psi$$.$RANDOM"
end_tagged() { python3 "$root/scripts/lib/end_tagged.py" "$@"; }
setsid python3 "$root/scripts/lib/end_tagged.py" "$run:" --watch $$ </dev/null >/dev/null 2>&1 &
interrupted() {
  trap - INT TERM HUP
  echo "[test.sh] interrupted: ending the tests' processes"
  end_tagged "$run:" | sed 's/^/[test.sh]   ended /'
  exit "$1"
}
trap 'interrupted 130' INT
trap 'interrupted 143' TERM
trap 'interrupted 129' HUP

# One test, tagged $1, the one matching the CTest regex $2, in its own fresh X server, its
# attempts by CTest: run in the background and waited for, so that a signal reaches the traps
# above at once.
run_test() {
  local tag=$1 pattern=$2
  (
    export PSI_TEST_RUN="$tag"
    bash "$root/scripts/lib/with-xvfb.sh" --new ctest --output-on-failure --timeout 900 \
      --repeat until-pass:3 -R "$pattern" "${ctest_args[@]}" 2>&1 | tee "$out"
  ) &
  wait $!
}

# The result lines CTest printed for the test named $1, one per attempt: "Passed", "***Failed",
# "***Skipped", ... (its fixtures' lines left out).
attempts() {
  awk -v name="$1" '{ for (i = 1; i < NF; i++) if ($i ~ /^#[0-9]+:$/ && $(i + 1) == name) {
    for (j = i + 2; j <= NF; j++) { f = $j; sub(/^\.+/, "", f); if (f != "") { print f; next } } } }' \
    "$out"
}

n=0
for t in "${tests[@]}"; do
  pattern="^$(printf '%s' "$t" | sed 's/[.[\*^$()+?{|]/\\&/g')\$"
  n=$((n + 1))
  run_test "$run:$n" "$pattern" || true
  left=$(end_tagged "$run:$n" || true)
  if [ -n "$left" ]; then
    echo "[test.sh] $t left processes running after it ended; ended:"
    printf '%s\n' "$left" | sed 's/^/[test.sh]   /'
    leaks+=("$t")
  fi
  mapfile -t results < <(attempts "$t")
  last=none  # no result line: ctest or the X server did not get to run it
  [ "${#results[@]}" -eq 0 ] || last=${results[-1]}
  case "$last" in
    Passed)
      passed=$((passed + 1))
      [ "${#results[@]}" -eq 1 ] || retried+=("$t") ;;
    # A test that could not run here (SKIP_RETURN_CODE: its data is absent) is not a pass.
    *Skipped|*Not) skipped=$((skipped + 1)); skips+=("$t") ;;
    *) failed=$((failed + 1)); failures+=("$t") ;;
  esac
done
echo
if [ "$skipped" -gt 0 ]; then
  echo "skipped tests (not counted as passed): ${skips[*]}"
fi
if [ "$failed" -gt 0 ]; then
  echo "failed tests: ${failures[*]}"
fi
if [ "${#leaks[@]}" -gt 0 ]; then
  echo "tests that left processes running (ended by test.sh): ${leaks[*]}"
fi
test_summary "$passed" "$failed" "$skipped" "${retried[@]}"
[ "$failed" -eq 0 ]
