#!/usr/bin/env bash
# The test command: installs what is missing, builds, and runs every test with CTest under a
# virtual X server (Mesa llvmpipe gives OpenGL 4.5 with geometry shaders).
#   bash scripts/test.sh                      the ParaView of this Debian (12: 5.11, 13: 5.13,
#                                             unstable: 6.1)
#   bash scripts/test.sh --paraview 6.1       the same suite inside a Debian system that ships
#                                             that ParaView (made once and cached, see
#                                             scripts/debian-system.sh); 5.11, 5.13, 6.1 or all
#   bash scripts/test.sh --only REGEX         only the tests whose names match REGEX
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
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
. "$root/scripts/lib/python-path.sh"
paraview=""
only=""
ctest_args=()
while [ "$#" -gt 0 ]; do
  case "$1" in
    --paraview) paraview=${2:?--paraview takes 5.11, 5.13, 6.1 or all}; shift 2 ;;
    --only) only=${2:?--only takes a regular expression}; shift 2 ;;
    *) ctest_args+=("$1"); shift ;;
  esac
done

if [ -n "$paraview" ]; then
  exec bash "$root/scripts/test-paraview.sh" "$paraview" ${only:+--only "$only"} "${ctest_args[@]}"
fi

bash "$root/scripts/setup-deps.sh"
bash "$root/scripts/build.sh"
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
out=$(mktemp)
trap 'rm -f "$out"' EXIT
for t in "${tests[@]}"; do
  pattern="^$(printf '%s' "$t" | sed 's/[.[\*^$()+?{|]/\\&/g')\$"
  ok=0
  for attempt in 1 2 3; do
    if xvfb-run -a -n "${PSI_XVFB_DISPLAY:-99}" -s "-screen 0 1280x1024x24 -noreset" \
      ctest --output-on-failure --timeout 900 -R "$pattern" "${ctest_args[@]}" 2>&1 | tee "$out"; then
      ok=1
      break
    fi
    echo "[test.sh] $t failed (attempt $attempt)"
  done
  if [ "$ok" = 1 ] && grep -q "\*\*\*Skipped\|Not Run" "$out"; then
    # A test that could not run here (SKIP_RETURN_CODE: its data is absent) is not a pass.
    skipped=$((skipped + 1))
    skips+=("$t")
  elif [ "$ok" = 1 ]; then
    passed=$((passed + 1))
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
echo "$passed passed, $failed failed, $skipped skipped"
[ "$failed" -eq 0 ]
