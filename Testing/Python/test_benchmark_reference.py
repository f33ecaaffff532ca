"""The benchmarks' reference (Bunyk + vtkUnstructuredGridLinearRayIntegrator, bench.Scene) is
exact only when the color map interpolates in RGB and has a point at every opacity point (VTK
9.2's integrator keeps the opacity function's points only where the color map has one).
bench.align_color_points adds those points: afterwards every opacity point is a color point,
and the color map is the same function as before (checked at 2,001 scalars)."""

from paraview import simple
from vtkmodules.vtkRenderingCore import vtkColorTransferFunction

from psivolume import bench, testing

t = testing.Checks("test_benchmark_reference")
lut = simple.GetColorTransferFunction("aligned")
lut.ColorSpace = "RGB"
lut.RGBPoints = [0.0, 0.0, 0.0, 1.0, 0.5, 1.0, 1.0, 1.0, 1.0, 1.0, 0.0, 0.0]
pwf = simple.GetOpacityTransferFunction("aligned")
pwf.Points = [0.0, 0.0, 0.5, 0.0, 0.2, 0.0, 0.5, 0.0, 0.3, 0.8, 0.5, 0.0, 0.7, 0.1, 0.5, 0.0,
              1.0, 1.0, 0.5, 0.0]


def samples():
    """The continuous color map at 2,001 scalars."""
    ctf = vtkColorTransferFunction()
    ctf.DeepCopy(lut.GetClientSideObject())
    return [ctf.GetColor(i / 2000.0) for i in range(2001)]


before = samples()
bench.align_color_points(lut, pwf)
xs = list(lut.RGBPoints)[0::4]
missing = [x for x in list(pwf.Points)[0::4] if not any(abs(x - c) < 1e-12 for c in xs)]
t.check(not missing, "every opacity point is a color point (missing %s)" % missing)
t.check(len(xs) == 6, "three color points added (%d points)" % len(xs))
after = samples()
worst = max(abs(a - b) for ca, cb in zip(before, after) for a, b in zip(ca, cb))
t.check(worst < 1e-6, "the color map is unchanged (worst %.2e)" % worst)
t.finish()
