#!/usr/bin/env bash
# Builds the Debian package paraview-psivolume for the ParaView installed on this Debian, with
# Debian's own tools (dpkg-shlibdeps, dpkg-deb), into dist/ (or $PSI_DEB_OUT); prints its path.
#   bash scripts/build-deb.sh && apt install ./dist/paraview-psivolume_*.deb
# The package depends on exactly the paraview it was built against (a plugin loads only into
# its own ParaView). It installs the plugin into ParaView's plugin directory, the Python package
# psivolume beside ParaView's, and /usr/bin/paraview.conf, which names the plugin's XML for
# paraview, pvpython, pvbatch and pvserver (Debian's ParaView ships no such file): 'PsiVolume'
# is listed in the plugin manager and loads by name. See docs/install.md.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${PSI_DEB_BUILD_DIR:-$root/build-deb}
out=${PSI_DEB_OUT:-$root/dist}
maintainer=${PSI_DEB_MAINTAINER:-"PsiVolume maintainers <psivolume@localhost>"}

bash "$root/scripts/setup-deps.sh" >&2
pv_version=$(dpkg-query -W -f='${Version}' paraview)
arch=$(dpkg --print-architecture)
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX=/usr \
  -DBUILD_TESTING=OFF -DPSI_BUILD_BENCHMARKS=OFF -DPSI_INSTALL_PARAVIEW_CONF=ON >/dev/null
cmake --build "$build" -j"$(nproc)" >&2
upstream=$(sed -n 's/^CMAKE_PROJECT_VERSION:STATIC=//p' "$build/CMakeCache.txt")
version="$upstream-1"

work="$build/deb"
stage="$work/paraview-psivolume"
rm -rf "$work"
DESTDIR="$stage" cmake --install "$build" --component runtime >/dev/null
find "$stage" -name '*.so' -o -name psi_reference_render | xargs strip --strip-unneeded

# Shared-library dependencies by dpkg-shlibdeps (it reads debian/control). ParaView's libraries
# carry no shlibs information: the exact paraview dependency below covers them.
plugin_dir=$(dirname "$(find "$stage" -name PsiVolume.so)")
mkdir -p "$work/debian" "$stage/DEBIAN"
printf 'Source: paraview-psivolume\n\nPackage: paraview-psivolume\nArchitecture: any\n' \
  > "$work/debian/control"
binaries=()
for f in "$plugin_dir"/*.so "$plugin_dir/psi_reference_render"; do binaries+=("-e$f"); done
shlibs=$(cd "$work" && dpkg-shlibdeps -O --ignore-missing-info -l"$plugin_dir" "${binaries[@]}" \
  | sed -n 's/^shlibs:Depends=//p')

cat > "$stage/DEBIAN/control" <<EOF
Package: paraview-psivolume
Version: $version
Architecture: $arch
Maintainer: $maintainer
Section: science
Priority: optional
Installed-Size: $(du -sk --exclude=DEBIAN "$stage" | cut -f1)
Depends: paraview (= $pv_version), python3-paraview (= $pv_version), python3-numpy${shlibs:+, $shlibs}
Description: 'Psi Volume' representation for tetrahedral meshes in ParaView
 Projected tetrahedra whose fragments integrate their own ray segment, by one of seven
 methods, with isosurfaces, adaptive sampling and depth peeling; a conforming
 tetrahedralization filter and a reader of tetrahedral .off files. Built for
 ParaView $pv_version only.
EOF
# pvpython may write byte code into the package's directory: remove it with the package.
package_dir=$(cd "$stage" && find . -type d -name psivolume | sed 's|^\.||')
printf '#!/bin/sh\nset -e\nrm -rf %s/__pycache__\n' "$package_dir" > "$stage/DEBIAN/prerm"
chmod 0755 "$stage/DEBIAN/prerm"

mkdir -p "$out"
deb="$out/paraview-psivolume_${version}_${arch}.deb"
dpkg-deb --root-owner-group --build "$stage" "$deb" >&2
echo "$deb"
