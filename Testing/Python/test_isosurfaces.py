"""Isosurfaces of 'Psi Volume' against ParaView's Contour filter rendered as a surface.

With the volume's opacity at zero, 'Psi Volume' with IsosurfaceValues draws plain contours. The
same view is rendered with the Contour filter (Surface, same color map, same lights), and the two
images are compared as numbers: the covered masks (pixels that differ from the background) and
the colors where both cover. Cases: one isovalue, several isovalues (several in one cell), an
isovalue exactly at a vertex value, a solid color, translucency, and properties/state."""
import os

import numpy as np

from paraview import simple
from vtkmodules.util.numpy_support import vtk_to_numpy

from psivolume import data, testing

t = testing.Checks("test_isosurfaces")
data.load_plugin(globals(), os.environ.get("PSI_PLUGIN"))
BG = [0.0, 0.0, 0.0]
SIZE = 160
OUT = os.environ.get("PSI_TEST_OUTPUT", "")

src, array = data.wavelet(8)
src.UpdatePipeline()
view = simple.CreateRenderView()
view.ViewSize = [SIZE, SIZE]
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.Background = BG
d = data.show_volume(src, array, view, unit_distance=2.0)
lo, hi = src.PointData[array].GetRange()
otf = simple.GetOpacityTransferFunction(array)
otf.Points = [lo, 0.0, 0.5, 0.0, hi, 0.0, 0.5, 0.0]  # volume invisible: plain contours
lut = simple.GetColorTransferFunction(array)
lut.AutomaticRescaleRangeMode = "Never"  # the contour's own range must not rescale the map
lut.RescaleTransferFunction(lo, hi)
view.ResetCamera()
cam = view.GetActiveCamera()
cam.Azimuth(31)
cam.Elevation(23)
view.ResetCamera()

t.check(d.GetProperty("IsosurfaceValues") is not None, "IsosurfaceValues is a property")
t.check(len(d.GetProperty("IsosurfaceValues")) == 0, "no isosurface by default")
t.check(abs(d.IsosurfaceOpacity - 1.0) < 1e-12, "IsosurfaceOpacity defaults to 1")
t.check(d.IsosurfaceUseColorMap == 1, "IsosurfaceUseColorMap defaults to on")
t.check(d.AdaptiveSampling == "Auto", "AdaptiveSampling defaults to Auto")
dom = d.GetProperty("IsosurfaceValues").SMProperty.GetDomain("scalar_range")
t.check(dom is not None and abs(dom.GetMinimum(0) - lo) < 1e-6 and abs(dom.GetMaximum(0) - hi) < 1e-6,
        "IsosurfaceValues has the colored array's range as its domain (value-list range helpers)")

simple.Render(view)
empty = testing.grab(view)
t.check(testing.covered(empty, BG) == 0,
        "zero opacity and no isosurface: empty image (%d)" % testing.covered(empty, BG))

contour = simple.Contour(Input=src, ContourBy=["POINTS", array], ComputeScalars=1)


def save(name, img):
    if OUT:
        testing.write_png(img, os.path.join(OUT, "iso_" + name + ".png"))


# Color tolerance: the Contour filter's normals are averaged from its triangles, the isosurfaces'
# from the cells' scalar gradients, and on this coarse mesh (cells of one unit against features
# of a few) the two disagree by a few percent of the diffuse term over the surface.
def compare(name, values, mask_tol=0.04, color_tol=0.08):
    """Psi Volume isosurfaces vs the Contour filter at `values`; returns (psi, contour) images."""
    d.IsosurfaceValues = values
    simple.Show(src, view)
    d.SetRepresentationType("Psi Volume")
    simple.Render(view)
    psi = testing.grab(view)
    simple.Hide(src, view)
    contour.Isosurfaces = values
    cd = simple.Show(contour, view)
    simple.ColorBy(cd, ("POINTS", array))
    cd.LookupTable = lut
    lut.RescaleTransferFunction(lo, hi)  # ColorBy rescales to the contour's range: undo
    simple.Render(view)
    ref = testing.grab(view)
    simple.Hide(contour, view)
    simple.Show(src, view)
    bg = np.array(BG) * 255.0
    m_psi = np.abs(psi - bg).sum(axis=2) > 2.0
    m_ref = np.abs(ref - bg).sum(axis=2) > 2.0
    union = max(int((m_psi | m_ref).sum()), 1)
    xor = int((m_psi ^ m_ref).sum())
    both = m_psi & m_ref
    # Silhouette pixels (a pixel's coverage differs between a rasterized triangle and a ray hit,
    # and a layer edge moves by a pixel) are left out of the color comparison: interior only.
    inner = both.copy()
    for dy, dx in ((0, 1), (0, -1), (1, 0), (-1, 0)):
        inner &= np.roll(np.roll(both, dy, axis=0), dx, axis=1)
    edge = np.zeros_like(both)
    gray_p, gray_r = psi.sum(axis=2), ref.sum(axis=2)
    for dy, dx in ((0, 1), (0, -1), (1, 0), (-1, 0)):
        edge |= np.abs(np.roll(np.roll(gray_r, dy, axis=0), dx, axis=1) - gray_r) > 60
    inner &= ~edge
    both = inner
    bright = gray_p[both].sum() / max(gray_r[both].sum(), 1e-9)
    print("  brightness psi/contour %.4f" % bright)
    t.check(0.9 < bright < 1.1, "%s: same lighting and color map (brightness ratio %.4f)" % (name, bright))
    diff = np.abs(psi - ref)[both] / 255.0
    mean = float(diff.mean()) if diff.size else 1.0
    mx = float(diff.max()) if diff.size else 1.0
    p95 = float(np.percentile(diff.max(axis=1), 95)) if diff.size else 1.0
    print("%-14s covered psi %5d contour %5d  mask mismatch %.4f  color mean %.4f p95 %.4f max %.4f"
          % (name, int(m_psi.sum()), int(m_ref.sum()), xor / union, mean, p95, mx))
    save(name + "_psi", psi)
    save(name + "_contour", ref)
    t.check(m_ref.sum() > 0.05 * SIZE * SIZE, "%s: the contour covers the view" % name)
    t.check(xor / union < mask_tol, "%s: covered masks agree (mismatch %.4f)" % (name, xor / union))
    t.check(mean < color_tol, "%s: colors agree (mean difference %.4f)" % (name, mean))
    t.check(not np.isnan(psi).any(), "%s: no NaN" % name)
    return psi, ref


mid = 0.5 * (lo + hi)
compare("one", [mid])
# Several isovalues, closer than one cell's scalar range: several crossings in one cell.
compare("several", [mid - 12.0, mid - 4.0, mid + 4.0, mid + 30.0])
# An isovalue exactly at a vertex value (no cracks, no NaN).
scal = vtk_to_numpy(simple.servermanager.Fetch(src).GetPointData().GetArray(array))
vertex_value = float(np.sort(scal)[len(scal) // 2])
psi_v, ref_v = compare("at_vertex", [vertex_value])
# Solid color instead of the color map.
d.IsosurfaceUseColorMap = 0
d.IsosurfaceColor = [1.0, 0.5, 0.0]
d.IsosurfaceValues = [mid]
simple.Render(view)
solid = testing.grab(view)
m = np.abs(solid).sum(axis=2) > 2.0
ratio = solid[m][:, 1].sum() / max(solid[m][:, 0].sum(), 1e-9)
t.check(m.sum() > 0 and abs(ratio - 0.5) < 0.02 and solid[m][:, 2].max() < 3.0,
        "solid IsosurfaceColor (green/red %.3f)" % ratio)
d.IsosurfaceUseColorMap = 1
# Translucent isosurface: half as bright over black.
d.IsosurfaceOpacity = 0.5
simple.Render(view)
half = testing.grab(view)
simple.Render(view)
d.IsosurfaceOpacity = 1.0
simple.Render(view)
full = testing.grab(view)
mm = np.abs(full).sum(axis=2) > 30.0
ratio = half[mm].sum() / max(full[mm].sum(), 1e-9)
# (0.5 of the front layer plus 0.25 of the one behind it, ...: between 0.5 and 0.75 of opaque)
t.check(0.5 < ratio < 0.8, "IsosurfaceOpacity 0.5 lets the background through (ratio %.3f)" % ratio)
# Each isosurface's own opacity (IsosurfaceOpacities, in the order of the values): an inner
# surface made fully transparent vanishes (the image is that of the outer one alone), and an
# entry of 0.5 gives what the common IsosurfaceOpacity 0.5 gives.
outer, inner_v = mid - 12.0, mid + 30.0
d.IsosurfaceValues = [outer]
simple.Render(view)
outer_only = testing.grab(view)
d.IsosurfaceValues = [inner_v, outer]  # given out of order: entries follow the values
d.IsosurfaceOpacities = [0.0, 1.0]
simple.Render(view)
inner_hidden = testing.grab(view)
t.check(testing.covered(outer_only, BG) > 1000 and
        testing.mean_error(inner_hidden, outer_only) < 0.2 / 255,
        "IsosurfaceOpacities: a surface of opacity 0 vanishes (%.4f)"
        % testing.mean_error(inner_hidden, outer_only))
d.IsosurfaceOpacities = [1.0, 0.5]
simple.Render(view)
per_surface = testing.grab(view)
d.IsosurfaceOpacities = [1.0]  # the outer one without an entry: IsosurfaceOpacity
d.IsosurfaceOpacity = 0.5
simple.Render(view)
common = testing.grab(view)
t.check(testing.mean_error(per_surface, common) < 0.2 / 255 and
        testing.mean_error(per_surface, inner_hidden) > 1.0 / 255,
        "IsosurfaceOpacities: an entry of 0.5 equals IsosurfaceOpacity 0.5 for that surface "
        "(%.4f), and lets the inner surface show (%.4f)"
        % (testing.mean_error(per_surface, common),
           testing.mean_error(per_surface, inner_hidden)))
d.IsosurfaceOpacities = []
d.IsosurfaceOpacity = 1.0
# Removing the isosurfaces restores the plain (here empty) image.
d.IsosurfaceValues = []
simple.Render(view)
t.check(testing.covered(testing.grab(view), BG) == 0, "isosurfaces removed: empty image again")
d.AdaptiveSampling = "Auto"
t.check(d.AdaptiveSampling == "Auto", "AdaptiveSampling accepts Auto")
t.finish()
