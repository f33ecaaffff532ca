"""Frame time of each 'Psi Volume' feature alone and combined, on the Blunt Fin.

pvpython Benchmarks/bench_features.py [--size 512] [--frames 4] [--rounds 3] [--budget 300]

Configurations: the plain volume; the features switched on and then off again ("off after use",
which must cost nothing: the program is the plain one); 1 and 4 isosurfaces, drawn by marching
tetrahedra in the geometry shader (default) and per fragment; adaptive transfer-function
sampling; both; and plain contours (volume opacity zero, where marching tetrahedra let early
discard drop the volume and draw only the surfaces). Rounds are interleaved (psivolume.timing:
every configuration once per round, in a rotating order) so that drifts of the machine hit all
alike, until every ratio to the plain volume is within 5% after at least --rounds rounds, or
--budget seconds are spent; each configuration's frame time is the median over its rounds of the median
over an orbit of --frames frames, 'vs plain' the median of its ratios to the plain volume taken
round by round."""
import argparse

from paraview import simple

from psivolume import bench, data, testing, timing

parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
parser.add_argument("--size", type=int, default=512)
parser.add_argument("--frames", type=int, default=4)
parser.add_argument("--rounds", type=int, default=3,
                    help="interleaved rounds at least, unless the budget is spent first")
parser.add_argument("--budget", type=float, default=300, help="seconds of interleaved rounds")
args = parser.parse_args()

data.load_plugin(globals())
src, array = bench.load("bluntfin")  # SKIP when the data is absent
src.UpdatePipeline()
lo, hi = src.PointData[array].GetRange()
view = simple.CreateRenderView()
view.ViewSize = [args.size, args.size]
view.OrientationAxesVisibility = 0
d = data.show_volume(src, array, view)
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
    timing.frame(view)  # compile / fetch the program outside the timing


def contender(name, *config):
    return timing.InProcess(name, view, lambda: apply(*config), orbit=True)


res = timing.interleaved([contender(*c) for c in CONFIGS], "plain volume", frames=args.frames,
                         warmup=0, min_rounds=args.rounds, budget=args.budget, min_turn=0,
                         log=lambda m: print("  " + m, flush=True))
d.UpdatePropertyInformation()
ntets = d.GetProperty("NumberOfTetrahedra").GetElement(0)
print("Blunt Fin (%s), %d tetrahedra, %dx%d, %d frames an orbit; %s" %
      (array, ntets, args.size, args.size, args.frames, res.summary()))
print("%-30s %10s %10s %10s %8s" % ("configuration", "median s", "min s", "max s", "vs plain"))
for name, *_ in CONFIGS:
    r = res.row(name)
    print("%-30s %10.4f %10.4f %10.4f %7.2fx" %
          (name, r["spf"], r["spf_min"], r["spf_max"], r["ratio"]))
off, plain = res.row("features off after use"), res.row("plain volume")
print("off = free: features off after use %.4f s vs plain %.4f s (difference %+.1f%%, plain's own "
      "spread over rounds %.1f%%)" % (off["spf"], plain["spf"], 100 * (off["ratio"] - 1),
                                      100 * (plain["spf_max"] - plain["spf_min"]) / plain["spf"]))
testing.exit_now(0)
