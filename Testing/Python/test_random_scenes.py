"""Scenes nobody wrote by hand: a seeded, reproducible random scene checker.

pvpython Testing/Python/test_random_scenes.py [--first SEED] [--seeds N] [--size PX] [--out DIR]

Each seed draws one scene: a mesh (a tetrahedralized Wavelet, a slab 20 times thinner than wide,
a box 8 times longer than wide, coordinates offset by 10^6, holes, a Delaunay mesh of random
points, one tetrahedron, nothing, hexahedra beside tetrahedra, the Blunt Fin when ../shared/data
has it), an array (point or cell data, a vector's magnitude or a component, a point and a cell
array of one name colored by either, names with spaces and non-ASCII letters, a constant field,
NaN in part of the mesh, a separate opacity array), points that no cell uses (near, far), a
transfer function (ParaView's ramp, a narrow spike, a step, opacity 1, all zero), a camera
(outside, inside the mesh, parallel projection, grazing) and settings (every integration method,
sort, projector, decomposition, adaptive sampling, early discard, an isosurface, the interaction
mode), and 0 to 2 further volumes in the same view (small tetrahedralized Wavelets beside, across
or inside the first, each with its own array, color map, opacity and unit distance: drawn
intermixed with it). It renders a still frame and an interactive one and checks:
- the still frame against the exact reference (psivolume.accuracy's reference ray caster; with
  further volumes, of them all as media that may share space) within the integration method's
  bound (BOUNDS: the linear-attenuation methods agree with the exact
  integral up to the 8-bit image and the pre-integration table; the three linear-opacity methods
  integrate another model, which the reference does not), where the reference draws the scene
  (not with an isosurface, which it does not draw, nor NaN scalars, whose cells the two skip
  differently);
- the mesh's footprint: the still frame covers the reference's pixels up to 2 pixels;
- an all-zero opacity draws nothing at all (without further volumes);
- the interactive frame, when it is the level of detail, within LOD_BOUND of the still frame
  (without isosurfaces, which it does not draw, a narrow spike, which it samples in bands, and
  the linear-opacity methods, whose model it does not draw; and with one volume);
- a still frame after the interactive one is the still frame again (never the level of detail).
A failure prints its seed and a one-line reproduction, and with --out writes its images (the still
frame, the reference, the interactive frame, the still frame at its camera) side by side. The suite runs a fixed set of seeds; a
long run (--seeds 500) is recorded in docs/testing.md."""
import argparse
import math
import os
import random
import tempfile

import numpy as np
from paraview import servermanager, simple

from psivolume import accuracy, data, testing

DATA_DIR = os.environ.get("PSI_DATA_DIR") or data.DATA_DIR  # the shared datasets

METHODS = ["Average", "Partial Pre-Integration", "Linear Exact", "Average Opacity",
           "Linear Luminance Average Opacity", "Linear Opacity Improved", "Full Pre-Integration"]
# Mean |difference| from the exact reference (/255), per method. The linear-attenuation methods
# are exact up to the 8-bit image, the tables and the color map inside a cell (measured: at most
# 0.58 over the first 120 seeds); 'Average' takes a mean color per segment (at most 0.18). The
# three linear-opacity methods integrate another optical model (the opacity function read as the
# opacity of one unit distance, varying linearly: Moreland's dissertation §5.3), which the
# reference does not: at opacity 1 they were 8 to 55/255 from its image (8 of 240 scenes), where
# the attenuation methods of the same scenes were within 0.2. They are held to the reference's
# footprint only (None).
BOUNDS = {"Average": 2.0, "Partial Pre-Integration": 2.0, "Linear Exact": 2.0,
          "Full Pre-Integration": 2.0, "Average Opacity": None,
          "Linear Luminance Average Opacity": None, "Linear Opacity Improved": None}
LOD_BOUND = 0.06  # mean |difference| of the level of detail from the still frame (fraction of 255)
FOOTPRINT_PX = 2
LOD, FULL = 1, 0


class Scene:
    """One seed's scene, as words (for the log) and as a pipeline."""

    def __init__(self, seed):
        self.seed = seed
        self.rng = random.Random(seed)
        self.words = []
        self.comparable = True  # the reference draws this scene
        self.empty = False
        self.separate = None  # the separate opacity array, if any

    def pick(self, what, options):
        choice = self.rng.choice(options)
        self.words.append("%s=%s" % (what, choice))
        return choice

    def describe(self):
        return "seed %d: %s" % (self.seed, ", ".join(self.words))


def wavelet(half):
    w = simple.Wavelet(WholeExtent=[-half, half] * 3)
    return simple.Tetrahedralize(Input=w)


def produce(dataset):
    """A pipeline source holding `dataset` (builtin session)."""
    src = simple.TrivialProducer()
    src.GetClientSideObject().SetOutput(dataset)
    src.UpdatePipeline()
    return src


def delaunay(rng, n):
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkPolyData
    pts = vtkPoints()
    for _ in range(n):
        pts.InsertNextPoint(rng.uniform(-6, 6), rng.uniform(-6, 6), rng.uniform(-6, 6))
    poly = vtkPolyData()
    poly.SetPoints(pts)
    tets = simple.Delaunay3D(Input=produce(poly))
    return simple.Calculator(Input=tets, ResultArrayName="RTData",
                             Function="100*sin(coordsX/2)*cos(coordsY/3) + 10*coordsZ")


def make_mesh(s):
    kind = s.pick("mesh", ["wavelet", "wavelet", "thin", "long", "offset", "holes", "delaunay",
                           "one", "empty", "bluntfin", "mixed"])
    half = s.rng.choice([3, 4, 5])
    if kind == "bluntfin":
        files = data.PLOT3D["bluntfin"][:2]
        if all(os.path.exists(os.path.join(DATA_DIR, f)) for f in files):
            return data.plot3d("bluntfin", DATA_DIR)
        s.words[-1] = "mesh=wavelet (no Blunt Fin data in %s)" % DATA_DIR
        kind = "wavelet"
    if kind == "mixed":  # hexahedra (voxels) beside tetrahedra, in one unstructured grid
        w = simple.Wavelet(WholeExtent=[-half, half] * 3)
        left = simple.ExtractSubset(Input=w, VOI=[-half, 0, -half, half, -half, half])
        right = simple.ExtractSubset(Input=w, VOI=[0, half, -half, half, -half, half])
        return simple.AppendDatasets(Input=[left, simple.Tetrahedralize(Input=right)]), "RTData"
    if kind == "delaunay":
        return delaunay(s.rng, 300), "RTData"
    if kind == "one":
        return produce(testing.one_tetrahedron("RTData", 4.0)), "RTData"
    src = wavelet(half)
    if kind in ("thin", "long", "offset"):
        t = simple.Transform(Input=src)
        t.Transform.Scale = {"thin": [1, 1, 0.05], "long": [8, 1, 1], "offset": [1, 1, 1]}[kind]
        if kind == "offset":
            t.Transform.Translate = [1e6, -1e6, 1e6]
        return t, "RTData"
    if kind == "holes":
        keep = simple.Calculator(Input=src, ResultArrayName="keep",
                                 Function="sin(1.7*coordsX)*sin(1.3*coordsY)")
        cut = simple.Threshold(Input=keep, Scalars=["POINTS", "keep"])  # cells with all points in
        cut.LowerThreshold, cut.UpperThreshold = -0.5, 2.0
        return cut, "RTData"
    if kind == "empty":
        cut = simple.Threshold(Input=src, Scalars=["POINTS", "RTData"])
        cut.LowerThreshold, cut.UpperThreshold = 1e9, 2e9
        s.empty = True
        return cut, "RTData"
    return src, "RTData"


def make_array(s, src, array):
    """(source, association, name, vector mode or None)."""
    kind = s.pick("array", ["point", "point", "cell", "vector", "same name", "odd name",
                            "constant", "nan", "separate opacity"])
    if kind == "point":
        return src, "POINTS", array, None
    if kind == "separate opacity":  # colored by the array, opacity from another (rep below)
        other = simple.Calculator(Input=src, ResultArrayName="o", Function="abs(coordsX)")
        s.separate = "o"
        s.comparable = False  # the reference draws one array
        return other, "POINTS", array, None
    if kind == "cell":
        return simple.PointDatatoCellData(Input=src), "CELLS", array, None
    if kind == "vector":
        v = simple.Calculator(Input=src, ResultArrayName="V",
                              Function="coordsX*iHat + %s/40*jHat + (coordsZ + 10)*kHat" % array)
        return v, "POINTS", "V", s.pick("vector mode", ["Magnitude", "X", "Y", "Z"])
    if kind == "same name":
        f = simple.Calculator(Input=src, ResultArrayName="f", Function="coordsX")
        both = simple.PointDatatoCellData(Input=f)
        both.PassPointData = 1
        cell = simple.Calculator(Input=both, AttributeType="Cell Data", ResultArrayName="f",
                                 Function="-f")
        return cell, s.pick("association", ["POINTS", "CELLS"]), "f", None
    if kind == "odd name":
        name = s.pick("name", ["my f", "Dichte \u03c1 (\u00e9t\u00e9)"])
        return simple.Calculator(Input=src, ResultArrayName=name, Function=array), "POINTS", \
            name, None
    if kind == "constant":
        return simple.Calculator(Input=src, ResultArrayName="c", Function="0*%s + 7" % array), \
            "POINTS", "c", None
    s.comparable = False  # NaN cells: the reference and the renderer skip them differently
    nan = simple.Calculator(Input=src, ResultArrayName="holes",
                            Function="%s/(coordsX>0)" % array)
    return nan, "POINTS", "holes", None


def set_transfer_function(s, rep, name, lo, hi):
    lut = simple.GetColorTransferFunction(name)
    pwf = simple.GetOpacityTransferFunction(name)
    kind = s.pick("tf", ["ramp", "ramp", "spike", "step", "opaque", "zero"])
    mid = lo + (hi - lo) * s.rng.uniform(0.3, 0.7)
    width = (hi - lo) * 0.02
    if kind == "ramp":
        pwf.Points = [lo, 0.0, 0.5, 0.0, hi, s.rng.choice([0.3, 1.0]), 0.5, 0.0]
    elif kind == "spike":
        pwf.Points = [lo, 0.0, 0.5, 0.0, mid - width, 0.0, 0.5, 0.0, mid, 1.0, 0.5, 0.0,
                      mid + width, 0.0, 0.5, 0.0, hi, 0.0, 0.5, 0.0]
    elif kind == "step":
        pwf.Points = [lo, 0.0, 0.5, 0.0, mid, 0.0, 0.5, 0.0, mid + width, 0.8, 0.5, 0.0,
                      hi, 0.8, 0.5, 0.0]
    elif kind == "opaque":
        pwf.Points = [lo, 1.0, 0.5, 0.0, hi, 1.0, 0.5, 0.0]
    else:
        pwf.Points = [lo, 0.0, 0.5, 0.0, hi, 0.0, 0.5, 0.0]
    return kind


def aim(s, view, bounds, to_bounds=False):
    """The seed's camera, reset to the data's bounds (`to_bounds`: to `bounds`, the cells')."""
    def reset():
        if to_bounds:
            view.SMProxy.ResetCamera(*bounds)
        else:
            view.ResetCamera()

    reset()
    cam = view.GetActiveCamera()
    kind = s.pick("camera", ["outside", "outside", "inside", "parallel", "grazing"])
    cam.Azimuth(s.rng.uniform(0, 360))
    cam.Elevation(s.rng.uniform(-60, 60) if kind != "grazing" else 89.0)
    view.CameraParallelProjection = 1 if kind == "parallel" else 0
    reset()
    if kind == "inside":
        c = [(bounds[0] + bounds[1]) / 2, (bounds[2] + bounds[3]) / 2,
             (bounds[4] + bounds[5]) / 2]
        pos, focal = list(view.CameraPosition), list(view.CameraFocalPoint)
        d = [f - p for f, p in zip(focal, pos)]
        n = math.sqrt(sum(x * x for x in d)) or 1.0
        quarter = 0.25 * min(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4])
        view.CameraPosition = [ci - quarter * x / n for ci, x in zip(c, d)]
        view.CameraFocalPoint = [ci + x / n for ci, x in zip(c, d)]
        view.CameraViewAngle = 60.0
    return kind


def apply_settings(s, rep, lo, hi):
    method = s.pick("method", METHODS)
    rep.IntegrationMethod = method
    rep.SortMethod = s.pick("sort", ["MPVONC", "Centroid"])
    rep.Projector = s.pick("projector", ["Auto", "Geometry Shader", "Compute Shader"])
    rep.Decomposition = s.pick("decomposition", ["Auto", "Silhouette", "Fan"])
    rep.AdaptiveSampling = s.pick("adaptive", ["Auto", "On", "Off"])
    rep.EarlyDiscard = s.pick("early discard", [0, 1])
    if s.pick("isosurface", [False, False, False, True]):
        rep.IsosurfaceValues = [lo + 0.6 * (hi - lo)]
        s.comparable = False  # the reference draws no isosurface
    rep.InteractionMode = s.pick("interaction", ["Auto", "Volume LOD", "Full frame"])
    rep.InteractiveBudget = 0.0
    return method


def add_unused_points(s, shown):
    """`shown`'s mesh with a point that no cell uses (testing.with_unused_point): none, one just
    beyond the mesh or one at (1e7, 1e7, 1e7). Drawn by a generator
    of its own, so that the seed's other choices are those of the checker without them. Returns
    (the source shown, the source without them)."""
    kind = random.Random("unused points %d" % s.seed).choice(["none", "none", "near", "far"])
    grid = servermanager.Fetch(shown) if kind != "none" else None
    if grid is None or not grid.IsA("vtkUnstructuredGrid") or grid.GetNumberOfPoints() == 0:
        return shown, shown
    s.words.append("unused point=%s" % kind)
    b = grid.GetBounds()
    far = [1e7] * 3 if kind == "far" else [b[1] + 0.5 * (b[1] - b[0]) + 1, b[3], b[5]]
    more = testing.with_unused_point(grid, far)
    return produce(more), shown


def add_volumes(s, view, bounds):
    """The seed's further volumes, 0 to 2 (drawn by a generator of their own, so that the seed's
    other choices are those of the checker without them): tetrahedralized Wavelets a third to
    two thirds of the first mesh's size, placed beside, across or inside it, each colored by an
    array of its own with its own color map, opacity ramp and unit distance. Returns [(display,
    source)]."""
    rng = random.Random("volumes %d" % s.seed)
    count = rng.choice([0, 0, 1, 2])
    if count == 0:
        return []
    s.words.append("volumes=%d" % (count + 1))
    side = [max(bounds[2 * k + 1] - bounds[2 * k], 1e-3) for k in range(3)]
    centre = [(bounds[2 * k] + bounds[2 * k + 1]) / 2 for k in range(3)]
    extra = []
    for k in range(count):
        place = rng.choice(["beside", "across", "inside"])
        reach = {"beside": 0.9, "across": 0.5, "inside": 0.15}[place]
        size = rng.uniform(1 / 3, 2 / 3)
        src = simple.Transform(Input=wavelet(3))  # the Wavelet spans 6 units
        src.Transform.Scale = [size * a / 6 for a in side]
        src.Transform.Translate = [c + rng.uniform(-reach, reach) * a
                                   for c, a in zip(centre, side)]
        name = "volume %d" % (k + 2)
        src = simple.Calculator(Input=src, ResultArrayName=name, Function="RTData")
        rep = simple.Show(src, view)
        simple.ColorBy(rep, ("POINTS", name))
        rep.SetRepresentationType("Psi Volume")
        rep.RescaleTransferFunctionToDataRange(True, False)
        lut = simple.GetColorTransferFunction(name)
        testing.apply_preset(lut, *rng.choice([("Viridis (matplotlib)", "Viridis"),
                                               ("Inferno (matplotlib)", "Inferno"),
                                               ("Cool to Warm", "Cool to Warm")]))
        lo, hi = lut.RGBPoints[0], lut.RGBPoints[-4]
        simple.GetOpacityTransferFunction(name).Points = [
            lo, 0.0, 0.5, 0.0, hi, rng.choice([0.3, 1.0]), 0.5, 0.0]
        rep.ScalarOpacityUnitDistance = max(1e-6, max(side) * rng.choice([0.1, 0.3]))
        s.words.append("volume %d=%s" % (k + 2, place))
        extra.append((rep, src))
    return extra


def footprint_misses(img, ref, px=FOOTPRINT_PX):
    a = np.abs(img).sum(axis=2) > 2
    b = np.abs(ref).sum(axis=2) > 2
    grown = b.copy()
    for dy in range(-px, px + 1):
        for dx in range(-px, px + 1):
            grown |= np.roll(np.roll(b, dy, axis=0), dx, axis=1)
    n = max(int(b.sum()), 1)
    return float((a & ~grown).sum()) / n


def show(s, view):
    """The seed's pipeline shown as 'Psi Volume' in `view` with its opacity, unit distance, camera
    and settings, and its further volumes: (display, source shown, opacity kind, method,
    [(display, source)] of the further volumes)."""
    src, array = make_mesh(s)
    shown, assoc, name, vector = make_array(s, src, array)
    shown, clean = add_unused_points(s, shown)
    if clean is not shown:  # the unit distance ParaView gives the mesh without them
        rep = simple.Show(clean, view)
        clean_unit = rep.ScalarOpacityUnitDistance
        simple.Delete(rep)
    rep = simple.Show(shown, view)
    simple.ColorBy(rep, (assoc, name) if vector is None else
                   (assoc, name, "Magnitude" if vector == "Magnitude" else vector))
    rep.SetRepresentationType("Psi Volume")
    if s.separate:
        rep.UseSeparateOpacityArray = 1
        rep.OpacityArrayName = ["POINTS", s.separate]
    rep.RescaleTransferFunctionToDataRange(True, False)
    lut = simple.GetColorTransferFunction(name)
    lo, hi = lut.RGBPoints[0], lut.RGBPoints[-4]
    tf = set_transfer_function(s, rep, name, lo, hi)
    bounds = clean.GetDataInformation().GetBounds()
    if bounds[0] > bounds[1]:
        bounds = [-1, 1, -1, 1, -1, 1]
    unit = s.pick("unit distance", ["ParaView's", "a tenth of the mesh", "the mesh"])
    if unit != "ParaView's":  # ParaView's: the mean cell size, the most opaque
        side = max(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4])
        rep.ScalarOpacityUnitDistance = max(1e-6, side * (0.1 if unit.startswith("a tenth") else 1))
    elif clean is not shown:
        rep.ScalarOpacityUnitDistance = clean_unit
    extra = add_volumes(s, view, bounds)
    aim(s, view, bounds, clean is not shown)
    return rep, shown, tf, apply_settings(s, rep, lo, hi), extra


def override(s, rep, overrides):
    """--set NAME=VALUE: one property changed after the seed's settings, to narrow a failure;
    returns the integration method then."""
    for name_value in overrides:
        prop, value = name_value.split("=", 1)
        try:
            value = float(value) if "." in value else int(value)
        except ValueError:
            pass  # an enumeration's text
        setattr(rep, prop, value)
        s.words.append("set %s" % name_value)
    return rep.GetProperty("IntegrationMethod").GetData()


def check_still(t, s, label, view, rep, shown, still, tf, method, extra):
    """The still frame: nothing drawn at an all-zero opacity; against the exact reference (within
    the method's bound) and its footprint, the further volumes `extra` ([(display, source)])
    media of the reference too. Returns the reference's image (None without one)."""
    if tf == "zero" and not list(rep.IsosurfaceValues) and not extra:
        t.check(testing.covered(still, [0, 0, 0]) == 0,
                "%s: an all-zero opacity draws nothing (%d pixels)"
                % (label, testing.covered(still, [0, 0, 0])))
    if not s.comparable or s.empty:
        return None
    with tempfile.TemporaryDirectory() as work:
        others = []
        for k, (other, src) in enumerate(extra):
            os.makedirs(os.path.join(work, str(k)))
            others.append(accuracy.Capture(view, other, src, os.path.join(work, str(k))))
        ref = accuracy.reference_image(accuracy.Capture(view, rep, shown, work),
                                       os.environ.get("PSI_REFERENCE_RENDER"), runs=1,
                                       others=others)[0][0]
    mean, worst = accuracy.errors(still, ref)
    if BOUNDS[method] is not None:
        t.check(mean <= BOUNDS[method], "%s: the still frame %.3f/255 from the exact "
                "reference (worst %.0f; bound %.1f)" % (label, mean, worst, BOUNDS[method]))
    else:
        print("        %s: %.3f/255 from the attenuation model's exact image (not its model)"
              % (method, mean))
    outside = footprint_misses(still, ref)
    t.check(outside < 0.01, "%s: the still frame within %d pixels of the reference's "
            "footprint (%.4f of it outside)" % (label, FOOTPRINT_PX, outside))
    return ref


def check_interactive(t, label, view, rep, tf, method, extra):
    """An interactive frame after a small turn and, where it is the level of detail, the still
    frame of the same camera: (interactive image, still image at its camera)."""
    view.GetActiveCamera().Azimuth(3)
    view.InteractiveRender()
    rep.UpdatePropertyInformation()
    drew = rep.GetProperty("LastInteractiveImage").GetElement(0)
    moved = moved_still = testing.grab(view)
    # The level of detail draws no isosurface, samples a narrow spike of the opacity once per
    # lattice spacing along the ray, in bands (0.109 from its still frame, which integrates the
    # spike exactly), and composites the attenuation model (as the methods with a bound do; the
    # linear-opacity methods' still frames were 0.06 to 0.25 from it at opacity 1): it is held
    # to the still frame only without them.
    if drew == LOD and not list(rep.IsosurfaceValues) and tf != "spike" and \
            BOUNDS[method] is not None and not extra:
        simple.Render(view)
        moved_still = testing.grab(view)
        err = testing.mean_error(moved, moved_still)
        t.check(err <= LOD_BOUND, "%s: the level of detail %.4f from its still frame (bound %.2f)"
                % (label, err, LOD_BOUND))
    view.GetActiveCamera().Azimuth(-3)
    return moved, moved_still


def check_scene(t, seed, size, out, overrides=()):
    s = Scene(seed)
    view = testing.black_view(size)
    rep, shown, tf, method, extra = show(s, view)
    method = override(s, rep, overrides) if overrides else method
    label = s.describe()
    failures = t.failures
    simple.Render(view)
    still = testing.grab(view)
    ref = check_still(t, s, label, view, rep, shown, still, tf, method, extra)
    moved, moved_still = check_interactive(t, label, view, rep, tf, method, extra)
    simple.Render(view)
    t.check(testing.mean_error(testing.grab(view), still) < 1e-6,
            "%s: a still frame after the interactive one is the still frame" % label)
    if t.failures != failures:
        print("  reproduce: pvpython Testing/Python/test_random_scenes.py --first %d --seeds 1 "
              "--size %d" % (seed, size))
        if out:
            panels = [still] + ([ref] if ref is not None else []) + [moved, moved_still]
            testing.write_png(np.concatenate(panels, axis=1),
                              os.path.join(out, "seed_%d.png" % seed))
    for other, _ in extra:
        simple.Delete(other)
    simple.Delete(rep)
    simple.Delete(view)
    return label


def delete_sources():
    """Every pipeline source, each once no other source takes it as its input."""
    def inputs(proxy):
        given = getattr(proxy, "Input", None)
        return given if isinstance(given, list) else [given]

    left = list(simple.GetSources().values())
    while left:
        taken = [i for p in left for i in inputs(p)]
        for source in [p for p in left if not any(p is i for i in taken)]:
            simple.Delete(source)
            left.remove(source)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--first", type=int, default=0)
    p.add_argument("--seeds", type=int, default=12)
    p.add_argument("--size", type=int, default=96)
    p.add_argument("--out", help="where a failing seed's still and interactive images go")
    p.add_argument("--set", action="append", default=[], metavar="NAME=VALUE",
                   help="a property of the display set after the seed's settings")
    args = p.parse_args()
    data.load_plugin(globals(), os.environ.get("PSI_PLUGIN"))
    t = testing.Checks("test_random_scenes")
    for seed in range(args.first, args.first + args.seeds):
        print("--- " + check_scene(t, seed, args.size, args.out, args.set))
        delete_sources()
    t.finish()


main()
