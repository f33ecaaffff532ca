#!/usr/bin/env bash
# Works around a Debian packaging fault that stops find_package(ParaView), inside a build tree:
#   bash scripts/lib/mend-paraview-cmake.sh BUILD/paraview-cmake
# prints the CMake options (one a line, e.g. -DParaView_DIR=BUILD/paraview-cmake/paraview-5.13)
# that make CMake read mended copies of ParaView's (and the system VTK's) CMake package files;
# prints nothing where nothing needs mending (Debian 12). Needs no root and changes nothing
# outside the directory given.
#
# The CMake files of Debian 13's ParaView 5.13 and of unstable's 6.1 (and its VTK 9.6) name their
# Python extension modules without the suffix the packages install them with
# (…/vtkmodules/vtkCommonCore.so for vtkCommonCore.cpython-313-x86_64-linux-gnu.so), and CMake
# refuses an imported target whose file is missing. Such a package directory is copied into the
# given directory, where each missing name is replaced by the installed module's path and the
# installation prefix, which the files compute from their own location, is set to the real one.
set -euo pipefail
shim=${1:?usage: mend-paraview-cmake.sh DIRECTORY}
for dir in /usr/lib/*/cmake/paraview-* /usr/lib/*/cmake/vtk-*; do
  [ -d "$dir" ] || continue
  name=$(basename "$dir")
  # "named installed" pairs: the missing path and the suffixed module installed beside it.
  pairs=$(grep -rhoE '"\$\{_IMPORT_PREFIX\}/lib/python3[^"]*\.so"' --include='*-targets-*.cmake' "$dir" |
    tr -d '"' | sed 's|^${_IMPORT_PREFIX}|/usr|' | sort -u |
    while IFS= read -r named; do
      [ -e "$named" ] && continue
      installed=$(ls "${named%.so}".cpython-*.so 2>/dev/null | head -n 1 || true)
      [ -z "$installed" ] || printf '%s %s\n' "$named" "$installed"
    done)
  [ -n "$pairs" ] || continue
  copy="$shim/$name"
  rm -rf "$copy"
  mkdir -p "$shim"
  cp -a "$dir" "$copy"
  # Each file's prefix from the original's location (the targets' _IMPORT_PREFIX, the module
  # properties' _vtk_module_import_prefix, from which the wrappers' hierarchy files are found);
  # relative paths out of the directory too.
  find "$copy" -name '*.cmake' | while IFS= read -r f; do
    real=$(dirname "$dir/${f#"$copy"/}")
    sed -i -e "s|get_filename_component(_IMPORT_PREFIX \"\${CMAKE_CURRENT_LIST_FILE}\" PATH)|set(_IMPORT_PREFIX \"$real\")|" \
      -e "s|\"\${CMAKE_CURRENT_LIST_DIR}/\.\./|\"$real/../|g" \
      -e "s|set(_vtk_module_import_prefix \"\${CMAKE_CURRENT_LIST_DIR}\")|set(_vtk_module_import_prefix \"$real\")|" \
      "$f"
  done
  while read -r named installed; do
    grep -rlF --include='*-targets-*.cmake' "\"\${_IMPORT_PREFIX}${named#/usr}\"" "$copy" |
      xargs -r sed -i "s|\"\${_IMPORT_PREFIX}${named#/usr}\"|\"$installed\"|g"
  done <<< "$pairs"
  case "$name" in
    # ParaView's own VTK (5.13) is found in its vtk/ folder: named too, so that a build tree
    # configured before (VTK_DIR in its cache) reads the mended copy as well
    paraview-*) echo "-DParaView_DIR=$copy"; [ ! -d "$copy/vtk" ] || echo "-DVTK_DIR=$copy/vtk" ;;
    vtk-*) echo "-DVTK_DIR=$copy" ;;
  esac
  echo "[mend] Debian's $name CMake files name $(wc -l <<< "$pairs") Python modules without their" \
    "cpython suffix: CMake reads a mended copy in $copy" >&2
done
