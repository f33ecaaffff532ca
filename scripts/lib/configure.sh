#!/usr/bin/env bash
# Configures a build tree of this checkout, the one way every script does:
#   bash scripts/lib/configure.sh BUILD [CMAKE_ARG...]
# runs cmake -S <checkout> -B BUILD with, on Debian 13 and unstable, the mended copies of
# ParaView's CMake files kept inside BUILD (scripts/lib/mend-paraview-cmake.sh), the shared
# datasets' folder when PSI_DATA_DIR is set, then the arguments given. Changes nothing outside
# BUILD.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:?usage: configure.sh BUILD [CMAKE_ARG...]}
shift
mapfile -t hints < <(bash "$root/scripts/lib/mend-paraview-cmake.sh" "$build/paraview-cmake")
cmake -S "$root" -B "$build" "${hints[@]}" ${PSI_DATA_DIR:+-DPSI_DATA_DIR="$PSI_DATA_DIR"} "$@" \
  >/dev/null
