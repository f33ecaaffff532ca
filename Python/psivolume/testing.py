"""Helpers for the pvpython tests: image capture and comparison, checks that count failures, and
the project's PNG writer (write_png: the accuracy report's plots, the tests' images, the GUI
tests' strict check, the README's screenshot)."""
import os
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter

SKIP = 77  # ctest SKIP_RETURN_CODE


class Checks:
    def __init__(self, name):
        self.name = name
        self.failures = 0

    def check(self, cond, what):
        print(("ok      " if cond else "FAILED  ") + what)
        sys.stdout.flush()
        if not cond:
            self.failures += 1

    def finish(self):
        print("%s: %s" % (self.name, "FAILED (%d)" % self.failures if self.failures else "passed"))
        exit_now(1 if self.failures else 0)


def exit_now(code):
    """Leaves pvpython with `code`. sys.exit() from a pvpython script under Xvfb makes the
    teardown fail with GLXBadContext and exit 1 even with ParaView's own mappers (measured with
    the built-in 'Volume' representation), which would turn every passing test into a failure."""
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(code)


def apply_preset(function, *names):
    """Applies the first of `names` this ParaView knows: ParaView 6 renamed presets ('Viridis
    (matplotlib)' is 'Viridis') and raises on an unknown name where 5.11 returned False."""
    for name in names:
        try:
            if function.ApplyPreset(name, True):
                return name
        except RuntimeError:
            pass
    raise RuntimeError("none of the presets %s exists in this ParaView" % (names,))


def black_view(size):
    """A size x size render view on a black background, without orientation axes: premultiplied
    volume colors read back as they are."""
    from paraview import simple
    view = simple.CreateRenderView()
    view.ViewSize = [size, size]
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [0.0, 0.0, 0.0]
    return view


def grab(view):
    """The view's current image as float RGB in [0, 255], rows from the bottom."""
    w2i = vtkWindowToImageFilter()
    w2i.SetInput(view.GetRenderWindow())
    w2i.ReadFrontBufferOff()
    w2i.ShouldRerenderOff()
    w2i.Update()
    im = w2i.GetOutput()
    dims = im.GetDimensions()
    a = vtk_to_numpy(im.GetPointData().GetScalars()).reshape(dims[1], dims[0], -1)
    return a[:, :, :3].astype(np.float64)


def mean_error(a, b):
    return float(np.abs(a - b).mean()) / 255.0


def covered(img, background):
    """Pixels that differ from the background color by more than 2/255."""
    bg = np.array(background, dtype=np.float64) * 255.0
    return int((np.abs(img - bg).sum(axis=2) > 2.0).sum())


def write_png(rgb, path):
    """Writes `rgb` (rows x columns x 3, bottom row first, as VTK orders images; values 0..255,
    clipped) to a PNG."""
    from vtkmodules.util.numpy_support import numpy_to_vtk
    from vtkmodules.vtkCommonDataModel import vtkImageData
    from vtkmodules.vtkIOImage import vtkPNGWriter

    h, w, _ = rgb.shape
    img = vtkImageData()
    img.SetDimensions(w, h, 1)
    arr = numpy_to_vtk(np.clip(rgb.reshape(-1, 3), 0, 255).astype(np.uint8), deep=1)
    img.GetPointData().SetScalars(arr)
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputData(img)
    writer.Write()


def one_tetrahedron(name="s", size=1.0):
    """A vtkUnstructuredGrid of one tetrahedron, corners at the origin and `size` along each axis,
    with the point array `name` = 0, 1, 2, 3."""
    from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
    from vtkmodules.vtkCommonDataModel import VTK_TETRA, vtkUnstructuredGrid
    grid = vtkUnstructuredGrid()
    points = vtkPoints()
    for p in ((0, 0, 0), (size, 0, 0), (0, size, 0), (0, 0, size)):
        points.InsertNextPoint(p)
    grid.SetPoints(points)
    grid.InsertNextCell(VTK_TETRA, 4, [0, 1, 2, 3])
    s = vtkDoubleArray()
    s.SetName(name)
    for v in (0.0, 1.0, 2.0, 3.0):
        s.InsertNextValue(v)
    grid.GetPointData().AddArray(s)
    return grid


def apply_requested(display):
    """Gives a 'Psi Volume' display the projector the test's command line asks for
    (`--projector compute` or `--projector geometry`; CTest's `.compute` variants), and returns it."""
    if "--projector" in sys.argv:
        asked = sys.argv[sys.argv.index("--projector") + 1]
        display.Projector = {"compute": "Compute Shader", "geometry": "Geometry Shader"}[asked]
    return display
