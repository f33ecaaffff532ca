"""'Psi Volume' as a ParaView user meets it: the plugin loads, the representation is listed and
renders, its properties work, non-tetrahedral input is tetrahedralized on the way in, its image
agrees with the exact ray caster (Bunyk + linear integrator), and state files round-trip."""
import os
import tempfile

from paraview import simple
from vtkmodules.vtkRenderingVolume import vtkUnstructuredGridLinearRayIntegrator

from psivolume import data, testing

t = testing.Checks("test_plugin_basics")
data.load_plugin(globals(), os.environ.get("PSI_PLUGIN"))
BG = [0.0, 0.0, 0.0]


def make_view(size=200):
    v = simple.CreateRenderView()
    v.ViewSize = [size, size]
    v.OrientationAxesVisibility = 0
    v.UseColorPaletteForBackground = 0
    v.Background = BG
    return v


def oblique(v):
    simple.Render(v)
    v.ResetCamera()
    c = v.GetActiveCamera()
    c.Azimuth(27)
    c.Elevation(19)
    c.Roll(7)
    v.ResetCamera()


src, array = data.wavelet(10)
src.UpdatePipeline()
ncells = src.GetDataInformation().GetNumberOfCells()
view = make_view()
d = data.show_volume(src, array, view, unit_distance=2.0)
simple.GetColorTransferFunction(array).ColorSpace = "RGB"  # exact for the linear integrator
t.check("Psi Volume" in d.Representation.Available, "'Psi Volume' is a representation type")
t.check(d.Representation == "Psi Volume", "representation set to 'Psi Volume'")
t.check(d.IntegrationMethod == "Partial Pre-Integration", "default integration method")
oblique(view)
simple.Render(view)
psi = testing.grab(view)
d.UpdatePropertyInformation()
t.check(d.GetProperty("NumberOfTetrahedra").GetElement(0) == ncells,
        "all %d tetrahedra drawn" % ncells)
t.check(d.GetProperty("NumberOfSkippedCells").GetElement(0) == 0, "no cell skipped")
cov = testing.covered(psi, BG)
t.check(cov > 0.25 * 200 * 200, "image is not empty (%d pixels covered)" % cov)

d.IntegrationMethod = "Average"
simple.Render(view)
avg = testing.grab(view)
t.check(testing.mean_error(avg, psi) > 0, "integration method changes the image")
try:
    d.IntegrationMethod = "No Such Method"
    t.check(False, "an unknown integration method is refused")
except ValueError:
    t.check(True, "an unknown integration method is refused")
d.IntegrationMethod = "Partial Pre-Integration"

# Exact reference: ParaView's Bunyk ray caster with the linear ray integrator, same view.
d.SetRepresentationType("Volume")
d.SelectMapper = "Bunyk ray cast"
simple.Render(view)
bunyk = d.GetClientSideObject().GetActiveRepresentation().GetActiveVolumeMapper()
bunyk.SetRayIntegrator(vtkUnstructuredGridLinearRayIntegrator())
simple.Render(view)
ref = testing.grab(view)
bunyk.SetRayIntegrator(None)
del bunyk  # a Python reference must not keep ParaView's mapper alive past its render window
d.SelectMapper = "Projected tetra"
simple.Render(view)
pt = testing.grab(view)
e_psi, e_pt = testing.mean_error(psi, ref), testing.mean_error(pt, ref)
print("mean error vs Bunyk+linear: Psi Volume %.5f, Projected tetra %.5f" % (e_psi, e_pt))
t.check(e_psi < 0.006, "Psi Volume agrees with the exact ray caster (mean error %.5f)" % e_psi)
d.SetRepresentationType("Psi Volume")

# Non-tetrahedral input (voxels) is tetrahedralized on the way in, as for 'Volume'.
hexes = simple.CleantoGrid(Input=src.Input)
view2 = make_view()
d2 = data.show_volume(hexes, array, view2, unit_distance=2.0)
simple.GetColorTransferFunction(array).ColorSpace = "RGB"
oblique(view2)
simple.Render(view2)
from_hexes = testing.grab(view2)
d2.UpdatePropertyInformation()
t.check(d2.GetProperty("NumberOfTetrahedra").GetElement(0) >= 5 * 20 ** 3,
        "hexahedral input drawn as tetrahedra (%d)" % d2.GetProperty("NumberOfTetrahedra").GetElement(0))
e_hex = testing.mean_error(from_hexes, psi)
t.check(e_hex < 0.01, "voxel input renders like the tetrahedralized mesh (%.5f)" % e_hex)
simple.Delete(d2)
simple.Delete(view2)

# State files: representation type, method and opacity survive save/load.
# 'Psi Volume' reads ScalarOpacityFunction / ScalarOpacityUnitDistance from its own copies
# (PsiScalarOpacityFunction / PsiScalarOpacityUnitDistance), the outputs of the one-way
# ShareProperties link from the VolumeRepresentation: what is set on the representation (here,
# and by the panel's 'Psi Volume Opacity' group) must reach them, and the state must restore both.
def opacity(rep):
    """(unit distance, Psi copy of it, opacity function, Psi copy of it) of a representation."""
    return (rep.ScalarOpacityUnitDistance, rep.PsiScalarOpacityUnitDistance,
            rep.ScalarOpacityFunction.SMProxy, rep.PsiScalarOpacityFunction.SMProxy)


def check_opacity(rep, what):
    unit, psi_unit, pwf, psi_pwf = opacity(rep)
    t.check(unit == 2.0 and psi_unit == 2.0,
            "%s: ScalarOpacityUnitDistance %g, 'Psi Volume' copy %g (2 expected)"
            % (what, unit, psi_unit))
    t.check(pwf is not None and psi_pwf == pwf and
            pwf == simple.GetOpacityTransferFunction(array).SMProxy,
            "%s: 'Psi Volume' uses the color map's opacity function" % what)


def draw_way(rep):
    """The last frame's LastDrawWay read-out."""
    rep.UpdatePropertyInformation()
    return rep.GetProperty("LastDrawWay").SMProperty.GetElement(0)


def measure(view, rep, what):
    """Renders until 'Auto' has timed its ways; every frame must use the compute projector the
    state forces. Returns the last frame's way."""
    for _ in range(30):
        simple.Render(view)
        way = draw_way(rep)
        t.check("compute shader" in way, "%s: the forced projector drawn (%s)" % (what, way))
        if "(measuring" not in way:
            break
    t.check("(chosen by measurement of" in way, "%s: a way chosen by measurement: %s" % (what, way))
    return way


check_opacity(d, "before save")
d.IntegrationMethod = "Average"
# the ways 'Auto' times, with the projector forced: both survive the state file
d.Projector = "Compute Shader"
d.EarlyRayTermination = "Auto"
measure(view, d, "before save")
before = testing.grab(view)
state = os.path.join(tempfile.mkdtemp(), "psi.pvsm")
simple.SaveState(state)
simple.ResetSession()
simple.LoadState(state)
view = simple.GetActiveViewOrCreate("RenderView")
view.ViewSize = [200, 200]
simple.Render(view)
after = testing.grab(view)
reps = [r for r in simple.GetRepresentations().values() if r.GetProperty("IntegrationMethod")]
t.check(any(r.Representation == "Psi Volume" and r.IntegrationMethod == "Average" for r in reps),
        "state file restores 'Psi Volume' and its integration method")
t.check(all(r.Projector == "Compute Shader" and r.EarlyRayTermination == "Auto" and
            r.Decomposition == "Auto" for r in reps),
        "state file restores the forced projector and the 'Auto' ways")
measure(view, reps[0], "after load")
for r in reps:
    check_opacity(r, "after load")
e_state = testing.mean_error(after, before)
t.check(e_state < 0.5 / 255, "reloaded state renders the same image (%.5f)" % e_state)
t.finish()
