"""Renders a dataset with the 'Psi Volume' representation to a PNG and prints its frame time.

pvpython scripts/psi_render.py [FILE] [--out image.png] [--size 512] [--array NAME]
                               [--method 'Partial Pre-Integration'|'Average'] [--frames 10]
With no FILE, renders the embedded default (Wavelet, tetrahedralized). FILE may be any file
ParaView reads, a PLOT3D grid file (...xyz.bin; its q file is found beside it), or one of the
names bluntfin, post, comb (the NASA datasets of ../shared/data)."""
import argparse
import os
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Python"))
import psi_data  # noqa: E402
from paraview import simple  # noqa: E402

parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
parser.add_argument("file", nargs="?")
parser.add_argument("--out", default="psi_volume.png")
parser.add_argument("--size", type=int, default=512)
parser.add_argument("--array")
parser.add_argument("--method", default="Partial Pre-Integration")
parser.add_argument("--frames", type=int, default=10)
parser.add_argument("--unit-distance", type=float)
args = parser.parse_args()

psi_data.load_plugin(globals())
if args.file:
    src, array = psi_data.open_any(args.file, args.array)
else:
    src, array = psi_data.wavelet()
if array is None:
    raise SystemExit("%s has no point or cell array to render" % args.file)

view = simple.CreateRenderView()
view.ViewSize = [args.size, args.size]
view.OrientationAxesVisibility = 0
d = psi_data.show_volume(src, array, view, unit_distance=args.unit_distance)
d.IntegrationMethod = args.method
view.ResetCamera()
cam = view.GetActiveCamera()
cam.Azimuth(30)
cam.Elevation(20)
view.ResetCamera()
simple.Render(view)  # first frame: upload, Psi table, shader compile
psi_data.wait(view)
times = []
for i in range(args.frames):
    cam.Azimuth(360.0 / max(args.frames, 1))
    t0 = time.perf_counter()
    simple.Render(view)
    psi_data.wait(view)
    times.append(time.perf_counter() - t0)
simple.SaveScreenshot(args.out, view, ImageResolution=[args.size, args.size])
d.UpdatePropertyInformation()
ntets = d.GetProperty("NumberOfTetrahedra").GetElement(0)
skipped = d.GetProperty("NumberOfSkippedCells").GetElement(0)
mean = sum(times) / len(times) if times else float("nan")
print("dataset   : %s (array %s)" % (args.file or "embedded Wavelet 41^3, tetrahedralized", array))
print("tetrahedra: %d drawn, %d skipped" % (ntets, skipped))
print("method    : %s" % args.method)
print("frame time: %.4f s mean over %d orbiting frames at %dx%d (%.0f tets/s)"
      % (mean, len(times), args.size, args.size, ntets / mean if mean > 0 else 0))
print("image     : %s" % os.path.abspath(args.out))
