"""Run by scripts/check-deb.sh in the paraview client (`paraview --script=... --exit`): writes
plugins.txt, one line per plugin of the client's plugin list ("NAME FILE loaded=0|1"), then a
line saying whether 'Psi Volume' is among the representations of a tetrahedral mesh, and
tree.txt: where the PsiVolume entry and its 'Auto Load' row are in the tree of Tools > Manage
Plugins, as "ROW CHILD" (QtTesting's indices, for scripts/lib/autoload-plugin.xml).
Where the rows are is ParaView's pqPluginDialog (setupTreeWidget, populatePluginTree,
addInfoNodes): one row per plugin; under it Version, Description (when not empty), Location,
Required Plugins, Status, Auto Load (and Delayed Load from 5.13); in the order they were added
up to 5.11, sorted by name at both levels from 5.13. The test script checks both labels before
it ticks, so a wrong guess fails rather than ticks another row."""
from paraview import simple
from paraview.servermanager import vtkSMProxyManager as pxm

info = pxm.GetProxyManager().GetPluginManager().GetLocalInformation()
plugins = [(info.GetPluginName(i), i) for i in range(info.GetNumberOfPlugins())]
with open("plugins.txt", "w") as out:
    for name, i in plugins:
        out.write("%s %s loaded=%d\n" % (name, info.GetPluginFileName(i), info.GetPluginLoaded(i)))
    rep = simple.Show(simple.Tetrahedralize(Input=simple.Wavelet()))
    domain = rep.GetProperty("Representation").SMProperty.GetDomain("list")
    names = [domain.GetString(k) for k in range(domain.GetNumberOfStrings())]
    out.write("representation 'Psi Volume': %s\n" % ("yes" if "Psi Volume" in names else "no"))
psi = [i for name, i in plugins if name == "PsiVolume"]
if psi:
    rows = ["Version"] + (["Description"] if info.GetDescription(psi[0]) else []) + \
        ["Location", "Required Plugins", "Status", "Auto Load"]
    if (pxm.GetVersionMajor(), pxm.GetVersionMinor()) >= (5, 13):
        plugins.sort()
        rows = sorted(rows + ["Delayed Load"])
    with open("tree.txt", "w") as out:
        out.write("%d %d\n" % ([i for _, i in plugins].index(psi[0]), rows.index("Auto Load")))
