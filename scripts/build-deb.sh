#!/usr/bin/env bash
# Builds the Debian package paraview-psivolume for the ParaView installed on this Debian with
# CMake's own packager: a Release build with the prefix /usr in build-deb/ (its own build tree),
# then `cpack -G DEB` (cmake/PsiVolumePackaging.cmake says what goes in and how); the package goes
# into dist/ (or $PSI_DEB_OUT) and its path is printed.
#   bash scripts/build-deb.sh && sudo apt install ./dist/paraview-psivolume_*.deb
#   bash scripts/build-deb.sh --paraview 6.1   the package for another Debian's ParaView (5.11:
#                                              Debian 12, 5.13: 13, 6.1: unstable), built in
#                                              that Debian's system of scripts/in-system.sh
# Needs no root and changes nothing outside its build tree and dist/: what the build needs and
# this Debian lacks is named (install it with `sudo bash scripts/setup-deps.sh`), not installed.
# The package depends on exactly the paraview it was built against (a plugin loads only into its
# own ParaView); its version is <project version>-1 on unstable and <...>-1~debN on Debian N.
# See docs/install.md.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
if [ "${1:-}" = --paraview ]; then
  source "$root/scripts/lib/deb-elsewhere.sh"
  suite=$(suite_elsewhere "${2:?--paraview takes 5.11, 5.13 or 6.1}")
  shift 2
  if [ -n "$suite" ]; then
    deb=$(psi_deb_in_system "$suite" build-deb.sh "$@")
    echo "$root/${deb#/psi/src/}"
    exit 0
  fi
fi
# Inside a system of in-system.sh, beside its build of the checkout (kept between runs).
build=${PSI_DEB_BUILD_DIR:-${PSI_BUILD_DIR:-$root/build}-deb}
out=${PSI_DEB_OUT:-$root/dist}
umask 022  # the package's files and folders as Debian wants them, whatever the caller's umask

missing=$(bash "$root/scripts/setup-deps.sh" --missing)
# the packaging's own commands, and the packages that have them
for tool in cpack:cmake dpkg-shlibdeps:dpkg-dev dpkg-buildflags:dpkg-dev file:file; do
  command -v "${tool%%:*}" >/dev/null || missing+=$'\n'"${tool#*:}"
done
missing=$(printf '%s\n' "$missing" | sed '/^$/d' | sort -u)
if [ -n "$missing" ]; then
  echo "build-deb: this Debian lacks what the build needs; install it (as root) with" >&2
  echo "  sudo bash scripts/setup-deps.sh" >&2
  echo "which installs these packages: $(echo $missing)" >&2
  exit 1
fi
# Debian's build flags, as dpkg-buildpackage sets them (scripts/lib/debian-flags.sh).
mapfile -t flags < <(bash "$root/scripts/lib/debian-flags.sh")
bash "$root/scripts/lib/configure.sh" "$build" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_INSTALL_PREFIX=/usr -DBUILD_TESTING=OFF -DPSI_BUILD_BENCHMARKS=OFF -DPSI_DEB_PACKAGE=ON \
  "${flags[@]}"
cmake --build "$build" -j"$(nproc)" >&2
rm -rf "$build/package"
(cd "$build" && cpack -G DEB) >&2
deb=$(find "$build/package" -maxdepth 1 -name 'paraview-psivolume_*.deb')
[ "$(printf '%s\n' "$deb" | grep -c .)" = 1 ] || { echo "build-deb: cpack made no package" >&2; exit 1; }
mkdir -p "$out"
cp "$deb" "$out/"
echo "$out/${deb##*/}"
