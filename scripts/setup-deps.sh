#!/usr/bin/env bash
# Installs everything needed to build and test the PsiVolume plugin on Debian 12.
# Debian's ParaView 5.11 ships its own VTK (9.2-dev); we build against find_package(ParaView).
# Idempotent: skips apt when every package is already installed.
set -euo pipefail
PKGS=(paraview paraview-dev python3-paraview qtbase5-dev libutfcpp-dev qttools5-dev libqt5svg5-dev
  qtxmlpatterns5-dev-tools libqt5x11extras5-dev libhdf5-dev libogg-dev libtheora-dev libtiff-dev
  libpng-dev libnetcdf-dev libopenmpi-dev libxml2-dev liblzma-dev liblz4-dev libjpeg-dev libglew-dev
  libgl2ps-dev libgdal-dev libfreetype-dev libavcodec-dev libavformat-dev libswscale-dev
  libavutil-dev libeigen3-dev libexpat1-dev libboost-dev python3-dev libx11-dev libgl-dev
  zlib1g-dev python3-mpi4py libdouble-conversion-dev libcgal-dev libosmesa6-dev xvfb xauth mesa-utils
  cmake g++ make python3-numpy python3-matplotlib libqt5opengl5-dev clang libclang-rt-14-dev)
missing=()
for p in "${PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  echo "[setup] installing ${#missing[@]} packages: ${missing[*]}"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
echo "[setup] dependencies present"
