"""Every property of 'Psi Volume' from pvpython: each value is accepted, reads back, renders a
finite, non-empty image, and the ones that should change the picture do (as numbers)."""

import os

import numpy as np
from paraview import simple

from psivolume import data, testing

t = testing.Checks("test_properties")
data.load_plugin(globals(), os.environ.get("PSI_PLUGIN"))
src, array = data.wavelet(8)
view = simple.CreateRenderView()
view.ViewSize = [160, 160]
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.Background = [0.0, 0.0, 0.0]
d = data.show_volume(src, array, view, unit_distance=3.0)
simple.Render(view)
view.ResetCamera()
view.GetActiveCamera().Azimuth(30)
view.GetActiveCamera().Elevation(20)
view.ResetCamera()


def render():
    simple.Render(view)
    img = testing.grab(view)
    return img


plain = render()
lo, hi = src.PointData[array].GetRange()
mid = 0.5 * (lo + hi)
t.check(testing.covered(plain, [0, 0, 0]) > 2000, "default rendering is not empty")

cases = [
    ("IntegrationMethod", list(d.GetProperty("IntegrationMethod").Available), None),
    ("SortMethod", ["MPVONC", "Centroid"], None),
    ("EarlyDiscard", [0, 1], None),
    ("EarlyRayTermination", ["Off", "On", "Auto"], None),
    ("AdaptiveSampling", ["On", "Auto", "Off"], None),
    ("IsosurfaceValues", [[mid], [lo + 0.3 * (hi - lo), mid, lo + 0.7 * (hi - lo)], []], None),
    ("IsosurfaceOpacities", [[0.5], [0.2, 0.9], []], None),
    ("IsosurfaceShading", ["Flat", "Unlit", "Smooth"], None),
    ("IsosurfaceMethod", ["Per Fragment", "Marching Tetrahedra", "Auto"], None),
]
for name, values, _ in cases:
    for v in values:
        setattr(d, name, v)
        img = render()
        got = getattr(d, name)
        same = list(got) == list(v) if isinstance(v, list) else got == v
        t.check(same, "%s = %r reads back (%r)" % (name, v, got))
        t.check(np.isfinite(img).all() and testing.covered(img, [0, 0, 0]) > 2000,
                "%s = %r renders a non-empty image" % (name, v))

# Effects that must show in the picture.
d.IsosurfaceValues = [mid]
d.IsosurfaceOpacity = 1.0
d.IsosurfaceUseColorMap = 1
with_iso = render()
t.check(testing.mean_error(with_iso, plain) > 0.005, "an isosurface changes the image")
d.IsosurfaceUseColorMap = 0
d.IsosurfaceColor = [0.0, 1.0, 0.0]
green = render()
t.check(green[:, :, 1].mean() > with_iso[:, :, 1].mean() + 1.0,
        "a solid green isosurface color shows (green %.1f vs %.1f)"
        % (green[:, :, 1].mean(), with_iso[:, :, 1].mean()))
d.IsosurfaceShading = "Unlit"
unlit = render()
t.check(testing.mean_error(unlit, green) > 0.002, "IsosurfaceShading Unlit changes the image")
d.IsosurfaceShading = "Flat"
flat = render()
t.check(testing.mean_error(flat, green) > 0.0005, "IsosurfaceShading Flat changes the image")
d.IsosurfaceShading = "Smooth"
d.IsosurfaceMethod = "Per Fragment"
per_fragment = render()
d.UpdatePropertyInformation()
t.check(d.GetProperty("LastUsedIsosurfaceMethod").GetElement(0) == 1, "per-fragment method used")
d.IsosurfaceMethod = "Marching Tetrahedra"
render()
d.UpdatePropertyInformation()
t.check(d.GetProperty("LastUsedIsosurfaceMethod").GetElement(0) == 0, "marching tetrahedra used")
d.IsosurfaceMethod = "Auto"
render()
d.UpdatePropertyInformation()
t.check(d.GetProperty("LastUsedIsosurfaceMethod").GetElement(0) == 1,
        "Auto: per fragment for a volume without zero-opacity regions")
t.check(testing.mean_error(per_fragment, green) < 0.5 / 255,
        "IsosurfaceMethod: both methods draw the same image (%.4f)"
        % testing.mean_error(per_fragment, green))
d.IsosurfaceOpacity = 0.3
faint = render()
t.check(testing.mean_error(faint, green) > 0.002, "isosurface opacity changes the image")
d.IsosurfaceValues = []
d.IsosurfaceUseColorMap = 1
d.IsosurfaceOpacity = 1.0
back = render()
t.check(testing.mean_error(back, plain) < 0.5 / 255, "removing the isovalues restores the image")
d.ScalarOpacityUnitDistance = 1.0
denser = render()
t.check(denser.mean() > plain.mean() + 1.0, "a shorter unit distance makes the volume denser")
d.ScalarOpacityUnitDistance = 3.0

# Read-outs.
d.UpdatePropertyInformation()
for name in ("NumberOfTetrahedra", "NumberOfSkippedCells", "LastRenderSeconds",
             "LastSortSeconds", "LastPreIntegrationSeconds", "LastSortCycles",
             "NumberOfIntermixedVolumes", "NumberOfIntermixedTetrahedra"):
    p = d.GetProperty(name)
    t.check(p is not None and p.GetNumberOfElements() == 1, "read-out %s is available" % name)
t.check(d.GetProperty("NumberOfTetrahedra").GetElement(0) == 5 * 16 ** 3,
        "NumberOfTetrahedra = %d" % d.GetProperty("NumberOfTetrahedra").GetElement(0))
t.check(d.GetProperty("LastRenderSeconds").GetElement(0) > 0, "LastRenderSeconds > 0")
t.finish()
