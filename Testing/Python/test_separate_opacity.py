"""A separate opacity array (UseSeparateOpacityArray, OpacityArrayName): color from one array,
opacity from another, as ParaView's 'Volume' draws it (color map of the colored array, opacity
function of the opacity array's values).

1. Self-consistency: with the colored array also as the opacity array, every integration method
   and every feature (near-plane clipping, opaque geometry, isosurfaces both ways, early discard)
   must draw the image it draws without a separate array: the opacity scalars travel their own
   path (buffer, plane, clipping fractions), so a slip in any of them shows. Full
   pre-integration, which tabulates one scalar, draws as partial pre-integration then (warned).
2. Parity: with another opacity array, each method agrees with 'Projected tetra' as well as the
   plain image does, and differs from the plain image as 'Projected tetra's' does.
3. Early discard is judged on the opacity array: with an opacity function that is zero on part
   of the opacity array's range, early discard on and off draw the same image; also with
   isosurfaces, which 'Auto' then draws by marching tetrahedra.
4. Cell data and a new time step of both arrays."""

import os

import numpy as np
from paraview import simple

from psivolume import data, testing

t = testing.Checks("test_separate_opacity")
data.load_plugin(globals(), os.environ.get("PSI_PLUGIN"))
src, array = data.wavelet(6)
calc = simple.Calculator(Input=src, ResultArrayName="Other",
                         Function="RTData*0.5 + 40*sin(coordsX)")
cells = simple.PointDatatoCellData(Input=calc)
# The features on a coarse mesh (4^3 voxels): long segments within each cell, where a slip in the
# opacity scalar's ends (near-plane clipping, isosurface pieces) shows in an 8-bit image.
coarse_src, _ = data.wavelet(2)
coarse = simple.Calculator(Input=coarse_src, ResultArrayName="Other",
                           Function="RTData*0.5 + 40*sin(coordsX)")
view = testing.black_view(120)
SAME = 0.05  # mean |difference| on 0..255: the same image up to float rounding ...
SAME_MAX = 1.0  # ... and no pixel off by more than one 8-bit step
pwf = simple.GetOpacityTransferFunction(array)
ramp = list(pwf.Points)


LAST = {}  # read-outs of the last 'Psi Volume' frame render() drew


def diff(a, b):
    return float(np.abs(a - b).mean())


def same(a, b):
    return diff(a, b) < SAME and float(np.abs(a - b).max()) <= SAME_MAX


def render(source, rep="Psi Volume", opacity=None, assoc="POINTS", setup=None):
    """Image of `source` colored by RTData, opacity from `opacity` (None: no separate array)."""
    d = simple.Show(source, view)
    d.SetRepresentationType(rep)
    if rep == "Volume":
        d.SelectMapper = "Projected tetra"
    simple.ColorBy(d, (assoc, array))
    d.ScalarOpacityUnitDistance = 3.0
    if rep == "Psi Volume":  # the display keeps its settings between renders: reset them
        testing.apply_requested(d)
        d.IntegrationMethod = "Partial Pre-Integration"
        d.IsosurfaceValues = []
        d.EarlyDiscard = 1
    d.UseSeparateOpacityArray = 1 if opacity else 0
    if opacity:
        d.OpacityArrayName = [assoc, opacity]
    if setup:
        setup(d)
    simple.Render(view)
    img = testing.grab(view)
    if rep == "Psi Volume":
        d.UpdatePropertyInformation()
        LAST["isosurface method"] = d.GetProperty("LastUsedIsosurfaceMethod").GetElement(0)
    d.UseSeparateOpacityArray = 0
    simple.Hide(source, view)
    return img


simple.Render(view)
render(calc)
view.ResetCamera()
view.GetActiveCamera().Elevation(20)
camera = [list(view.CameraPosition), list(view.CameraFocalPoint), list(view.CameraViewUp)]
methods = list(simple.Show(calc, view).GetProperty("IntegrationMethod").Available)
simple.Hide(calc, view)
t.check(len(methods) == 7, "seven integration methods (%d)" % len(methods))

# 1. The colored array as its own opacity array: the same image, method by method.
for m in methods:
    plainMethod = "Partial Pre-Integration" if m == "Full Pre-Integration" else m
    plain = render(calc, setup=lambda d: setattr(d, "IntegrationMethod", plainMethod))
    own = render(calc, opacity=array, setup=lambda d: setattr(d, "IntegrationMethod", m))
    t.check(testing.covered(plain, [0, 0, 0]) > 2000, "%s: the image is not empty" % m)
    t.check(same(plain, own), "%s: own array as opacity array draws the plain image "
            "(mean %.3f, max %.0f)" % (m, diff(plain, own), np.abs(plain - own).max()))


def inside(d):
    view.CameraPosition = [0.3, 0.2, 0.7]
    view.CameraFocalPoint = [0.3, 0.2, -5.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]


def restore():
    view.CameraPosition, view.CameraFocalPoint, view.CameraViewUp = camera


sphere = simple.Sphere(Radius=1.0, ThetaResolution=24, PhiResolution=24)
features = [
    ("near-plane clipping (camera inside)", inside, restore),
    ("opaque geometry inside", lambda d: simple.Show(sphere, view),
     lambda: simple.Hide(sphere, view)),
    ("isosurfaces, marching tetrahedra",
     lambda d: (setattr(d, "IsosurfaceValues", [120.0, 180.0]), setattr(d, "IsosurfaceOpacity", 0.1),
                setattr(d, "IsosurfaceMethod", "Marching Tetrahedra")), None),
    ("isosurfaces, per fragment",
     lambda d: (setattr(d, "IsosurfaceValues", [120.0, 180.0]), setattr(d, "IsosurfaceOpacity", 0.1),
                setattr(d, "IsosurfaceMethod", "Per Fragment")), None),
    ("early discard", lambda d: setattr(
        pwf, "Points", [ramp[0], 0.0, 0.5, 0.0, 160.0, 0.0, 0.5, 0.0, ramp[-4], 1.0, 0.5, 0.0]),
     lambda: setattr(pwf, "Points", ramp)),
]
for name, setup, undo in features:
    plain = render(coarse, setup=setup)
    own = render(coarse, opacity=array, setup=setup)
    if undo:
        undo()
    t.check(same(plain, own), "%s: own array as opacity array draws the plain image "
            "(mean %.3f, max %.0f)" % (name, diff(plain, own), np.abs(plain - own).max()))

# 2. Another opacity array: as 'Projected tetra' draws it. The linear-opacity methods have
# another optical model (their plain images differ from 'Projected tetra' by far more than the
# bound): for them only the change is checked here; part 1 checks their opacity path exactly.
vol0, psi0 = render(calc, "Volume"), render(calc)
bound = max(4.0 * diff(vol0, psi0), 3.0)
vol = render(calc, "Volume", opacity="Other")
t.check(diff(vol, vol0) > 5.0, "'Volume' changes with the opacity array (%.2f)" % diff(vol, vol0))
for m in methods:
    method = lambda d: setattr(d, "IntegrationMethod", m)  # noqa: E731
    plain = render(calc, setup=method)
    psi = render(calc, opacity="Other", setup=method)
    t.check(diff(psi, plain) > 5.0, "%s: 'Psi Volume' changes with the opacity array (%.2f)"
            % (m, diff(psi, plain)))
    if diff(plain, vol0) < bound:
        t.check(diff(psi, vol) < bound, "%s: agrees with 'Volume' (%.2f, bound %.2f)"
                % (m, diff(psi, vol), bound))
    else:
        print("        %s: another optical model (plain image %.2f from 'Volume')"
              % (m, diff(plain, vol0)))

# 3. Early discard judged on the opacity array: zero opacity over the lower half of Other's range.
lo, hi = calc.PointData["Other"].GetRange()
pwf.Points = [lo, 0.0, 0.5, 0.0, 0.5 * (lo + hi), 0.0, 0.5, 0.0, hi, 1.0, 0.5, 0.0]
on = render(calc, opacity="Other", setup=lambda d: setattr(d, "EarlyDiscard", 1))
off = render(calc, opacity="Other", setup=lambda d: setattr(d, "EarlyDiscard", 0))
pwf.Points = ramp
t.check(testing.covered(on, [0, 0, 0]) > 500, "early discard: the image is not empty")
t.check(same(on, off), "early discard on the opacity array: on and off agree (%.3f)"
        % diff(on, off))

# 3b. Early discard, another opacity array and marching tetrahedra together, as 'Auto' combines
# them: isosurfaces of the colored array and an opacity function that is zero over part of the
# opacity array's range, here an array over about the same range that falls where the colored
# one rises. 'Auto' draws the isosurfaces by marching tetrahedra; the image must be the one drawn
# without early discard (whose volume pieces between isosurfaces are bounded by the colored
# scalar, not the opacity scalar), and the per-fragment isosurfaces' image.
def isosurfaces(method, discard):
    def setup(d):
        d.IsosurfaceValues = [120.0, 180.0]
        d.IsosurfaceOpacity = 0.5
        d.IsosurfaceMethod = method
        d.EarlyDiscard = discard
    return setup


for name, base in (("fine", calc), ("coarse", coarse)):
    r = base.PointData[array].GetRange()  # the same range, falling where RTData rises
    mesh = simple.Calculator(Input=base, ResultArrayName="Apart",
                             Function="%r - RTData + 10*sin(coordsY)" % (r[0] + r[1]))
    mesh.UpdatePipeline()
    lo, hi = mesh.PointData["Apart"].GetRange()
    pwf.Points = [lo, 0.0, 0.5, 0.0, 0.5 * (lo + hi), 0.0, 0.5, 0.0, hi, 1.0, 0.5, 0.0]
    auto = render(mesh, opacity="Apart", setup=isosurfaces("Auto", 1))
    auto_method = LAST["isosurface method"]
    triangles = render(mesh, opacity="Apart", setup=isosurfaces("Marching Tetrahedra", 0))
    fragments = render(mesh, opacity="Apart", setup=isosurfaces("Per Fragment", 0))
    pwf.Points = ramp
    t.check(auto_method == 0, "%s, zero opacity and isosurfaces: 'Auto' draws them by marching "
            "tetrahedra (%d)" % (name, auto_method))
    t.check(testing.covered(auto, [0, 0, 0]) > 2000, "%s: the image is not empty" % name)
    t.check(same(auto, triangles), "%s: 'Auto' draws the image of marching tetrahedra without "
            "early discard (mean %.3f, max %.0f)" % (name, diff(auto, triangles),
                                                     np.abs(auto - triangles).max()))
    t.check(diff(fragments, triangles) < SAME, "%s: and of per-fragment isosurfaces (mean %.3f, "
            "max %.0f)" % (name, diff(fragments, triangles), np.abs(fragments - triangles).max()))

# 4. Cell data; a new time step of both arrays (the same points and cells).
cvol = render(cells, "Volume", opacity="Other", assoc="CELLS")
cpsi = render(cells, opacity="Other", assoc="CELLS")
cpsi0 = render(cells, assoc="CELLS")
t.check(diff(cpsi, cpsi0) > 5.0 and diff(cpsi, cvol) < bound,
        "cell data: changes (%.2f) and agrees with 'Volume' (%.2f)"
        % (diff(cpsi, cpsi0), diff(cpsi, cvol)))
d = simple.Show(calc, view)
d.SetRepresentationType("Psi Volume")
testing.apply_requested(d)
d.IsosurfaceValues = []
d.EarlyDiscard = 1
simple.ColorBy(d, ("POINTS", array))
d.ScalarOpacityUnitDistance = 3.0
d.UseSeparateOpacityArray = 1
d.OpacityArrayName = ["POINTS", "Other"]
simple.Render(view)
calc.Function = "RTData*0.25 + 60*cos(coordsY)"
simple.Render(view)
stepped = testing.grab(view)
simple.Hide(calc, view)
fresh = simple.Calculator(Input=src, ResultArrayName="Other",
                          Function="RTData*0.25 + 60*cos(coordsY)")
t.check(same(stepped, render(fresh, opacity="Other")),
        "a new opacity array on the same mesh draws as a fresh one")
t.finish()
