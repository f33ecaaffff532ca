"""The accuracy report (psivolume.accuracy) inside ParaView: run on the active source and view
under ParaView's progress, its rows shown in a layout of their own, as a table (a spreadsheet
view) and as error against time (a point chart, one series per row, named as in the report).

The plugin's toolbar button 'Accuracy report' and Tools > Accuracy report call run_report().
From pvpython or the GUI's Python shell, once the plugin is loaded:

    import psivolume.gui
    psivolume.gui.OPTIONS.update(frames=1, budget=20)   # what the button runs with
    rows, views = psivolume.gui.run_report()

The tables are the plugin's 'PsiReportTable' sources (XML/PsiVolumeReportTable.xml: VTK's
delimited-text reader reading a string property), which hold the rows as text: a saved state shows
them again, and neither the report nor loading the state runs a script in the user's __main__ (a
ProgrammableSource would, after star imports of numpy: 608 names, `sum`, `max` and `vtk` among
them, replaced the user's). PsiPython.gui_report compares __main__ before and after."""
import contextlib
import csv
import io
import math
import tempfile

from paraview import servermanager, simple

from . import accuracy, accuracy_plots
from .progress import Progress

TITLE = "Accuracy report"
# The options of accuracy.report that run_report() (the button) uses unless told otherwise: the
# report's own defaults, but shorter timing (at most two minutes of rounds).
OPTIONS = dict(frames=3, budget=120.0)
# The table's columns, named as the report's (accuracy_plots.HEADER), numbered in its order: the
# spreadsheet view orders columns by name. The chart's X column has the report's name.
NAME, NOTE, X = "1 method", "9 note", "s/frame"
# The numeric columns and the row's key of each.
NUMBERS = [("2 s/frame", "spf"), ("3 CPU s/frame", "cpu"), ("4 once s", "once"),
           ("5 time / Average", "ratio"), ("6 mean err", "mean"), ("7 max err", "max"),
           ("8 mean err x s", "err_s")]


def run_report(view=None, src=None, out_dir=None, **options):
    """accuracy.report on `view` (default: the active one) and `src`'s volume in it (default: the
    active source), with OPTIONS updated by `options`, under ParaView's progress; writes its
    files to `out_dir` (default: a new temporary folder) and shows the rows (show_rows).
    Returns (rows, views)."""
    view = view or simple.GetActiveView()
    src = src or simple.GetActiveSource()
    check_scene(view, src)
    out_dir = out_dir or tempfile.mkdtemp(prefix="psi_accuracy_")
    rep = servermanager.GetRepresentation(src, view)
    with Progress(TITLE) as progress, alone(view, rep):
        rows = accuracy.report(view, rep, src, out_dir, progress=progress,
                               **dict(OPTIONS, **options))
    views = show_rows(rows, "%s: %s" % (TITLE, source_name(src)))
    simple.SetActiveSource(src)
    print("%s: %s" % (TITLE, out_dir))
    return rows, views


def check_scene(view, src):
    """Raises, saying what is missing, unless `src` is shown in the render view `view`."""
    if view is None or view.GetXMLName() != "RenderView":
        raise RuntimeError("%s: make a render view active (the report renders its volume)" % TITLE)
    if src is None:
        raise RuntimeError("%s: select the source whose volume to measure" % TITLE)
    rep = servermanager.GetRepresentation(src, view)
    if rep is None or not rep.Visibility:
        raise RuntimeError("%s: show %s in the active view first" % (TITLE, source_name(src)))


@contextlib.contextmanager
def alone(view, rep):
    """`rep` alone in `view` while the report runs: the other representations (other sources,
    color legends) and the orientation axes hidden, for the exact reference draws the volume
    only; all of them shown again afterwards."""
    hidden = [r for r in view.Representations
              if r.SMProxy is not rep.SMProxy and r.GetProperty("Visibility") is not None
              and r.Visibility]
    axes = view.OrientationAxesVisibility
    try:
        for r in hidden:
            r.Visibility = 0
        view.OrientationAxesVisibility = 0
        yield
    finally:
        for r in hidden:
            r.Visibility = 1
        view.OrientationAxesVisibility = axes
        simple.Render(view)


def source_name(src):
    return servermanager.ProxyManager().GetProxyName("sources", src) or src.GetXMLLabel()


def number(v):
    return float("nan") if v is None else float(v)


def table_columns(rows):
    """The report's table: the rows' names, each numeric column of NUMBERS, the notes."""
    return ([[NAME, "string", [r["name"] for r in rows]]] +
            [[header, "number", [number(r.get(key)) for r in rows]] for header, key in NUMBERS] +
            [[NOTE, "string", [r.get("note") or "" for r in rows]]])


def chart_columns(rows):
    """Error against time: the column X (seconds per frame) and one column per plotted row,
    named as the report's plot names it (accuracy_plots.point_label), holding its mean error at
    its own line and NaN at the others, so that each row is a series of one point."""
    pts = accuracy_plots.plotted(rows)
    floor = accuracy_plots.error_floor(pts)
    columns = [[X, "number", [r["spf"] for r in pts]]]
    for k, r in enumerate(pts):
        values = [float("nan")] * len(pts)
        values[k] = max(r["mean"], floor)
        columns.append([accuracy_plots.point_label(r), "number", values])
    return columns


def table_text(columns):
    """`columns` ([name, "string" or "number", values]) as comma-separated text with a header
    line, as VTK's delimited-text reader reads it back: a number as Python's repr ("nan" where
    missing), a string without double quotes (the reader drops a field with doubled ones) and
    "-" for an empty one (a column of empty strings would be read as numbers)."""
    def field(kind, v):
        if kind == "number":
            return repr(float(v)) if math.isfinite(v) else "nan"
        return str(v).replace('"', "'") or "-"
    out = io.StringIO()
    writer = csv.writer(out, quoting=csv.QUOTE_MINIMAL, lineterminator="\n")
    writer.writerow([name.replace('"', "'") for name, _, _ in columns])
    for row in zip(*[[field(kind, v) for v in values] for _, kind, values in columns]):
        writer.writerow(row)
    return out.getvalue()


def table_source(columns, name):
    """A 'PsiReportTable' source holding `columns` (table_text), registered as `name` in the
    pipeline browser."""
    proxy = servermanager._getPyProxy(
        servermanager.ProxyManager().NewProxy("internal_sources", "PsiReportTable"))
    controller = servermanager.ParaViewPipelineController()
    controller.PreInitializeProxy(proxy)
    proxy.Text = table_text(columns)
    proxy.UpdateVTKObjects()
    controller.PostInitializeProxy(proxy)
    controller.RegisterPipelineProxy(proxy, name)
    return proxy


def show_rows(rows, name):
    """A new layout `name`: the rows as a table in a spreadsheet view, beside error against time
    in a point chart (both axes logarithmic, as the report's plot). Returns (spreadsheet, chart)."""
    table = table_source(table_columns(rows), name)
    chart_data = chart_columns(rows)
    points = table_source(chart_data, name + " (error against time)")
    layout = simple.CreateLayout(name)
    sheet = simple.CreateView("SpreadSheetView")
    simple.AssignViewToLayout(view=sheet, layout=layout, hint=0)
    simple.Show(table, sheet)
    layout.SplitHorizontal(0, 0.5)
    chart = simple.CreateView("XYPointChartView")
    simple.AssignViewToLayout(view=chart, layout=layout, hint=2)
    show_chart(points, chart, [c[0] for c in chart_data[1:]], name)
    simple.Render(sheet)
    simple.Render(chart)
    return sheet, chart


# vtkPlotPoints' markers for accuracy_plots.point_style's (VTK has no star nor triangle).
VTK_MARKERS = dict(cross=1, star=2, square=3, circle=4, diamond=5, triangle=5)


def show_chart(points, chart, series, title):
    """`points` (chart_columns) in the point chart `chart`, each series styled as the report's
    plot draws its point."""
    d = simple.Show(points, chart)
    d.UseIndexForXAxis = 0
    d.XArrayName = X
    d.SeriesVisibility = series
    styles = {name: accuracy_plots.point_style(name.replace(" (error 0)", "")) for name in series}
    d.SeriesMarkerStyle = [v for n in series for v in (n, str(VTK_MARKERS[styles[n][0]]))]
    d.SeriesMarkerSize = [v for n in series
                          for v in (n, str(int(round(1.4 * styles[n][2] ** 0.5))))]
    d.SeriesColor = [v for n in series for v in (n,) + tuple("%.3f" % c for c in styles[n][1])]
    chart.ChartTitle = title
    chart.BottomAxisTitle = "seconds per frame"
    chart.LeftAxisTitle = "mean error vs exact reference (0..255)"
    chart.BottomAxisLogScale = 1
    chart.LeftAxisLogScale = 1
    return d
