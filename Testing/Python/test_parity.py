"""Parity walk: what ParaView 5.11's 'Volume' representation honours, 'Psi Volume' honours too.
Each step changes one thing (the array, a vector component, point or cell data, the color map,
the opacity function, log scale, the unit distance, the scalar bar, visibility, a second view,
DepthPeelingForVolumes, a separate opacity array and its component, a time step, a state saved
and loaded) and renders 'Volume' ('Projected tetra') and 'Psi Volume' of the same mesh in the
same view. Each must react as 'Volume' does: its image changes exactly when 'Volume's' changes,
and after the change the two images agree as well as they did before (Projected tetra is not
exact, so 'agree' is within a bound measured on the baseline)."""
import os
import tempfile

import numpy as np
from paraview import simple

from psivolume import data, testing

t = testing.Checks("test_parity")
data.load_plugin(globals(), os.environ.get("PSI_PLUGIN"))
src, array = data.wavelet(6)
calc = data.with_vector(src)
calc2 = simple.Calculator(Input=calc, ResultArrayName="Other", Function="RTData*0.5 + 40*sin(coordsX)")
cells = simple.PointDatatoCellData(Input=calc2)
view = testing.black_view(120)
CHANGED = 0.5  # mean |difference| on 0..255 that counts as a change


def show(source, rep):
    d = simple.Show(source, view)
    d.SetRepresentationType(rep)
    if rep == "Volume":
        d.SelectMapper = "Projected tetra"
    return d


def pair(source, setup):
    """Images of 'Volume' and 'Psi Volume' of `source` after `setup(display)`."""
    out = []
    for rep in ("Volume", "Psi Volume"):
        d = show(source, rep)
        setup(d)
        simple.Render(view)
        out.append(testing.grab(view))
        simple.Hide(source, view)
    return out


def color(d, assoc="POINTS", name=array, comp=None, unit=3.0):
    simple.ColorBy(d, (assoc, name) if comp is None else (assoc, name, comp))
    d.ScalarOpacityUnitDistance = unit


def diff(a, b):
    return float(np.abs(a - b).mean())


base_setup = lambda d: color(d)  # noqa: E731
simple.Render(view)
vol0, psi0 = pair(calc2, base_setup)
view.ResetCamera()
view.GetActiveCamera().Elevation(20)
vol0, psi0 = pair(calc2, base_setup)
agree0 = diff(vol0, psi0)
t.check(testing.covered(psi0, [0, 0, 0]) > 2000, "baseline is not empty")
print("baseline: 'Volume' vs 'Psi Volume' mean difference %.2f/255" % agree0)
bound = max(4.0 * agree0, 3.0)


def step(name, source, setup, undo=None, expect_change=True):
    vol, psi = pair(source, setup)
    dv, dp, agree = diff(vol, vol0), diff(psi, psi0), diff(vol, psi)
    print("%-32s 'Volume' %6.2f  'Psi Volume' %6.2f  between %6.2f" % (name, dv, dp, agree))
    t.check((dv > CHANGED) == expect_change, "%s: 'Volume' %s (%.2f)"
            % (name, "changes" if expect_change else "is unchanged", dv))
    t.check((dp > CHANGED) == (dv > CHANGED), "%s: 'Psi Volume' reacts as 'Volume' (%.2f vs %.2f)"
            % (name, dp, dv))
    t.check(agree < bound, "%s: the two still agree (%.2f, bound %.2f)" % (name, agree, bound))
    if undo:
        undo()


lut = simple.GetColorTransferFunction(array)
pwf = simple.GetOpacityTransferFunction(array)
lo, hi = calc2.PointData[array].GetRange()
step("another array", calc2, lambda d: color(d, name="Other"))
step("vector magnitude", calc2, lambda d: color(d, name="V", comp="Magnitude"))
step("vector component Z", calc2, lambda d: color(d, name="V", comp="Z"))
step("cell data", cells, lambda d: color(d, assoc="CELLS"))
step("color map preset", calc2, lambda d: (color(d), testing.apply_preset(lut, "Viridis (matplotlib)", "Viridis")),
     undo=lambda: lut.ApplyPreset("Cool to Warm", True))
saved = list(pwf.Points)
step("opacity function", calc2,
     lambda d: (color(d), setattr(pwf, "Points", [lo, 0.0, 0.5, 0.0, 0.5 * (lo + hi), 0.0, 0.5, 0.0,
                                                   hi, 1.0, 0.5, 0.0])),
     undo=lambda: setattr(pwf, "Points", saved))
step("color map log scale", calc2, lambda d: (color(d), setattr(lut, "UseLogScale", 1)),
     undo=lambda: setattr(lut, "UseLogScale", 0))
step("unit distance", calc2, lambda d: color(d, unit=1.0))
step("scalar bar", calc2, lambda d: (color(d), d.SetScalarBarVisibility(view, True)),
     undo=lambda: simple.GetScalarBar(lut, view).__setattr__("Visibility", 0))
# Under ParaView 6.1 the steps above leave both representations' images 21/255 from the first
# baseline after their undos (the cause is ParaView's, not identified): the checks that compare
# with "unchanged" take a baseline of the view as it is now.
vol0, psi0 = pair(calc2, base_setup)
step("DepthPeelingForVolumes off", calc2,
     lambda d: (color(d), setattr(view, "DepthPeelingForVolumes", 0)),
     undo=lambda: setattr(view, "DepthPeelingForVolumes", 1), expect_change=False)
step("hidden", calc2, lambda d: (color(d), setattr(d, "Visibility", 0)))


def separate(d, name="Other", comp=None):
    """Opacity from array `name` (component `comp`); the opacity function rescaled to its range,
    as ParaView does when the array is chosen (the color map keeps the colored array's)."""
    color(d)
    d.UseSeparateOpacityArray = 1
    d.OpacityArrayName = ["POINTS", name]
    if comp is not None:
        d.OpacityComponent = comp
    d.RescaleTransferFunctionToDataRange(False, True)


def no_separate():
    for rep in ("Volume", "Psi Volume"):
        d = show(calc2, rep)
        d.UseSeparateOpacityArray = 0
        simple.Hide(calc2, view)
    pwf.Points = saved


step("separate opacity array", calc2, separate, undo=no_separate)
# (component Y of V is RTData / 40: rescaled, the same opacity; X is not)
step("separate opacity component", calc2, lambda d: separate(d, "V", 0), undo=no_separate)
formula = calc2.Function
step("time step (new Other, same mesh)", calc2,
     lambda d: (setattr(calc2, "Function", "RTData*0.25 + 60*cos(coordsY)"),
                calc2.UpdatePipeline(), separate(d)),
     undo=lambda: (no_separate(), setattr(calc2, "Function", formula)))

# A second view of the same representation type: each view draws the mesh at its own camera.
vol0, psi0 = pair(calc2, base_setup)
view2 = testing.black_view(120)
imgs = {}
for rep in ("Volume", "Psi Volume"):
    for v in (view, view2):
        d = simple.Show(calc2, v)
        d.SetRepresentationType(rep)
        color(d)
    simple.Render(view2)
    view2.ResetCamera()
    view2.GetActiveCamera().Azimuth(90)
    simple.Render(view2)
    simple.Render(view)
    imgs[rep] = (testing.grab(view), testing.grab(view2))
    simple.Hide(calc2, view)
    simple.Hide(calc2, view2)
for rep, (a, b) in imgs.items():
    t.check(diff(a, vol0 if rep == "Volume" else psi0) < CHANGED,
            "%s: the first view is unchanged by a second one" % rep)
    t.check(diff(a, b) > CHANGED and testing.covered(b, [0, 0, 0]) > 2000,
            "%s: the second view draws its own camera" % rep)
t.check(diff(imgs["Volume"][1], imgs["Psi Volume"][1]) < bound, "second view: the two agree")
simple.Delete(view2)

# State save and load: both representations come back as they were, separate opacity array,
# its component and the opacity function's range included.
saved_images = {}
for rep in ("Volume", "Psi Volume"):
    d = show(calc2, rep)
    separate(d, "V", 0)
    simple.Render(view)
    saved_images[rep] = testing.grab(view)
    state = os.path.join(tempfile.mkdtemp(), "parity.pvsm")
    simple.SaveState(state)
    simple.ResetSession()
    data.load_plugin(globals(), os.environ.get("PSI_PLUGIN"))
    simple.LoadState(state)
    view = simple.GetActiveViewOrCreate("RenderView")
    view.ViewSize = [120, 120]
    simple.Render(view)
    loaded = testing.grab(view)
    shown = [r for r in simple.GetRepresentations().values() if r.Visibility]
    t.check(len(shown) == 1 and shown[0].Representation == rep and
            shown[0].UseSeparateOpacityArray == 1, "state: '%s' with its opacity array" % rep)
    # ('Volume' itself comes back 8/255 off here, its opacity function range not as saved:
    # ParaView's own matter, reported, not checked)
    if rep == "Psi Volume":
        t.check(diff(loaded, saved_images[rep]) < CHANGED, "state: '%s' renders as before (%.2f)"
                % (rep, diff(loaded, saved_images[rep])))
    else:
        print("        state: 'Volume' after load %.2f off" % diff(loaded, saved_images[rep]))
    calc2 = simple.FindSource("Other") or [s for s in simple.GetSources().values()
                                           if s.GetXMLName() == "Calculator"][-1]
    pwf = simple.GetOpacityTransferFunction(array)
    saved = list(pwf.Points)
    simple.Hide(calc2, view)
t.check(diff(saved_images["Volume"], saved_images["Psi Volume"]) < bound,
        "state: the two agree (%.2f)" % diff(saved_images["Volume"], saved_images["Psi Volume"]))
t.finish()
