"""Benchmark (not a test): 'Psi Volume' against ParaView's own unstructured volume mappers, in one
run, on the same data, views and transfer function.

pvpython Benchmarks/bench_mappers.py [--data bluntfin|post|comb|wavelet|FILE] [--size 512]
                                     [--frames 12] [--error-views 3] [--mappers ...]
Prints seconds/frame, tets/s, the ratio to 'Projected tetra', and the mean and max pixel error
(0..255 per channel) against an exact reference: VTK's Bunyk ray caster with
vtkUnstructuredGridLinearRayIntegrator (linear color and attenuation, split at transfer-function
control points). The color map is put in RGB space so that the reference is exact for it
(ParaView's default Diverging space is not linear between control points, which the linear
integrator assumes)."""
import argparse
import math
import os
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Python"))
import psi_data  # noqa: E402
from paraview import simple  # noqa: E402
from vtkmodules.vtkRenderingVolume import vtkUnstructuredGridLinearRayIntegrator  # noqa: E402
from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402
import numpy as np  # noqa: E402

p = argparse.ArgumentParser()
p.add_argument("--data", default="bluntfin")
p.add_argument("--size", type=int, default=512)
p.add_argument("--frames", type=int, default=12)
p.add_argument("--error-views", type=int, default=3)
p.add_argument("--unit-distance", type=float)
p.add_argument("--png-dir", default="")
p.add_argument("--mappers", nargs="*", default=[
    "Psi Volume|Partial Pre-Integration", "Psi Volume|Average", "Projected tetra",
    "Bunyk ray cast", "Resample To Image"])
args = p.parse_args()

psi_data.load_plugin(globals())
if args.data == "wavelet":
    src, array = psi_data.wavelet()
elif args.data in psi_data.PLOT3D:
    if not os.path.exists(os.path.join(psi_data.SHARED_DATA, psi_data.PLOT3D[args.data][0])):
        raise SystemExit("SKIP: %s not found in %s" % (args.data, psi_data.SHARED_DATA))
    src, array = psi_data.plot3d(args.data)
else:
    src, array = psi_data.open_any(args.data)
src.UpdatePipeline()
ncells = src.GetDataInformation().GetNumberOfCells()

view = simple.CreateRenderView()
view.ViewSize = [args.size, args.size]
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.Background = [0.0, 0.0, 0.0]
d = psi_data.show_volume(src, array, view, representation="Volume",
                         unit_distance=args.unit_distance)
lut = simple.GetColorTransferFunction(array)
lut.ColorSpace = "RGB"
simple.Render(view)
view.ResetCamera()
cam = view.GetActiveCamera()
cam.Elevation(25)
view.ResetCamera()
cam.Zoom(1.3)


def set_mapper(name):
    if name.startswith("Psi Volume"):
        d.SetRepresentationType("Psi Volume")
        d.IntegrationMethod = name.split("|")[1]
    else:
        d.SetRepresentationType("Volume")
        d.SelectMapper = name


def grab():
    w2i = vtkWindowToImageFilter()
    w2i.SetInput(view.GetRenderWindow())
    w2i.ReadFrontBufferOff()
    w2i.ShouldRerenderOff()
    w2i.Update()
    im = w2i.GetOutput()
    a = vtk_to_numpy(im.GetPointData().GetScalars()).reshape(args.size, args.size, -1)
    return a[:, :, :3].astype(np.float64)


def orbit_to(k, n):
    cam.SetPosition(*view.CameraPosition)  # no-op keeps VTK camera in sync
    cam.Azimuth(360.0 / n)


# Reference images at the error viewpoints (Bunyk + linear integrator: exact, slow).
error_steps = [int(i * args.frames / args.error_views) for i in range(args.error_views)]
references = {}
set_mapper("Bunyk ray cast")
simple.Render(view)
bunyk = d.GetClientSideObject().GetActiveRepresentation().GetActiveVolumeMapper()
linear = vtkUnstructuredGridLinearRayIntegrator()
start = [view.CameraPosition[:], view.CameraFocalPoint[:], view.CameraViewUp[:]]


def reset_camera():
    view.CameraPosition, view.CameraFocalPoint, view.CameraViewUp = start


t0 = time.perf_counter()
bunyk.SetRayIntegrator(linear)
reset_camera()
for k in range(args.frames):
    if k in error_steps:
        simple.Render(view)
        references[k] = grab()
    cam.Azimuth(360.0 / args.frames)
ref_seconds = (time.perf_counter() - t0) / max(len(references), 1)
bunyk.SetRayIntegrator(None)

rows = []
for name in args.mappers:
    set_mapper(name)
    reset_camera()
    simple.Render(view)  # warm-up: uploads, tables, shader compilation
    psi_data.wait(view)
    times, errs, maxes = [], [], []
    for k in range(args.frames):
        t = time.perf_counter()
        simple.Render(view)
        psi_data.wait(view)
        times.append(time.perf_counter() - t)
        if k in references:
            img = grab()
            e = np.abs(img - references[k])
            errs.append(e.mean())
            maxes.append(e.max())
            if args.png_dir:
                simple.SaveScreenshot(os.path.join(args.png_dir, "%s_%d.png" % (
                    name.replace(" ", "_").replace("|", "_"), k)), view)
        cam.Azimuth(360.0 / args.frames)
    spf = sum(times) / len(times)
    rows.append((name, spf, ncells / spf, float(np.mean(errs)), float(np.max(maxes))))

pt = [r for r in rows if r[0] == "Projected tetra"]
pt_spf = pt[0][1] if pt else float("nan")
pt_err = pt[0][3] if pt else float("nan")
print()
print("dataset %s: %d tetrahedra, %dx%d, %d orbit frames, error at %d views vs Bunyk+linear "
      "integrator (%.1f s/frame)" % (args.data, ncells, args.size, args.size, args.frames,
                                     len(references), ref_seconds))
print("%-36s %10s %12s %11s %11s %11s %9s" % ("mapper", "s/frame", "tets/s", "speed/PT",
                                             "mean err", "err/PT", "max err"))
for name, spf, tps, err, mx in rows:
    print("%-36s %10.4f %12.0f %10.2fx %11.3f %10.2fx %9.0f" % (
        name, spf, tps, pt_spf / spf, err, err / pt_err if pt_err else float("nan"), mx))
