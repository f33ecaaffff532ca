"""Frame time of each 'Psi Volume' feature alone and combined (issue 5), on the Blunt Fin.

pvpython Benchmarks/bench_features.py [--size 512] [--frames 4] [--rounds 3]

Configurations: the plain volume; the features switched on and then off again ("off after use",
which must cost nothing: the program is the plain one); 1 and 4 isosurfaces; adaptive
transfer-function sampling; and both. Rounds are interleaved (every configuration once per
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


CONFIGS = [
    ("plain volume", [], "Off"),
    ("features off after use", None, "Off"),
    ("isosurfaces 1", iso(1), "Off"),
    ("isosurfaces 4", iso(4), "Off"),
    ("adaptive sampling", [], "On"),
    ("isosurfaces 1 + adaptive", iso(1), "On"),
    ("isosurfaces 4 + adaptive", iso(4), "On"),
]


def apply(values, adaptive):
    if values is None:  # switch everything on, draw, and off again
        d.IsosurfaceValues = iso(4)
        d.AdaptiveSampling = "On"
        simple.Render(view)
        values = []
    d.IsosurfaceValues = values
    d.AdaptiveSampling = adaptive
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


results = {name: [] for name, _, _ in CONFIGS}
for r in range(args.rounds):
    k = r % len(CONFIGS)
    for name, values, adaptive in CONFIGS[k:] + CONFIGS[:k]:
        apply(values, adaptive)
        results[name].append(time_orbit())
d.UpdatePropertyInformation()
ntets = d.GetProperty("NumberOfTetrahedra").GetElement(0)
plain = statistics.median(results["plain volume"])
spread = max(results["plain volume"]) - min(results["plain volume"])
print("Blunt Fin (%s), %d tetrahedra, %dx%d, %d frames x %d interleaved rounds" %
      (array, ntets, args.size, args.size, args.frames, args.rounds))
print("%-28s %10s %10s %10s %8s" % ("configuration", "median s", "min s", "max s", "vs plain"))
for name, _, _ in CONFIGS:
    v = results[name]
    print("%-28s %10.4f %10.4f %10.4f %7.2fx" %
          (name, statistics.median(v), min(v), max(v), statistics.median(v) / plain))
off = statistics.median(results["features off after use"])
print("off = free: features off after use %.4f s vs plain %.4f s (difference %+.1f%%, plain's own "
      "spread over rounds %.1f%%)" % (off, plain, 100 * (off / plain - 1), 100 * spread / plain))
psi_testing.exit_now(0)
