#!/usr/bin/env bash
# The test command: installs what is missing (Debian 12), builds, and runs every test with CTest
# under a virtual X server (Mesa llvmpipe gives OpenGL 4.5 with geometry shaders).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/setup-deps.sh"
bash "$root/scripts/build.sh"
cd "$root/build"
# One retry per test: on this machine a pvpython process occasionally fails to open the Xvfb
# display ("bad X server connection", seen only under heavy concurrent load). A real failure
# fails twice and still fails the run.
xvfb-run -a -s "-screen 0 1280x1024x24" ctest --output-on-failure --timeout 900 \
  --repeat until-pass:2 "$@"
