"""Benchmark (not a test): 'Psi Volume' against ParaView's own unstructured volume mappers, in one
run, on the same data, views and transfer function.

pvpython Benchmarks/bench_mappers.py [--data bluntfin|post|comb|wavelet|FILE] [--size 512]
                                     [--frames 12] [--error-views 3] [--budget 300] [--mappers ...]
Prints seconds/frame (median over interleaved rounds, psivolume.timing), tets/s, the speed
relative to 'Projected tetra' (taken round by round), and the mean and max pixel error
(0..255 per channel) against an exact reference: VTK's Bunyk ray caster with
vtkUnstructuredGridLinearRayIntegrator (linear color and attenuation, split at transfer-function
control points). The color map is put in RGB space so that the reference is exact for it."""
import argparse

from psivolume import bench, data, testing

p = argparse.ArgumentParser()
p.add_argument("--data", default="bluntfin")
p.add_argument("--size", type=int, default=512)
p.add_argument("--frames", type=int, default=12)
p.add_argument("--error-views", type=int, default=3)
p.add_argument("--budget", type=float, default=300, help="seconds of interleaved timing rounds")
p.add_argument("--unit-distance", type=float)
p.add_argument("--png-dir", default="")
p.add_argument("--transparent-below", type=float, default=0.0,
               help="opacity 0 below this fraction of the scalar range (e.g. 0.5)")
p.add_argument("--mappers", nargs="*", default=[
    "Psi Volume|Partial Pre-Integration", "Psi Volume|Average", "Projected tetra",
    "Bunyk ray cast", "Resample To Image"])
args = p.parse_args()

data.load_plugin(globals())
src, array = bench.load(args.data)
scene = bench.Scene(src, array, args.size, args.frames, args.unit_distance,
                    args.transparent_below)
steps = [int(i * args.frames / args.error_views) for i in range(args.error_views)]
refs, ref_seconds = scene.references(steps)
errors = {name: scene.errors(name, refs, args.png_dir) for name in args.mappers}
baseline = "Projected tetra" if "Projected tetra" in args.mappers else args.mappers[0]
timing = scene.timing(args.mappers, baseline, budget=args.budget)
rows = [(name, timing.row(name)["spf"] or float("nan"), timing.row(name)["ratio"] or float("nan"))
        + errors[name] for name in args.mappers]
pt_err = errors.get("Projected tetra", (float("nan"),))[0]
print()
print("dataset %s: %d tetrahedra, %dx%d, %d orbit frames, error at %d views vs Bunyk+linear "
      "integrator (%.1f s/frame)%s" % (args.data, scene.cells, args.size, args.size, args.frames,
                                       len(refs), ref_seconds,
                                       ", opacity 0 below %.0f%% of the range" % (
                                           100 * args.transparent_below)
                                       if args.transparent_below else ""))
print(timing.summary())
print("%-36s %10s %12s %11s %11s %11s %9s" % ("mapper", "s/frame", "tets/s",
                                             "speed/PT" if baseline == "Projected tetra"
                                             else "speed/1st",
                                             "mean err", "err/PT", "max err"))
for name, spf, ratio, err, mx in rows:
    print("%-36s %10.4f %12.0f %10.2fx %11.3f %10.2fx %9.0f" % (
        name, spf, scene.cells / spf, 1.0 / ratio, err, err / pt_err if pt_err else float("nan"), mx))
testing.exit_now(0)
