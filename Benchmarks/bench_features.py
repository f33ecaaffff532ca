"""Frame time of each 'Psi Volume' feature alone and combined, on the Blunt Fin.

pvpython Benchmarks/bench_features.py [--size 512] [--frames 4] [--rounds 3]

Configurations: the plain volume; the features switched on and then off again ("off after use",
which must cost nothing: the program is the plain one); 1 and 4 isosurfaces, drawn by marching
tetrahedra in the geometry shader (default) and per fragment; adaptive transfer-function
sampling; both; and plain contours (volume opacity zero, where marching tetrahedra let early
discard drop the volume and draw only the surfaces). Rounds are interleaved (every configuration once per
round, in a rotating order) so that drifts of the machine hit all alike; each configuration's
frame time is the median over its rounds of the mean over an orbit of frames."""
import argparse
import os
import statistics
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Python"))
import psi_bench  # noqa: E402
import psi_data  # noqa: E402
import psi_testing  # noqa: E402
from paraview import simple  # noqa: E402

parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
parser.add_argument("--size", type=int, default=512)
parser.add_argument("--frames", type=int, default=4)
parser.add_argument("--rounds", type=int, default=3)
args = parser.parse_args()

psi_data.load_plugin(globals())
src, array = psi_bench.load("bluntfin")  # SKIP when the data is absent
src.UpdatePipeline()
lo, hi = src.PointData[array].GetRange()
view = simple.CreateRenderView()
view.ViewSize = [args.size, args.size]
view.OrientationAxesVisibility = 0
d = psi_data.show_volume(src, array, view)
view.ResetCamera()
cam = view.GetActiveCamera()
cam.Azimuth(30)
cam.Elevation(20)
view.ResetCamera()


def iso(n):
    return [lo + (hi - lo) * (k + 1) / (n + 1) for k in range(n)]


MT, PF = "Marching Tetrahedra", "Per Fragment"
# name, isovalues (None: everything on, drawn, then off again), adaptive sampling, isosurface
# method, volume opacity zero (plain contours)
CONFIGS = [
    ("plain volume", [], "Off", MT, False),
    ("features off after use", None, "Off", MT, False),
    ("isosurfaces 1", iso(1), "Off", MT, False),
    ("isosurfaces 4", iso(4), "Off", MT, False),
    ("isosurfaces 1 per fragment", iso(1), "Off", PF, False),
    ("isosurfaces 4 per fragment", iso(4), "Off", PF, False),
    ("adaptive Auto (default)", [], "Auto", MT, False),
    ("adaptive sampling", [], "On", MT, False),
    ("isosurfaces 1 + adaptive", iso(1), "On", MT, False),
    ("isosurfaces 4 + adaptive", iso(4), "On", MT, False),
    ("contours 4 (opacity 0)", iso(4), "Off", MT, True),
    ("contours 4 per fragment", iso(4), "Off", PF, True),
]
otf = simple.GetOpacityTransferFunction(array)
ramp = list(otf.Points)


def apply(values, adaptive, method, contours_only):
    if values is None:  # switch everything on, draw, and off again
        d.IsosurfaceValues = iso(4)
        d.AdaptiveSampling = "On"
        d.IsosurfaceMethod = PF
        simple.Render(view)
        values = []
    otf.Points = [lo, 0.0, 0.5, 0.0, hi, 0.0, 0.5, 0.0] if contours_only else ramp
    d.IsosurfaceValues = values
    d.AdaptiveSampling = adaptive
    d.IsosurfaceMethod = method
    simple.Render(view)  # compile / fetch the program outside the timing
    psi_data.wait(view)


def time_orbit():
    times = []
    for _ in range(args.frames):
        cam.Azimuth(360.0 / args.frames)
        t0 = time.perf_counter()
        simple.Render(view)
        psi_data.wait(view)
        times.append(time.perf_counter() - t0)
    return sum(times) / len(times)


results = {c[0]: [] for c in CONFIGS}
for r in range(args.rounds):
    k = r % len(CONFIGS)
    for name, *config in CONFIGS[k:] + CONFIGS[:k]:
        apply(*config)
        results[name].append(time_orbit())
d.UpdatePropertyInformation()
ntets = d.GetProperty("NumberOfTetrahedra").GetElement(0)
plain = statistics.median(results["plain volume"])
spread = max(results["plain volume"]) - min(results["plain volume"])
print("Blunt Fin (%s), %d tetrahedra, %dx%d, %d frames x %d interleaved rounds" %
      (array, ntets, args.size, args.size, args.frames, args.rounds))
print("%-30s %10s %10s %10s %8s" % ("configuration", "median s", "min s", "max s", "vs plain"))
for name, *_ in CONFIGS:
    v = results[name]
    print("%-30s %10.4f %10.4f %10.4f %7.2fx" %
          (name, statistics.median(v), min(v), max(v), statistics.median(v) / plain))
off = statistics.median(results["features off after use"])
print("off = free: features off after use %.4f s vs plain %.4f s (difference %+.1f%%, plain's own "
      "spread over rounds %.1f%%)" % (off, plain, 100 * (off / plain - 1), 100 * spread / plain))
psi_testing.exit_now(0)
