"""Narrow opacity spikes are integrated exactly by adaptive sampling, and 'Auto' (the default)
finds them. A slab of tetrahedra with the exactly linear scalar s = z / 40 (z from 0 to 40), white,
seen along z in parallel projection, with a tent-shaped opacity of width w (a fraction of the
scalar range) around s = 0.5: each ray's optical depth is the integral of opacity / unit distance
along z, 40 * (w / 2) / u, so the exact opacity is 1 - exp(-20 w / u). The unit distance is
u = 20 w, so that the exact opacity is 1 - 1/e for every width; widths from 10% down to 0.01% of
the range, far below the 1024-sample table's spacing (0.1%). Adaptive sampling On and Auto must
be within 2% of the exact opacity; Off (the sampled table) is printed for comparison."""
import math
import os

from paraview import simple

from psivolume import data, testing

t = testing.Checks("test_narrow_spikes")
data.load_plugin(globals(), os.environ.get("PSI_PLUGIN"))
grid = simple.Wavelet(WholeExtent=[0, 6, 0, 6, 0, 40])
calc = simple.Calculator(Input=grid, ResultArrayName="s", Function="coordsZ/40")
slab = simple.Tetrahedralize(Input=calc)
view = testing.black_view(120)
d = simple.Show(slab, view)
simple.ColorBy(d, ("POINTS", "s"))
d.SetRepresentationType("Psi Volume")
lut = simple.GetColorTransferFunction("s")
lut.ColorSpace = "RGB"
lut.RGBPoints = [0.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0]
pwf = simple.GetOpacityTransferFunction("s")
simple.Render(view)  # the first render resets the camera: set it afterwards
view.CameraParallelProjection = 1
view.CameraFocalPoint = [3, 3, 20]
view.CameraPosition = [3, 3, 100]
view.CameraViewUp = [0, 1, 0]
view.CameraParallelScale = 4.0
t.check(d.GetProperty("AdaptiveSampling").GetElement(0) in (2, "Auto"),
        "AdaptiveSampling defaults to Auto (%s)" % d.GetProperty("AdaptiveSampling").GetElement(0))


def opacity(width, mode):
    """Mean gray of the slab's middle (premultiplied white over black: the opacity)."""
    lo, hi = 0.5 - width / 2, 0.5 + width / 2
    pwf.Points = [0.0, 0.0, 0.5, 0.0, lo, 0.0, 0.5, 0.0, 0.5, 1.0, 0.5, 0.0,
                  hi, 0.0, 0.5, 0.0, 1.0, 0.0, 0.5, 0.0]
    d.ScalarOpacityUnitDistance = 20.0 * width
    d.AdaptiveSampling = mode
    simple.Render(view)
    d.UpdatePropertyInformation()
    img = testing.grab(view)
    return img[40:80, 40:80, :].mean() / 255.0, d.GetProperty("LastNumberOfAdaptiveNodes").GetElement(0)


exact = 1.0 - math.exp(-1.0)
for width in (0.1, 0.01, 0.003, 0.001, 0.0003, 0.0001):
    off, _ = opacity(width, "Off")
    on, n_on = opacity(width, "On")
    auto, n_auto = opacity(width, "Auto")
    print("w = %.2f%%: exact %.4f, Off %.4f, On %.4f (%d nodes), Auto %.4f (%d nodes)"
          % (100 * width, exact, off, on, n_on, auto, n_auto))
    t.check(abs(on - exact) <= 0.02 * exact, "w = %.2f%%: On within 2%% (%.4f)" % (100 * width, on))
    t.check(abs(auto - exact) <= 0.02 * exact,
            "w = %.2f%%: Auto within 2%% (%.4f)" % (100 * width, auto))
    if width <= 0.001:
        t.check(n_auto > 0, "w = %.2f%%: Auto samples adaptively" % (100 * width))

# ParaView's default transfer function has no feature the table misses: Auto draws as Off.
pwf.Points = [0.0, 0.0, 0.5, 0.0, 1.0, 1.0, 0.5, 0.0]  # the default linear ramp
lut.ApplyPreset("Cool to Warm", True)
d.ScalarOpacityUnitDistance = 1.0
d.AdaptiveSampling = "Auto"
simple.Render(view)
d.UpdatePropertyInformation()
t.check(d.GetProperty("LastNumberOfAdaptiveNodes").GetElement(0) == 0,
        "default transfer function: Auto does not sample adaptively")
t.finish()
