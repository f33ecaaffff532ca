#!/usr/bin/env bash
# Installs a package of scripts/build-deb.sh, checks it as a user meets it and removes it again
# (root; changes the system while it runs):
#   bash scripts/check-deb.sh dist/paraview-psivolume_0.1-1~deb12_amd64.deb
#   bash scripts/check-deb.sh --paraview 6.1 dist/paraview-psivolume_0.1-1_amd64.deb
# (--paraview: in the Debian system that ships that ParaView, seen through a throwaway overlay,
# as scripts/build-deb.sh --paraview builds it; the cached system is left as it was.)
#   bash scripts/check-deb.sh --fresh --paraview 6.1 dist/paraview-psivolume_0.1-1_amd64.deb
# (--fresh: in a brand-new minimal Debian system made for the check and deleted after it, apt
# installing ParaView and all it needs from the archive: scripts/lib/check-deb-fresh.sh.)
# - a fresh system: apt resolves every dependency from the archive with nothing installed
#   (simulated with an empty dpkg status);
# - pvpython: LoadDistributedPlugin('PsiVolume') with no path, the embedded default drawn,
#   psivolume imported from /usr (Testing/Python/test_installed.py --by-name);
# - pvbatch: the same script;
# - paraview (the GUI): 'PsiVolume' in the plugin manager's list, not loaded until asked; its
#   'Auto Load' ticked in Tools > Manage Plugins loads it at the next start;
# - after `apt-get remove`: none of the package's files left, paraview's files as installed,
#   nothing else under /usr and /etc changed by the removal, and, where the installation brought
#   no other package, all of it as before the installation.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
if [ "${1:-}" = --fresh ]; then
  shift
  exec bash "$root/scripts/lib/check-deb-fresh.sh" "$@"
fi
if [ "${1:-}" = --paraview ]; then
  source "$root/scripts/lib/deb-elsewhere.sh"
  suite=$(psi_deb_suite "${2:?--paraview takes 5.11, 5.13 or 6.1}")
  shift 2
  if [ -n "$suite" ]; then
    rel=$(psi_deb_relative "${1:?usage: check-deb.sh [--paraview X] DEB}")
    psi_deb_in_system "$suite" check-deb.sh "$rel"
    exit 0
  fi
fi
deb=$(realpath "${1:?usage: check-deb.sh [--paraview X] DEB}")
source "$root/scripts/lib/apt.sh"  # psi_apt: one apt-get at a time, waiting for dpkg's lock
# pvpython 5.13 and later lose buffered output when a script leaves through os._exit into a pipe.
export PYTHONUNBUFFERED=1 DEBIAN_FRONTEND=noninteractive
xvfb=(xvfb-run -a -n "${PSI_XVFB_DISPLAY:-99}" -s "-screen 0 1280x1024x24 -noreset")
script="$root/Testing/Python/test_installed.py"
work=$(mktemp -d)
trap 'psi_apt "" remove -y -qq paraview-psivolume >/dev/null 2>&1 || true; rm -rf "$work"' EXIT
cd "$work"
# Every file under /usr and /etc but byte code (pvpython run as root writes it beside the modules).
system_files() { find /usr /etc -xdev ! -name '*.pyc' ! -name __pycache__ | sort; }
system_files > before.txt
packages() { dpkg-query -W -f='${db:Status-Abbrev}${Package}\n' | sed -n 's/^ii *//p' | sort; }
packages > packages-before.txt
: > empty-status
apt-get -s -o Dir::State::status="$work/empty-status" install "$deb" > fresh.txt \
  || { tail -n 20 fresh.txt; echo "FAILED: not installable on a fresh system"; exit 1; }
echo "ok      on a fresh system apt would install it with $(grep -c '^Inst' fresh.txt) packages," \
  "paraview $(sed -n 's/^Inst paraview (\([^ ]*\).*/\1/p' fresh.txt) among them"

psi_apt "" install -y -qq "$deb" >/dev/null
system_files > installed.txt
dpkg -L paraview-psivolume | sort > listed.txt
# its own files and folders (not the shared ones: /usr, /usr/lib, ParaView's plugins/)
files=$(grep -i 'psivolume\|paraview.conf' listed.txt)
env -u PYTHONPATH "${xvfb[@]}" pvpython --force-offscreen-rendering "$script" --by-name --prefix /usr
env -u PYTHONPATH "${xvfb[@]}" pvbatch --force-offscreen-rendering "$script" --by-name --prefix /usr
# The GUI, in a throwaway home (root's ParaView settings stay as they were): the plugin
# manager's list has PsiVolume, not loaded; Tools > Manage Plugins, its 'Auto Load' ticked in the
# dialog by a test script (scripts/lib/autoload-plugin.xml), then at the next start it is loaded
# and 'Psi Volume' is a representation. A client left in a dialog by a failed event is killed.
mkdir home
gui() { env -u PYTHONPATH HOME="$work/home" XDG_CONFIG_HOME="$work/home/.config" "${xvfb[@]}" \
  timeout 90 paraview "$@" --exit > gui.log 2>&1; }
gui_list() {  # loaded=$1, 'Psi Volume' a representation: $2, or fails saying $3
  rm -f plugins.txt; gui --script="$root/scripts/lib/gui_plugins.py" || true
  grep -q "^PsiVolume .*/PsiVolume.so loaded=$1$" plugins.txt \
    && grep -q "^representation 'Psi Volume': $2$" plugins.txt \
    || { cat plugins.txt gui.log; echo "FAILED: $3"; exit 1; }
}
gui_list 0 no "not in the GUI's plugin list, or loaded before it is asked"
echo "ok      the GUI's plugin manager lists: $(grep '^PsiVolume' plugins.txt)"
read -r row child < tree.txt
sed "s/@ROW@/$row/g; s/@CHILD@/$child/g" "$root/scripts/lib/autoload-plugin.xml" > autoload.xml
gui --test-script="$work/autoload.xml" && ! grep -E "Couldn't find|Failed to|FAILED|Unhandled" gui.log \
  || { cat gui.log; echo "FAILED: Tools > Manage Plugins could not tick PsiVolume's Auto Load"; exit 1; }
gui_list 1 yes "not loaded at the start after Auto Load was ticked in Tools > Manage Plugins"
echo "ok      Auto Load ticked in Tools > Manage Plugins: at the next start $(grep '^PsiVolume' plugins.txt)," \
  "'Psi Volume' a representation"

psi_apt "" remove -y -qq paraview-psivolume >/dev/null
left=$(for f in $files; do [ -e "$f" ] || [ -L "$f" ] && echo "$f"; done || true)
[ -z "$left" ] || { echo "FAILED: left after removal: $left"; exit 1; }
dpkg -V paraview python3-paraview || { echo "FAILED: paraview's files changed"; exit 1; }
system_files > after.txt
# Nothing new, nothing gone but what the package listed (its folders too, when no other package
# has them); and, when it brought no other package, all as before the installation.
comm -23 installed.txt after.txt | comm -23 - listed.txt > changed.txt
comm -13 installed.txt after.txt >> changed.txt
[ ! -s changed.txt ] || { cat changed.txt; echo "FAILED: the removal changed more"; exit 1; }
brought=$(packages | comm -13 packages-before.txt - | wc -l)
as="as installed less its own files (the $brought packages it brought stay)"
if [ "$brought" = 0 ]; then
  diff before.txt after.txt || { echo "FAILED: /usr or /etc differ from before"; exit 1; }
  as="as before"
fi
echo "ok      removed: none of its files left, paraview's files as installed, /usr and /etc $as"
echo "check-deb: passed"
