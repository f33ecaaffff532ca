#!/usr/bin/env bash
# Checks a package of scripts/build-deb.sh the way Debian checks packages (piuparts): installs
# it with apt, runs the installed plugin, removes and purges it, and checks that the system is
# as before (root; changes the system while it runs, and undoes it):
#   bash scripts/check-deb.sh dist/paraview-psivolume_0.1-1~deb12_amd64.deb
#   bash scripts/check-deb.sh --paraview 6.1 dist/paraview-psivolume_0.1-1_amd64.deb
# (--paraview: in the Debian system that ships that ParaView, seen through a throwaway overlay,
# as scripts/build-deb.sh --paraview builds it; the cached system is left as it was.)
#   bash scripts/check-deb.sh --fresh --paraview 6.1 dist/paraview-psivolume_0.1-1_amd64.deb
# (--fresh: in a brand-new minimal Debian system made for the check and deleted after it, apt
# installing ParaView and all it needs from the archive: scripts/lib/check-deb-fresh.sh.)
# - lintian: no error or warning that the package does not override (its overrides file);
# - no file of the package belongs to an installed package (dpkg -S), and a fresh system's apt
#   resolves every dependency from the archive (simulated with an empty dpkg status);
# - `apt-get install ./DEB`, dependencies resolved; then every file of the package is its own
#   (dpkg -S names it alone);
# - pvpython: LoadDistributedPlugin('PsiVolume') with no path, the embedded default drawn,
#   psivolume imported from /usr (Testing/Python/test_installed.py --by-name); pvbatch the same;
# - paraview (the GUI): 'PsiVolume' in the plugin manager's list, not loaded until asked; its
#   'Auto Load' ticked in Tools > Manage Plugins loads it at the next start;
# - `apt-get remove`, then `apt-get purge`, and the packages the installation brought purged too:
#   the files and folders under /etc, /usr, /opt, /srv and /var/lib (apt's and dpkg's own state
#   aside) exactly as before the installation (type, mode, size, link target), and ParaView's
#   packages, whose plugins' folder it shares, unchanged (dpkg -V).
# Python's byte code (*.pyc, __pycache__) is left out of the comparison: pvpython run as root
# writes it beside ParaView's own modules.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# lintian on DEB (its version: this machine's): fails on an error or warning not overridden.
lint() {
  command -v lintian >/dev/null || { echo "FAILED: lintian is not installed (apt-get install lintian)"; exit 1; }
  local out rc=0
  out=$(lintian --fail-on error,warning "$1" 2>&1) || rc=$?
  out=$(printf '%s\n' "$out" | grep -v '^running with root privileges' || true)
  if [ "$rc" != 0 ] || printf '%s\n' "$out" | grep -q '^[EW]: '; then
    printf '%s\n' "$out"; echo "FAILED: lintian"; exit 1
  fi
  echo "ok      lintian $(lintian --version | sed 's/^Lintian v//'): no error or warning" \
    "($(dpkg-deb --fsys-tarfile "$1" | tar -xOf - ./usr/share/lintian/overrides/paraview-psivolume 2>/dev/null |
      grep -c '^[^#]') overridden, each with its reason)"
}
if [ "${1:-}" = --fresh ]; then
  shift
  lint "${@: -1}"
  exec bash "$root/scripts/lib/check-deb-fresh.sh" "$@"
fi
if [ "${1:-}" = --paraview ]; then
  source "$root/scripts/lib/deb-elsewhere.sh"
  suite=$(suite_elsewhere "${2:?--paraview takes 5.11, 5.13 or 6.1}")
  shift 2
  if [ -n "$suite" ]; then
    rel=$(psi_deb_relative "${1:?usage: check-deb.sh [--paraview X] DEB}")
    lint "$1"
    PSI_DEB_LINTED=1 psi_deb_in_system "$suite" check-deb.sh "$rel"
    exit 0
  fi
fi
[ "$(id -u)" -eq 0 ] || { echo "check-deb: needs root (it installs and purges the package)" >&2; exit 1; }
deb=$(realpath "${1:?usage: check-deb.sh [--paraview X] DEB}")
source "$root/scripts/lib/apt.sh"  # psi_apt: one apt-get at a time, waiting for dpkg's lock
# pvpython 5.13 and later lose buffered output when a script leaves through os._exit into a pipe.
export PYTHONUNBUFFERED=1 DEBIAN_FRONTEND=noninteractive
xvfb=(bash "$root/scripts/lib/with-xvfb.sh" --new)
script="$root/Testing/Python/test_installed.py"
[ "${PSI_DEB_LINTED:-}" = 1 ] || lint "$deb"
work=$(mktemp -d)
trap 'dpkg --purge paraview-psivolume >/dev/null 2>&1 || true; rm -rf "$work"' EXIT
cd "$work"
# The files and folders a package may leave or change, with what a change shows in: type, mode,
# size (not a folder's: it depends on the file system), link target (apt's, dpkg's and its hooks'
# own state, logs, caches, temporary files, byte code aside, as piuparts leaves them aside).
snapshot() {
  find /etc /usr /opt /srv /var/lib -xdev \( -path /var/lib/apt -o -path /var/lib/dpkg \
    -o -path /var/lib/systemd -o -path /var/lib/adequate -o -name __pycache__ \) -prune \
    -o -type d -printf '%p d %m\n' -o ! -name '*.pyc' -printf '%p %y %m %s %l\n' 2>/dev/null | sort
}
packages() { dpkg-query -W -f='${db:Status-Abbrev}${Package}\n' | sed -n 's/^ii *//p' | sort; }
dpkg-deb -c "$deb" | awk '{print $6}' | sed 's|^\./|/|; s|/$||' | grep . | sort > contents.txt
dpkg-deb -c "$deb" | awk '$1 !~ /^d/ {print $6}' | sed 's|^\./|/|' | sort > files.txt
# No file of the package may belong to another package (dpkg would refuse or, worse, take it).
taken=$(xargs -r dpkg-query -S < files.txt 2>/dev/null | grep -v '^paraview-psivolume: ' || true)
[ -z "$taken" ] || { echo "$taken"; echo "FAILED: files of the package belong to other packages"; exit 1; }
# Nor exist unowned (dpkg would overwrite them silently).
there=$(while read -r f; do [ -e "$f" ] || [ -L "$f" ] && echo "$f"; done < files.txt || true)
[ -z "$there" ] || { echo "$there"; echo "FAILED: files of the package are there already"; exit 1; }
echo "ok      none of its $(wc -l < files.txt) files is another package's or on the system"
# ParaView's packages, whose folders it shares (the plugins' directory): checked unchanged at the end.
shared="paraview python3-paraview"
snapshot > before.txt
packages > packages-before.txt
dpkg -V $shared > verify-before.txt || true
: > empty-status
apt-get -s -o Dir::State::status="$work/empty-status" install "$deb" > fresh.txt \
  || { tail -n 20 fresh.txt; echo "FAILED: not installable on a fresh system"; exit 1; }
echo "ok      on a fresh system apt would install it with $(grep -c '^Inst' fresh.txt) packages," \
  "paraview $(sed -n 's/^Inst paraview (\([^ ]*\).*/\1/p' fresh.txt) among them"

psi_apt "" install -y -qq "$deb" >/dev/null
packages | comm -13 packages-before.txt - | grep -vx paraview-psivolume > brought.txt || true
echo "ok      installed with apt ($(wc -l < brought.txt) packages brought with it)"
owners=$(xargs -r dpkg-query -S < files.txt | grep -v '^paraview-psivolume: ' || true)
[ -z "$owners" ] || { echo "$owners"; echo "FAILED: files of the package claimed by others too"; exit 1; }
env -u PYTHONPATH "${xvfb[@]}" pvpython --force-offscreen-rendering "$script" --by-name --prefix /usr
env -u PYTHONPATH "${xvfb[@]}" pvbatch --force-offscreen-rendering "$script" --by-name --prefix /usr
# The installed mapper from plain VTK Python (Debian's python3 and vtkmodules, no ParaView).
env -u PYTHONPATH "${xvfb[@]}" /usr/bin/python3 "$root/Testing/Python/test_plain_vtk.py" \
  /usr/lib/python3/dist-packages | sed 's/^/plain VTK: /'
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
left=$(while read -r f; do [ -e "$f" ] || [ -L "$f" ] && echo "$f"; done < files.txt || true)
[ -z "$left" ] || { echo "$left"; echo "FAILED: files left after apt-get remove"; exit 1; }
# (dpkg: apt refuses to purge a package without conffiles that the removal has already forgotten)
dpkg --purge paraview-psivolume >/dev/null
[ ! -s brought.txt ] || psi_apt "" purge -y -qq $(cat brought.txt) >/dev/null
! dpkg-query -W -f='${db:Status-Abbrev}' paraview-psivolume 2>/dev/null | grep -q . \
  || { echo "FAILED: dpkg still knows paraview-psivolume after the purge"; exit 1; }
packages | diff packages-before.txt - > packages.diff \
  || { cat packages.diff; echo "FAILED: the packages differ from before"; exit 1; }
snapshot > after.txt
diff before.txt after.txt > files.diff || { cat files.diff
  echo "FAILED: after the purge the files differ from before (<: before, >: after)"; exit 1; }
dpkg -V $shared > verify-after.txt || true
diff verify-before.txt verify-after.txt || { echo "FAILED: files of $shared changed"; exit 1; }
echo "ok      removed and purged (with the $(wc -l < brought.txt) packages it brought):" \
  "$(wc -l < before.txt) files and folders as before, $shared unchanged"
echo "check-deb: passed"
