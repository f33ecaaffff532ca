"""Helpers for the pvpython tests: checks that count failures, image comparison, small scenes.
Image capture and the PNG writer are psivolume.images (grab and write_png are here too, for the
tests), leaving the program psivolume.process.exit_now."""
import sys

import numpy as np

from .images import grab, write_png  # noqa: F401 (the tests' names for them)
from .process import exit_now

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


def mean_error(a, b):
    return float(np.abs(a - b).mean()) / 255.0


def covered(img, background):
    """Pixels that differ from the background color by more than 2/255."""
    bg = np.array(background, dtype=np.float64) * 255.0
    return int((np.abs(img - bg).sum(axis=2) > 2.0).sum())


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


def with_unused_point(grid, point):
    """A copy of the vtkUnstructuredGrid `grid` with `point` appended to its point list, used by
    no cell (as readers and filters that keep a shared point list make them), carrying point 0's
    values in every point array (their ranges stay)."""
    from vtkmodules.vtkCommonDataModel import vtkUnstructuredGrid
    more = vtkUnstructuredGrid()
    more.DeepCopy(grid)
    more.GetPoints().InsertNextPoint(point)
    point_data = more.GetPointData()
    for i in range(point_data.GetNumberOfArrays()):
        a = point_data.GetAbstractArray(i)
        a.InsertNextTuple(0, a)
    return more


def apply_requested(display):
    """Gives a 'Psi Volume' display the projector the test's command line asks for
    (`--projector compute` or `--projector geometry`; CTest's `.compute` variants), and returns it."""
    if "--projector" in sys.argv:
        asked = sys.argv[sys.argv.index("--projector") + 1]
        display.Projector = {"compute": "Compute Shader", "geometry": "Geometry Shader"}[asked]
    return display
