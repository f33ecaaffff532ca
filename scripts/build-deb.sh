#!/usr/bin/env bash
# Builds the Debian package paraview-psivolume for the ParaView installed on this Debian, with
# Debian's own tools (dpkg-shlibdeps, dpkg-deb), into dist/ (or $PSI_DEB_OUT); prints its path.
#   bash scripts/build-deb.sh && apt install ./dist/paraview-psivolume_*.deb
#   bash scripts/build-deb.sh --paraview 6.1   the package for another Debian's ParaView (5.11:
#                                              Debian 12, 5.13: 13, 6.1: unstable), built in
#                                              that Debian's system of scripts/in-system.sh
# The package depends on exactly the paraview it was built against (a plugin loads only into
# its own ParaView); its version is <project version>-1 on unstable and <...>-1~debN on Debian N.
# It installs the plugin into ParaView's plugin directory, the Python package psivolume beside
# ParaView's, and what makes ParaView list the plugin, so that 'PsiVolume' is in the plugin
# manager and loads by name in paraview, pvpython, pvbatch and pvserver: on Debian 13 and later a
# link in the directory of other packages' plugins that Debian's paraview.conf names; on Debian
# 12, whose ParaView reads only /usr/bin/paraview.conf and ships none, that file.
# See docs/install.md.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
if [ "${1:-}" = --paraview ]; then
  source "$root/scripts/lib/deb-elsewhere.sh"
  suite=$(psi_deb_suite "${2:?--paraview takes 5.11, 5.13 or 6.1}")
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
# The maintainer as Debian's own tools take it (dch, debmake): DEBFULLNAME and DEBEMAIL.
maintainer=${PSI_DEB_MAINTAINER:-"${DEBFULLNAME:-PsiVolume maintainers} <${DEBEMAIL:-psivolume@localhost}>"}

bash "$root/scripts/setup-deps.sh" >&2
pv_version=$(dpkg-query -W -f='${Version}' paraview)
arch=$(dpkg --print-architecture)
# Where ParaView lists plugins from: Debian's 5.13 and later read the paraview.conf of ParaView's
# library directory, which names a directory for other packages' plugins; 5.11 reads only
# /usr/bin/paraview.conf, which it does not ship.
debian_conf=$(dpkg -L paraview | grep '/paraview-[0-9.]*/paraview\.conf$' || true)
shared_plugins=""
if [ -n "$debian_conf" ]; then
  shared_plugins=$(grep '^/' "$debian_conf" | grep -v '\.xml$' | head -n 1 || true)
  [ -n "$shared_plugins" ] || { echo "build-deb: $debian_conf names no directory for" \
    "other packages' plugins: PsiVolume could not be listed without changing paraview's files" >&2
    exit 1; }
fi
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX=/usr \
  -DBUILD_TESTING=OFF -DPSI_BUILD_BENCHMARKS=OFF \
  -DPSI_INSTALL_PARAVIEW_CONF="$([ -n "$debian_conf" ] && echo OFF || echo ON)" >/dev/null
cmake --build "$build" -j"$(nproc)" >&2
upstream=$(sed -n 's/^CMAKE_PROJECT_VERSION:STATIC=//p' "$build/CMakeCache.txt")
# Debian N's package sorts below unstable's, as Debian's own backports do (0.1-1~deb13 < 0.1-1).
release=$(. /etc/os-release && echo "${VERSION_ID:-}")
version="$upstream-1${release:+~deb$release}"

work="$build/deb"
stage="$work/paraview-psivolume"
rm -rf "$work"
DESTDIR="$stage" cmake --install "$build" --component runtime >/dev/null
find "$stage" -name '*.so' -o -name psi_reference_render | xargs strip --strip-unneeded
plugin_dir=$(dirname "$(find "$stage" -name PsiVolume.so)")
# Debian 13 and later: ParaView lists the plugins of that directory (and of its subdirectories)
# without loading them; a link to the plugin's directory, where its libraries are ($ORIGIN).
if [ -n "$shared_plugins" ]; then
  mkdir -p "$stage$shared_plugins"
  ln -s "$(realpath -m --relative-to="$shared_plugins" "${plugin_dir#"$stage"}")" \
    "$stage$shared_plugins/PsiVolume"
fi

source "$root/scripts/lib/deb-docs.sh"
psi_deb_docs "$stage" "$version" "$maintainer" "$pv_version"

# Shared-library dependencies by dpkg-shlibdeps (it reads debian/control). ParaView's libraries
# carry no shlibs information before 5.13 and a range from then on: the exact paraview
# dependency below covers them, so its range is dropped.
mkdir -p "$work/debian" "$stage/DEBIAN"
printf 'Source: paraview-psivolume\n\nPackage: paraview-psivolume\nArchitecture: any\n' \
  > "$work/debian/control"
binaries=()
for f in "$plugin_dir"/*.so "$plugin_dir/psi_reference_render"; do binaries+=("-e$f"); done
shlibs=$(cd "$work" && dpkg-shlibdeps -O --ignore-missing-info -l"$plugin_dir" "${binaries[@]}" \
  | sed -n 's/^shlibs:Depends=//p' | sed 's/, /\n/g' | grep -v '^paraview ' | paste -sd, \
  | sed 's/,/, /g')

cat > "$stage/DEBIAN/control" <<EOF
Package: paraview-psivolume
Version: $version
Architecture: $arch
Maintainer: $maintainer
Section: science
Priority: optional
Installed-Size: $(du -sk --exclude=DEBIAN "$stage" | cut -f1)
Depends: paraview (= $pv_version), python3-paraview (= $pv_version), python3:any, python3-numpy${shlibs:+, $shlibs}
Description: 'Psi Volume' representation for tetrahedral meshes in ParaView
 Projected tetrahedra whose fragments integrate their own ray segment, by
 one of seven methods, with isosurfaces, adaptive sampling and depth
 peeling; a conforming tetrahedralization filter and a reader of
 tetrahedral .off files. Built for ParaView $pv_version only.
EOF
# pvpython may write byte code into the package's directory: remove it with the package.
package_dir=$(cd "$stage" && find . -type d -name psivolume | sed 's|^\.||')
printf '#!/bin/sh\nset -e\nrm -rf %s/__pycache__\n' "$package_dir" > "$stage/DEBIAN/prerm"
chmod 0755 "$stage/DEBIAN/prerm"

mkdir -p "$out"
deb="$out/paraview-psivolume_${version}_${arch}.deb"
dpkg-deb --root-owner-group --build "$stage" "$deb" >&2
echo "$deb"
