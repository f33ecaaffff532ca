"""'Psi Volume' while the camera moves (the Interaction group): interactive renders draw the
volume level of detail when the mode or the budget calls for it, and the full frame otherwise;
still renders and screenshots never show it; the level of detail is a volume close to the full
frame (no further from it than 'Projected tetra' is), covering the same footprint; a new array,
new data or a new time step gives a new level of detail; an empty mesh, one tetrahedron and NaN
scalars neither crash nor draw garbage; a state file restores the Interaction group. In 'Auto'
the level of detail is built in the first interactive render past the budget, which draws it.

Three parts, each its own test (one argument): `modes` (which image each mode and budget draws,
its error and footprint, still renders and screenshots, hard inputs, a state file), `changes` (a
new array, new data) and `time` (a new time step)."""
import os
import sys
import tempfile

import numpy as np
from paraview import servermanager, simple

from psivolume import data, testing

t = testing.Checks("test_interaction")
data.load_plugin(globals(), os.environ.get("PSI_PLUGIN"))
BG = [0.0, 0.0, 0.0]
FULL, LOD, SURFACE = 0, 1, 2
SIZE = 200

view = testing.black_view(SIZE)
src, scalars = data.wavelet(12)
d = data.show_volume(src, scalars, view, unit_distance=2.0)
# one way of drawing the full frame, so that two full frames are the same image to the bit (under
# 'Auto' the first frames time ways that agree within 1/255: PsiRendering.MeasuredChoice)
d.EarlyRayTermination, d.Projector, d.Decomposition = "On", "Geometry Shader", "Silhouette"
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


def dilate(mask, px):
    """`mask` grown by `px` pixels (a square neighbourhood)."""
    out = mask.copy()
    for dy in range(-px, px + 1):
        for dx in range(-px, px + 1):
            out |= np.roll(np.roll(mask, dy, axis=0), dx, axis=1)
    return out


def footprint_misses(img, ref, px=2):
    """Pixels of `img`'s footprint farther than `px` pixels from `ref`'s, and pixels of `ref`'s
    farther than `px` from the edge of `img`'s, as fractions of `ref`'s footprint: the level of
    detail draws one ray per 1.5 x 1.5 pixels, so its edges may blur by a pixel or two."""
    a, b = footprint(img), footprint(ref)
    n = max(b.sum(), 1)
    return (a & ~dilate(b, px)).sum() / n, (b & ~dilate(a, px)).sum() / n


def rti_bound(source, array):
    """1.25 x the mean error of ParaView's 'Resample To Image' (its own cheaper image, at its
    default 128^3) of `array` of `source` against the still frame of `view`, seen from `view`'s
    camera: the level of detail must be as close to the exact frame as that."""
    frame = still()
    other = testing.black_view(SIZE)
    rti = data.show_volume(source, array, other, representation="Volume", unit_distance=2.0)
    rti.SelectMapper = "Resample To Image"
    copy_camera(other)
    simple.Render(other)
    bound = 1.25 * testing.mean_error(testing.grab(other), frame)
    simple.Delete(other)
    return bound


def copy_camera(other):
    other.CameraPosition = view.CameraPosition
    other.CameraFocalPoint = view.CameraFocalPoint
    other.CameraViewUp = view.CameraViewUp
    other.CameraViewAngle = view.CameraViewAngle


def modes():
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
    t.check(used == LOD and testing.mean_error(img, full) > 0,
            "'Auto' past the budget: the first interactive frame is the level of detail, built in it "
            "(drew %d)" % used)
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
    pt = data.show_volume(src, scalars, pt_view, representation="Volume", unit_distance=2.0)
    pt.SelectMapper = "Projected tetra"
    copy_camera(pt_view)
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
    outside, uncovered = footprint_misses(lod, full)
    t.check(outside < 0.01 and uncovered < 0.01, "the level of detail covers the volume's footprint "
            "up to 2 pixels (%.4f of it outside, %.4f not covered)" % (outside, uncovered))

    # --- Still renders and screenshots never show it.
    t.check(testing.mean_error(still(), full) < 1e-6, "a still render after moving is the full frame")
    interactive()
    with tempfile.TemporaryDirectory() as tmp:
        shot = os.path.join(tmp, "shot.png")
        simple.SaveScreenshot(shot, view, ImageResolution=[SIZE, SIZE])
        t.check(testing.mean_error(testing.grab(view), full) < 1e-6,
                "a screenshot after moving is the full frame")


def changes():
    # --- A new array, new data: a new level of detail (never a stale image).
    def rescale_to(name, source):
        """The color map and the opacity function of `name` over its range in `source`."""
        r = source.PointData[name].GetRange()
        simple.GetColorTransferFunction(name).RescaleTransferFunction(*r)
        simple.GetOpacityTransferFunction(name).RescaleTransferFunction(*r)

    calc = simple.Calculator(Input=src, ResultArrayName="twice", Function="2*%s" % scalars)
    d2 = data.show_volume(calc, "twice", view, unit_distance=2.0)
    simple.Hide(src, view)
    d2.InteractionMode = "Volume LOD"
    rescale_to("twice", calc)
    full2 = still()
    lod2, used = interactive(d2)
    bound2 = rti_bound(calc, "twice")
    t.check(used == LOD and testing.mean_error(lod2, full2) <= bound2,
            "a new array: its own level of detail (%.4f; bound %.4f)"
            % (testing.mean_error(lod2, full2), bound2))
    calc.Function = "-2*%s" % scalars
    rescale_to("twice", calc)
    full3 = still()
    lod3, used = interactive(d2)
    bound3 = rti_bound(calc, "twice")  # on the new data
    t.check(used == LOD and testing.covered(full3, BG) > SIZE * SIZE / 10 and
            testing.mean_error(full3, full2) > 0.001 and
            testing.mean_error(lod3, full3) <= bound3 and
            testing.mean_error(lod3, full3) < testing.mean_error(lod3, lod2),
            "new data: a new level of detail (drew %d), close to the new frame (%.4f; bound %.4f), "
            "not the old one" % (used, testing.mean_error(lod3, full3), bound3))
    simple.Delete(d2)
    simple.Delete(calc)



def time_step():
    # --- A new time step: a new level of detail. A file series of two time steps (0 and 1): the
    # Wavelet's array at t = 0, its negative, shifted, at t = 1.
    def time_series():
        from vtkmodules.numpy_interface import dataset_adapter as dsa
        from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridWriter
        grid = servermanager.Fetch(src)
        values = np.array(dsa.WrapDataObject(grid).PointData[scalars])
        files = []
        for step, field in enumerate((values, 400.0 - values)):
            copy = grid.NewInstance()
            copy.ShallowCopy(grid)
            wrapped = dsa.WrapDataObject(copy)
            wrapped.PointData.append(field, "timed")
            files.append(os.path.join(tempfile.mkdtemp(), "timed_%d.vtu" % step))
            writer = vtkXMLUnstructuredGridWriter()
            writer.SetFileName(files[-1])
            writer.SetInputData(copy)
            writer.Write()
        return simple.XMLUnstructuredGridReader(FileName=files)

    timed = time_series()
    simple.Hide(src, view)
    dt = data.show_volume(timed, "timed", view, unit_distance=2.0)
    dt.InteractionMode = "Volume LOD"
    scene = simple.GetAnimationScene()  # its time is every view's
    scene.UpdateAnimationUsingDataTimeSteps()
    scene.AnimationTime = 0.0
    full_t0 = still()
    lod_t0, _ = interactive(dt)
    scene.AnimationTime = 1.0
    full_t1 = still()
    lod_t1, used = interactive(dt)
    bound_t1 = rti_bound(timed, "timed")
    t.check(used == LOD and testing.mean_error(full_t1, full_t0) > 0.001 and
            testing.mean_error(lod_t1, full_t1) <= bound_t1 and
            testing.mean_error(lod_t1, full_t1) < testing.mean_error(lod_t1, lod_t0),
            "a new time step: a new level of detail (drew %d), close to the new frame (%.4f; bound "
            "%.4f), not the old one (%.4f)" % (used, testing.mean_error(lod_t1, full_t1), bound_t1,
                                               testing.mean_error(lod_t1, lod_t0)))
    scene.AnimationTime = 0.0

    simple.Hide(timed, view)
    simple.Show(src, view)


def hard_inputs():
    # --- Hard inputs: an empty mesh, one tetrahedron, NaN scalars.
    def one_tetrahedron():
        from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridWriter
        grid = testing.one_tetrahedron()
        path = os.path.join(tempfile.mkdtemp(), "one.vtu")
        writer = vtkXMLUnstructuredGridWriter()
        writer.SetFileName(path)
        writer.SetInputData(grid)
        writer.Write()
        return simple.XMLUnstructuredGridReader(FileName=[path])

    for name, function in (("empty", None), ("one", None), ("nan", "nan")):
        if name == "empty":
            clip = simple.Threshold(Input=src, Scalars=["POINTS", scalars])
            clip.LowerThreshold, clip.UpperThreshold = 1e9, 2e9
            shown, arr = clip, scalars
        elif name == "one":
            shown, arr = one_tetrahedron(), "s"
        else:
            shown = simple.Calculator(Input=src, ResultArrayName="holes",
                                      Function="%s/(coordsX>0)" % scalars)
            arr = "holes"
        simple.Hide(src, view)
        r = data.show_volume(shown, arr, view, unit_distance=2.0)
        if name == "one":  # opaque at every value: lattice points outside the cell would show
            simple.GetOpacityTransferFunction(arr).Points = [0.0, 0.5, 0.5, 0.0, 3.0, 0.5, 0.5, 0.0]
            view.ResetCamera()  # the cell filling the view
        r.InteractionMode = "Volume LOD"
        full_one = still()
        img, used = interactive(r)
        t.check(np.isfinite(img).all(), "%s: a finite image" % name)
        if name == "one":
            outside, uncovered = footprint_misses(img, full_one)
            t.check(used == LOD and footprint(full_one).sum() > SIZE * SIZE / 20 and
                    outside < 0.01 and uncovered < 0.01,
                    "one tetrahedron: the level of detail is its footprint up to 2 pixels, "
                    "transparent outside (%.4f of it drawn outside, %.4f not covered; %d pixels)"
                    % (outside, uncovered, footprint(full_one).sum()))
        if name == "nan":
            t.check(used == LOD, "NaN scalars: the level of detail is drawn")
        simple.Hide(shown, view)

    # --- A state file saves and restores the Interaction group (in a new session: last).
    r.InteractionMode = "ParaView surface"
    r.InteractiveBudget = 0.75
    with tempfile.TemporaryDirectory() as tmp:
        state = os.path.join(tmp, "interaction.pvsm")
        simple.SaveState(state)
        simple.ResetSession()
        simple.LoadState(state)
        loaded = [rep for rep in simple.GetActiveView().Representations
                  if rep.GetXMLName() == "UnstructuredGridRepresentation"
                  and rep.InteractionMode == "ParaView surface"]
        t.check(len(loaded) == 1 and abs(loaded[0].InteractiveBudget - 0.75) < 1e-12,
                "a state file restores the interaction mode and budget (%s)"
                % [(rep.InteractionMode, rep.InteractiveBudget) for rep in loaded])


PARTS = dict(modes=[modes, hard_inputs], changes=[changes], time=[time_step])
part = sys.argv[1] if len(sys.argv) > 1 else ""
if part not in PARTS:
    sys.exit("test_interaction: give one part of %s" % sorted(PARTS))
for run in PARTS[part]:
    run()
t.finish()
