"""The plugin and the Python package as installed (`cmake --install`, the Debian package of
scripts/build-deb.sh): psivolume imports from the install tree with the checkout's Python/ off
the path, the plugin loads by path (--prefix) or by name (--by-name, from ParaView's plugin
list) with every PsiVolume library from the installed directory, 'Psi Volume' draws the
embedded default (the Wavelet, tetrahedralized) as the installed reference renderer does, and
ParaView's reader factory opens a .off file with the installed tetrahedral reader: what an
install changes (the tests of the build tree cover the rest)."""
import argparse
import os
import sys
import tempfile

from paraview import simple

CHECKOUT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
ap = argparse.ArgumentParser()
ap.add_argument("--prefix", help="the install prefix the package and plugin must come from")
ap.add_argument("--by-name", action="store_true", help="LoadDistributedPlugin('PsiVolume')")
args = ap.parse_args()

import psivolume  # noqa: E402 (after the path is as the caller set it)
from psivolume import accuracy, data, testing  # noqa: E402

t = testing.Checks("test_installed")
package = os.path.dirname(os.path.abspath(psivolume.__file__))
t.check(os.path.join(CHECKOUT, "Python") not in [os.path.abspath(p) for p in sys.path],
        "the checkout's Python/ is not on sys.path")
t.check(not package.startswith(CHECKOUT + os.sep), "psivolume imported from %s" % package)
plugin = data.find_plugin()
if args.prefix:
    prefix = os.path.abspath(args.prefix) + os.sep
    t.check(package.startswith(prefix), "psivolume is the installed one")
    t.check(plugin.startswith(prefix), "psivolume finds the installed plugin: %s" % plugin)
if args.by_name:
    simple.LoadDistributedPlugin("PsiVolume", remote=False, ns=globals())
else:
    simple.LoadPlugin(plugin, remote=False, ns=globals())

with open("/proc/self/maps") as maps:
    loaded = sorted({line.split()[-1] for line in maps if "PsiVolume" in line.split()[-1]})
t.check(len(loaded) >= 2 and all(os.path.dirname(p) == os.path.dirname(plugin) for p in loaded),
        "every PsiVolume library loaded from %s: %s" % (os.path.dirname(plugin), loaded))

src, array = data.wavelet()
src.UpdatePipeline()
ncells = src.GetDataInformation().GetNumberOfCells()
view = testing.black_view(200)
d = data.show_volume(src, array, view)
t.check(d.Representation == "Psi Volume", "'Psi Volume' is the representation")
simple.Render(view)
view.ResetCamera()
simple.Render(view)
image = testing.grab(view)
d.UpdatePropertyInformation()
t.check(d.GetProperty("NumberOfTetrahedra").GetElement(0) == ncells,
        "all %d tetrahedra drawn" % ncells)
covered = testing.covered(image, [0.0, 0.0, 0.0])
t.check(covered > 0.25 * 200 * 200, "the image is not empty (%d pixels covered)" % covered)
reference = accuracy.find_reference_renderer()
t.check(os.path.samefile(os.path.dirname(reference), os.path.dirname(plugin))
        and os.access(reference, os.X_OK),
        "the accuracy report's reference renderer is installed beside the plugin")
# the installed reference renderer draws what 'Psi Volume' drew (the accuracy report's exact row)
with tempfile.TemporaryDirectory() as work:
    exact = accuracy.reference_image(accuracy.Capture(view, d, src, work), runs=1)[0][0]
mean, worst = accuracy.errors(image, exact)
t.check(mean < 1.0, "the installed reference renderer's image: 'Psi Volume' %.3f/255 from it "
        "(worst %.0f)" % (mean, worst))

# ParaView's reader factory offers the installed tetrahedral OFF reader (the plugin's XML)
with tempfile.TemporaryDirectory() as work:
    path = os.path.join(work, "one.off")
    with open(path, "w") as f:
        f.write("4 1\n0 0 0 0\n1 0 0 1\n0 1 0 2\n0 0 1 3\n0 1 2 3\n")
    reader = simple.OpenDataFile(path)
    t.check(reader is not None and reader.GetXMLName() == "PsiOFFTetReader",
            "a .off file opens with the installed tetrahedral reader (%s)"
            % (reader.GetXMLName() if reader else None))
    if reader is not None:
        reader.UpdatePipeline()
        t.check(reader.GetDataInformation().GetNumberOfCells() == 1, "and reads its tetrahedron")
t.finish()
