"""The accuracy report on the user's own scene, one case per run (PsiPython.report_scene.<case>):
  settings  the report (psivolume.gui.run_report and psivolume.accuracy.report) leaves the scene
            as it found it: the display's settings, its color and opacity maps, the view's, its
            camera, the other representations' visibility and the active source; after a report,
            after one whose reference renderer fails, after one that fails in its timing rounds
  names     arrays named with a space, with non-ASCII letters, with quotes, a backslash and
            dollar signs (matplotlib's math in the plot's title): the report runs, and its
            reference is the image of that array (the same as the image of the same values under
            a plain name; 'Psi Volume' close to it)
  cells     a point array and a cell array of one name, the display colored by the cell array:
            the reference draws the cell array ('Psi Volume', which honours the association, is
            close to it; the point array's reference is far from it)
  failure   a failure of the exact reference renderer raises one line that names it and gives
            its reason (the last line it wrote to stderr)
  volumes   a view with two volumes (the second another array with its own color map, on
            'Volume', placed by the display's Position where it shares no space with the first
            but overlaps it on screen): the report measures the whole image ('Psi Volume' draws
            both intermixed, close to the reference of both; ParaView's mapper draws both, the
            reference's footprint); both displays left as they were

    pvpython --force-offscreen-rendering test_report_scene.py CASE"""
import os
import stat
import sys
import tempfile

import numpy as np
from paraview import simple

from psivolume import accuracy, data, gui, testing, timing

checks = testing.Checks("report_scene")
SIZE = 64
# The test's reference renderer (its ENVIRONMENT; none named: the one beside the plugin).
REFERENCE = os.environ.get("PSI_REFERENCE_RENDER")
# The report as fast as it goes: one timing round, no child pvpython.
FAST = dict(frames=1, budget=0.1, paraview_mappers=[], resample_dims=[],
            reference_renderer=REFERENCE)
FAKE_REASON = "fake renderer: the mesh has no cells"


# ------------------------------------------------------------------------------ the scene's state
def property_values(proxy):
    """{name: value} of `proxy`'s properties, information-only ones left out (proxies by id)."""
    values = {}
    for name in proxy.ListProperties():
        p = proxy.GetProperty(name).SMProperty
        if p.GetInformationOnly():
            continue
        if p.IsA("vtkSMProxyProperty"):
            values[name] = tuple(p.GetProxy(i).GetGlobalIDAsString() if p.GetProxy(i) else None
                                 for i in range(p.GetNumberOfProxies()))
        elif p.IsA("vtkSMVectorProperty"):
            values[name] = tuple(p.GetElement(i) for i in range(p.GetNumberOfElements()))
    return values


def camera_state(view):
    c = view.GetActiveCamera()
    return (c.GetPosition(), c.GetFocalPoint(), c.GetViewUp(), c.GetViewAngle(),
            c.GetParallelScale(), c.GetParallelProjection())


def state(view, rep):
    """What a user sees of the scene, by part."""
    s = {"display " + k: v for k, v in property_values(rep).items()}
    s.update({"color map " + k: v for k, v in property_values(rep.LookupTable).items()})
    s.update({"opacity map " + k: v
              for k, v in property_values(rep.ScalarOpacityFunction).items()})
    s.update({"view " + k: v for k, v in property_values(view).items()})
    s["camera"] = camera_state(view)
    s["visible representations"] = tuple(
        r.GetGlobalIDAsString() for r in view.Representations
        if r.GetProperty("Visibility") is not None and r.Visibility)
    active = simple.GetActiveSource()
    s["active source"] = active.GetGlobalIDAsString() if active else None
    return s


def changed_by_rendering(view, rep):
    """The parts of state() that a still and an interactive render alone change: not settings."""
    before = state(view, rep)
    simple.Render(view)
    view.InteractiveRender()
    simple.Render(view)
    after = state(view, rep)
    return {k for k in before if before[k] != after.get(k)}


def check_same(before, after, ignored, what):
    if ignored:
        print("        (%s: not compared, changed by rendering alone: %s)"
              % (what, ", ".join(sorted(ignored))))
    diff = ["%s: %s -> %s" % (k, before[k], after.get(k)) for k in sorted(before)
            if k not in ignored and before[k] != after.get(k)]
    checks.check(not diff, "%s: the scene as it was%s" % (
        what, "" if not diff else "; changed: " + "; ".join(d[:160] for d in diff)))


# ------------------------------------------------------------------------------ scenes
def user_scene(src, array, association="POINTS", size=SIZE, rescale=True):
    """`src` shown in a size x size view as 'Psi Volume' colored by (association, array) (its
    maps rescaled to the array's range with `rescale`), the camera turned, no orientation axes."""
    view = simple.CreateRenderView()
    view.ViewSize = [size, size]
    view.OrientationAxesVisibility = 0  # not in the reference (psivolume.gui hides them)
    rep = simple.Show(src, view)
    simple.ColorBy(rep, (association, array))
    rep.SetRepresentationType("Psi Volume")
    if rescale:
        rep.RescaleTransferFunctionToDataRange(True, False)
    view.ResetCamera()
    view.GetActiveCamera().Azimuth(40)
    view.GetActiveCamera().Elevation(15)
    view.ResetCamera()
    simple.SetActiveView(view)
    simple.SetActiveSource(src)
    return view, rep


def user_settings(rep):
    """Settings a user may have chosen, none of them the report's own."""
    rep.IntegrationMethod = "Linear Exact"
    rep.AdaptiveSampling = "On"
    modes = list(rep.GetProperty("InteractionMode").Available)
    rep.InteractionMode = [m for m in modes if m != rep.InteractionMode][-1]
    rep.ScalarOpacityUnitDistance = 2.5


def failing_renderer(folder):
    """A reference renderer that writes two lines to stderr and exits 2."""
    path = os.path.join(folder, "failing_renderer.sh")
    with open(path, "w") as f:
        f.write("#!/bin/sh\necho 'reading the mesh' >&2\necho '%s' >&2\nexit 2\n" % FAKE_REASON)
    os.chmod(path, os.stat(path).st_mode | stat.S_IXUSR)
    return path


class FailingFrames:
    """timing.frame failing at its `n`-th call while the block runs: the report fails in its
    timing rounds, the camera turned and a method set."""

    def __init__(self, n):
        self.n, self.calls = n, 0

    def __enter__(self):
        self.frame = timing.frame

        def frame(*args, **kw):
            self.calls += 1
            if self.calls >= self.n:
                raise RuntimeError("a frame failed")
            return self.frame(*args, **kw)

        timing.frame = frame

    def __exit__(self, *exc):
        timing.frame = self.frame


def raises(run):
    """The exception `run()` raises, or None."""
    try:
        run()
    except Exception as e:  # noqa: BLE001 (which one is part of what is checked)
        return e
    return None


def under(context, run):
    """`run` to be run inside `context`."""
    def run_under():
        with context:
            run()
    return run_under


def check_kept(what, view, rep, run, fails=False):
    """`run()`, a report on `view`'s `rep`, runs (or with `fails` raises); the scene as it was."""
    ignored = changed_by_rendering(view, rep)
    before = state(view, rep)
    e = raises(run)
    checks.check((e is not None) == fails, "%s %s: %r" % (what, "raises" if fails else "runs", e))
    check_same(before, state(view, rep), ignored, what)


# ------------------------------------------------------------------------------ the cases
def settings_scene(src, array, representation="Psi Volume"):
    """The user's scene with settings of their own, an outline beside, the orientation axes."""
    view, rep = user_scene(src, array)
    simple.Show(simple.Outline(Input=src), view)
    simple.SetActiveSource(src)
    view.OrientationAxesVisibility = 1
    user_settings(rep)
    if representation != "Psi Volume":
        rep.SetRepresentationType(representation)
    simple.Render(view)
    return view, rep


def case_settings(work):
    src, array = data.wavelet(3)
    reports = {
        "gui.run_report": lambda view, rep, **o: lambda: gui.run_report(
            view, src, os.path.join(work, "gui"), **dict(FAST, **o)),
        "accuracy.report": lambda view, rep, **o: lambda: accuracy.report(
            view, rep, src, os.path.join(work, "report"), **dict(FAST, **o))}
    for name, report in reports.items():
        view, rep = settings_scene(src, array)
        check_kept(name, view, rep, report(view, rep))
        # the display on 'Volume', its reference renderer failing (after the switch to 'Psi Volume')
        view, rep = settings_scene(src, array, "Volume")
        check_kept(name + ", its reference renderer failing", view, rep,
                   report(view, rep, reference_renderer=failing_renderer(work)), fails=True)
        # failing in the timing rounds, a method set and the camera turned meanwhile
        view, rep = settings_scene(src, array)
        check_kept(name + ", failing in its timing rounds", view, rep,
                   under(FailingFrames(2), report(view, rep)), fails=True)
    # a composite source (the report merges its blocks with a filter of ParaView's)
    group = simple.GroupDatasets(Input=[src])
    view, rep = user_scene(group, array)
    user_settings(rep)
    check_kept("accuracy.report on a multiblock", view, rep, lambda: accuracy.report(
        view, rep, group, os.path.join(work, "group"), **FAST))


def reference_of(view, rep, src, work):
    """The exact reference image of the display's scene, as the report renders it."""
    folder = tempfile.mkdtemp(dir=work)
    images, _ = accuracy.reference_image(accuracy.Capture(view, rep, src, folder), REFERENCE,
                                         runs=1)
    return images[0]


def reference_and_report(view, rep, src, work, folder, label):
    """The exact reference image and the report's rows on the scene; a failure of either is a
    failed check (the reference then None, the rows empty)."""
    ref = None
    try:
        ref = reference_of(view, rep, src, work)
        return ref, accuracy.report(view, rep, src, os.path.join(work, folder), **FAST)
    except Exception as e:  # noqa: BLE001
        checks.check(False, "%sthe report runs: %s: %s" % (label, type(e).__name__, e))
        return ref, []


def row_errors(rows, name):
    r = {row["name"]: row for row in rows}.get(name) or {}
    return r.get("mean", float("nan")), r.get("max", float("nan"))


def case_names(work):
    """The report on arrays of odd names holding RTData: the same images as RTData's own."""
    src, _ = data.wavelet(3)
    view, rep = user_scene(src, "RTData", size=96)
    plain = reference_of(view, rep, src, work)
    for name in ("my f", "Dichte \u03c1 (\u00e9t\u00e9)", 'a "b" \\ c $^$'):
        named = simple.Calculator(Input=src, ResultArrayName=name, Function="RTData")
        view, rep = user_scene(named, name, size=96)
        ref, rows = reference_and_report(view, rep, named, work, "names", "array %r: " % name)
        if ref is not None:
            d = float(np.abs(ref - plain).max())
            checks.check(d == 0, "array %r: the reference is RTData's (max |diff| %g)" % (name, d))
        mean, mx = row_errors(rows, "Partial Pre-Integration + adaptive")
        checks.check(mean < 1 and mx < 2, "array %r: 'Psi Volume' close to the reference (mean "
                     "%.3f, max %.1f)" % (name, mean, mx))


def same_name_scene():
    """Point f = x; its cell averages; cell f = -(those): one name, two associations."""
    tets = simple.Tetrahedralize(Input=simple.Wavelet(WholeExtent=[-4, 4, -4, 4, -4, 4]))
    points = simple.Calculator(Input=tets, ResultArrayName="f", Function="coordsX")
    cells = simple.PointDatatoCellData(Input=points)
    cells.PassPointData = 1
    negated = simple.Calculator(Input=cells, AttributeType="Cell Data", ResultArrayName="f",
                                Function="-f")
    negated.UpdatePipeline()
    return negated


def case_cells(work):
    src = same_name_scene()
    view, rep = user_scene(src, "f", "CELLS", size=96)
    checks.check(list(rep.ColorArrayName) == ["CELLS", "f"], "colored by the cell array f")
    simple.Render(view)
    still = testing.grab(view)
    ref, rows = reference_and_report(view, rep, src, work, "cells", "")
    if ref is not None:
        e = float(np.abs(still - ref).mean())
        drawn = testing.covered(ref, view.GetRenderer().GetBackground())
        checks.check(drawn > 1000, "the reference draws the volume (%d pixels)" % drawn)
        checks.check(e < 1, "the reference is the still frame's cell array (mean |diff| %.3f)" % e)
    for method in ("Average", "Partial Pre-Integration + adaptive"):
        mean, mx = row_errors(rows, method)
        checks.check(mean < 1, "the report: '%s' close to the reference (mean %.3f, max %.1f)"
                     % (method, mean, mx))
    # (one color map per name: the point array's reference is drawn with the cells' map)
    view, rep = user_scene(src, "f", "POINTS", size=96, rescale=False)
    point_ref = reference_of(view, rep, src, work)
    if ref is not None:
        d = float(np.abs(point_ref - ref).mean())
        checks.check(d > 5, "the point array's reference differs (mean |diff| %.1f)" % d)


def check_one_line(e, reasons, what):
    text = str(e)
    checks.check(isinstance(e, RuntimeError) and "\n" not in text.strip()
                 and "exact reference renderer" in text and all(r in text for r in reasons),
                 "%s: one line naming the exact reference renderer and %s: %s: %r"
                 % (what, " and ".join(map(repr, reasons)), type(e).__name__, text))


def case_failure(work):
    src, array = data.wavelet(3)
    view, rep = user_scene(src, array)
    cap = accuracy.Capture(view, rep, src, work)
    failing = failing_renderer(work)
    check_one_line(raises(lambda: accuracy.reference_image(cap, failing)), [FAKE_REASON],
                   "a failing renderer")
    check_one_line(raises(lambda: gui.run_report(view, src, work, **dict(
        FAST, reference_renderer=failing))), [FAKE_REASON], "the report, its renderer failing")
    os.remove(cap.mesh)  # the real renderer, its mesh file gone
    check_one_line(raises(lambda: accuracy.reference_image(cap, REFERENCE)), [cap.mesh],
                   "psi_reference_render without its mesh")
    absent = os.path.join(work, "absent_renderer")
    check_one_line(raises(lambda: accuracy.reference_image(cap, absent)), ["absent_renderer"],
                   "a renderer that is not there")


def case_volumes(work):
    src, array = data.wavelet(3)
    view, rep = user_scene(src, array, size=96)
    other = simple.Calculator(Input=src, ResultArrayName="other", Function="400-%s" % array)
    second = data.show_volume(other, "other", view, representation="Volume")
    testing.apply_preset(simple.GetColorTransferFunction("other"), "Viridis (matplotlib)",
                         "Viridis")
    # apart in depth, overlapping the first on screen
    data.display_translation(second).SetData([4.0, 2.5, 7.0])
    view.ResetCamera()
    simple.SetActiveSource(src)
    simple.Render(view)
    alone = reference_of(view, rep, src, work)  # the first volume's alone
    ignored = changed_by_rendering(view, second)
    before = state(view, second)
    rows = []
    try:
        rows = accuracy.report(view, rep, src, os.path.join(work, "volumes"),
                               **dict(FAST, paraview_mappers=["Projected tetra"]))
    except Exception as e:  # noqa: BLE001
        checks.check(False, "two volumes: the report runs: %s: %s" % (type(e).__name__, e))
    check_same(before, state(view, second), ignored, "two volumes: the second display")
    checks.check(second.Representation == "Volume" and
                 list(data.display_translation(second)) == [4.0, 2.5, 7.0],
                 "two volumes: the second display on 'Volume' at its place again")
    mean, mx = row_errors(rows, "Partial Pre-Integration")
    checks.check(mean < 1, "two volumes: 'Psi Volume' draws both, close to the reference of "
                 "both (mean %.3f, max %.1f)" % (mean, mx))
    displays = accuracy.volume_displays(view, rep, src)
    cap = accuracy.volume_captures(view, displays, tempfile.mkdtemp(dir=work))
    both = accuracy.reference_image(cap, REFERENCE, runs=1)[0][0]
    bg = view.GetRenderer().GetBackground()
    checks.check(len(displays) == 2 and testing.covered(both, bg) > 1.3 * testing.covered(alone, bg),
                 "two volumes: the reference draws both (%d displays; %d pixels, the first alone "
                 "%d)" % (len(displays), testing.covered(both, bg), testing.covered(alone, bg)))
    pv = {r["name"]: r for r in rows}.get("ParaView Projected tetra", {})
    checks.check(pv.get("mean", float("nan")) < 10, "two volumes: ParaView's mapper drew both "
                 "(mean %.2f from the reference; %s)" % (pv.get("mean", float("nan")),
                                                          pv.get("note") or "no note"))


CASES = dict(settings=case_settings, names=case_names, cells=case_cells, failure=case_failure,
             volumes=case_volumes)

if __name__ == "__main__":
    data.load_plugin(globals(), os.environ.get("PSI_PLUGIN"))
    case = sys.argv[1]
    with tempfile.TemporaryDirectory(prefix="psi_report_scene_") as folder:
        CASES[case](folder)
    checks.finish()
