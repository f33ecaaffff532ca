#!/usr/bin/env bash
# Installs everything needed to build and test the PsiVolume plugin against the ParaView of this
# Debian: 12 (ParaView 5.11, Qt 5, its own VTK 9.2), 13 (5.13, Qt 6, its own VTK 9.3) or unstable
# (6.1, Qt 6, on the system VTK 9.6). Idempotent: skips apt when every package is installed.
#   sudo bash scripts/setup-deps.sh
# Needs root (run as another user it calls sudo). What it changes: the system's packages, by
# apt-get (`apt-get update`, then `apt-get install --no-install-recommends` of the missing ones);
# nothing else. Building needs no root: scripts/build-deb.sh asks
#   bash scripts/setup-deps.sh --missing
# which changes nothing, needs no root and prints the missing packages of the build, one a line.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/lib/paraview-versions.sh"
source "$here/lib/apt.sh"
SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"

only_list=0
[ "${1:-}" = --missing ] && only_list=1

apt_update() {
  # Debian unstable's Release file can be past its Valid-Until date on a mirror that lags; apt
  # then refuses it. Retry once without the check, and say so.
  local err rc=0
  err=$(mktemp)
  if ! psi_apt "$SUDO" update -qq 2>"$err"; then
    if grep -qi "is no longer valid\|expired" "$err"; then
      echo "[setup] this mirror's Release file is past its Valid-Until date; updating without that check"
      psi_apt "$SUDO" -o Acquire::Check-Valid-Until=false update -qq || rc=$?
    else
      cat "$err" >&2
      rc=1
    fi
  fi
  rm -f "$err"
  return "$rc"
}

# The ParaView this Debian ships: installed, else the candidate (after an update on a fresh system).
paraview_series() {
  local v
  v=$(installed_paraview_version)
  if [ -z "$v" ]; then
    v=$(apt-cache policy paraview 2>/dev/null | sed -n 's/^ *Candidate: *//p')
    if [ "$only_list" = 1 ] && { [ -z "$v" ] || [ "$v" = "(none)" ]; }; then
      # no update without root: the series of this Debian's release
      v=$(system_paraview_series)
    elif [ -z "$v" ] || [ "$v" = "(none)" ]; then
      apt_update >&2
      v=$(apt-cache policy paraview | sed -n 's/^ *Candidate: *//p')
    fi
  fi
  [ -n "$v" ] && [ "$v" != "(none)" ] || { echo "[setup] this system offers no paraview package" >&2; exit 1; }
  paraview_series_of "$v"
}

COMMON=(paraview paraview-dev python3-paraview libutfcpp-dev libhdf5-dev libogg-dev libtheora-dev
  libtiff-dev libpng-dev libnetcdf-dev libopenmpi-dev libxml2-dev liblzma-dev liblz4-dev libjpeg-dev
  libgl2ps-dev libgdal-dev libfreetype-dev libavcodec-dev libavformat-dev libswscale-dev
  libavutil-dev libeigen3-dev libexpat1-dev libboost-dev python3-dev libx11-dev libgl-dev
  zlib1g-dev python3-mpi4py libdouble-conversion-dev libcgal-dev xvfb xauth mesa-utils cmake g++
  make python3-numpy python3-matplotlib clang git dpkg-dev file gdb ccache)
QT6=(qt6-base-dev qt6-tools-dev qt6-tools-dev-tools qt6-svg-dev qt6-5compat-dev libxcursor-dev)
series=$(paraview_series)
case "$series" in
  5.11) PKGS=("${COMMON[@]}" qtbase5-dev qttools5-dev libqt5svg5-dev qtxmlpatterns5-dev-tools
          libqt5x11extras5-dev libglew-dev libosmesa6-dev libqt5opengl5-dev libclang-rt-14-dev) ;;
  5.13) PKGS=("${COMMON[@]}" "${QT6[@]}" libglew-dev libclang-rt-dev libadios2-mpi-c++11-dev
          libgmsh-dev) ;;
  6.*) PKGS=("${COMMON[@]}" "${QT6[@]}" libvtk9-dev libvtk9-qt-dev libclang-rt-dev libegl-dev
          libgmsh-dev libtbb-dev) ;;
  *) echo "[setup] ParaView $series: not a version this plugin is built for (5.11, 5.13, 6.1)" >&2
     exit 1 ;;
esac
# scripts/check-deb.sh's lintian: for checking the package, not for building it.
[ "$only_list" = 1 ] || PKGS+=(lintian)
missing=()
for p in "${PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ "$only_list" = 1 ]; then
  [ ${#missing[@]} -eq 0 ] || printf '%s\n' "${missing[@]}"
  exit 0
fi
if [ ${#missing[@]} -gt 0 ]; then
  echo "[setup] ParaView $series: installing ${#missing[@]} packages: ${missing[*]}"
  apt_update
  DEBIAN_FRONTEND=noninteractive psi_apt "$SUDO" install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
echo "[setup] dependencies present (ParaView $series)"
