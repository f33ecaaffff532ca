"""Bad input to 'Psi Volume': every case must end in a clear message in ParaView's output
or a correct image, never a crash, a hang, or a black frame without explanation.

Usage: pvpython --force-offscreen-rendering test_bad_input.py [CASE ...]
CTest runs each case in its own process (Testing/Readers.cmake), so that a crash or a hang in one
case is reported as that case's failure. Cases that need ../shared/data exit with 77 (skipped)
when it is absent. Messages are captured with observers on VTK's output window.

Images are compared with a reference rendered in the same view and camera: the same mesh
without the offending cells, the same field on a clean mesh, or ParaView's own 'Projected tetra'
mapper; the tolerances are stated at each check."""
import faulthandler
import os
import sys
import tempfile
import time

import numpy as np
from paraview import simple
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray
from vtkmodules.util.vtkConstants import VTK_STRING
from vtkmodules.vtkCommonCore import vtkCommand, vtkOutputWindow
from vtkmodules.vtkCommonDataModel import (
    VTK_HEXAHEDRON, VTK_TETRA, VTK_WEDGE, vtkCellArray, vtkUnstructuredGrid)
from vtkmodules.vtkCommonCore import vtkPoints

from psivolume import data, testing

DATA = os.environ.get("PSI_DATA_DIR") or data.DATA_DIR
BG = [0.0, 0.0, 0.0]
SIZE = 200
CASE_TIMEOUT = 240  # seconds; a hang prints every thread's stack and fails

t = testing.Checks("test_bad_input")


# ---------------------------------------------------------------- messages of VTK's output window
class Messages:
    """Errors and warnings printed through VTK's output window (what ParaView shows the user)."""

    def __init__(self):
        self.items = []
        ow = vtkOutputWindow.GetInstance()
        for ev in (vtkCommand.ErrorEvent, vtkCommand.WarningEvent):
            ow.AddObserver(ev, self._on)

    @calldata_type(VTK_STRING)
    def _on(self, obj, event, text):
        self.items.append((event, text or ""))

    def mark(self):
        return len(self.items)

    def since(self, mark, kind=None, contains=None):
        out = []
        for ev, text in self.items[mark:]:
            if kind and ev != kind:
                continue
            if contains and contains.lower() not in text.lower():
                continue
            out.append(text)
        return out


MSG = Messages()


def short(text):
    return " ".join(text.split())[:240]


# ---------------------------------------------------------------- meshes built in numpy
def field(p):
    """A smooth field on [0,1]^3 with a blob and waves, in [0, ~1.3]."""
    x, y, z = p[:, 0], p[:, 1], p[:, 2]
    r2 = (x - 0.45) ** 2 + (y - 0.55) ** 2 + (z - 0.5) ** 2
    return np.exp(-6.0 * r2) + 0.15 * np.sin(5.0 * x) * np.cos(4.0 * y) + 0.15 * z


def box_points(n):
    g = np.linspace(0.0, 1.0, n + 1)
    z, y, x = np.meshgrid(g, g, g, indexing="ij")
    return np.column_stack([x.ravel(), y.ravel(), z.ravel()])


def box_cubes(n):
    """Corner indices (VTK hexahedron order) of the n^3 cubes of box_points(n)."""
    m = n + 1
    k, j, i = np.meshgrid(np.arange(n), np.arange(n), np.arange(n), indexing="ij")
    b = (i + j * m + k * m * m).ravel()
    dx, dy, dz = 1, m, m * m
    return np.column_stack([b, b + dx, b + dx + dy, b + dy,
                            b + dz, b + dx + dz, b + dx + dy + dz, b + dy + dz])


def box_tets(n):
    """Kuhn (Freudenthal) split: 6 tetrahedra per cube along its main diagonal; conforming."""
    m = n + 1
    k, j, i = np.meshgrid(np.arange(n), np.arange(n), np.arange(n), indexing="ij")
    b = (i + j * m + k * m * m).ravel().astype(np.int64)
    e = [1, m, m * m]
    tets = []
    for a, bb, c in ((0, 1, 2), (0, 2, 1), (1, 0, 2), (1, 2, 0), (2, 0, 1), (2, 1, 0)):
        tets.append(np.column_stack([b, b + e[a], b + e[a] + e[bb], b + e[a] + e[bb] + e[c]]))
    return np.stack(tets, axis=1).reshape(-1, 4)


def make_grid(points, cells, cell_type=VTK_TETRA, point_scalars=None, cell_scalars=None,
              name="f"):
    ug = vtkUnstructuredGrid()
    pts = vtkPoints()
    pts.SetData(numpy_to_vtk(np.ascontiguousarray(points, dtype=np.float64), deep=1))
    ug.SetPoints(pts)
    cells = np.ascontiguousarray(cells, dtype=np.int64)
    npc = cells.shape[1] if len(cells) else 4
    ca = vtkCellArray()
    offsets = np.arange(0, (len(cells) + 1) * npc, npc, dtype=np.int64)
    ca.SetData(numpy_to_vtkIdTypeArray(offsets, deep=1),
               numpy_to_vtkIdTypeArray(cells.ravel(), deep=1))
    ug.SetCells(cell_type, ca)
    if point_scalars is not None:
        a = numpy_to_vtk(np.ascontiguousarray(point_scalars, dtype=np.float64), deep=1)
        a.SetName(name)
        ug.GetPointData().SetScalars(a)
    if cell_scalars is not None:
        a = numpy_to_vtk(np.ascontiguousarray(cell_scalars, dtype=np.float64), deep=1)
        a.SetName(name)
        ug.GetCellData().SetScalars(a)
    return ug


def producer(dataset):
    tp = simple.TrivialProducer()
    tp.GetClientSideObject().SetOutput(dataset)
    tp.UpdatePipeline()
    return tp


# ---------------------------------------------------------------- views and rendering
def make_view():
    v = simple.CreateRenderView()
    v.ViewSize = [SIZE, SIZE]
    v.OrientationAxesVisibility = 0
    v.UseColorPaletteForBackground = 0
    v.Background = BG
    return v


def aim(view, bounds):
    """A fixed oblique camera on `bounds`, the same for every image compared in a case."""
    c = view.GetActiveCamera()
    ctr = [(bounds[0] + bounds[1]) / 2, (bounds[2] + bounds[3]) / 2, (bounds[4] + bounds[5]) / 2]
    c.SetFocalPoint(*ctr)
    c.SetPosition(ctr[0] + 1.0, ctr[1] + 0.6, ctr[2] + 0.8)
    c.SetViewUp(0, 0, 1)
    view.ResetCamera(*[float(x) for x in bounds])


def show(src, view, array, assoc="POINTS", rng=None, representation="Psi Volume", unit=None):
    d = simple.Show(src, view)
    simple.ColorBy(d, (assoc, array))
    d.SetRepresentationType(representation)
    lut = simple.GetColorTransferFunction(array)
    pwf = simple.GetOpacityTransferFunction(array)
    if rng is not None:
        lut.RescaleTransferFunction(rng[0], rng[1])
        pwf.RescaleTransferFunction(rng[0], rng[1])
    else:
        d.RescaleTransferFunctionToDataRange(True, False)
    lut.ColorSpace = "RGB"
    if unit is not None:
        d.ScalarOpacityUnitDistance = unit
    return d


def render_only(view, display, all_displays):
    for d in all_displays:
        d.Visibility = 1 if d is display else 0
    simple.Render(view)
    return testing.grab(view)


def info(display):
    display.UpdatePropertyInformation()
    return (int(display.GetProperty("NumberOfTetrahedra").GetElement(0)),
            int(display.GetProperty("NumberOfSkippedCells").GetElement(0)))


def diff(a, b):
    d = np.abs(a - b)
    return float(d.mean()), float(d.max())


def check_image(img, what, min_cover=0.05):
    finite = bool(np.isfinite(img).all())
    t.check(finite, "%s: image values are finite" % what)
    cov = testing.covered(img, BG)
    t.check(cov >= min_cover * SIZE * SIZE, "%s: image not empty (%d of %d pixels covered, need "
            ">= %.0f%%)" % (what, cov, SIZE * SIZE, 100 * min_cover))
    return cov


def need(path):
    if not os.path.exists(path):
        print("SKIP: %s is absent (the shared data of ../shared/data, see its MANIFEST.md)" % path)
        testing.exit_now(testing.SKIP)


# ---------------------------------------------------------------- cases
def case_nontet():
    """Hexahedra and wedges go through the representation's tetrahedralization and render like a
    tetrahedral mesh of the same field (the splits differ, hence a tolerance)."""
    n = 14
    p = box_points(n)
    f = field(p)
    rng = (float(f.min()), float(f.max()))
    tets = make_grid(p, box_tets(n), VTK_TETRA, point_scalars=f)
    cubes = box_cubes(n)
    hexes = make_grid(p, cubes, VTK_HEXAHEDRON, point_scalars=f)
    # Each cube as two wedges (prisms) split along the diagonal plane of its x-y faces.
    w1 = cubes[:, [0, 1, 3, 4, 5, 7]]
    w2 = cubes[:, [1, 2, 3, 5, 6, 7]]
    wedges = make_grid(p, np.vstack([w1, w2]), VTK_WEDGE, point_scalars=f)
    view = make_view()
    ds = [show(producer(g), view, "f", rng=rng, unit=0.15) for g in (tets, hexes, wedges)]
    aim(view, [0, 1, 0, 1, 0, 1])
    ref = render_only(view, ds[0], ds)
    check_image(ref, "tetrahedra (reference)", 0.3)
    for d, name, ncells in ((ds[1], "hexahedra", len(cubes)), (ds[2], "wedges", 2 * len(cubes))):
        m = MSG.mark()
        img = render_only(view, d, ds)
        ntets, skipped = info(d)
        check_image(img, name, 0.3)
        t.check(skipped == 0, "%s: no cell skipped (%d)" % (name, skipped))
        t.check(ntets >= 3 * ncells, "%s: %d cells drawn as %d tetrahedra" % (name, ncells, ntets))
        mean, mx = diff(img, ref)
        t.check(mean < 1.5, "%s: image matches the tetrahedral mesh of the same field (mean "
                "|diff| %.3f/255 < 1.5, max %.0f)" % (name, mean, mx))
        errs = MSG.since(m, "ErrorEvent")
        t.check(not errs, "%s: no error printed%s" % (name, (": " + short(errs[0])) if errs else ""))


def case_surface():
    """A surface-only grid (triangles and quads) has nothing to volume render: the user must be
    told why the frame is empty."""
    path = os.path.join(DATA, "blow.vtk")
    need(path)
    r = simple.LegacyVTKReader(FileNames=[path])
    r.UpdatePipeline()
    ncells = r.GetDataInformation().GetNumberOfCells()
    view = make_view()
    m = MSG.mark()
    d = show(r, view, "thickness9")
    simple.Render(view)
    view.ResetCamera()
    simple.Render(view)
    img = testing.grab(view)
    ntets, skipped = info(d)
    msgs = MSG.since(m)
    for s in msgs:
        print("    message: " + short(s))
    t.check(ntets == 0, "surface: no tetrahedra drawn (%d)" % ntets)
    t.check(skipped > 0, "surface: NumberOfSkippedCells reports the %d surface cells (%d)"
            % (ncells, skipped))
    cov = testing.covered(img, BG)
    explained = [s for s in msgs if "skipped" in s.lower() or "no 3d" in s.lower()
                 or "no volume cells" in s.lower()
                 or "tetrahedr" in s.lower()]
    t.check(cov == 0 or not explained, "surface: the frame is empty (%d pixels)" % cov)
    t.check(len(explained) > 0, "surface: a message explains the empty frame")


def case_cellscalars():
    """No point scalars, cell scalars only: each tetrahedron is constant. Checked against the same
    mesh with private points per tetrahedron carrying the cell value as point scalars, and against
    ParaView's 'Projected tetra' mapper with the cell array (independent implementation)."""
    n = 12
    p = box_points(n)
    tets = box_tets(n)
    f = field(p)
    cf = f[tets].mean(axis=1)
    rng = (float(cf.min()), float(cf.max()))
    cells = make_grid(p, tets, cell_scalars=cf)
    # Explicitly constant per tetrahedron: 4 private points each.
    private = make_grid(p[tets.ravel()], np.arange(4 * len(tets)).reshape(-1, 4),
                        point_scalars=np.repeat(cf, 4))
    smooth = make_grid(p, tets, point_scalars=f)
    view = make_view()
    src_cells = producer(cells)
    d_cells = show(src_cells, view, "f", "CELLS", rng=rng, unit=0.15)
    d_private = show(producer(private), view, "f", "POINTS", rng=rng, unit=0.15)
    d_smooth = show(producer(smooth), view, "f", "POINTS", rng=rng, unit=0.15)
    ds = [d_cells, d_private, d_smooth]
    aim(view, [0, 1, 0, 1, 0, 1])
    m = MSG.mark()
    img = render_only(view, d_cells, ds)
    ntets, skipped = info(d_cells)
    errs = MSG.since(m, "ErrorEvent")
    t.check(not errs, "cell scalars: no error%s" % ((": " + short(errs[0])) if errs else ""))
    check_image(img, "cell scalars", 0.3)
    t.check(ntets == len(tets) and skipped == 0, "cell scalars: all %d tetrahedra drawn (%d, "
            "%d skipped)" % (len(tets), ntets, skipped))
    ref = render_only(view, d_private, ds)
    mean, mx = diff(img, ref)
    t.check(mean < 0.25 and mx <= 8, "cell scalars render as tetrahedra of constant value (mean "
            "|diff| %.3f/255 < 0.25, max %.0f <= 8, vs private points)" % (mean, mx))
    sm = render_only(view, d_smooth, ds)
    ms, _ = diff(img, sm)
    t.check(ms > 0.2, "cell scalars differ from the smooth point field (mean |diff| %.3f/255)"
            % ms)
    # ParaView's projected tetrahedra with the same cell array, in the same view.
    d_pt = show(src_cells, view, "f", "CELLS", rng=rng, representation="Volume", unit=0.15)
    d_pt.SelectMapper = "Projected tetra"
    ptimg = render_only(view, d_pt, ds + [d_pt])
    mp, mxp = diff(img, ptimg)
    print("cell scalars vs Projected tetra: mean %.3f/255 max %.0f" % (mp, mxp))
    t.check(mp < 3.0, "cell scalars agree with ParaView's 'Projected tetra' (mean |diff| %.3f/255 "
            "< 3)" % mp)


def case_nonfinite():
    """NaN/Inf point scalars (and NaN cell scalars): the tetrahedra touching them are skipped and
    counted in NumberOfSkippedCells, with a warning; the image equals the image of the mesh
    without those tetrahedra (no NaN reaching the frame: no black or garbage pixels)."""
    n = 14
    p = box_points(n)
    tets = box_tets(n)
    f = field(p)
    rng = (float(f.min()), float(f.max()))
    rs = np.random.RandomState(6)
    bad = rs.choice(len(p), size=len(p) // 40, replace=False)
    g = f.copy()
    g[bad[0::3]] = np.nan
    g[bad[1::3]] = np.inf
    g[bad[2::3]] = -np.inf
    badtet = (~np.isfinite(g[tets])).any(axis=1)
    expected = int(badtet.sum())
    view = make_view()
    d_bad = show(producer(make_grid(p, tets, point_scalars=g)), view, "f", rng=rng, unit=0.15)
    d_ref = show(producer(make_grid(p, tets[~badtet], point_scalars=np.where(np.isfinite(g), g, 0))),
                 view, "f", rng=rng, unit=0.15)
    ds = [d_bad, d_ref]
    aim(view, [0, 1, 0, 1, 0, 1])
    m = MSG.mark()
    img = render_only(view, d_bad, ds)
    ntets, skipped = info(d_bad)
    warns = MSG.since(m, "WarningEvent", "NaN")
    for s in warns:
        print("    message: " + short(s))
    t.check(skipped == expected, "NaN/Inf points: NumberOfSkippedCells = %d (expected %d of %d)"
            % (skipped, expected, len(tets)))
    t.check(ntets == len(tets) - expected, "NaN/Inf points: %d tetrahedra drawn" % ntets)
    t.check(len(warns) > 0 and str(expected) in warns[0],
            "NaN/Inf points: a warning reports the %d skipped tetrahedra" % expected)
    check_image(img, "NaN/Inf points", 0.3)
    ref = render_only(view, d_ref, ds)
    mean, mx = diff(img, ref)
    t.check(mean < 0.05 and mx <= 2, "NaN/Inf points: image equals the mesh without those "
            "tetrahedra (mean |diff| %.4f/255 < 0.05, max %.0f <= 2)" % (mean, mx))

    # Cell scalars with NaN and Inf.
    cf = f[tets].mean(axis=1)
    crng = (float(cf.min()), float(cf.max()))
    badc = rs.choice(len(tets), size=len(tets) // 30, replace=False)
    cg = cf.copy()
    cg[badc[0::2]] = np.nan
    cg[badc[1::2]] = np.inf
    keep = np.isfinite(cg)
    view2 = make_view()
    d_cbad = show(producer(make_grid(p, tets, cell_scalars=cg)), view2, "f", "CELLS", rng=crng,
                  unit=0.15)
    d_cref = show(producer(make_grid(p, tets[keep], cell_scalars=cg[keep])), view2, "f", "CELLS",
                  rng=crng, unit=0.15)
    aim(view2, [0, 1, 0, 1, 0, 1])
    m = MSG.mark()
    img = render_only(view2, d_cbad, [d_cbad, d_cref])
    ntets, skipped = info(d_cbad)
    warns = MSG.since(m, "WarningEvent", "NaN")
    t.check(skipped == int((~keep).sum()), "NaN/Inf cells: NumberOfSkippedCells = %d (expected %d)"
            % (skipped, int((~keep).sum())))
    t.check(len(warns) > 0, "NaN/Inf cells: a warning is printed")
    check_image(img, "NaN/Inf cells", 0.3)
    ref = render_only(view2, d_cref, [d_cbad, d_cref])
    mean, mx = diff(img, ref)
    t.check(mean < 0.05 and mx <= 2, "NaN/Inf cells: image equals the mesh without those cells "
            "(mean |diff| %.4f/255, max %.0f)" % (mean, mx))


def case_empty():
    """Empty grids: nothing to draw is not an error; the frame is the background. The skipped
    count must describe the current input, not a previous one."""
    view = make_view()
    empty = vtkUnstructuredGrid()
    empty.SetPoints(vtkPoints())
    a = numpy_to_vtk(np.zeros(0), deep=1)
    a.SetName("f")
    empty.GetPointData().SetScalars(a)
    # Points but no cells.
    p = box_points(3)
    pointsonly = make_grid(p, np.zeros((0, 4), dtype=np.int64), point_scalars=field(p))
    # A real pipeline producing nothing: a threshold that selects no cell.
    src, arr = data.wavelet(5)
    thr = simple.Threshold(Input=src, Scalars=["POINTS", arr])
    thr.LowerThreshold = 1e6
    thr.UpperThreshold = 2e6
    thr.UpdatePipeline()
    for name, source in (("empty grid", producer(empty)), ("points, no cells", producer(pointsonly)),
                         ("threshold selecting nothing", thr)):
        m = MSG.mark()
        d = simple.Show(source, view)
        arrname = arr if source is thr else "f"
        simple.ColorBy(d, ("POINTS", arrname))
        d.SetRepresentationType("Psi Volume")
        simple.Render(view)
        img = testing.grab(view)
        ntets, skipped = info(d)
        errs = MSG.since(m, "ErrorEvent")
        t.check(not errs, "%s: no error%s" % (name, (": " + short(errs[0])) if errs else ""))
        t.check(testing.covered(img, BG) == 0 and np.isfinite(img).all(),
                "%s: the frame is the background" % name)
        t.check(ntets == 0 and skipped == 0, "%s: 0 tetrahedra, 0 skipped (%d, %d)"
                % (name, ntets, skipped))
        simple.Hide(source, view)

    # The same representation, first with NaN cells, then with an empty input.
    n = 4
    p = box_points(n)
    tets = box_tets(n)
    cg = field(p)[tets].mean(axis=1)
    cg[::7] = np.nan
    grid = make_grid(p, tets, cell_scalars=cg)
    tp = producer(grid)
    d = show(tp, view, "f", "CELLS", rng=(0.0, 1.0))
    view.ResetCamera()
    simple.Render(view)
    _, skipped = info(d)
    before = testing.covered(testing.grab(view), BG)
    t.check(skipped == len(tets[::7]) and before > 0, "NaN cells before emptying: %d skipped, %d "
            "pixels covered" % (skipped, before))
    empty2 = make_grid(np.zeros((0, 3)), np.zeros((0, 4), dtype=np.int64),
                       cell_scalars=np.zeros(0))
    tp.GetClientSideObject().SetOutput(empty2)
    tp.MarkModified(tp)
    tp.UpdatePipeline()
    simple.Render(view)
    img = testing.grab(view)
    ntets, skipped = info(d)
    t.check(testing.covered(img, BG) == 0, "input emptied: the frame is the background")
    t.check(ntets == 0, "input emptied: NumberOfTetrahedra is 0 (%d)" % ntets)
    t.check(skipped == 0, "input emptied: NumberOfSkippedCells is 0, not the previous input's "
            "count (%d)" % skipped)


def case_degenerate():
    """Inverted tetrahedra render like positively oriented ones; zero-volume tetrahedra (repeated
    vertex, four coplanar points, all four points equal) add nothing and produce no NaN."""
    n = 12
    p = box_points(n)
    tets = box_tets(n)
    f = field(p)
    rng = (float(f.min()), float(f.max()))
    inv = tets.copy()
    inv[0::2, [0, 1]] = inv[0::2, [1, 0]]  # every other tetrahedron inverted
    allinv = tets[:, [1, 0, 2, 3]]
    m1 = n + 1
    rs = np.random.RandomState(7)
    base = rs.randint(0, n, size=(600, 3))
    b = base[:, 0] + base[:, 1] * m1 + base[:, 2] * m1 * m1
    coplanar = np.column_stack([b, b + 1, b + 1 + m1, b + m1])            # a square's corners
    collinear = np.column_stack([b, b + 1, b + 1, b])                      # repeated vertices
    collapsed = np.column_stack([b, b, b, b])                              # one point
    degenerate = np.vstack([tets, coplanar, collinear, collapsed])
    view = make_view()
    grids = [("reference", tets), ("half inverted", inv), ("all inverted", allinv),
             ("with %d zero-volume tetrahedra" % (3 * len(b)), degenerate)]
    ds = [show(producer(make_grid(p, c, point_scalars=f)), view, "f", rng=rng, unit=0.15)
          for _, c in grids]
    aim(view, [0, 1, 0, 1, 0, 1])
    ref = render_only(view, ds[0], ds)
    check_image(ref, "reference", 0.3)
    for (name, cells), d in zip(grids[1:], ds[1:]):
        m = MSG.mark()
        img = render_only(view, d, ds)
        ntets, skipped = info(d)
        errs = MSG.since(m, "ErrorEvent")
        t.check(not errs, "%s: no error%s" % (name, (": " + short(errs[0])) if errs else ""))
        t.check(np.isfinite(img).all(), "%s: finite image" % name)
        mean, mx = diff(img, ref)
        print("%s: %d tetrahedra drawn, %d skipped, mean |diff| %.4f/255, max %.0f"
              % (name, ntets, skipped, mean, mx))
        t.check(mean < 0.1 and mx <= 3, "%s: image equals the positively oriented mesh (mean "
                "|diff| %.4f/255 < 0.1, max %.0f <= 3)" % (name, mean, mx))


def case_quadratic():
    """Quadratic (10-node) tetrahedra with cell data only (the FEA jaw): tetrahedralized on the way
    in, rendered with the cell array; compared with ParaView's 'Projected tetra'."""
    path = os.path.join(DATA, "fea_kiefer_dataset.vtu")
    need(path)
    r = simple.XMLUnstructuredGridReader(FileName=[path])
    r.UpdatePipeline()
    ncells = r.GetDataInformation().GetNumberOfCells()
    arr = r.CellData.keys()[0]
    t.check(len(r.PointData.keys()) == 0, "quadratic: the file has cell data only (%s)" % arr)
    crng = r.CellData[arr].GetRange(0)
    view = make_view()
    m = MSG.mark()
    d = show(r, view, arr, "CELLS", rng=crng)
    view.ResetCamera()
    c = view.GetActiveCamera()
    c.Azimuth(30)
    c.Elevation(20)
    view.ResetCamera()
    t0 = time.time()
    img = render_only(view, d, [d])
    print("quadratic: Psi Volume frame %.2f s" % (time.time() - t0))
    ntets, skipped = info(d)
    for s in MSG.since(m):
        print("    message: " + short(s))
    errs = MSG.since(m, "ErrorEvent")
    t.check(not errs, "quadratic: no error%s" % ((": " + short(errs[0])) if errs else ""))
    check_image(img, "quadratic", 0.02)
    t.check(skipped == 0, "quadratic: no cell skipped (%d)" % skipped)
    t.check(ntets >= ncells, "quadratic: %d quadratic tetrahedra drawn as %d linear ones"
            % (ncells, ntets))
    d_pt = show(r, view, arr, "CELLS", rng=crng, representation="Volume")
    d_pt.SelectMapper = "Projected tetra"
    d.Visibility = 0
    ptimg = render_only(view, d_pt, [d_pt])
    mean, mx = diff(img, ptimg)
    print("quadratic vs Projected tetra: mean %.3f/255 max %.0f" % (mean, mx))
    t.check(mean < 3.0, "quadratic: agrees with ParaView's 'Projected tetra' (mean |diff| "
            "%.3f/255 < 3)" % mean)


def case_multiblock():
    """A multiblock of two tetrahedral blocks renders like the merged mesh."""
    n = 12
    p = box_points(n)
    tets = box_tets(n)
    f = field(p)
    rng = (float(f.min()), float(f.max()))
    cx = p[tets].mean(axis=1)[:, 0]
    left, right = tets[cx < 0.5], tets[cx >= 0.5]
    a = producer(make_grid(p, left, point_scalars=f))
    b = producer(make_grid(p, right, point_scalars=f))
    group = simple.GroupDatasets(Input=[a, b])
    group.UpdatePipeline()
    whole = producer(make_grid(p, tets, point_scalars=f))
    view = make_view()
    m = MSG.mark()
    d_mb = simple.Show(group, view)
    t.check("Psi Volume" in d_mb.Representation.Available,
            "multiblock: 'Psi Volume' is offered (%s)" % d_mb.Representation.Available)
    d_mb = show(group, view, "f", rng=rng, unit=0.15)
    d_ref = show(whole, view, "f", rng=rng, unit=0.15)
    aim(view, [0, 1, 0, 1, 0, 1])
    img = render_only(view, d_mb, [d_mb, d_ref])
    ntets, skipped = info(d_mb)
    for s in MSG.since(m):
        print("    message: " + short(s))
    errs = MSG.since(m, "ErrorEvent")
    t.check(not errs, "multiblock: no error%s" % ((": " + short(errs[0])) if errs else ""))
    check_image(img, "multiblock", 0.3)
    t.check(ntets == len(tets), "multiblock: all %d tetrahedra of both blocks drawn (%d)"
            % (len(tets), ntets))
    ref = render_only(view, d_ref, [d_mb, d_ref])
    mean, mx = diff(img, ref)
    t.check(mean < 0.05 and mx <= 2, "multiblock: image equals the merged mesh (mean |diff| "
            "%.4f/255, max %.0f)" % (mean, mx))


def case_large():
    """More tetrahedra than one draw call (the mapper draws chunks of 4M = 4,194,304): a 95^3
    Kuhn grid, 5,144,250 tetrahedra, against a 40^3 grid of the same field."""
    n, nref = 95, 40
    p = box_points(n)
    f = field(p)
    tets = box_tets(n)
    t.check(len(tets) > (1 << 22), "large: %d tetrahedra > one chunk of %d" % (len(tets), 1 << 22))
    big = make_grid(p, tets, point_scalars=f)
    del tets
    pr = box_points(nref)
    fr = field(pr)
    small = make_grid(pr, box_tets(nref), point_scalars=fr)
    rng = (float(fr.min()), float(fr.max()))
    view = make_view()
    d_big = show(producer(big), view, "f", rng=rng, unit=0.15)
    d_small = show(producer(small), view, "f", rng=rng, unit=0.15)
    aim(view, [0, 1, 0, 1, 0, 1])
    m = MSG.mark()
    t0 = time.time()
    img = render_only(view, d_big, [d_big, d_small])
    view.GetRenderWindow().WaitForCompletion()
    secs = time.time() - t0
    ntets, skipped = info(d_big)
    print("large: %d tetrahedra drawn in %.1f s (first frame, with upload)" % (ntets, secs))
    errs = MSG.since(m, "ErrorEvent")
    t.check(not errs, "large: no error%s" % ((": " + short(errs[0])) if errs else ""))
    t.check(ntets == big.GetNumberOfCells(), "large: all %d tetrahedra drawn (%d)"
            % (big.GetNumberOfCells(), ntets))
    check_image(img, "large", 0.3)
    ref = render_only(view, d_small, [d_big, d_small])
    mean, mx = diff(img, ref)
    print("large vs 40^3 grid: mean %.3f/255 max %.0f" % (mean, mx))
    t.check(mean < 1.0, "large: image matches the coarse grid of the same field (mean |diff| "
            "%.3f/255 < 1)" % mean)


def case_reader():
    """The tetrahedral OFF reader from ParaView's file dialog path: a valid file renders, a
    malformed one gives an error naming the line and an empty output."""
    d = tempfile.mkdtemp()
    good = os.path.join(d, "good.off")
    bad = os.path.join(d, "bad.off")
    n = 6
    p = box_points(n)
    tets = box_tets(n)
    f = field(p)
    with open(good, "w") as fh:
        fh.write("# generated by test_bad_input.py\n%d %d\n" % (len(p), len(tets)))
        for q, s in zip(p, f):
            fh.write("%.9g %.9g %.9g %.9g\n" % (q[0], q[1], q[2], s))
        for c in tets:
            fh.write("%d %d %d %d\n" % tuple(c))
    with open(bad, "w") as fh:
        fh.write("5 1\n0 0 0 0\n1 0 0 1\n0 1 0 2\n0 0 1 3\n1 1 1 4\n0 1 2 7\n")
    r = simple.OpenDataFile(good)
    t.check(r is not None and r.GetXMLName() == "PsiOFFTetReader",
            "reader: .off opens with the tetrahedral OFF reader (%s)"
            % (r.GetXMLName() if r else None))
    if r is None:
        return
    r.UpdatePipeline()
    t.check(r.GetDataInformation().GetNumberOfCells() == len(tets), "reader: %d tetrahedra read"
            % r.GetDataInformation().GetNumberOfCells())
    view = make_view()
    dd = show(r, view, "scalars", unit=0.15)
    aim(view, [0, 1, 0, 1, 0, 1])
    img = render_only(view, dd, [dd])
    check_image(img, "reader", 0.3)
    m = MSG.mark()
    rb = simple.OpenDataFile(bad)
    rb.UpdatePipeline()
    errs = MSG.since(m, "ErrorEvent", "out of range")
    for s in errs:
        print("    message: " + short(s))
    t.check(len(errs) > 0 and "line 7" in errs[0], "reader: a malformed file gives an error naming "
            "the line")
    t.check(rb.GetDataInformation().GetNumberOfCells() == 0, "reader: and an empty output")
    check_compact_file(d, view)
    check_off_reader_choice(good, bad, d)


def check_compact_file(d, view):
    """A literature-style file as compact as the format allows (single-digit values, single
    spaces, no newline after the last line: the least the reader's size check accepts) draws as
    the same mesh written out in full: the unit cube's corners, scalar = corner id, in 6 Kuhn
    tetrahedra."""
    corners = [(i & 1, i >> 1 & 1, i >> 2 & 1, i) for i in range(8)]
    tets = [(0, 1, 3, 7), (0, 1, 5, 7), (0, 2, 3, 7), (0, 2, 6, 7), (0, 4, 5, 7), (0, 4, 6, 7)]
    compact = "8 6\n" + "\n".join("%d %d %d %d" % r for r in corners + tets)
    full = "# the same mesh in full\n8 6\n" + "".join(
        "%.6f %.6f %.6f %.6f\n" % r for r in corners) + "".join("%d %d %d %d\n" % c for c in tets)
    for src in simple.GetSources().values():
        simple.Hide(src, view)
    images = []
    for name, text in (("compact.off", compact), ("full.off", full)):
        path = os.path.join(d, name)
        with open(path, "w") as fh:
            fh.write(text)
        r = simple.OpenDataFile(path)
        r.UpdatePipeline()
        cells = r.GetDataInformation().GetNumberOfCells()
        t.check(cells == 6, "reader: %s, 6 tetrahedra read (%d)" % (name, cells))
        dd = show(r, view, "scalars", rng=[0.0, 7.0], unit=0.5)
        aim(view, [0, 1, 0, 1, 0, 1])
        images.append(render_only(view, dd, [dd]))
        simple.Hide(r, view)
        check_image(images[-1], "reader: " + name, 0.1)
    mean, mx = diff(images[0], images[1])
    t.check(mx == 0, "reader: the compact file draws as the full one (mean %.3f/255, max %.0f)"
            % (mean, mx))


def possible_readers(path):
    """The readers ParaView's reader factory offers for a file, by its extension and each reader's
    CanReadFile: the GUI's File > Open (pqLoadDataReaction::DetermineFileReader) opens the "choose
    a reader" dialog when there is more than one, or none."""
    from paraview import servermanager
    factory = servermanager.vtkSMProxyManager.GetProxyManager().GetReaderFactory()
    found = factory.GetReaders(path, servermanager.ActiveConnection.Session)
    return [found.GetString(i + 1) for i in range(0, found.GetLength(), 3)]


def check_off_reader_choice(good, bad, d):
    """Each .off file has exactly one reader: tetrahedral meshes (well formed or not) this
    plugin's, polygonal surfaces ParaView's own (5.13 and later; 5.11 has no surface OFF reader)."""
    surface = os.path.join(d, "surface.off")
    with open(surface, "w") as fh:
        fh.write("OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n")
    for path in (good, bad):
        t.check(possible_readers(path) == ["PsiOFFTetReader"], "reader: %s has one reader, the "
                "tetrahedral one (%s)" % (os.path.basename(path), possible_readers(path)))
    from paraview import servermanager
    sm = servermanager.vtkSMProxyManager
    if (sm.GetVersionMajor(), sm.GetVersionMinor()) < (5, 13):
        t.check(possible_readers(surface) == [], "reader: a surface .off file is not offered to the "
                "tetrahedral reader (%s)" % possible_readers(surface))
        return
    t.check(possible_readers(surface) == ["offreader"], "reader: a surface .off file has one "
            "reader, ParaView's own (%s)" % possible_readers(surface))
    rs = simple.OpenDataFile(surface)
    t.check(rs is not None and rs.GetXMLName() == "offreader", "reader: a surface .off file "
            "opens with ParaView's OFF reader (%s)" % (rs.GetXMLName() if rs else None))
    if rs is not None:
        rs.UpdatePipeline()
        info = rs.GetDataInformation()
        t.check(info.GetNumberOfCells() == 4 and info.GetNumberOfPoints() == 4,
                "reader: the surface read, 4 triangles on 4 points (%d, %d)"
                % (info.GetNumberOfCells(), info.GetNumberOfPoints()))


def case_unitdistance():
    """ScalarOpacityUnitDistance 0 or -1 has no optical meaning (opacity per unit distance): the
    volume is not drawn, as with 'Projected tetra', and a warning names the value; a positive
    distance draws again."""
    n = 8
    p = box_points(n)
    tets = box_tets(n)
    f = field(p)
    view = make_view()
    d = show(producer(make_grid(p, tets, point_scalars=f)), view, "f", unit=0.15)
    aim(view, [0, 1, 0, 1, 0, 1])
    good = render_only(view, d, [d])
    check_image(good, "unit distance 0.15", 0.3)
    for unit in (0.0, -1.0):
        d.ScalarOpacityUnitDistance = unit
        m = MSG.mark()
        img = render_only(view, d, [d])
        warns = MSG.since(m, "WarningEvent", "unit distance")
        for s in warns:
            print("    message: " + short(s))
        cov = testing.covered(img, BG)
        t.check(cov == 0, "unit distance %g: nothing drawn (%d pixels covered)" % (unit, cov))
        t.check(len(warns) == 1, "unit distance %g: one warning names it (%d)" % (unit, len(warns)))
        m = MSG.mark()
        render_only(view, d, [d])
        t.check(not MSG.since(m, "WarningEvent", "unit distance"),
                "unit distance %g: the warning is not repeated every frame" % unit)
    d.ScalarOpacityUnitDistance = 0.15
    again = render_only(view, d, [d])
    t.check(diff(again, good)[1] == 0, "unit distance 0.15 again: the same image")


def case_outofrange():
    """Integer settings outside their values, as the server manager lets them through (it does
    not check enumeration domains): each is clamped, with a warning naming it, and the image is
    the clamped value's."""
    n = 8
    p = box_points(n)
    tets = box_tets(n)
    view = make_view()
    d = show(producer(make_grid(p, tets, point_scalars=field(p))), view, "f", unit=0.15)
    aim(view, [0, 1, 0, 1, 0, 1])
    # one way fixed: under 'Auto' the frames of a measurement may draw others (within 1/255)
    d.EarlyRayTermination, d.Projector, d.Decomposition = "Off", "Geometry Shader", "Silhouette"
    for name, bad, clamped in (("IntegrationMethod", 99, 6), ("IntegrationMethod", -3, 0),
                               ("SortMethod", 7, 1), ("AdaptiveSampling", 5, 2),
                               ("IsosurfaceMethod", -1, 0), ("IsosurfaceShading", 9, 2)):
        d.GetProperty(name).SetElement(0, clamped)
        d.UpdateVTKObjects()
        ref = render_only(view, d, [d])
        d.GetProperty(name).SetElement(0, bad)
        m = MSG.mark()
        d.UpdateVTKObjects()
        img = render_only(view, d, [d])
        warns = MSG.since(m, "WarningEvent", name)
        for s in warns:
            print("    message: " + short(s))
        t.check(len(warns) >= 1 and str(bad) in warns[0],
                "%s = %d: a warning names it (%d)" % (name, bad, len(warns)))
        t.check(diff(img, ref)[1] == 0, "%s = %d draws as %d" % (name, bad, clamped))
        d.GetProperty(name).SetElement(0, clamped)
        d.UpdateVTKObjects()


CASES = {
    "nontet": case_nontet,
    "surface": case_surface,
    "cellscalars": case_cellscalars,
    "nonfinite": case_nonfinite,
    "empty": case_empty,
    "degenerate": case_degenerate,
    "quadratic": case_quadratic,
    "multiblock": case_multiblock,
    "large": case_large,
    "reader": case_reader,
    "unitdistance": case_unitdistance,
    "outofrange": case_outofrange,
}

if __name__ == "__main__":
    names = [a for a in sys.argv[1:] if not a.startswith("-")] or list(CASES)
    unknown = [n for n in names if n not in CASES]
    if unknown:
        print("unknown case(s) %s; cases: %s" % (unknown, " ".join(CASES)))
        testing.exit_now(2)
    # pvpython replaces sys.stderr with an object without a file descriptor.
    err = open(os.devnull if sys.__stderr__ is None else "/dev/stderr", "w")
    faulthandler.enable(file=err)
    faulthandler.dump_traceback_later(CASE_TIMEOUT * len(names), exit=True, file=err)
    data.load_plugin(globals(), os.environ.get("PSI_PLUGIN"))
    for name in names:
        print("== case %s" % name)
        t0 = time.time()
        CASES[name]()
        print("== case %s: %.1f s" % (name, time.time() - t0))
    faulthandler.cancel_dump_traceback_later()
    t.finish()
