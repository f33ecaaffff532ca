#!/usr/bin/env bash
# Mends a Debian packaging fault that stops find_package(ParaView), and says what it did.
#
# The CMake files of Debian 13's ParaView 5.13 and of unstable's 6.1 name their Python extension
# modules without the suffix the packages install them with (…/vtkmodules/vtkCommonCore.so for
# vtkCommonCore.cpython-313-x86_64-linux-gnu.so), and CMake refuses an imported target whose
# file is missing. For each such name a symbolic link to the installed module is made; nothing
# is made where the named file exists or no suffixed module is installed beside it.
set -euo pipefail
made=0
for targets in /usr/lib/*/cmake/paraview-*/vtk/*-targets-*.cmake /usr/lib/*/cmake/paraview-*/*-targets-*.cmake \
    /usr/lib/*/cmake/vtk-*/*-targets-*.cmake; do
  [ -f "$targets" ] || continue
  while IFS= read -r named; do
    [ -e "$named" ] && continue
    dir=$(dirname "$named")
    base=$(basename "$named" .so)
    installed=$(ls "$dir/$base".cpython-*.so 2>/dev/null | head -n1 || true)
    [ -n "$installed" ] || continue
    ln -s "$(basename "$installed")" "$named"
    made=$((made + 1))
  done < <(grep -o '"${_IMPORT_PREFIX}/lib/python3[^"]*\.so"' "$targets" | tr -d '"' |
    sed 's|^${_IMPORT_PREFIX}|/usr|' | sort -u)
done
if [ "$made" -gt 0 ]; then
  echo "[setup] Debian's ParaView CMake files name $made Python modules without their" \
    "cpython suffix; linked each name to the installed module so that find_package(ParaView) works"
fi
