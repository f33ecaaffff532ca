"""Renders a dataset with the 'Psi Volume' representation to a PNG and prints its frame time.

pvpython scripts/psi_render.py [FILE] [--out image.png] [--size 512] [--array NAME]
                               [--method 'Partial Pre-Integration'|'Average'] [--frames 10]
                               [--data-dir DIR] [--build-dir DIR] [--plugin FILE]
With no FILE, renders the embedded default (Wavelet, tetrahedralized). FILE may be any file
ParaView reads, a PLOT3D grid file (...xyz.bin; its q file is found beside it), or one of the
names bluntfin, post, comb (the NASA datasets of ../shared/data, or of --data-dir). The plugin
is the installed one, else the build's (build/, or --build-dir; --plugin names the file). The checkout's Python/ goes on
PYTHONPATH (scripts/run.sh sets it: PYTHONPATH=Python pvpython scripts/psi_render.py ...)."""
import argparse
import os

from paraview import simple

from psivolume import data, timing

parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
parser.add_argument("file", nargs="?")
parser.add_argument("--out", default="psi_volume.png")
parser.add_argument("--size", type=int, default=512)
parser.add_argument("--array")
parser.add_argument("--method", default="Partial Pre-Integration")
parser.add_argument("--frames", type=int, default=10)
parser.add_argument("--unit-distance", type=float)
parser.add_argument("--data-dir", help="the shared datasets (default: ../shared/data)")
parser.add_argument("--build-dir", help="the build holding the plugin (default: build/)")
parser.add_argument("--plugin", help="the plugin's file (default: found in the build)")
args = parser.parse_args()

data.load_plugin(globals(), args.plugin, args.build_dir)
src, array = data.open_or_wavelet(args.file, args.array, data_dir=args.data_dir)
view, d = data.volume_view(src, array, args.size, args.unit_distance)
d.IntegrationMethod = args.method
# the first frame (upload, Psi table, shader compile) untimed, then an orbit
frames = max(args.frames, 1)
spf = timing.time_frames(view, frames, warmup=1, orbit=True)[0]
simple.SaveScreenshot(args.out, view, ImageResolution=[args.size, args.size])
d.UpdatePropertyInformation()
ntets = d.GetProperty("NumberOfTetrahedra").GetElement(0)
skipped = d.GetProperty("NumberOfSkippedCells").GetElement(0)
print("dataset   : %s (array %s)" % (args.file or "embedded Wavelet 41^3, tetrahedralized", array))
print("tetrahedra: %d drawn, %d skipped" % (ntets, skipped))
print("method    : %s" % args.method)
print("frame time: %.4f s median over %d orbiting frames at %dx%d (%.0f tets/s)"
      % (spf, frames, args.size, args.size, ntets / spf if spf > 0 else 0))
print("image     : %s" % os.path.abspath(args.out))
