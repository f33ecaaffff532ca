"""Benchmark (not a test): what accuracy costs in time, for every integration method.

pvpython Benchmarks/bench_integration.py [--data bluntfin] [--size 512] [--frames 6]
                                         [--plot integration_cost.png] [--build-dir build]
                                         [--cpu-program FILE]
For each method: CPU ns per segment and max/mean error over Moreland's sweeps (from
bench_integration_cpu, against each method's own optical-model reference), frame time of
'Psi Volume' on the dataset (median over interleaved rounds with 'Projected tetra',
psivolume.timing), and mean image error against the exact reference image (Bunyk +
linear integrator; methods 4-6 assume a different optical model, linear opacity, so part of their
image error is the model difference). Writes the table and a plot (error vs time, one point per
method) as PNG."""
import argparse
import csv
import glob
import io
import os
import subprocess

from psivolume import bench, data, testing

here = os.path.dirname(os.path.abspath(__file__))

p = argparse.ArgumentParser()
p.add_argument("--data", default="bluntfin")
p.add_argument("--size", type=int, default=512)
p.add_argument("--frames", type=int, default=6)
p.add_argument("--error-views", type=int, default=2)
p.add_argument("--budget", type=float, default=300, help="seconds of interleaved timing rounds")
p.add_argument("--plot", default="integration_cost.png")
p.add_argument("--build-dir", default=os.path.join(here, "..", "build"),
               help="the build holding the plugin and bench_integration_cpu (default: build/)")
p.add_argument("--cpu-program", help="bench_integration_cpu (default: in the build's bin/)")
args = p.parse_args()

exe = args.cpu_program or (glob.glob(os.path.join(args.build_dir, "bin",
                                                  "bench_integration_cpu")) or [""])[0]
if not exe:
    raise SystemExit("bench_integration_cpu not built (scripts/build.sh)")
cpu = {row["method"]: row for row in csv.DictReader(io.StringIO(
    subprocess.run([exe, "--csv"], check=True, capture_output=True, text=True).stdout))}

data.load_plugin(globals(), build_dir=args.build_dir)
src, array = bench.load(args.data)
scene = bench.Scene(src, array, args.size, args.frames)
refs, ref_seconds = scene.references([int(i * args.frames / args.error_views)
                                      for i in range(args.error_views)])
# The methods as the plugin offers them: the IntegrationMethod enumeration (one entry per row of
# psi::IntegrationMethodTable(), which bench_integration_cpu iterates too).
methods = list(scene.rep.GetProperty("IntegrationMethod").Available)
missing = [m for m in methods if m not in cpu]
if missing:
    raise SystemExit("bench_integration_cpu has no row for %s: rebuild it" % ", ".join(missing))
names = ["Psi Volume|" + m for m in methods] + ["Projected tetra"]
timing = scene.timing(names, "Projected tetra", budget=args.budget)
rows = []
for m in methods:
    err, mx = scene.errors("Psi Volume|" + m, refs)
    spf = timing.row("Psi Volume|" + m)["spf"]
    c = cpu[m]
    scene.rep.UpdatePropertyInformation()
    pre = scene.rep.GetProperty("LastPreIntegrationSeconds").GetElement(0) \
        if c.get("pre_integration_table") == "1" else 0.0
    rows.append((m, float(c["ns_per_segment"]), float(c["max_err_D1"]), float(c["mean_err"]),
                 spf, err, mx, pre))
pt_err, _ = scene.errors("Projected tetra", refs)
pt_spf = timing.row("Projected tetra")["spf"]
print(timing.summary())

print()
print("dataset %s: %d tetrahedra at %dx%d; image error vs Bunyk+linear at %d views; "
      "Projected tetra: %.4f s/frame, mean image error %.3f" % (
          args.data, scene.cells, args.size, args.size, len(refs), pt_spf, pt_err))
header = ("method", "ns/seg", "sweep max D=1", "sweep mean", "s/frame", "image mean", "image max",
          "table build s")
print("%-34s %8s %14s %11s %9s %11s %10s %13s" % header)
for m, ns, smax, smean, spf, err, mx, pre in rows:
    print("%-34s %8.1f %14.2e %11.2e %9.4f %11.3f %10.0f %13.3f" % (m, ns, smax, smean, spf, err, mx, pre))

import matplotlib  # noqa: E402
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
fig, axes = plt.subplots(1, 2, figsize=(12, 4.8))
for m, ns, smax, smean, spf, err, mx, pre in rows:
    axes[0].scatter(ns, max(smax, 1e-16))
    axes[0].annotate(m, (ns, max(smax, 1e-16)), fontsize=7)
    axes[1].scatter(spf, err)
    axes[1].annotate(m, (spf, err), fontsize=7)
axes[1].scatter(pt_spf, pt_err, marker="x", color="k")
axes[1].annotate("ParaView Projected tetra", (pt_spf, pt_err), fontsize=7)
axes[0].set_xlabel("CPU ns per segment")
axes[0].set_ylabel("max error over Moreland's sweep, D = 1")
axes[0].set_yscale("log")
axes[0].set_title("Segment integral: error vs cost")
axes[1].set_xlabel("seconds per frame (%s, %d tets, %dx%d, llvmpipe)" % (
    args.data, scene.cells, args.size, args.size))
axes[1].set_ylabel("mean image error vs exact reference (0..255)")
axes[1].set_title("Rendering: error vs frame time")
fig.tight_layout()
fig.savefig(args.plot, dpi=110)
print("plot: %s" % os.path.abspath(args.plot))
testing.exit_now(0)
