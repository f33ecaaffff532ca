#!/usr/bin/env bash
# The test command: installs what is missing, builds, and runs every test with CTest under a
# virtual X server (Mesa llvmpipe gives OpenGL 4.5 with geometry shaders).
#   bash scripts/test.sh                      the ParaView of this Debian (12: 5.11, 13: 5.13,
#                                             unstable: 6.1)
#   bash scripts/test.sh --paraview 6.1       the same suite inside a Debian system that ships
#                                             that ParaView (made once and cached, see
#                                             scripts/debian-system.sh); 5.11, 5.13, 6.1 or all
#   bash scripts/test.sh --only REGEX         only the tests whose names match REGEX
#   bash scripts/test.sh --jobs N             N tests at a time (default 2; RUN_SERIAL ones alone)
#   bash scripts/test.sh --tsan               the level of detail's tests and the interaction's modes
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
jobs=2
ctest_args=()
while [ "$#" -gt 0 ]; do
  case "$1" in
    --paraview) paraview=${2:?--paraview takes 5.11, 5.13, 6.1 or all}; shift 2 ;;
    --only) only=${2:?--only takes a regular expression}; shift 2 ;;
    --tsan) tsan=1; shift ;;
    --jobs) jobs=${2:?--jobs takes a number}; shift 2 ;;
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
  only=${only:-'^(PsiRepresentations\.LODImage|PsiPython\.(interaction\.modes|lod_inputs))$'}
else
  bash "$root/scripts/build.sh"
fi
# pvpython 5.13+ loses buffered output when a script leaves through os._exit into a pipe
# (psivolume.process): unbuffered, a failing test's check lines reach the log.
export PYTHONUNBUFFERED=1
cd "$build"
mapfile -t tests < <(ctest -N | sed -n 's/^ *Test *#[0-9]*: //p' | grep -E -- "${only:-.}" || true)
[ "${#tests[@]}" -gt 0 ] || { echo "[test.sh] no test matches '${only}'"; exit 1; }

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
# attempts by CTest, its output into the file $3: run in the background and waited for, so that a
# signal reaches the traps above at once.
run_test() {
  local tag=$1 pattern=$2 out=$3
  (
    export PSI_TEST_RUN="$tag"
    bash "$root/scripts/lib/with-xvfb.sh" --new ctest --output-on-failure --timeout 900 \
      --repeat until-pass:3 -R "$pattern" "${ctest_args[@]}" >"$out" 2>&1
  ) &
  wait $!
}

# The result lines CTest printed into the log $2 for the test named $1, one per attempt:
# "Passed", "***Failed", "***Skipped", ... (its fixtures' lines left out).
attempts() {
  awk -v name="$1" '{ for (i = 1; i < NF; i++) if ($i ~ /^#[0-9]+:$/ && $(i + 1) == name) {
    for (j = i + 2; j <= NF; j++) { f = $j; sub(/^\.+/, "", f); if (f != "") { print f; next } } } }' \
    "$2"
}

# The tests CTest must run alone (RUN_SERIAL: the MPI and client/server tests, the largest mesh);
# the others run $jobs at a time (--jobs, default 2): much of a test's time is one thread (the
# driver compiling shaders, ParaView's Python), so two of them share 2 cores well.
mapfile -t serial < <(ctest --show-only=json-v1 | python3 -c '
import json, sys
for t in json.load(sys.stdin)["tests"]:
    if any(p["name"] == "RUN_SERIAL" and p["value"] for p in t.get("properties", [])):
        print(t["name"])')
is_serial() { [ "${#serial[@]}" -gt 0 ] && printf '%s\n' "${serial[@]}" | grep -qxF -- "$1"; }
results=$(mktemp -d)
trap 'rm -rf "$results"' EXIT

# Test number $1, named $2: run, the processes it left ended, its output printed whole once it
# ends (two tests' lines never interleave), its outcome written to $results/$1: passed, retried
# (passed on a retry), skipped or failed, then "leaked" when it left processes running.
one_test() {
  local n=$1 t=$2 out=$results/$1.log pattern left last outcome lines
  pattern="^$(printf '%s' "$t" | sed 's/[.[\*^$()+?{|]/\\&/g')\$"
  run_test "$run:$n" "$pattern" "$out" || true
  left=$(end_tagged "$run:$n" || true)
  mapfile -t lines < <(attempts "$t" "$out")
  last=none  # no result line: ctest or the X server did not get to run it
  [ "${#lines[@]}" -eq 0 ] || last=${lines[-1]}
  case "$last" in
    Passed) outcome=passed; [ "${#lines[@]}" -eq 1 ] || outcome=retried ;;
    # A test that could not run here (SKIP_RETURN_CODE: its data is absent) is not a pass.
    *Skipped|*Not) outcome=skipped ;;
    *) outcome=failed ;;
  esac
  {
    flock 9
    cat "$out"
    if [ -n "$left" ]; then
      echo "[test.sh] $t left processes running after it ended; ended:"
      printf '%s\n' "$left" | sed 's/^/[test.sh]   /'
    fi
  } 9>>"$results/lock"
  echo "$outcome${left:+ leaked}" >"$results/$n"
}

# The tests running in the background (not the sentinel, which runs as long as test.sh); prune
# keeps those still running.
lanes=()
prune() {
  local alive=() p
  for p in "${lanes[@]}"; do
    ! kill -0 "$p" 2>/dev/null || alive+=("$p")
  done
  lanes=("${alive[@]}")
}
n=0
for t in "${tests[@]}"; do
  n=$((n + 1))
  prune
  if is_serial "$t"; then
    [ "${#lanes[@]}" -eq 0 ] || wait "${lanes[@]}" || true  # alone: the running tests end first
    lanes=()
    one_test "$n" "$t"
  else
    while [ "${#lanes[@]}" -ge "$jobs" ]; do
      wait -n "${lanes[@]}" || true
      prune
    done
    one_test "$n" "$t" &
    lanes+=($!)
  fi
done
[ "${#lanes[@]}" -eq 0 ] || wait "${lanes[@]}" || true
passed=0
failed=0
skipped=0
failures=()
skips=()
retried=()
leaks=()
for i in "${!tests[@]}"; do
  t=${tests[$i]}
  outcome=failed leaked=""
  [ ! -f "$results/$((i + 1))" ] || read -r outcome leaked <"$results/$((i + 1))"
  case "$outcome" in
    passed) passed=$((passed + 1)) ;;
    retried) passed=$((passed + 1)); retried+=("$t") ;;
    skipped) skipped=$((skipped + 1)); skips+=("$t") ;;
    *) failed=$((failed + 1)); failures+=("$t") ;;
  esac
  [ -z "$leaked" ] || leaks+=("$t")
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
