#!/usr/bin/env bash
# Configures and builds the plugin, its tests and benchmarks (Release) into build/, or into
# $PSI_BUILD_DIR (scripts/in-system.sh keeps each Debian system's build elsewhere so), with the
# shared datasets at ../shared/data or $PSI_DATA_DIR (CMake's PSI_DATA_DIR), with Debian's
# compiler flags (scripts/lib/debian-flags.sh), as the package is built.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${PSI_BUILD_DIR:-$root/build}
mapfile -t flags < <(bash "$root/scripts/lib/debian-flags.sh")
bash "$root/scripts/lib/configure.sh" "$build" -DCMAKE_BUILD_TYPE=Release "${flags[@]}"
cmake --build "$build" -j"$(nproc)"
