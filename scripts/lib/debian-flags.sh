#!/usr/bin/env bash
# Prints, one a line, the CMake arguments that give a build Debian's compiler and linker flags as
# dpkg-buildpackage sets them (hardening: all of it), with CMake's Release optimization in place
# of their -O2 and no debugging information. scripts/build-deb.sh builds the package so, and
# scripts/build.sh the tests' tree the same way: the tests build what ships, and the package's
# compile is the tests' compile again, which ccache answers (scripts/lib/configure.sh).
# Prints nothing where dpkg-buildflags is missing (a machine without dpkg-dev).
#   mapfile -t flags < <(bash scripts/lib/debian-flags.sh)
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
command -v dpkg-buildflags >/dev/null || exit 0
export DEB_BUILD_MAINT_OPTIONS=hardening=+all
export DEB_CFLAGS_MAINT_STRIP="-g -O2" DEB_CXXFLAGS_MAINT_STRIP="-g -O2"
flag() { (cd "$root" && dpkg-buildflags --get "$1"); }
echo "-DCMAKE_C_FLAGS=$(flag CPPFLAGS) $(flag CFLAGS)"
echo "-DCMAKE_CXX_FLAGS=$(flag CPPFLAGS) $(flag CXXFLAGS)"
for kind in EXE SHARED MODULE; do
  echo "-DCMAKE_${kind}_LINKER_FLAGS=$(flag LDFLAGS)"
done
