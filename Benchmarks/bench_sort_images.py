"""Benchmark (not a test): image difference between centroid and MPVONC visibility order from many
viewpoints, as in Maximo et al. 2010, Table 1: max error, mean error, % of differing pixels.

pvpython Benchmarks/bench_sort_images.py [--data bluntfin] [--size 512] [--views 12]"""
import argparse

import numpy as np

from paraview import simple

from psivolume import bench, data, testing

p = argparse.ArgumentParser()
p.add_argument("--data", default="bluntfin")
p.add_argument("--size", type=int, default=512)
p.add_argument("--views", type=int, default=12)
args = p.parse_args()

data.load_plugin(globals())
src, array = bench.load(args.data)
scene = bench.Scene(src, array, args.size, args.views)
scene.set_mapper("Psi Volume|Partial Pre-Integration")
rep = scene.rep
maxes, means, differing, cycles = [], [], [], []
for k in range(args.views):
    imgs = {}
    for sort in ("Centroid", "MPVONC"):
        rep.SortMethod = sort
        simple.Render(scene.view)
        imgs[sort] = testing.grab(scene.view)
        if sort == "MPVONC":
            rep.UpdatePropertyInformation()
            cycles.append(rep.GetProperty("LastSortCycles").GetElement(0))
    d = np.abs(imgs["Centroid"] - imgs["MPVONC"]).max(axis=2)
    covered = testing.covered(imgs["MPVONC"], [0, 0, 0])
    maxes.append(d.max())
    means.append(d.mean())
    differing.append(100.0 * (d > 0).sum() / max(covered, 1))
    scene.step()
print("\n%s, %d tetrahedra, %dx%d, %d views: centroid vs MPVONC order (0..255)" % (
    args.data, scene.cells, args.size, args.size, args.views))
print("max error %.0f, mean error %.4f, differing pixels %.2f%% of covered (mean over views; "
      "max error is the max over views); MPVONC cycles broken per view: %.1f" % (
          max(maxes), float(np.mean(means)), float(np.mean(differing)), float(np.mean(cycles))))
testing.exit_now(0)
