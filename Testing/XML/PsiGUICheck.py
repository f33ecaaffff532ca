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
#
# Loaded with runpy.run_path (no __pycache__ in the source tree). The test image is written by the
# project's PNG writer, psivolume.testing.write_png (the test's ENVIRONMENT puts the checkout's
# Python/ on the client's PYTHONPATH). Prints one line per check on the process's own
# stdout/stderr (the shell widget's output is not on the console): Testing/GUI.cmake counts
# "PsiGUICheck passed:" lines and fails on "PsiGUICheck FAILED".
import os
import sys

LEVEL = 8  # per-channel difference (0-255) above which a pixel counts as changed
MAX_PIXELS = 150  # of 90000; a method swap changes thousands


def _say(stream, text):
    stream.write(text + "\n")
    stream.flush()


def _capture(size):
    from paraview import simple

    view = simple.GetActiveView()
    if view is None:
        raise RuntimeError("no active view")
    old_size, old_ppi = list(view.ViewSize), view.PPI
    view.ViewSize, view.PPI = list(size), 72
    try:
        image = view.SMProxy.CaptureWindow(1)
    finally:
        view.ViewSize, view.PPI = old_size, old_ppi
    if image is None:
        raise RuntimeError("CaptureWindow returned nothing")
    return image


def _pixels(image):
    from vtkmodules.util.numpy_support import vtk_to_numpy

    dims = image.GetDimensions()
    rgb = vtk_to_numpy(image.GetPointData().GetScalars())[:, :3].astype(int)
    return dims[0], dims[1], rgb


def check(baseline_dir, test_dir, name, test_name=None, level=LEVEL, max_pixels=MAX_PIXELS,
          size=(300, 300)):
    """Compares the active view with baseline_dir/name.png; writes it to test_dir/test_name.png."""
    test_name = test_name or name
    try:
        from vtkmodules.vtkIOImage import vtkPNGReader

        from psivolume.testing import write_png

        tw, th, test = _pixels(_capture(size))
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
