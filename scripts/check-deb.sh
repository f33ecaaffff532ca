#!/usr/bin/env bash
# Installs a package of scripts/build-deb.sh, checks it as a user meets it and removes it again
# (root; changes the system while it runs):
#   bash scripts/check-deb.sh dist/paraview-psivolume_0.1-1_amd64.deb
# - pvpython: LoadDistributedPlugin('PsiVolume') with no path, the embedded default drawn,
#   psivolume imported from /usr (Testing/Python/test_installed.py --by-name);
# - pvbatch: the same script;
# - paraview (the GUI): 'PsiVolume' in the plugin manager's list, not loaded until asked;
# - after `apt-get remove`: none of the package's files left, paraview's files as installed.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
deb=$(realpath "$1")
xvfb=(xvfb-run -a -s "-screen 0 1280x1024x24 -noreset")
script="$root/Testing/Python/test_installed.py"
work=$(mktemp -d)
trap 'apt-get remove -y -qq paraview-psivolume >/dev/null 2>&1 || true; rm -rf "$work"' EXIT
cd "$work"

apt-get install -y -qq "$deb" >/dev/null
# its own files and folders (not the shared ones: /usr, /usr/lib, ParaView's plugins/)
files=$(dpkg -L paraview-psivolume | grep -i 'psivolume\|paraview.conf')
env -u PYTHONPATH "${xvfb[@]}" pvpython --force-offscreen-rendering "$script" --by-name --prefix /usr
env -u PYTHONPATH "${xvfb[@]}" pvbatch --force-offscreen-rendering "$script" --by-name --prefix /usr
cat > gui.py <<'PY'
from paraview import servermanager
info = servermanager.vtkSMProxyManager.GetProxyManager().GetPluginManager().GetLocalInformation()
with open("plugins.txt", "w") as out:
    for i in range(info.GetNumberOfPlugins()):
        out.write("%s %s loaded=%d\n" % (info.GetPluginName(i), info.GetPluginFileName(i),
                                         info.GetPluginLoaded(i)))
PY
env -u PYTHONPATH "${xvfb[@]}" paraview --script="$work/gui.py" --exit >/dev/null 2>&1 || true
grep -q '^PsiVolume .*/PsiVolume.so loaded=0$' plugins.txt || { cat plugins.txt; echo "FAILED: not in the GUI's plugin list"; exit 1; }
echo "ok      the GUI's plugin manager lists: $(grep '^PsiVolume' plugins.txt)"

apt-get remove -y -qq paraview-psivolume >/dev/null
left=$(for f in $files; do [ -e "$f" ] && echo "$f"; done || true)
[ -z "$left" ] || { echo "FAILED: left after removal: $left"; exit 1; }
dpkg -V paraview python3-paraview || { echo "FAILED: paraview's files changed"; exit 1; }
echo "ok      removed: none of its files left, paraview's files as installed"
echo "check-deb: passed"
