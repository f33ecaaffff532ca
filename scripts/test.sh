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
# Each test gets its own fresh Xvfb server, started with -noreset: by default Xvfb resets
# whenever its last client disconnects and refuses connections meanwhile, which made a
# pvpython/pvbatch process (most often a rank of the 2-rank MPI test) fail with "bad X server
# connection" now and then (measured: two processes opening and closing the display 3,000 times
# failed 13-17% of the time by default, 0% with -noreset). Up to two retries remain, each in
# another fresh server, as a guard; a real failure fails every attempt and fails the run.
# xvfb-run -a takes the first display number from PSI_XVFB_DISPLAY (default 99) whose lock file
# is free; a Debian system of scripts/in-system.sh has a /tmp of its own but shares X's abstract
# sockets with the host, so in-system.sh starts each system's numbers elsewhere.
# A test that passes only on a retry is counted as passed and named in the summary line, so that
# a flaky test is seen. Every process a test starts is ended when its attempt ends, also when
# test.sh is interrupted or killed (see the tag below and scripts/lib/end_tagged.py).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
. "$root/scripts/lib/python-path.sh"
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
if [ -n "$tsan" ]; then
  export PSI_BUILD_DIR=${PSI_BUILD_DIR:-$root/build-tsan}
  cmake -S "$root" -B "$PSI_BUILD_DIR" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPSI_SANITIZE_THREAD=ON \
    -DPSI_BUILD_BENCHMARKS=OFF >/dev/null
  cmake --build "$PSI_BUILD_DIR" -j"$(nproc)" --target PsiVolume TestLODImage
  only=${only:-'^(PsiRepresentations\.LODImage|PsiPython\.(interaction|lod_inputs))$'}
else
  bash "$root/scripts/build.sh"
fi
# pvpython 5.13+ loses buffered output when a script leaves through os._exit into a pipe
# (psivolume.process): unbuffered, a failing test's check lines reach the log.
export PYTHONUNBUFFERED=1
cd "${PSI_BUILD_DIR:-$root/build}"
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

# Each attempt runs with PSI_TEST_RUN=<run>:<n> in its environment, which every process it starts
# inherits, also one in a session or process group of its own (each MPI rank, test_pvserver.py's
# server) or orphaned (a pvserver rank whose smTestDriver was killed waits for its client forever,
# one rank busy-waiting in MPI at a full core). What is still running when the attempt ends is
# ended and named; on INT, TERM or HUP test.sh ends the attempt's processes before it exits; a
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

# One attempt, tagged $1, at the test matching the CTest regex $2, in its own fresh X server:
# run in the background and waited for, so that a signal reaches the traps above at once.
run_attempt() {
  local tag=$1 pattern=$2
  (
    export PSI_TEST_RUN="$tag"
    xvfb-run -a -n "${PSI_XVFB_DISPLAY:-99}" -s "-screen 0 1280x1024x24 -noreset" \
      ctest --output-on-failure --timeout 900 -R "$pattern" "${ctest_args[@]}" 2>&1 | tee "$out"
  ) &
  wait $!
}

n=0
for t in "${tests[@]}"; do
  pattern="^$(printf '%s' "$t" | sed 's/[.[\*^$()+?{|]/\\&/g')\$"
  ok=0
  for attempt in 1 2 3; do
    n=$((n + 1))
    run_attempt "$run:$n" "$pattern" && ok=1
    left=$(end_tagged "$run:$n" || true)
    if [ -n "$left" ]; then
      echo "[test.sh] $t left processes running after it ended; ended:"
      printf '%s\n' "$left" | sed 's/^/[test.sh]   /'
      leaks+=("$t")
    fi
    [ "$ok" = 1 ] && break
    echo "[test.sh] $t failed (attempt $attempt)"
  done
  if [ "$ok" = 1 ] && grep -q "\*\*\*Skipped\|Not Run" "$out"; then
    # A test that could not run here (SKIP_RETURN_CODE: its data is absent) is not a pass.
    skipped=$((skipped + 1))
    skips+=("$t")
  elif [ "$ok" = 1 ]; then
    passed=$((passed + 1))
    [ "$attempt" = 1 ] || retried+=("$t")
  else
    failed=$((failed + 1))
    failures+=("$t")
  fi
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
# The first words stay "N passed, M failed" (.ci/run and test-paraview.sh read them).
echo "$passed passed, $failed failed, $skipped skipped," \
  "${#retried[@]} passed only on a retry${retried[*]:+: ${retried[*]}}"
[ "$failed" -eq 0 ]
