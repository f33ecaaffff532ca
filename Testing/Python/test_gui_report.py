"""`import psivolume` after LoadPlugin, with no PYTHONPATH (the plugin puts the package's folder on
sys.path, Plugin/PsiPluginPython.h), then the accuracy report as the GUI's 'Accuracy report'
runs it (psivolume.gui.run_report) on a small mesh: under ParaView's progress, its rows in a new
layout as a table (a spreadsheet view) whose first column names them in the report's order,
and as error against time (a point chart, one series per row, named as the report's plot).

    pvpython test_gui_report.py [--plugin PLUGIN] --package-dir DIR [--import-only]

PLUGIN (default: $PSI_TEST_PLUGIN) is loaded by path; DIR is the folder psivolume must come
from: the checkout's Python/ for the build tree (PsiPython.gui_report), the install's for an
install (Testing/Install/run_installed.py, with --import-only)."""
import argparse
import builtins
import importlib.util
import math
import os
import sys
import tempfile

from paraview import servermanager, simple

ap = argparse.ArgumentParser()
ap.add_argument("--plugin", default=os.environ.get("PSI_TEST_PLUGIN"))
ap.add_argument("--package-dir", required=True)
ap.add_argument("--import-only", action="store_true")
args = ap.parse_args()
folder = os.path.realpath(args.package_dir)


def comes_from_folder(spec):
    return spec is not None and os.path.realpath(spec.origin).startswith(folder + os.sep)


failures = []


def check(cond, what):
    print(("ok      " if cond else "FAILED  ") + what, flush=True)
    if not cond:
        failures.append(what)


def finish():
    print("gui_report: %s" % ("FAILED (%d)" % len(failures) if failures else "passed"), flush=True)
    os._exit(1 if failures else 0)  # as psivolume.testing.exit_now: no teardown under Xvfb


check(not comes_from_folder(importlib.util.find_spec("psivolume")),
      "before LoadPlugin, psivolume does not import from %s" % folder)
simple.LoadPlugin(args.plugin, remote=False, ns={})
import psivolume  # noqa: E402 (after LoadPlugin: that is what is tested)
import psivolume.gui  # noqa: E402

check(comes_from_folder(psivolume.__spec__), "after LoadPlugin, psivolume imports from %s (%s)"
      % (folder, psivolume.__file__))
check(sys.path.count(folder) <= 1, "the folder is on sys.path once")
if args.import_only:
    finish()

from psivolume import accuracy, accuracy_plots, data, gui  # noqa: E402

src, array = data.wavelet(3)
view, rep = data.volume_view(src, array, 96)
simple.Show(simple.Wavelet(), view)  # another representation: hidden while the report runs,
view.OrientationAxesVisibility = 1  # and the orientation axes (they are not in the reference)
simple.SetActiveView(view)
simple.SetActiveSource(src)
handler = servermanager.ActiveConnection.Session.GetProgressHandler()
steps = []
handler.AddObserver("ProgressEvent", lambda h, e: steps.append(h.GetLastProgressText()))


def main_names():
    """{name: id of its value} of __main__, the user's namespace."""
    return {k: id(v) for k, v in vars(sys.modules["__main__"]).items()}


def report_and_changed_names(*args, fails=False, **options):
    """gui.run_report's result (with `fails`: the RuntimeError it raised) and the names of
    __main__ it changed (bound, rebound or removed)."""
    before = main_names()
    try:
        result = gui.run_report(*args, **options)
    except RuntimeError as e:
        if not fails:
            raise
        result = e
    after = main_names()
    return result, sorted(k for k in set(before) | set(after) if before.get(k) != after.get(k))


(rows, (sheet, chart)), changed = report_and_changed_names(
    frames=1, budget=0.1, paraview_mappers=[], resample_dims=[])
check(not changed, "the user's namespace (__main__) as before the report: %d names changed %s"
      % (len(changed), changed[:8]))

methods = list(rep.GetProperty("IntegrationMethod").Available)
expected = [n for m in methods for n in (m, m + " + adaptive")] + [
    accuracy.INTERACTIVE, accuracy.REFERENCE]
check([r["name"] for r in rows] == expected, "the report's rows: %s" % [r["name"] for r in rows])
# (ParaView's progress handler drops events closer than 0.1 s to the last one: steps seconds
# apart reach it whatever the machine, the first one always)
reported = [s for s in steps if s and s.startswith(gui.TITLE + ": ")]
check(len(set(reported)) >= 3 and reported[0].endswith("the mesh and the scene"),
      "ParaView's progress told the report's steps: %s" % reported)
# the outline or the axes in the images would differ from the reference by ~200 at their pixels
if os.environ.get("PSI_TEST_REFERENCE"):
    check(os.path.realpath(accuracy.find_reference_renderer()) ==
          os.path.realpath(os.environ["PSI_TEST_REFERENCE"]),
          "the report found the reference renderer of the plugin loaded: %s"
          % accuracy.find_reference_renderer())
average = rows[0]
check(average["max"] < 100, "Average's largest error %.0f: the outline and the axes hidden "
      "meanwhile" % average["max"])

# (ParaView runs the tables' ProgrammableSource scripts in __main__, which gets numpy_interface's
# all, max, ...: the builtins are named as such below)
name = gui.TITLE + ": Tetrahedralize1"
table = servermanager.Fetch(simple.FindSource(name))
column = table.GetColumnByName(gui.NAME)
names = [column.GetValue(i) for i in range(column.GetNumberOfValues())]
check(names == expected, "the table's first column names the rows in order")
shown_sheet = sheet.GetClientSideObject()  # its columns after 'Row ID' (vtkOriginalIndices)
sheet_columns = [c for c in (shown_sheet.GetColumnName(i)
                             for i in range(shown_sheet.GetNumberOfColumns()))
                 if shown_sheet.GetColumnVisibility(shown_sheet.GetColumnByName(c))
                 and c != "vtkOriginalIndices"]
check(sheet_columns[:3] == [gui.NAME, "2 s/frame", "3 CPU s/frame"],
      "the spreadsheet shows the report's columns in its order: %s" % sheet_columns)
errors = table.GetColumnByName("6 mean err")
check(errors is not None and
      builtins.all(math.isfinite(errors.GetValue(i)) for i in range(len(names))),
      "the table's mean errors are numbers")
layout = simple.GetLayoutByName(name)
check(layout is not None and layout.GetViewLocation(sheet) != -1
      and layout.GetViewLocation(chart) != -1, "spreadsheet and chart in the layout '%s'" % name)
check(sheet.GetXMLName() == "SpreadSheetView" and
      servermanager.GetRepresentation(simple.FindSource(name), sheet).Visibility == 1,
      "the table shown in the spreadsheet view")
shown = simple.GetDisplayProperties(simple.FindSource(name + " (error against time)"), chart)
labels = [accuracy_plots.point_label(r) for r in rows]
check(chart.GetXMLName() == "XYPointChartView" and list(shown.SeriesVisibility) == labels,
      "the chart's series are the rows, named as the report's plot: %s"
      % list(shown.SeriesVisibility))
check(view.OrientationAxesVisibility == 1 and
      builtins.all(r.Visibility for r in view.Representations if r.GetProperty("Visibility")),
      "the outline and the axes shown again afterwards")
try:
    gui.run_report(chart)
    check(False, "run_report on a chart view raises")
except RuntimeError as e:
    check("render view" in str(e), "run_report on a chart view says why not: %s" % e)


def failing_chart(*args):
    raise RuntimeError("a chart that fails")


# A report that fails after its tables' scripts have run (the chart fails): the namespace as before.
show_chart, gui.show_chart = gui.show_chart, failing_chart
failed, changed = report_and_changed_names(view, src, fails=True, frames=1, budget=0.1,
                                           paraview_mappers=[], resample_dims=[])
gui.show_chart = show_chart
check("a chart that fails" in str(failed), "a report whose chart fails raises: %s" % failed)
check(not changed, "after a report that failed, the user's namespace as before: %d names changed "
      "%s" % (len(changed), changed[:8]))

# A saved state shows the tables again, and loading it (the tables' update included) leaves the
# user's namespace as it was (a ProgrammableSource would run its script in __main__).
def load_state_and_changed_names():
    """The tables of a state saved now and loaded into a new session (their updates included),
    and the names of __main__ the load changed (this test's own names are locals here)."""
    with tempfile.TemporaryDirectory() as tmp:
        state = os.path.join(tmp, "report.pvsm")
        simple.SaveState(state)
        simple.ResetSession()
        before = main_names()
        simple.LoadState(state)
        loaded = simple.FindSource(name)
        tables = (servermanager.Fetch(loaded) if loaded else None,
                  servermanager.Fetch(simple.FindSource(name + " (error against time)")))
        after = main_names()
    return tables, sorted(k for k in set(before) | set(after) if before.get(k) != after.get(k))


(table, chart_table), changed = load_state_and_changed_names()
column = table.GetColumnByName(gui.NAME) if table else None
loaded_names = [column.GetValue(i) for i in range(column.GetNumberOfValues())] if column else []
check(loaded_names == expected and chart_table.GetNumberOfColumns() == len(labels) + 1,
      "a saved state shows the tables again: %s" % loaded_names)
check(not changed, "loading the state leaves the user's namespace as it was: %d names changed %s"
      % (len(changed), changed[:8]))
finish()
