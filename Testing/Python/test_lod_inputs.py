"""The volume level of detail on inputs common in real data, each against the still frame it
stands in for (results, never timings), and its build's progress:
- the first interactive render after a still frame past the budget already draws the level of
  detail (it is built in that render, fast enough to cost less than the still frame);
- a point array and a cell array of one name (Point Data to Cell Data passing the point data,
  then a cell Calculator writing f = -f): colored by either, the level of detail draws that one
  (the other is the mirror image);
- switching from one array to another and between a vector's components: never the old image;
- a slab 50 times thinner than wide, seen across: the level of detail samples it as finely as its
  lattice (a sample distance of the mean spacing took one or two samples across it: 0.063 from
  the still frame, against 0.009 now and 0.003 for the unscaled Wavelet);
- a constant field on a mesh with holes: no speckles;
- a point that no cell uses, near or far: the level of detail spans the cells, not the points;
- deleting the representation right after an interactive render, then a new one: no stale image.
Each level of detail must be nearer its own still frame than the wrong image, and as near as
the same level of detail on a plain scene."""
import os

from paraview import servermanager, simple

from psivolume import data, testing

t = testing.Checks("test_lod_inputs")
data.load_plugin(globals(), os.environ.get("PSI_PLUGIN"))
SIZE = 160
FULL, LOD = 0, 1


def scene(src, assoc, array, view):
    return data.show_volume(src, array, view, unit_distance=2.0, assoc=assoc)


def still(view):
    simple.Render(view)
    return testing.grab(view)


def interactive(view, d):
    view.InteractiveRender()
    d.UpdatePropertyInformation()
    return testing.grab(view), d.GetProperty("LastInteractiveImage").GetElement(0)


def check_lod(view, d, label, wrong=None):
    """The still frame, then the first interactive frame: the level of detail, close to it."""
    d.InteractionMode = "Auto"
    d.InteractiveBudget = 0.0  # every still frame is past it
    full = still(view)
    lod, used = interactive(view, d)
    err = testing.mean_error(lod, full)
    t.check(used == LOD, "%s: the first interactive frame after a still frame past the budget "
            "is the level of detail (drew %d)" % (label, used))
    if wrong is not None:
        t.check(err < testing.mean_error(lod, wrong),
                "%s: the level of detail nearer the still frame (%.4f) than the wrong image "
                "(%.4f)" % (label, err, testing.mean_error(lod, wrong)))
    return full, lod, err


# --- Progress: a build reports to ParaView's progress handler (the representation's progress
# events, which ParaView's progress bar shows), rising from 0 to 1; a current level of detail
# reports nothing.
view = testing.black_view(SIZE)
src, scalars = data.wavelet(10)
d = scene(src, "POINTS", scalars, view)
d.InteractionMode = "Volume LOD"
view.ResetCamera()
simple.Render(view)
steps = []
rep = d.GetClientSideObject().GetActiveRepresentation()
rep.AddObserver("ProgressEvent", lambda obj, _: steps.append((obj.GetProgress(),
                                                               obj.GetProgressText() or "")))
view.InteractiveRender()
built = list(steps)
view.GetActiveCamera().Azimuth(5)
view.InteractiveRender()
values = [v for v, _ in built]
t.check(len(built) >= 10 and values[0] == 0.0 and values[-1] == 1.0 and
        values == sorted(values) and all("level of detail" in text for _, text in built),
        "the build reports its progress: %d steps from %.2f to %.2f, rising (%r)"
        % (len(built), values[0] if values else -1, values[-1] if values else -1,
           built[-1][1] if built else None))
t.check(len(steps) == len(built), "a current level of detail reports no progress (%d more)"
        % (len(steps) - len(built)))
simple.Delete(d)
simple.Delete(view)

# --- One name, two associations.
view = testing.black_view(SIZE)
src, scalars = data.wavelet(10)
pointf = simple.Calculator(Input=src, ResultArrayName="f", Function="coordsX")
both = simple.PointDatatoCellData(Input=pointf)
both.PassPointData = 1
cellf = simple.Calculator(Input=both, AttributeType="Cell Data", ResultArrayName="f",
                          Function="-f")
d = scene(cellf, "CELLS", "f", view)
view.ResetCamera()
cell_full = still(view)
simple.ColorBy(d, ("POINTS", "f"))
d.RescaleTransferFunctionToDataRange(True, False)
point_full = still(view)
t.check(testing.mean_error(point_full, cell_full) > 0.02,
        "the point and the cell array draw mirror images (%.4f apart)"
        % testing.mean_error(point_full, cell_full))
_, _, perr = check_lod(view, d, "colored by the point array f", wrong=cell_full)
simple.ColorBy(d, ("CELLS", "f"))
d.RescaleTransferFunctionToDataRange(True, False)
_, lod, cerr = check_lod(view, d, "colored by the cell array f", wrong=point_full)
t.check(cerr <= 2 * perr, "the cell array's level of detail as close to its still frame as the "
        "point array's (%.4f; %.4f)" % (cerr, perr))
simple.Delete(d)

# --- Switching arrays and vector components: a new image each time.
vec = data.with_vector(src)
d = scene(vec, "POINTS", scalars, view)
view.ResetCamera()
images = {}
for label, color, mode, component in (("RTData", scalars, None, None),
                                      ("V magnitude", "V", "Magnitude", 0),
                                      ("V X", "V", "Component", 0),
                                      ("V Z", "V", "Component", 2)):
    simple.ColorBy(d, ("POINTS", color) if mode is None else
                   ("POINTS", color, "Magnitude" if mode == "Magnitude" else "X Y Z"[2 * component]))
    d.RescaleTransferFunctionToDataRange(True, False)
    images[label] = check_lod(view, d, label)
for label, (full, lod, err) in images.items():
    nearest = min(images, key=lambda other: testing.mean_error(lod, images[other][0]))
    t.check(nearest == label, "%s: its level of detail is nearest its own still frame (%.4f), "
            "not another's (nearest: %s)" % (label, err, nearest))
simple.Delete(d)

# --- A thin slab seen across: the Wavelet scaled by 0.02 along z, its unit distance too, so that
# seen along z it is optically the unscaled Wavelet; its level of detail must be as close to its
# still frame as the unscaled one's is.
errors = {}
for label, scale in (("the Wavelet seen along z", 1.0), ("a slab 50 times thinner", 0.02)):
    shape = simple.Transform(Input=src)
    shape.Transform.Scale = [1.0, 1.0, scale]
    d = scene(shape, "POINTS", scalars, view)
    d.ScalarOpacityUnitDistance = 2.0 * scale
    view.CameraPosition = [0, 0, 60]
    view.CameraFocalPoint = [0, 0, 0]
    view.CameraViewUp = [0, 1, 0]
    view.ResetCamera()
    _, _, errors[scale] = check_lod(view, d, label)
    simple.Delete(d)
# (measured: 0.0093 for the slab, 0.0028 unscaled; one sample per mean spacing gave 0.063)
t.check(errors[0.02] <= 0.02, "the thin slab's level of detail close to its still frame (%.4f; "
        "the unscaled Wavelet's %.4f)" % (errors[0.02], errors[1.0]))

# --- A constant field on a mesh with holes, opaque: the hidden lattice points must not widen the
# ray caster's transfer-function table (with 0 there its table spanned [0, 7] for a color map over
# [7, 7.001]: speckles, 0.099 from the still frame; 0.014 now).
keep = simple.Calculator(Input=src, ResultArrayName="keep",
                         Function="sin(1.7*coordsX)*sin(1.3*coordsY)")
holes = simple.Threshold(Input=keep, Scalars=["POINTS", "keep"])
holes.LowerThreshold, holes.UpperThreshold = -0.5, 2.0
constant = simple.Calculator(Input=holes, ResultArrayName="c", Function="0*%s + 7" % scalars)
d = scene(constant, "POINTS", "c", view)
lut = simple.GetColorTransferFunction("c")
simple.GetOpacityTransferFunction("c").Points = [lut.RGBPoints[0], 1.0, 0.5, 0.0,
                                                 lut.RGBPoints[-4], 1.0, 0.5, 0.0]
d.ScalarOpacityUnitDistance = 1.0
view.ResetCamera()
_, _, err = check_lod(view, d, "a constant field with holes")
t.check(err < 0.04, "the constant field's level of detail close to its still frame (%.4f)" % err)
simple.Delete(d)

# --- A point that no cell uses, near or far (a shared point list): the level of detail's lattice
# spans the cells' points, not the point list (spanning it, it drew nothing of the mesh: 0 % of
# the still frame's pixels with the point at 1e4 or 1e7).
for far in (1e4, 1e7):
    grid = servermanager.Fetch(src)
    more = simple.TrivialProducer()
    more.GetClientSideObject().SetOutput(testing.with_unused_point(grid, [far] * 3))
    more.UpdatePipeline()
    d = scene(more, "POINTS", scalars, view)
    view.SMProxy.ResetCamera(*src.GetDataInformation().GetBounds())
    full, lod, err = check_lod(view, d, "a point no cell uses at %g" % far)
    drawn, wanted = testing.covered(lod, [0, 0, 0]), testing.covered(full, [0, 0, 0])
    t.check(err < 0.05 and drawn >= 0.9 * wanted, "a point no cell uses at %g: the level of "
            "detail covers the still frame's pixels (%d of %d) and is close to it (%.4f)"
            % (far, drawn, wanted, err))
    simple.Delete(d)
    simple.Delete(more)

# --- Deleted right after an interactive render; a new representation on new data.
d = scene(src, "POINTS", scalars, view)
view.ResetCamera()
full, lod, err = check_lod(view, d, "a new representation after a deleted one")
t.check(err < 0.05, "its level of detail is of its own data (%.4f from its still frame)" % err)
simple.Delete(d)
t.finish()
