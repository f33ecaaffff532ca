"""Shared parts of the pvpython benchmarks: a scene orbited at a fixed size, images grabbed from
the view, and the exact reference (ParaView's Bunyk ray caster with VTK's linear ray integrator)
at chosen orbit steps."""
import os

import numpy as np
from paraview import simple
from vtkmodules.vtkRenderingVolume import vtkUnstructuredGridLinearRayIntegrator

from . import data, images, process, timing
from .data import set_mapper  # noqa: F401 (the benchmarks' name for it)


def load(name, data_dir=None):
    """Source and array for 'wavelet', a PLOT3D name or a file (shared datasets from `data_dir`,
    default data.DATA_DIR). A benchmark on a PLOT3D dataset whose files are absent prints SKIP
    and ends here."""
    if name == "wavelet":
        return data.wavelet()
    if name in data.PLOT3D:
        if not os.path.exists(data.shared_file(name, data_dir)):
            print("SKIP: %s not found in %s" % (name, data_dir or data.DATA_DIR))
            process.exit_now(0)
        return data.plot3d(name, data_dir)
    return data.open_any(name, data_dir=data_dir)


# 'Psi Volume' with each projector (vtkPsiVolumeMapper::Projectors); plain 'Psi Volume' is Auto.
PROJECTORS = {"Psi Volume GS": "Geometry Shader", "Psi Volume CS": "Compute Shader"}


def scale_view(source, array, mapper, size):
    """The scene of bench_scale.py and bench_threads.py: `source` colored by `array` in a
    size x size view, drawn by `mapper` ("Psi Volume GS", "Psi Volume CS", either with " fan"
    for Shirley and Tuchman's fan and/or " back to front" or " front to back" for
    EarlyRayTermination 'Off' or 'On' (each way fixed, nothing timed), "Psi Volume" for every
    'Auto' (the ways timed on the first frames, psi::MeasuredChoice), "Outline" for the
    'Outline' representation, or one of ParaView's SelectMapper values), the camera reset and
    raised 25 degrees. Returns (view, rep)."""
    view = simple.CreateRenderView()
    view.ViewSize = [size, size]
    view.OrientationAxesVisibility = 0
    rep = data.show_volume(source, array, view, representation="Volume")
    if mapper == "Outline":  # ParaView's fixed cost of a frame, to take from the others'
        rep.SetRepresentationType("Outline")
    elif mapper.startswith("Psi Volume"):
        rep.SetRepresentationType("Psi Volume")
        if mapper == "Psi Volume":
            rep.Projector = rep.Decomposition = rep.EarlyRayTermination = "Auto"
        else:
            direction = {" back to front": "Off", " front to back": "On"}
            ending = next((e for e in direction if mapper.endswith(e)), "")
            name = mapper[:len(mapper) - len(ending)]
            fan = name.endswith(" fan")
            rep.Projector = PROJECTORS.get(name[:-len(" fan")] if fan else name, "Auto")
            rep.Decomposition = "Fan" if fan else "Silhouette"
            rep.EarlyRayTermination = direction.get(ending, "Auto")
    else:
        rep.SelectMapper = mapper
    view.ResetCamera()
    view.GetActiveCamera().Elevation(25)
    view.ResetCamera()
    return view, rep


def align_color_points(lut, pwf):
    """Adds a color point at every opacity point (colors interpolated in RGB, so the map does not
    change). VTK 9.2's vtkUnstructuredGridLinearRayIntegrator, the reference of these benchmarks,
    takes the opacity function's control points only where the color map has one too (its loop
    over the opacity points ends at the first), so Bunyk + linear is exact only with aligned
    points and a color map interpolating in RGB."""
    rgb = list(lut.RGBPoints)
    xs = rgb[0::4]
    for x in list(pwf.Points)[0::4]:
        if any(abs(x - c) <= 1e-12 * max(1.0, abs(x)) for c in xs):
            continue
        k = max(i for i in range(len(xs)) if xs[i] < x) if xs[0] < x else -1
        if k < 0 or k + 1 >= len(xs):
            continue  # outside the color map: clamped, constant there
        w = (x - xs[k]) / (xs[k + 1] - xs[k])
        c = [rgb[4 * k + j] + w * (rgb[4 * (k + 1) + j] - rgb[4 * k + j]) for j in (1, 2, 3)]
        rgb[4 * (k + 1):4 * (k + 1)] = [x] + c
        xs = rgb[0::4]
    lut.RGBPoints = rgb


class Scene:
    """One view orbiting a volume; the color map is in RGB space, with a point at every opacity
    point, so that the linear integrator (linear between control points) is exact for it."""

    def __init__(self, src, array, size=512, frames=12, unit_distance=None, transparent_below=0.0):
        self.frames = frames
        self.view = simple.CreateRenderView()
        self.view.ViewSize = [size, size]
        self.view.OrientationAxesVisibility = 0
        self.view.UseColorPaletteForBackground = 0
        self.view.Background = [0.0, 0.0, 0.0]
        self.rep = data.show_volume(src, array, self.view, representation="Volume",
                                    unit_distance=unit_distance)
        simple.GetColorTransferFunction(array).ColorSpace = "RGB"
        if transparent_below > 0:
            # opacity 0 on the lower part of the range, then a ramp to 1: a typical user choice,
            # and the case HAPT's early discard (section 3.5) is for
            pwf = simple.GetOpacityTransferFunction(array)
            lo, hi = pwf.Points[0], pwf.Points[-4]
            cut = lo + transparent_below * (hi - lo)
            pwf.Points = [lo, 0.0, 0.5, 0.0, cut, 0.0, 0.5, 0.0, hi, 1.0, 0.5, 0.0]
        align_color_points(simple.GetColorTransferFunction(array),
                           simple.GetOpacityTransferFunction(array))
        simple.Render(self.view)
        self.view.ResetCamera()
        cam = self.view.GetActiveCamera()
        cam.Elevation(25)
        self.view.ResetCamera()
        cam.Zoom(1.3)
        self.start = [self.view.CameraPosition[:], self.view.CameraFocalPoint[:],
                      self.view.CameraViewUp[:]]
        src.UpdatePipeline()
        self.cells = src.GetDataInformation().GetNumberOfCells()

    def reset_camera(self):
        self.view.CameraPosition, self.view.CameraFocalPoint, self.view.CameraViewUp = self.start

    def step(self):
        self.view.GetActiveCamera().Azimuth(360.0 / self.frames)

    def set_mapper(self, name):
        """'Psi Volume|<IntegrationMethod>' or one of ParaView's SelectMapper values."""
        set_mapper(self.rep, name)

    def references(self, steps):
        """Exact reference images (Bunyk + linear integrator) at the given orbit steps."""
        self.set_mapper("Bunyk ray cast")
        simple.Render(self.view)
        bunyk = self.rep.GetClientSideObject().GetActiveRepresentation().GetActiveVolumeMapper()
        bunyk.SetRayIntegrator(vtkUnstructuredGridLinearRayIntegrator())
        self.reset_camera()
        refs, seconds = {}, []
        for k in range(self.frames):
            if k in steps:
                seconds.append(timing.frame(self.view)[0])
                refs[k] = images.grab(self.view)
            self.step()
        bunyk.SetRayIntegrator(None)
        return refs, timing.frame_time(seconds) if seconds else float("nan")

    def errors(self, name, refs, png_dir=""):
        """Mean and max pixel error (0..255) of `name` against the reference images, over the
        orbit steps that have one."""
        self.set_mapper(name)
        self.reset_camera()
        errs, maxes = [], []
        for k in range(self.frames):
            if k in refs:
                simple.Render(self.view)
                img = images.grab(self.view)
                e = np.abs(img - refs[k])
                errs.append(e.mean())
                maxes.append(e.max())
                if png_dir:
                    simple.SaveScreenshot(os.path.join(png_dir, "%s_%d.png" % (
                        name.replace(" ", "_").replace("|", "_"), k)), self.view)
            self.step()
        self.reset_camera()
        return (float(np.mean(errs)) if errs else float("nan"),
                float(np.max(maxes)) if maxes else float("nan"))

    def timing(self, names, baseline, frames=3, budget=300.0):
        """Seconds per frame of each of `names` (mapper names as set_mapper takes them) in
        interleaved rounds, ratios to `baseline` (timing.interleaved), at the orbit's start."""
        def contender(name):
            def prepare():
                self.set_mapper(name)
                self.reset_camera()
            return timing.InProcess(name, self.view, prepare)

        return timing.interleaved([contender(n) for n in names], baseline, frames=frames,
                                  budget=budget, min_rounds=5,
                                  log=lambda m: print("  " + m, flush=True))
