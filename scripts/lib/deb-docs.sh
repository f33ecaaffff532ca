# Sourced by scripts/build-deb.sh: the documentation every Debian package carries (Debian Policy
# §12.5, §12.7), under usr/share/doc/<package>/ of the staging tree, and the one lintian override.

# psi_deb_docs STAGE VERSION MAINTAINER PARAVIEW_VERSION
psi_deb_docs() {
  local stage=$1 version=$2 maintainer=$3 paraview=$4
  local doc="$stage/usr/share/doc/paraview-psivolume" dist
  mkdir -p "$doc" "$stage/usr/share/lintian/overrides"
  dist=$(. /etc/os-release && echo "${VERSION_ID:+${VERSION_CODENAME:-}}")
  {
    echo "paraview-psivolume ($version) ${dist:-unstable}; urgency=medium"
    echo
    echo "  * Built for ParaView $paraview by scripts/build-deb.sh."
    echo
    echo " -- $maintainer  $(date -R -u -d "@${SOURCE_DATE_EPOCH:-$(date +%s)}")"
  } | gzip -9n > "$doc/changelog.Debian.gz"
  # The machine-readable format, with LICENSE's text (its paragraphs joined by " .").
  {
    echo "Format: https://www.debian.org/doc/packaging-manuals/copyright-format/1.0/"
    echo "Upstream-Name: PsiVolume"
    echo
    echo "Files: *"
    echo "Copyright: $(sed -n 's/^Copyright (c) //p' "$root/LICENSE" | head -n 1)"
    echo "License: BSD-3-clause"
    sed -n '/^Copyright/,$p' "$root/LICENSE" | tail -n +2 | sed -e '1{/^$/d}' -e 's/^$/./' -e 's/^/ /'
  } > "$doc/copyright"
  # A package built here, not uploaded to Debian: no bug (ITP) for its changelog to close.
  local overrides="$stage/usr/share/lintian/overrides/paraview-psivolume"
  echo "paraview-psivolume: initial-upload-closes-no-bugs" > "$overrides"
  # Debian 12's ParaView reads its plugin list from /usr/bin/paraview.conf, not a command.
  if [ -e "$stage/usr/bin/paraview.conf" ]; then
    echo "paraview-psivolume: no-manual-page [usr/bin/paraview.conf]" >> "$overrides"
  fi
}
