#!/usr/bin/env bash
# Configures and builds the plugin, its tests and benchmarks (Release) into build/, or into
# $PSI_BUILD_DIR (scripts/test.sh --paraview keeps one build per ParaView there).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${PSI_BUILD_DIR:-$root/build}
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j"$(nproc)"
