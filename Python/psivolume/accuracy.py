"""What accuracy costs, for the user's own data: every integration method of 'Psi Volume'
(adaptive sampling off and on), its interactive image (the volume level of detail), ParaView's
own unstructured-volume mappers and 'Resample To Image' at several sampling dimensions (the
mapper users pick for speed), timed at the same view and measured against the exact reference,
the project's CPU ray caster (Reference/PsiReferenceRaycaster, run by
build/bin/psi_reference_render). One-time costs are reported apart from the frame times: the
resampling of 'Resample To Image' (its first frame) and the level of detail's build.

From pvpython or the GUI's Python shell (the checkout's Python/ folder on sys.path or
PYTHONPATH), on the active view and the active source's volume:
    from psivolume import accuracy; accuracy.report(out_dir="accuracy")
As a command (scripts/accuracy-report.sh wraps it under Xvfb), with PYTHONPATH=Python:
    pvpython -m psivolume.accuracy [FILE|bluntfin|post|comb|spx] [--array NAME] [--out DIR]
                                   [--size 384] [--frames 3] [--wavelet-half 20]
                                   [--unit-distance U] [--no-paraview] [--paraview-timeout 120]
                                   [--paraview-mappers 'Projected tetra' 'Z sweep' ...]
                                   [--resample-dims 64 128 256] [--budget 300]
                                   [--data-dir DIR] [--plugin FILE] [--build-dir DIR]
                                   [--reference-renderer FILE] [--pvpython FILE] [--threads N]
(where things are: the shared datasets, the plugin, the build to find it in, the reference
renderer, the pvpython of the children; the llvmpipe thread count the report names. Nothing is
read from the environment.)
Times come from interleaved rounds (psivolume.timing): every method and mapper once per round,
medians over the rounds, ratios to Average taken round by round, until every ratio's spread is
within 5% or the budget is spent. Prints the table and writes DIR/report.md, DIR/accuracy.png (error against time),
DIR/methods.png (each image and its error map) and the rows as DIR/report.json. ParaView's
mappers run in a child pvpython each (a crash there is a row of the table, not the end of the
report)."""
import argparse
import glob
import json
import os
import signal
import subprocess
import tempfile
import time

import numpy as np
from paraview import servermanager, simple
from vtkmodules.vtkCommonDataModel import vtkDataSetAttributes, vtkUnstructuredGrid
from vtkmodules.vtkCommonMath import vtkMatrix4x4
from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkFiltersGeneral import vtkDataSetTriangleFilter, vtkTransformFilter
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridWriter
from vtkmodules.vtkRenderingCore import vtkColorTransferFunction, vtkVolume

from . import accuracy_plots, data, process, restore, timing
from .images import grab

PARAVIEW_MAPPERS = ["Projected tetra", "Z sweep", "Bunyk ray cast"]
RESAMPLE = "Resample To Image"
RESAMPLE_DIMS = [64, 128, 256]  # sampling dimensions (cubed); ParaView's default is 128
INTERACTIVE = "Psi Volume (interactive)"
FIRST_PREFIX = "PSI_FIRST_FRAME "  # a child's first frame, in seconds, before it is ready
REFERENCE = "Exact reference (CPU)"
BASELINE = "Average"  # ratios to it, round by round: Moreland's Table 6.4 gives the same
TF_SAMPLES = 512  # extra breakpoints where the color map or opacity is not linear between nodes
# The colored array's name in the mesh file: the user's own may be any text, which VTK's XML writer
# writes unescaped (a quote in it makes the file unreadable).
MESH_ARRAY = "scalars"
SKIP = 77  # the command's exit code when the shared dataset it names is absent (CTest's skip)


def find_reference_renderer(renderer=None, plugin=None):
    """`renderer` when given, else psi_reference_render beside the plugin (data.find_plugin(
    `plugin`)) when installed, else in the bin/ of the plugin's build."""
    if renderer:
        return renderer
    plugin = data.find_plugin(plugin)
    beside = os.path.join(os.path.dirname(plugin), "psi_reference_render")  # installed
    if os.path.exists(beside):
        return beside
    # <build>/lib*/paraview-X.Y/plugins/PsiVolume/PsiVolume.so
    build = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(plugin)))))
    hits = glob.glob(os.path.join(build, "bin", "psi_reference_render"))
    if not hits:
        raise RuntimeError("psi_reference_render not built: run scripts/build.sh")
    return hits[0]


class Capture:
    """The scene of a view as the reference and the child processes need it: mesh file, color
    map, opacity, unit distance, camera, size, background."""

    def __init__(self, view, rep, src, work):
        self.view, self.rep, self.src, self.work = view, rep, src, work
        self.others = []  # the captures of the view's other volumes (volume_captures)
        self.array = rep.ColorArrayName[1]
        self.association = rep.ColorArrayName[0] or data.association(src, self.array)
        # the display's own maps (a separate color map is not the one of the array's name)
        self.lut = rep.LookupTable or simple.GetColorTransferFunction(self.array)
        self.pwf = rep.ScalarOpacityFunction or simple.GetOpacityTransferFunction(self.array)
        self.size = list(view.ViewSize)
        self.mesh = os.path.join(work, "mesh.vtu")
        self.write_mesh()

    def write_mesh(self):
        """The source's mesh with the colored array alone, named MESH_ARRAY (single_array)."""
        grid = servermanager.Fetch(self.src)
        if grid.IsA("vtkCompositeDataSet"):
            active = simple.GetActiveSource()  # the new filter becomes active: not for long
            merged = simple.MergeBlocks(Input=self.src)
            grid = servermanager.Fetch(merged)
            simple.Delete(merged)
            simple.SetActiveSource(active)
        if not grid.IsA("vtkUnstructuredGrid"):
            tets = vtkDataSetTriangleFilter()
            tets.SetInputData(grid)
            tets.Update()
            grid = tets.GetOutput()
        grid = self.placed(grid)
        self.cells = grid.GetNumberOfCells()
        w = vtkXMLUnstructuredGridWriter()
        w.SetFileName(self.mesh)
        w.SetInputData(single_array(grid, self.array, self.association))
        w.SetDataModeToAppended()
        w.Write()

    def placed(self, grid):
        """`grid` in world coordinates: moved by the display's Position (ParaView 5.13 and later:
        Translation), Orientation, Scale and Origin, as its volume's matrix places it
        (vtkProp3D's), when they move it."""
        volume = vtkVolume()
        volume.SetPosition(list(data.display_translation(self.rep)))
        volume.SetOrientation(list(self.rep.Orientation))
        volume.SetScale(list(self.rep.Scale))
        volume.SetOrigin(list(self.rep.Origin))
        m = volume.GetMatrix()
        if all(m.GetElement(i, j) == (i == j) for i in range(4) for j in range(4)):
            return grid
        move = vtkTransform()
        move.SetMatrix(m)
        placed = vtkTransformFilter()
        placed.SetTransform(move)
        placed.SetInputData(grid)
        placed.Update()
        return placed.GetOutput()

    def component(self):
        if self.lut.VectorMode == "Magnitude":
            return -1
        return int(self.lut.VectorComponent)

    def background(self):
        return list(self.view.GetRenderer().GetBackground())

    def table(self):
        """Rows (s, r, g, b, opacity): every color and opacity node, and TF_SAMPLES more when
        the color space is not RGB or a node has a midpoint or sharpness (not linear between)."""
        ctf = vtkColorTransferFunction()  # the continuous map (no 256-color discretization)
        ctf.DeepCopy(self.lut.GetClientSideObject())
        opacity = self.pwf.GetClientSideObject()
        rgb = list(self.lut.RGBPoints)
        pts = list(self.pwf.Points)
        s = set(rgb[0::4]) | set(pts[0::4])
        linear = (self.lut.ColorSpace == "RGB" and all(
            m == 0.5 and h == 0.0 for m, h in zip(pts[2::4], pts[3::4])))
        lo, hi = min(s), max(s)
        rng = self.src.GetDataInformation().DataInformation.GetArrayInformation(
            self.array, 0 if self.association == "POINTS" else 1)
        if rng is not None:
            r = rng.GetComponentRange(-1 if self.component() < 0 else self.component())
            lo, hi = min(lo, r[0]), max(hi, r[1])
        if not linear:
            s |= set(np.linspace(lo, hi, TF_SAMPLES).tolist())
        rows = []
        for v in sorted(s):
            c = ctf.GetColor(v)
            rows.append((v, c[0], c[1], c[2], opacity.GetValue(v)))
        return rows

    def ndc_to_world(self):
        m = vtkMatrix4x4()
        m.DeepCopy(self.view.GetActiveCamera().GetCompositeProjectionTransformMatrix(
            self.size[0] / float(self.size[1]), -1, 1))
        m.Invert()
        return [m.GetElement(i, j) for i in range(4) for j in range(4)]

    def write_reference_scene(self, path):
        with open(path, "w", encoding="utf-8") as f:
            f.write("array %s\nassociation %s\n" % (quoted(MESH_ARRAY), self.association.lower()))
            f.write("component %d\nsize %d %d\n" % (self.component(), self.size[0], self.size[1]))
            f.write("background %r %r %r\nunit %r\n" % (tuple(self.background()) + (
                self.rep.ScalarOpacityUnitDistance,)))
            f.write("ndc_to_world %s\n" % " ".join(repr(v) for v in self.ndc_to_world()))
            rows = self.table()
            f.write("tf %d\n" % len(rows))
            for row in rows:
                f.write("%r %r %r %r %r\n" % row)

    def child_volume(self):
        """This volume as a child draws it: its mesh, array and maps, unit distance."""
        return dict(mesh=self.mesh, array=MESH_ARRAY, association=self.association,
                    unit=float(self.rep.ScalarOpacityUnitDistance),
                    rgb_points=list(self.lut.RGBPoints),
                    color_space=self.lut.GetProperty("ColorSpace").GetData(),
                    vector_mode=self.lut.GetProperty("VectorMode").GetData(),
                    vector_component=int(self.lut.VectorComponent),
                    opacity_points=list(self.pwf.Points))

    def write_child_scene(self, path):
        v = self.view
        scene = dict(volumes=[c.child_volume() for c in [self] + self.others],
                     size=self.size, background=self.background(),
                     camera=dict(position=list(v.CameraPosition),
                                 focal=list(v.CameraFocalPoint), up=list(v.CameraViewUp),
                                 angle=float(v.CameraViewAngle),
                                 parallel=int(v.CameraParallelProjection),
                                 scale=float(v.CameraParallelScale)))
        with open(path, "w") as f:
            json.dump(scene, f)


def volume_displays(view, rep, src):
    """`rep` (of `src`) first, then every other visible display of `view` drawn as a volume ('Psi
    Volume' or 'Volume'): [(display, its source)]. The report measures the whole image, all of
    them."""
    found = [(rep, src)]
    for other in simple.GetSources().values():
        d = servermanager.GetRepresentation(other, view)
        if d is not None and d != rep and d.Visibility and \
                d.GetProperty("Representation") is not None and \
                d.Representation in ("Psi Volume", "Volume"):
            found.append((d, other))
    return found


def volume_captures(view, displays, work):
    """The captures of `displays` ([(display, source)], volume_displays), each in a folder of its
    own under `work`: the first, with the others as its `others`."""
    caps = []
    for k, (d, src) in enumerate(displays):
        folder = os.path.join(work, "volume_%d" % k) if k else work
        os.makedirs(folder, exist_ok=True)
        caps.append(Capture(view, d, src, folder))
    caps[0].others = caps[1:]
    return caps[0]


def single_array(grid, array, association):
    """`grid`'s points and cells with one array, the one named `array` of `association` ('POINTS'
    or 'CELLS': a point and a cell array may share a name), renamed MESH_ARRAY; and the ghost
    arrays, which ParaView's mappers honour."""
    out = vtkUnstructuredGrid()
    out.CopyStructure(grid)
    pairs = [(grid.GetPointData(), out.GetPointData()), (grid.GetCellData(), out.GetCellData())]
    src, dst = pairs[0 if association == "POINTS" else 1]
    found = src.GetArray(array)
    if found is None:
        raise RuntimeError("%s: the mesh has no %s array named %r" % (
            REFERENCE, "point" if association == "POINTS" else "cell", array))
    colored = found.NewInstance()
    colored.ShallowCopy(found)
    colored.SetName(MESH_ARRAY)
    dst.AddArray(colored)
    for src, dst in pairs:
        ghosts = src.GetArray(vtkDataSetAttributes.GhostArrayName())
        if ghosts is not None:
            dst.AddArray(ghosts)
    return out


def quoted(name):
    """`name` in double quotes, a backslash before each quote and backslash in it (as C++'s
    std::quoted reads it: the scene file's words are separated by blanks)."""
    return '"%s"' % name.replace("\\", "\\\\").replace('"', '\\"')


def exit_status(code):
    """subprocess's return code in words: a negative one is the signal that ended the process."""
    if code < 0:
        try:
            return "signal %s" % signal.Signals(-code).name
        except ValueError:
            return "signal %d" % -code
    return "exit status %d" % code


def run_reference_renderer(argv):
    """Runs psi_reference_render (`argv`); when it fails, raises one line saying so and why: its
    last line on stderr (its reason, psi_reference_render.cxx), else how it ended."""
    name = "the exact reference renderer %s" % argv[0]
    try:
        p = subprocess.run(argv, capture_output=True, text=True, errors="replace")
    except OSError as e:
        raise RuntimeError("%s could not start: %s" % (name, e.strerror or e)) from None
    if p.returncode != 0:
        lines = [line.strip() for line in p.stderr.splitlines() if line.strip()]
        raise RuntimeError("%s failed (%s): %s" % (name, exit_status(p.returncode),
                                                   lines[-1] if lines else "no message"))


def reference_image(cap, exe=None, runs=2, others=None):
    """The reference image (float RGB 0..255, rows from the bottom) and its seconds, rendered by
    the reference renderer `exe` (default: find_reference_renderer()) `runs` times: the error
    between the runs is the reference's own row (0 when deterministic). `others`: the captures
    of the view's other volumes, drawn with `cap`'s as media that may share space (each its own
    mesh and transfer function; PsiReferenceMedia.h; default: cap.others)."""
    exe = find_reference_renderer(exe)
    volumes = []
    for c in [cap] + list(cap.others if others is None else others):
        scene = os.path.join(c.work, "reference.txt")
        c.write_reference_scene(scene)
        volumes += [c.mesh, scene]
    images, seconds = [], []
    for k in range(runs):
        out = os.path.join(cap.work, "reference_%d.raw" % k)
        t = time.perf_counter()
        run_reference_renderer([exe] + volumes + [out])
        seconds.append(time.perf_counter() - t)
        img = np.fromfile(out, dtype=np.float64).reshape(cap.size[1], cap.size[0], 3)
        images.append(np.clip(img, 0, 1) * 255.0)
    return images, timing.frame_time(seconds)


def psi_contenders(cap, methods, back_to_front=False):
    """'Psi Volume' with each method, adaptive sampling off and on, and with `back_to_front` also
    each method with EarlyRayTermination off ("M, back to front"): (contenders, images)."""
    contenders, images = [], {}
    own = cap.rep.EarlyRayTermination  # the display's own, for every other row
    front = own != "Off"
    variants = [("Off", own), ("On", own)] + ([("Off", "Off")] if back_to_front and front else [])
    for m in methods:
        for adaptive, termination in variants:
            name = "%s%s%s" % (m, " + adaptive" if adaptive == "On" else "",
                               ", back to front" if front and termination == "Off" else "")

            def prepare(m=m, adaptive=adaptive, termination=termination):
                for c in [cap] + cap.others:  # the first one's settings draw them all
                    data.set_mapper(c.rep, "Psi Volume|" + m)
                    c.rep.AdaptiveSampling = adaptive
                    c.rep.EarlyRayTermination = termination

            prepare()
            simple.Render(cap.view)
            images[name] = grab(cap.view)
            contenders.append(timing.InProcess(name, cap.view, prepare))
    return contenders, images


def interactive_contender(cap, method):
    """The interactive image of 'Psi Volume': InteractionMode 'Volume LOD' (a coarse probe of
    the mesh drawn by VTK's GPU ray caster, whatever the method; `method` is set for the still
    frame before it), timed with InteractiveRender. Returns (contender, image, the level of
    detail's build seconds, note)."""
    own = cap.rep.EarlyRayTermination

    def prepare():
        for c in [cap] + cap.others:
            data.set_mapper(c.rep, "Psi Volume|" + method)
            c.rep.AdaptiveSampling = "Off"
            c.rep.EarlyRayTermination = own
            c.rep.InteractionMode = "Volume LOD"

    prepare()
    simple.Render(cap.view)
    cap.view.InteractiveRender()
    image = grab(cap.view)  # the back buffer as drawn, not re-rendered
    cap.rep.UpdatePropertyInformation()
    drew = cap.rep.GetProperty("LastInteractiveImage").GetElement(0)
    build = cap.rep.GetProperty("LODBuildSeconds").GetElement(0)
    note = "" if drew == 1 else "drew %d, not the level of detail (1)" % drew
    return timing.InProcess(INTERACTIVE, cap.view, prepare, interactive=True), image, build, note


def resample_row(dims):
    return "ParaView %s %d^3" % (RESAMPLE, dims)


def paraview_contenders(cap, mappers, timeout=120, resample_dims=(), plugin=None, pvpython=None):
    """ParaView's mappers, and 'Resample To Image' at each of `resample_dims`, each in a child
    pvpython that stays up for the rounds (a crash there is a row of the table with its note):
    (contenders, images, once), `once` the first frame's seconds of each 'Resample To Image'
    (its resampling), apart from its frame time. The children run `pvpython` (default: the one
    on PATH) and load the plugin `plugin` when they draw 'Psi Volume'."""
    scene = os.path.join(cap.work, "scene.json")
    cap.write_child_scene(scene)
    runs = [("ParaView " + m, m, None) for m in mappers] + \
        [(resample_row(d), RESAMPLE, d) for d in resample_dims]
    contenders, images, once = [], {}, {}
    for row, mapper, dims in runs:
        out = os.path.join(cap.work, "pv_%d.npy" % len(contenders))
        proc = timing.ChildProcess(child_command(mapper, scene, out, dims, plugin, pvpython),
                                   env=timing.child_environment(), timeout=timeout)
        images[row] = np.load(out) if proc.ready and os.path.exists(out) else None
        first = proc.line(FIRST_PREFIX)
        if dims and first:
            once[row] = float(first)
        contenders.append(timing.Child(row, proc))
    return contenders, images, once


def child_command(mapper, scene, out, dims=None, plugin=None, pvpython=None):
    """The command of a child pvpython (`pvpython`, default: the one on PATH) drawing `mapper`
    (with sampling dimensions `dims` cubed, for 'Resample To Image') on the scene written by
    Capture.write_child_scene to `scene` (child_main), loading the plugin `plugin`."""
    argv = [timing.pvpython(pvpython), "--force-offscreen-rendering", "-m", __spec__.name,
            "--child-mapper", mapper, "--child-scene", scene, "--child-out", out]
    if plugin:
        argv += ["--plugin", plugin]
    return argv + (["--child-dims", str(dims)] if dims else [])


def errors(img, ref):
    if img is None:
        return float("nan"), float("nan")
    e = np.abs(img - ref)
    return float(e.mean()), float(e.max())


def report(view=None, rep=None, src=None, out_dir="psi_accuracy", frames=3,
           paraview_mappers=PARAVIEW_MAPPERS, title=None, paraview_timeout=120, budget=300.0,
           resample_dims=RESAMPLE_DIMS, progress=None, plugin=None, reference_renderer=None,
           pvpython=None, threads="all", back_to_front=False):
    """Renders the active (or given) view's volume with every method and mapper, the
    interactive image of 'Psi Volume' and 'Resample To Image' at each of `resample_dims`,
    measures each image against the exact reference at the same view, prints the table and
    writes out_dir/report.md, accuracy.png and methods.png. Returns the rows as dicts.
    `progress(fraction, step)`, when given, is told each step (psivolume.progress.Progress).
    The display, its maps, the view and its camera are left as they were, also when it fails.
    Where things are: `plugin` (default: the one loaded, data.find_plugin), which the child
    pvpythons (`pvpython`, default: the one on PATH) load; `reference_renderer` (default:
    find_reference_renderer beside that plugin). `threads`: the llvmpipe thread count the
    report names (this process's LP_NUM_THREADS; "all": Mesa's default). `back_to_front`: also
    each method with EarlyRayTermination off, to show what early ray termination changes."""
    step = progress or (lambda fraction, text: None)
    view = view or simple.GetActiveView()
    src = src or simple.GetActiveSource()
    rep = rep or simple.GetDisplayProperties(src, view)
    os.makedirs(out_dir, exist_ok=True)
    displays = volume_displays(view, rep, src)
    with restore.scene(view, *[d for d, _ in displays]), \
            tempfile.TemporaryDirectory(prefix="psi_accuracy_") as work:
        simple.Render(view)
        step(0.0, "the mesh and the scene")
        cap = volume_captures(view, displays, work)
        plugin = data.find_plugin(plugin)
        cap.plugin, cap.pvpython = plugin, pvpython
        cap.reference_renderer = find_reference_renderer(reference_renderer, plugin)
        rows, ref, timed, method = measure(cap, step, frames, paraview_mappers, paraview_timeout,
                                           budget, resample_dims, back_to_front)
    for r in rows:
        r["mean"], r["max"] = errors(r["image"], ref)
        r["err_s"] = r["mean"] * r["spf"] if r["spf"] is not None else float("nan")
    info = dict(title=title or "%s (%s)" % (src.GetXMLLabel(), cap.array), cells=cap.cells,
                size=cap.size, frames=frames, timing=timed.summary(), baseline=BASELINE,
                rounds=timed.rounds, converged=timed.converged,
                threads=threads, interactive_method=method)
    print(accuracy_plots.table_text(rows, info))
    step(0.95, "the plots")
    accuracy_plots.write_all(rows, ref, info, out_dir)
    step(1.0, "done")
    return [{k: v for k, v in r.items() if k != "image"} for r in rows]


def measure(cap, step, frames, paraview_mappers, paraview_timeout, budget, resample_dims,
            back_to_front=False):
    """The images and times of the scene `cap` (report()), changing the display's settings as it
    goes: (rows with their images, the reference image, the timing result, the method of the
    interactive row)."""
    rep, view = cap.rep, cap.view
    for c in [cap] + cap.others:
        if c.rep.Representation != "Psi Volume":
            c.rep.SetRepresentationType("Psi Volume")
    simple.Render(view)
    step(0.05, "the exact reference")
    refs, ref_seconds = reference_image(cap, cap.reference_renderer)
    method = rep.GetProperty("IntegrationMethod").GetData()
    methods = list(rep.GetProperty("IntegrationMethod").Available)
    step(0.2, "the images of 'Psi Volume'")
    psi, images = psi_contenders(cap, methods, back_to_front)
    live, images[INTERACTIVE], build, live_note = interactive_contender(cap, method)
    step(0.3, "ParaView's mappers")
    pv, pv_images, once = paraview_contenders(cap, paraview_mappers, paraview_timeout,
                                              resample_dims, cap.plugin, cap.pvpython)
    images.update(pv_images)
    once[INTERACTIVE] = build
    step(0.4, "timing rounds")
    started = time.perf_counter()

    def log(message):
        print("  " + message, flush=True)
        spent = (time.perf_counter() - started) / max(budget, 1e-3)
        step(0.4 + 0.55 * min(spent, 1.0), "timing rounds")

    timed = timing.interleaved(psi + [live] + pv, BASELINE, frames=frames, budget=budget,
                               min_rounds=5, log=log)
    rows = []
    for c in psi + [live] + pv:
        note = timed.notes[c.name] or (live_note if c is live else "")
        rows.append(dict(name=c.name, image=images.get(c.name), once=once.get(c.name),
                         note=note, **timed.row(c.name)))
    rows.append(dict(name=REFERENCE, spf=ref_seconds, image=refs[-1], note="", once=None,
                     spf_min=ref_seconds, spf_max=ref_seconds, cpu=None, ratio=None,
                     ratio_spread=None, rounds=1))
    return rows, refs[0], timed, method


def child_volume(view, v, args):
    """One volume of a child's scene (Capture.child_volume) shown in `view` with `args`' mapper,
    with color and opacity maps of its own (every mesh's array has the same name)."""
    reader = simple.XMLUnstructuredGridReader(FileName=[v["mesh"]])
    d = simple.Show(reader, view)
    simple.ColorBy(d, (v["association"], v["array"]))
    d.UseSeparateColorMap = 1
    lut = simple.GetColorTransferFunction(v["array"], d, separate=True)
    pwf = simple.GetOpacityTransferFunction(v["array"], d, separate=True)
    d.LookupTable, d.ScalarOpacityFunction = lut, pwf
    lut.AutomaticRescaleRangeMode = "Never"
    lut.RGBPoints = v["rgb_points"]
    lut.ColorSpace = v["color_space"]
    lut.VectorMode = v["vector_mode"]
    lut.VectorComponent = v["vector_component"]
    pwf.Points = v["opacity_points"]
    data.set_mapper(d, args.child_mapper)
    if args.child_dims:
        d.SamplingDimensions = [args.child_dims] * 3
    d.ScalarOpacityUnitDistance = v["unit"]
    return d


def child_main(args):
    """One mapper on the captured scene (one of ParaView's, or 'Psi Volume|<method>'): saves its
    image as .npy, then draws the timing rounds it is asked for (timing.serve_rounds)."""
    with open(args.child_scene) as f:
        s = json.load(f)
    if args.child_mapper.startswith("Psi Volume"):
        data.load_plugin(globals(), args.plugin, args.build_dir)
    view = simple.CreateRenderView()
    view.ViewSize = s["size"]
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = s["background"]
    displays = [child_volume(view, v, args) for v in s["volumes"]]
    c = s["camera"]
    view.CameraPosition, view.CameraFocalPoint, view.CameraViewUp = (
        c["position"], c["focal"], c["up"])
    view.CameraViewAngle = c["angle"]
    view.CameraParallelProjection = c["parallel"]
    view.CameraParallelScale = c["scale"]
    # the first frame, apart: 'Resample To Image' resamples the mesh in it
    print(FIRST_PREFIX + repr(timing.frame(view)[0]), flush=True)
    np.save(args.child_out, grab(view))
    timing.serve_rounds(view, displays[0])
    process.exit_now(0)


def command_scene(args):
    """Source, array and a view for the command line: FILE, a shared dataset or the Wavelet."""
    if args.file:
        name = args.file
        shared = name in data.PLOT3D or name in data.NAMED_FILES
        if shared and not os.path.exists(data.shared_file(name, args.data_dir)):
            print("SKIP: %s not found in %s" % (name, args.data_dir or data.DATA_DIR))
            process.exit_now(SKIP)
    src, array = data.open_or_wavelet(args.file, args.array, args.wavelet_half, args.data_dir)
    view, d = data.volume_view(src, array, args.size, args.unit_distance)
    simple.SetActiveView(view)
    simple.SetActiveSource(src)
    title = args.file or "Wavelet %d^3, tetrahedralized" % (2 * args.wavelet_half + 1)
    return view, d, src, "%s (%s)" % (title, array)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("file", nargs="?")
    p.add_argument("--array")
    p.add_argument("--out", default="psi_accuracy")
    p.add_argument("--size", type=int, default=384)
    p.add_argument("--frames", type=int, default=3)
    p.add_argument("--wavelet-half", type=int, default=20)
    p.add_argument("--unit-distance", type=float)
    p.add_argument("--back-to-front", action="store_true",
                   help="also each method with EarlyRayTermination off")
    p.add_argument("--no-paraview", action="store_true",
                   help="skip ParaView's own mappers ('Resample To Image' too)")
    p.add_argument("--paraview-mappers", nargs="*", default=PARAVIEW_MAPPERS,
                   help="which of ParaView's mappers (default: %s)" % ", ".join(PARAVIEW_MAPPERS))
    p.add_argument("--resample-dims", type=int, nargs="*", default=RESAMPLE_DIMS,
                   help="'Resample To Image' rows at these sampling dimensions, cubed (default: "
                        "%s; none: no such row)" % " ".join(map(str, RESAMPLE_DIMS)))
    p.add_argument("--paraview-timeout", type=float, default=120,
                   help="seconds each ParaView mapper may take (Z sweep is slow on big meshes)")
    p.add_argument("--budget", type=float, default=300,
                   help="seconds of timing rounds at most (they stop earlier once every ratio "
                        "to Average is within 5%%)")
    p.add_argument("--data-dir", help="the shared datasets (default: ../shared/data beside the "
                   "checkout)")
    p.add_argument("--plugin", help="the plugin's file (default: the installed one, else the "
                   "build's)")
    p.add_argument("--build-dir", help="the build to find the plugin in (default: build/)")
    p.add_argument("--reference-renderer", help="psi_reference_render (default: beside the "
                   "plugin, or in the build's bin/)")
    p.add_argument("--pvpython", help="the pvpython of the child processes (default: PATH's)")
    p.add_argument("--threads", default="all", help="the llvmpipe thread count the report names "
                   "(LP_NUM_THREADS; default: all)")
    p.add_argument("--child-mapper", help=argparse.SUPPRESS)
    p.add_argument("--child-scene", help=argparse.SUPPRESS)
    p.add_argument("--child-out", help=argparse.SUPPRESS)
    p.add_argument("--child-dims", type=int, help=argparse.SUPPRESS)
    args = p.parse_args()
    if args.child_mapper:
        child_main(args)
    data.load_plugin(globals(), args.plugin, args.build_dir)
    view, rep, src, title = command_scene(args)
    report(view, rep, src, args.out, args.frames,
           [] if args.no_paraview else args.paraview_mappers, title, args.paraview_timeout,
           args.budget, [] if args.no_paraview else args.resample_dims,
           plugin=data.find_plugin(args.plugin, args.build_dir),
           reference_renderer=args.reference_renderer, pvpython=args.pvpython,
           threads=args.threads, back_to_front=args.back_to_front)
    process.exit_now(0)


if __name__ == "__main__":
    main()
