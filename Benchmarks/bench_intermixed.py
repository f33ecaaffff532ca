"""Benchmark (not a test): what several volumes in one view cost. One tetrahedralized Wavelet of n
tetrahedra as one display (its lower and upper halves in z appended into one dataset), against the
same halves as two displays of n/2, which 'Psi Volume' draws intermixed in one visibility order and one
pass; beside ParaView's 'Volume' with 'Projected tetra' on the same two scenes (which draws the
two displays one after the other).

pvpython Benchmarks/bench_intermixed.py [--sizes 20 40] [--size 512] [--frames 3] [--budget 300]

--sizes are half-extents of ParaView's Wavelet (5 tetrahedra per voxel: 20 gives 320,000, 40
gives 2,560,000). For each size, in one process, one view per contender, interleaved rounds
(psivolume.timing.interleaved) print s/frame (median over the rounds) and the ratio to 'Psi
Volume' with one display (the target: two displays at most 1.1x); and the largest difference
(/255) of the two-display image from the one-display image of the same mapper at the same
view. Absolute times vary with the machine; the ratios are taken within one run."""
import argparse

import numpy as np
from paraview import simple

from psivolume import data, testing, timing


def wavelet(z0, z1, half):
    w = simple.Wavelet(WholeExtent=[-half, half, -half, half, z0, z1])
    return simple.Tetrahedralize(Input=w)


def view_of(sources, representation, mapper, size):
    view = testing.black_view(size)
    for src in sources:
        d = data.show_volume(src, "RTData", view, representation=representation,
                             unit_distance=2.0)  # ParaView sets each display its own otherwise
        if mapper:
            d.SelectMapper = mapper
    lut = simple.GetColorTransferFunction("RTData")
    lut.RescaleTransferFunction(37.0, 277.0)
    simple.GetOpacityTransferFunction("RTData").RescaleTransferFunction(37.0, 277.0)
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    half = sources[0].GetDataInformation().GetBounds()[1]
    view.CameraPosition = [2.2 * half * s for s in (1.0, 0.8, 2.4)]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    simple.Render(view)
    return view


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--sizes", type=int, nargs="+", default=[20, 40])
    ap.add_argument("--size", type=int, default=512)
    ap.add_argument("--frames", type=int, default=3)
    ap.add_argument("--budget", type=float, default=300.0)
    args = ap.parse_args()
    data.load_plugin(globals())
    simple._DisableFirstRenderCameraReset()
    for half in args.sizes:
        lower, upper = wavelet(-half, 0, half), wavelet(0, half, half)
        whole = simple.AppendDatasets(Input=[lower, upper])  # the same tetrahedra, one dataset
        views = {
            "Psi Volume, one display": view_of([whole], "Psi Volume", None, args.size),
            "Psi Volume, two displays": view_of([lower, upper], "Psi Volume", None, args.size),
            "Projected tetra, one display": view_of([whole], "Volume", "Projected tetra", args.size),
            "Projected tetra, two displays": view_of([lower, upper], "Volume", "Projected tetra",
                                                     args.size),
        }
        tets = whole.GetDataInformation().GetNumberOfCells()
        base = "Psi Volume, one display"
        contenders = [timing.InProcess(name, v) for name, v in views.items()]
        res = timing.interleaved(contenders, base, frames=args.frames, budget=args.budget)
        print("\nWavelet half-extent %d: %d tetrahedra, %d x %d pixels; %s"
              % (half, tets, args.size, args.size, res.summary()))
        print("| contender | s/frame | / %s |" % base)
        print("|---|---|---|")
        for name in views:
            row = res.row(name)
            print("| %s | %.3f | %.2f |" % (name, row["spf"], row["ratio"]))
        for mapper in ("Psi Volume", "Projected tetra"):
            one, two = (views["%s, %s" % (mapper, n)] for n in ("one display", "two displays"))
            simple.Render(one)  # the rounds' last frames were turned by their jitter
            simple.Render(two)
            one, two = testing.grab(one), testing.grab(two)
            print("%s: two displays against one, largest difference %.0f/255"
                  % (mapper, float(np.abs(one - two).max())))
        for v in views.values():
            simple.Delete(v)
        del views, contenders
    testing.exit_now(0)


if __name__ == "__main__":
    main()
