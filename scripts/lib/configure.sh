#!/usr/bin/env bash
# Configures a build tree of this checkout, the one way every script does:
#   bash scripts/lib/configure.sh BUILD [CMAKE_ARG...]
# runs cmake -S <checkout> -B BUILD with, on Debian 13 and unstable, the mended copies of
# ParaView's CMake files kept inside BUILD (scripts/lib/mend-paraview-cmake.sh), the shared
# datasets' folder when PSI_DATA_DIR is set, ccache as the compiler launcher where it is
# installed, then the arguments given. Changes nothing outside BUILD (and ccache's cache).
# ccache with base_dir / (paths relative to each object's folder): two trees at the same depth,
# such as build/ and build-deb/, compiled with the same flags, share their objects; CI builds the
# tests' tree, then the package's (scripts/build-deb.sh), whose compile is then mostly hits.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:?usage: configure.sh BUILD [CMAKE_ARG...]}
shift
mapfile -t hints < <(bash "$root/scripts/lib/mend-paraview-cmake.sh" "$build/paraview-cmake")
launcher=()
if command -v ccache >/dev/null; then
  for lang in C CXX; do
    launcher+=("-DCMAKE_${lang}_COMPILER_LAUNCHER=$(command -v env);CCACHE_BASEDIR=/;ccache")
  done
fi
cmake -S "$root" -B "$build" "${hints[@]}" ${PSI_DATA_DIR:+-DPSI_DATA_DIR="$PSI_DATA_DIR"} \
  "${launcher[@]}" "$@" >/dev/null
