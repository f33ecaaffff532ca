# Strict pixel check of the active render view, called from the pqevents GUI tests through the
# Python shell (<pqevent object=".../pythonShell/consoleWidget" command="executeCommand" .../>).
#
# Why: ParaView 5.11's own comparison (<pqcompareview>, --test-baseline: vtkTesting with
# vtkImageDifference) ignores every pixel whose best match within +-2 pixels differs by less
# than 105 levels in each channel. Switching the integration method of a volume changes pixels by
# at most ~50 levels, so that comparison passes (error exactly 0) whatever method is drawn. This
# check captures the view the way <pqcompareview> does (ViewSize 300x300, PPI 72,
# CaptureWindow(1)), compares it with the same baseline PNG, and fails when more than MAX_PIXELS
# pixels differ by more than LEVEL in some channel. Same-method replays differ by 0 on llvmpipe.
# A script that compares the view with itself (XML/PsiVolumeGUIIntermixedState.xml) needs no
# baseline: capture writes the reference into the test directory, check reads it from there.
#
# Loaded with runpy.run_path (no __pycache__ in the source tree). The test image is written by the
# project's PNG writer, psivolume.images.write_png (the test's ENVIRONMENT puts the checkout's
# Python/ on the client's PYTHONPATH). Prints one line per check on the process's own
# stdout/stderr (the shell widget's output is not on the console): Testing/GUI.cmake counts
# "PsiGUICheck passed:" lines and fails on "PsiGUICheck FAILED".
import os
import re
import sys

LEVEL = 8  # per-channel difference (0-255) above which a pixel counts as changed
MAX_PIXELS = 150  # of 90000; a method swap changes thousands


def _say(stream, text):
    stream.write(text + "\n")
    stream.flush()


def _capture(size, volumes_only=False):
    """The active view at `size`; with `volumes_only`, without its orientation axes and color
    legends (ParaView 5.13 and later show a legend by default, drawn in each view its own way)."""
    from paraview import simple

    view = simple.GetActiveView()
    if view is None:
        raise RuntimeError("no active view")
    old_size, old_ppi = list(view.ViewSize), view.PPI
    view.ViewSize, view.PPI = list(size), 72
    legends = [r for r in view.Representations if volumes_only and r.Visibility and
               r.GetXMLName().startswith("ScalarBar")]
    axes = volumes_only and view.OrientationAxesVisibility
    for r in legends:
        r.Visibility = 0
    if axes:
        view.OrientationAxesVisibility = 0
    try:
        image = view.SMProxy.CaptureWindow(1)
    finally:
        view.ViewSize, view.PPI = old_size, old_ppi
        for r in legends:
            r.Visibility = 1
        if axes:
            view.OrientationAxesVisibility = 1
    if image is None:
        raise RuntimeError("CaptureWindow returned nothing")
    return image


def _pixels(image):
    from vtkmodules.util.numpy_support import vtk_to_numpy

    dims = image.GetDimensions()
    rgb = vtk_to_numpy(image.GetPointData().GetScalars())[:, :3].astype(int)
    return dims[0], dims[1], rgb


def check(baseline_dir, test_dir, name, test_name=None, level=LEVEL, max_pixels=MAX_PIXELS,
          size=(300, 300), volumes_only=False):
    """Compares the active view with baseline_dir/name.png; writes it to test_dir/test_name.png.
    `volumes_only`: without the view's orientation axes and color legends (_capture)."""
    test_name = test_name or name
    try:
        from vtkmodules.vtkIOImage import vtkPNGReader

        from psivolume.images import write_png

        tw, th, test = _pixels(_capture(size, volumes_only))
        os.makedirs(test_dir, exist_ok=True)
        test_png = os.path.join(test_dir, test_name + ".png")
        write_png(test.reshape(th, tw, 3), test_png)
        baseline_png = os.path.join(baseline_dir, name + ".png")
        if not os.path.exists(baseline_png):
            _say(sys.__stderr__, "PsiGUICheck FAILED: %s: no baseline %s (test image written to %s)"
                 % (name, baseline_png, test_png))
            return False
        reader = vtkPNGReader()
        reader.SetFileName(baseline_png)
        reader.Update()
        bw, bh, base = _pixels(reader.GetOutput())
        if (tw, th) != (bw, bh):
            _say(sys.__stderr__, "PsiGUICheck FAILED: %s: image %dx%d, baseline %dx%d"
                 % (name, tw, th, bw, bh))
            return False
        diff = abs(test - base).max(axis=1)
        changed = int((diff > level).sum())
        summary = "%s: %d pixels differ by more than %d (limit %d), largest difference %d, mean %.3f" \
            % (test_name, changed, level, max_pixels, int(diff.max()), float(diff.mean()))
        if changed > max_pixels:
            _say(sys.__stderr__, "PsiGUICheck FAILED: " + summary + "; test image " + test_png)
            return False
        _say(sys.__stdout__, "PsiGUICheck passed: " + summary)
        return True
    except Exception as error:  # the shell would swallow the traceback
        _say(sys.__stderr__, "PsiGUICheck FAILED: %s: %s: %s" % (name, type(error).__name__, error))
        return False


def capture(test_dir, name, min_covered=0.1, size=(300, 300), volumes_only=False):
    """Writes the active view to test_dir/name.png as the reference that later checks of the same
    session compare with (check(test_dir, test_dir, name, ...)): a script that compares the view
    with itself needs no baseline made by hand. A view that draws next to nothing is no
    reference: fails when fewer than `min_covered` of the pixels differ from the corner pixel
    (the background) by more than LEVEL. Prints "PsiGUICheck captured:" or "PsiGUICheck FAILED"
    (the driver counts only check's lines: a reference that is missing fails the check)."""
    try:
        from psivolume.images import write_png

        width, height, rgb = _pixels(_capture(size, volumes_only))
        covered = float((abs(rgb - rgb[0]).max(axis=1) > LEVEL).mean())
        summary = "%s: %.1f%% of the pixels differ from the background (at least %.1f%%)" \
            % (name, 100 * covered, 100 * min_covered)
        if covered < min_covered:
            _say(sys.__stderr__, "PsiGUICheck FAILED: " + summary)
            return False
        os.makedirs(test_dir, exist_ok=True)
        write_png(rgb.reshape(height, width, 3), os.path.join(test_dir, name + ".png"))
        _say(sys.__stdout__, "PsiGUICheck captured: " + summary)
        return True
    except Exception as error:  # the shell would swallow the traceback
        _say(sys.__stderr__, "PsiGUICheck FAILED: %s: %s: %s" % (name, type(error).__name__, error))
        return False


def check_interaction(expected):
    """Whether the active representation's last interactive frame was drawn by `expected`
    (its LastInteractiveImage read-out: 0 the full frame, 1 the volume level of detail, 2
    ParaView's surface). Prints "PsiGUICheck passed:" or "PsiGUICheck FAILED", as check does."""
    try:
        from paraview import simple

        rep = simple.GetDisplayProperties()
        rep.UpdatePropertyInformation()
        drew = rep.GetProperty("LastInteractiveImage").GetElement(0)
        if drew != expected:
            _say(sys.__stderr__, "PsiGUICheck FAILED: the interactive frames were drawn by %d, "
                 "not %d (LastInteractiveImage)" % (drew, expected))
            return False
        _say(sys.__stdout__, "PsiGUICheck passed: the interactive frames were drawn by %d" % drew)
        return True
    except Exception as e:  # noqa: BLE001 - any error is a failed check, said as such
        _say(sys.__stderr__, "PsiGUICheck FAILED: interaction: %r" % (e,))
        return False


def check_report(source):
    """Whether the accuracy report (the plugin's 'Accuracy report' action) on the source named
    `source` showed its rows: a layout 'Accuracy report: <source>' holding a spreadsheet view of
    the table whose first column ('1 method') names every method of 'Psi Volume' (adaptive sampling off
    and on), the interactive image and the exact reference, in the report's order, and a point
    chart with a series per row. Prints "PsiGUICheck passed:" or "PsiGUICheck FAILED", as check does."""
    try:
        from paraview import servermanager, simple

        src = simple.FindSource(source)
        rep = [servermanager.GetRepresentation(src, v) for v in simple.GetRenderViews()][0]
        methods = list(rep.GetProperty("IntegrationMethod").Available)
        expected = [n for m in methods for n in (m, m + " + adaptive")] + [
            "Psi Volume (interactive)", "Exact reference (CPU)"]
        name = "Accuracy report: " + source
        layout = simple.GetLayoutByName(name)
        table = simple.FindSource(name)
        if layout is None or table is None:
            raise RuntimeError("no layout or table '%s'" % name)
        column = servermanager.Fetch(table).GetColumnByName("1 method")
        names = [column.GetValue(i) for i in range(column.GetNumberOfValues())]
        if names != expected or len(expected) != 16:
            raise RuntimeError("the table's rows are %s, not %s" % (names, expected))
        kinds = sorted(v.GetXMLName() for v in simple.GetViewsInLayout(layout))
        if kinds != ["SpreadSheetView", "XYPointChartView"]:
            raise RuntimeError("the layout holds %s" % kinds)
        chart = [v for v in simple.GetViewsInLayout(layout) if v.GetXMLName() != "SpreadSheetView"]
        series = list(simple.GetDisplayProperties(
            simple.FindSource(name + " (error against time)"), chart[0]).SeriesVisibility)
        if len(series) != len(expected):
            raise RuntimeError("the chart shows the series %s" % series)
        _say(sys.__stdout__,
             "PsiGUICheck passed: the report's table names its %d rows" % len(names))
        return True
    except Exception as e:  # noqa: BLE001 - any error is a failed check, said as such
        _say(sys.__stderr__, "PsiGUICheck FAILED: accuracy report: %r" % (e,))
        return False


# --- the panel's read-out of the last frame against the representation's own properties ------
#
# The read-out (Qt/pqPsiFrameStatsWidget) shows "last frame: X ms (sort Y ms), N tetrahedra,
# M cells skipped[, K sort cycles][; drawn intermixed with V other volumes (T tetrahedra in
# all, the settings of the view's first)][; drawn W]": X and Y are LastRenderSeconds and
# LastSortSeconds in milliseconds, 2 decimals below 10 ms and 1 from there; W is LastDrawWay; N, M, K and T are NumberOfTetrahedra, NumberOfSkippedCells,
# LastSortCycles and NumberOfIntermixedTetrahedra with thousands separators, K and T only when
# above 0.
# QtTesting's pqcheck compares a widget's property with a string fixed in the script, and the
# client's Python has no Qt bindings, so the label's text is read through the plugin's C function
# pqPsiFrameStatsReadouts (ctypes) and compared here, in the same Python command as the
# properties: no render can come in between, both are of the same frame.

_READOUT = re.compile(
    r"^last frame: ([0-9]+\.[0-9]+) ms \(sort ([0-9]+\.[0-9]+) ms\), ([0-9,]+) tetrahedra, "
    r"([0-9,]+) cells skipped(?:, ([0-9,]+) sort cycles)?"
    r"(?:; drawn intermixed with ([0-9,]+) other volumes? \(([0-9,]+) tetrahedra in all, the "
    r"settings of the view's first\))?"
    r"(?:; drawn ((?:front to back \([0-9]+ masks\)|back to front), (?:geometry|compute) shader, "
    r"(?:silhouettes|fan) \((?:as set|measuring \(way [0-9]+\)|chosen by measurement of [0-9]+ "
    r"ways)\)))?$")
# (shown in the read-out's n-th group, information property, how the processes' values combine)
_SHOWN = (
    (1, "LastRenderSeconds", "max"),
    (2, "LastSortSeconds", "max"),
    (3, "NumberOfTetrahedra", "sum"),
    (4, "NumberOfSkippedCells", "sum"),
    (5, "LastSortCycles", "sum"),
    (7, "NumberOfIntermixedTetrahedra", "sum"),
)


def _shown_readouts():
    """The text of every read-out shown now, from the plugin loaded in this client."""
    import ctypes

    from paraview import servermanager

    plugins = servermanager.vtkSMProxyManager.GetProxyManager().GetPluginManager() \
        .GetLocalInformation()
    paths = [plugins.GetPluginFileName(i) for i in range(plugins.GetNumberOfPlugins())
             if plugins.GetPluginName(i) == "PsiVolume" and plugins.GetPluginLoaded(i)]
    if not paths:
        raise RuntimeError("the PsiVolume plugin is not loaded in the client")
    # RTLD_NOLOAD: the library ParaView loaded, never a second copy (whose widget class would
    # not be the one on the panel)
    library = ctypes.CDLL(paths[0], mode=os.RTLD_NOLOAD | os.RTLD_LAZY)
    readouts = library.pqPsiFrameStatsReadouts
    readouts.restype = ctypes.c_char_p
    text = readouts().decode("utf-8")
    return text.split("\n") if text else []


def _server_values(owner, names):
    """{name: value} of the information properties `names` of the 'Psi Volume' proxy `owner` as
    the server's processes hold them, combined as in _SHOWN (counts summed, times the largest):
    in a client/server session ParaView pulls information properties from the client's copy of
    the representation, which draws nothing. Each server process calls the property's own
    command on its representation; the results are reduced over the server's MPI processes
    (vtkMultiProcessController::AllReduce) and read from the first one, all through
    ClientServer streams."""
    from paraview.modules.vtkRemotingClientServerStream import vtkClientServerStream
    from paraview.modules.vtkRemotingCore import vtkPVSession

    session = owner.GetSession()
    where = vtkPVSession.RENDER_SERVER

    def run(text):
        stream = vtkClientServerStream()
        if not stream.StreamFromString(text):
            raise RuntimeError("bad ClientServer stream: %s" % text)
        session.ExecuteStream(where, stream, False)
        return session.GetLastResult(where).StreamToString().strip()

    ops = {"max": 0, "sum": 2}  # vtkCommunicator::MAX_OP, SUM_OP
    # interpreter ids for this query only (ParaView's own objects go by their global ids)
    ids = {"rep": 5050501, "ctrl": 5050502, "max_in": 5050503, "max_out": 5050504,
           "sum_in": 5050505, "sum_out": 5050506}
    combine = dict((name, how) for _, name, how in _SHOWN)
    lines = ["New vtkDoubleArray id_value(%d)" % ids["max_in"],
             "New vtkDoubleArray id_value(%d)" % ids["max_out"],
             "New vtkIdTypeArray id_value(%d)" % ids["sum_in"],
             "New vtkIdTypeArray id_value(%d)" % ids["sum_out"],
             "Invoke id_value(1) GetVTKObject uint32_value(%d)" % owner.GetGlobalID(),
             "Assign id_value(%d) LastResult()" % ids["rep"]]
    index = {}  # name: (how, its position in the array of its kind)
    filled = {"max": 0, "sum": 0}
    for name in names:
        how = combine[name]
        index[name] = (how, filled[how])
        filled[how] += 1
        lines += ["Invoke id_value(%d) %s" % (ids["rep"], owner.GetProperty(name).GetCommand()),
                  "Invoke id_value(%d) InsertNextValue LastResult()" % ids[how + "_in"]]
    lines += ["Invoke id_value(1) GetProcessModule",
              "Invoke LastResult() GetGlobalController",
              "Assign id_value(%d) LastResult()" % ids["ctrl"]]
    for how in ("max", "sum"):
        lines.append("Invoke id_value(%d) AllReduce id_value(%d) id_value(%d) int32_value(%d)"
                     % (ids["ctrl"], ids[how + "_in"], ids[how + "_out"], ops[how]))
    try:
        run("\n".join(lines))
        values = {}
        for name, (how, i) in index.items():
            reply = run("Invoke id_value(%d) GetValue int64_value(%d)" % (ids[how + "_out"], i))
            match = re.match(r"^Reply (?:float64|int64)\(([^)]*)\)$", reply)
            if not match:
                raise RuntimeError("the server answered %r for %s" % (reply, name))
            values[name] = float(match.group(1)) if how == "max" else int(match.group(1))
        return values
    finally:
        run("\n".join("Delete id_value(%d)" % i for i in ids.values()))


def _draw_way(rep):
    """The representation's LastDrawWay where this process renders (builtin session); None on a
    server, whose string read-out the panel gathers from its first process."""
    from paraview import servermanager

    if servermanager.ActiveConnection.IsRemote():
        return None
    rep.UpdatePropertyInformation()
    return rep.GetProperty("LastDrawWay").SMProperty.GetElement(0)


def _property_values(rep):
    """{name: value} of the read-out's information properties of the representation `rep`: pulled
    with UpdatePropertyInformation where this process renders (builtin session), else from the
    server's processes (_server_values)."""
    from paraview import servermanager

    names = [name for _, name, _ in _SHOWN]
    owner = rep.GetProperty(names[0]).SMProperty.GetParent()  # the 'Psi Volume' sub-proxy
    if servermanager.ActiveConnection.IsRemote():
        return _server_values(owner, names), "the server's processes"
    rep.UpdatePropertyInformation()
    return dict((name, rep.GetProperty(name).SMProperty.GetElement(0)) for name in names), \
        "properties"


def _compare_milliseconds(shown, seconds):
    """'' if the read-out's `shown` milliseconds are `seconds` as the read-out rounds them (2
    decimals below 10 ms, else 1), else what is wrong. Values read from the server come with 6
    significant digits, hence the relative slack."""
    ms = 1000.0 * seconds
    decimals = len(shown.split(".")[1])
    if decimals != (2 if ms < 10 else 1) and abs(ms - 10) > 1e-3:
        return "%s ms has %d decimals for %.6g ms" % (shown, decimals, ms)
    if abs(float(shown) - ms) > 0.5 * 10 ** -decimals + 1e-5 * ms:
        return "%s ms shown for %.6g ms" % (shown, ms)
    return ""


def check_readout(stage, volumes=None):
    """Whether the read-out shown on the panel has the numbers of the active representation's
    information properties (the same frame: read in this one call), each within the read-out's
    rounding; with `volumes`, that it says the frame drew that many volumes intermixed. Prints
    "PsiGUICheck passed:" or "PsiGUICheck FAILED" (`stage` names the check) and returns the
    verdict."""
    try:
        from paraview import simple

        readouts = _shown_readouts()
        if len(readouts) != 1:
            raise RuntimeError("%d read-outs shown: %r" % (len(readouts), readouts))
        match = _READOUT.match(readouts[0])
        if not match:
            raise RuntimeError("the read-out %r is not of a drawn frame" % readouts[0])
        values, source = _property_values(simple.GetDisplayProperties())
        if not (values["LastRenderSeconds"] > 0 and values["NumberOfTetrahedra"] > 0):
            raise RuntimeError("no frame in the properties: %r" % values)
        wrong = []
        others = int(match.group(6).replace(",", "")) if match.group(6) else 0
        if volumes is not None and others != volumes - 1:
            wrong.append("drawn intermixed with %d other volumes, %d expected"
                         % (others, volumes - 1))
        way = _draw_way(simple.GetDisplayProperties())
        if way is not None and match.group(8) != way:
            wrong.append("drawn %r shown for LastDrawWay %r" % (match.group(8), way))
        for group, name, how in _SHOWN:
            shown = match.group(group)
            if how == "max":
                problem = _compare_milliseconds(shown, values[name])
            elif shown is None:  # sort cycles, intermixed: shown only when above 0
                problem = "" if values[name] == 0 else "%s %d not shown" % (name, values[name])
            else:
                count = int(shown.replace(",", ""))
                problem = "" if count == values[name] else "%s shown for %d" % (shown, values[name])
            if problem:
                wrong.append("%s: %s" % (name, problem))
        summary = "%r against %s %s" % (readouts[0], source, ", ".join(
            "%s=%s" % (name, values[name]) for _, name, _ in _SHOWN))
        if wrong:
            _say(sys.__stderr__, "PsiGUICheck FAILED: read-out (%s): %s; %s"
                 % (stage, "; ".join(wrong), summary))
            return False
        _say(sys.__stdout__, "PsiGUICheck passed: read-out (%s): %s" % (stage, summary))
        return True
    except Exception as e:  # noqa: BLE001 - any error is a failed check, said as such
        _say(sys.__stderr__, "PsiGUICheck FAILED: read-out (%s): %r" % (stage, e))
        return False


def hide_if_all_passed(verdicts, expected):
    """Hides the active representation if `verdicts` holds `expected` True values: the read-out
    then says the representation is hidden, which the script checks with pqcheck. A check that
    never ran (an error in the Python shell is not reported anywhere else) leaves it shown, and
    the test fails there."""
    from paraview import simple

    if len(verdicts) == expected and all(verdicts):
        simple.Hide()
    else:
        _say(sys.__stderr__, "PsiGUICheck FAILED: read-out checks: %r, %d expected"
             % (verdicts, expected))
