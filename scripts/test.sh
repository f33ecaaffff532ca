#!/usr/bin/env bash
# The test command: installs what is missing (Debian 12), builds, and runs every test with CTest
# under a virtual X server (Mesa llvmpipe gives OpenGL 4.5 with geometry shaders).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/setup-deps.sh"
bash "$root/scripts/build.sh"
cd "$root/build"
xvfb-run -a -s "-screen 0 1280x1024x24" ctest --output-on-failure --timeout 900 "$@"
