"""'Psi Volume' while the camera moves (the Interaction group): interactive renders draw the
volume level of detail when the mode or the budget calls for it, and the full frame otherwise;
still renders and screenshots never show it; the level of detail is a volume close to the full
frame (no further from it than 'Projected tetra' is), covering the same footprint; a new array,
new data or a new time step gives a new level of detail; an empty mesh, one tetrahedron and NaN
scalars neither crash nor draw garbage."""
import os
import tempfile
import time

import numpy as np
from paraview import simple

from psivolume import data, testing

t = testing.Checks("test_interaction")
data.load_plugin(globals())
BG = [0.0, 0.0, 0.0]
FULL, LOD, SURFACE = 0, 1, 2
SIZE = 200

view = testing.black_view(SIZE)
src, array = data.wavelet(12)
d = data.show_volume(src, array, view, unit_distance=2.0)
simple.Render(view)
view.ResetCamera()
view.GetActiveCamera().Azimuth(30)
view.GetActiveCamera().Elevation(20)


def still():
    simple.Render(view)
    return testing.grab(view)


def interactive(display=None):
    """The image of an interactive render, and what drew `display` in it (default: d)."""
    display = display or d
    view.InteractiveRender()
    display.UpdatePropertyInformation()
    return testing.grab(view), display.GetProperty("LastInteractiveImage").GetElement(0)


def footprint(img):
    return np.abs(img - np.array(BG) * 255).sum(axis=2) > 2


# --- Which image an interactive render draws, by mode and budget.
full = still()
d.InteractionMode = "Full frame"
img, used = interactive()
t.check(used == FULL and testing.mean_error(img, full) < 1e-6,
        "'Full frame': the interactive frame is the full frame (drew %d)" % used)
d.InteractionMode = "Auto"
d.InteractiveBudget = 60.0
img, used = interactive()
t.check(used == FULL, "'Auto' within the budget: the full frame (drew %d)" % used)
d.InteractiveBudget = 0.0
full = still()  # a still frame longer than a budget of 0
img, used = interactive()
t.check(used == FULL and testing.mean_error(img, full) < 1e-6,
        "'Auto' past the budget, the level of detail not built yet: the first interactive frame "
        "is the full frame, its build runs meanwhile (drew %d)" % used)
frames, deadline = 1, time.time() + 120
while used != LOD and time.time() < deadline:
    time.sleep(0.05)
    img, used = interactive()
    frames += 1
t.check(used == LOD, "'Auto' past the budget: the level of detail once built, at the %dth "
        "interactive frame (drew %d)" % (frames, used))
d.UpdatePropertyInformation()
t.check(d.GetProperty("LODBuildSeconds").GetElement(0) > 0, "the build time is read out")
d.InteractionMode = "Volume LOD"
lod, used = interactive()
t.check(used == LOD, "'Volume LOD': the level of detail (drew %d)" % used)

# --- ParaView's own level of detail: its surface past LODThreshold, only in 'ParaView surface'.
view.LODThreshold = 0.0  # ParaView asks for its level of detail at any size
d.InteractionMode = "ParaView surface"
img, used = interactive()
t.check(used == SURFACE, "'ParaView surface' past LODThreshold: ParaView's surface (drew %d)" % used)
d.InteractionMode = "Volume LOD"
img, used = interactive()
t.check(used == LOD and testing.mean_error(img, lod) < 1e-6,
        "'Volume LOD' past LODThreshold: the volume level of detail (drew %d)" % used)
view.LODThreshold = 1e9

# --- The level of detail is a volume close to the full frame.
t.check(testing.mean_error(lod, full) > 0, "the level of detail is not the full frame")
pt_view = testing.black_view(SIZE)
pt = data.show_volume(src, array, pt_view, representation="Volume", unit_distance=2.0)
pt.SelectMapper = "Projected tetra"
pt_view.CameraPosition = view.CameraPosition
pt_view.CameraFocalPoint = view.CameraFocalPoint
pt_view.CameraViewUp = view.CameraViewUp
pt_view.CameraViewAngle = view.CameraViewAngle
simple.Render(pt_view)
pt_img = testing.grab(pt_view)
pt.SelectMapper = "Resample To Image"  # ParaView's own image volume, at its default 128^3
simple.Render(pt_view)
rti_img = testing.grab(pt_view)
lod_err, pt_err = testing.mean_error(lod, full), testing.mean_error(pt_img, full)
rti_err = testing.mean_error(rti_img, full)
# ParaView's cheaper images: the level of detail must be as close to the exact frame as they are
bound = 1.25 * max(pt_err, rti_err)
if os.environ.get("PSI_TEST_OUTPUT"):
    for name, img in (("full", full), ("lod", lod), ("pt", pt_img)):
        np.save(os.path.join(os.environ["PSI_TEST_OUTPUT"], "interaction_%s.npy" % name), img)
print("mean error against the full frame: level of detail %.4f, 'Projected tetra' %.4f, "
      "'Resample To Image' %.4f" % (lod_err, pt_err, rti_err))
t.check(lod_err <= bound, "the level of detail within ParaView's cheaper images' error "
        "(%.4f; 'Projected tetra' %.4f, 'Resample To Image' %.4f)" % (lod_err, pt_err, rti_err))
a, b = footprint(lod), footprint(full)
iou = (a & b).sum() / max((a | b).sum(), 1)
t.check(iou > 0.9, "the level of detail covers the volume's footprint (IoU %.3f)" % iou)

# --- Still renders and screenshots never show it.
t.check(testing.mean_error(still(), full) < 1e-6, "a still render after moving is the full frame")
interactive()
with tempfile.TemporaryDirectory() as tmp:
    shot = os.path.join(tmp, "shot.png")
    simple.SaveScreenshot(shot, view, ImageResolution=[SIZE, SIZE])
    t.check(testing.mean_error(testing.grab(view), full) < 1e-6,
            "a screenshot after moving is the full frame")

# --- A new array, new data: a new level of detail (never a stale image).
def rescale_to(name, source):
    """The color map and the opacity function of `name` over its range in `source`."""
    r = source.PointData[name].GetRange()
    simple.GetColorTransferFunction(name).RescaleTransferFunction(*r)
    simple.GetOpacityTransferFunction(name).RescaleTransferFunction(*r)


calc = simple.Calculator(Input=src, ResultArrayName="twice", Function="2*%s" % array)
d2 = data.show_volume(calc, "twice", view, unit_distance=2.0)
simple.Hide(src, view)
d2.InteractionMode = "Volume LOD"
rescale_to("twice", calc)
full2 = still()
lod2, used = interactive(d2)
t.check(used == LOD and testing.mean_error(lod2, full2) <= bound,
        "a new array: its own level of detail (%.4f)" % testing.mean_error(lod2, full2))
calc.Function = "-2*%s" % array
rescale_to("twice", calc)
full3 = still()
lod3, used = interactive(d2)
# ParaView's 'Resample To Image' of the new data, for the bound on this scene
simple.Hide(src, pt_view)
rti3_display = data.show_volume(calc, "twice", pt_view, representation="Volume", unit_distance=2.0)
rti3_display.SelectMapper = "Resample To Image"
simple.Render(pt_view)
bound3 = 1.25 * testing.mean_error(testing.grab(pt_view), full3)
t.check(used == LOD and testing.covered(full3, BG) > SIZE * SIZE / 10 and
        testing.mean_error(full3, full2) > 0.001 and
        testing.mean_error(lod3, full3) <= bound3 and
        testing.mean_error(lod3, full3) < testing.mean_error(lod3, lod2),
        "new data: a new level of detail (drew %d), close to the new frame (%.4f; bound %.4f), "
        "not the old one" % (used, testing.mean_error(lod3, full3), bound3))
simple.Delete(d2)
simple.Delete(calc)

# --- Hard inputs: an empty mesh, one tetrahedron, NaN scalars.
def one_tetrahedron():
    from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
    from vtkmodules.vtkCommonDataModel import VTK_TETRA, vtkUnstructuredGrid
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridWriter
    grid = vtkUnstructuredGrid()
    points = vtkPoints()
    for p in ((0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)):
        points.InsertNextPoint(p)
    grid.SetPoints(points)
    grid.InsertNextCell(VTK_TETRA, 4, [0, 1, 2, 3])
    s = vtkDoubleArray()
    s.SetName("s")
    for v in (0.0, 1.0, 2.0, 3.0):
        s.InsertNextValue(v)
    grid.GetPointData().AddArray(s)
    path = os.path.join(tempfile.mkdtemp(), "one.vtu")
    writer = vtkXMLUnstructuredGridWriter()
    writer.SetFileName(path)
    writer.SetInputData(grid)
    writer.Write()
    return simple.XMLUnstructuredGridReader(FileName=[path])


for name, function in (("empty", None), ("one", None), ("nan", "nan")):
    if name == "empty":
        clip = simple.Threshold(Input=src, Scalars=["POINTS", array])
        clip.LowerThreshold, clip.UpperThreshold = 1e9, 2e9
        shown, arr = clip, array
    elif name == "one":
        shown, arr = one_tetrahedron(), "s"
    else:
        shown = simple.Calculator(Input=src, ResultArrayName="holes",
                                  Function="%s/(coordsX>0)" % array)
        arr = "holes"
    simple.Hide(src, view)
    r = data.show_volume(shown, arr, view, unit_distance=2.0)
    if name == "one":  # opaque at every value: lattice points outside the cell would show
        simple.GetOpacityTransferFunction(arr).Points = [0.0, 0.5, 0.5, 0.0, 3.0, 0.5, 0.5, 0.0]
    r.InteractionMode = "Volume LOD"
    full_one = still()
    img, used = interactive(r)
    t.check(np.isfinite(img).all(), "%s: a finite image" % name)
    if name == "one":
        a, b = footprint(img), footprint(full_one)
        iou = (a & b).sum() / max((a | b).sum(), 1)
        t.check(used == LOD and iou > 0.7,
                "one tetrahedron: the level of detail is its footprint, transparent outside "
                "(IoU %.3f)" % iou)
    if name == "nan":
        t.check(used == LOD, "NaN scalars: the level of detail is drawn")
    simple.Hide(shown, view)

t.finish()
