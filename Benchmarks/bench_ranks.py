"""Benchmark (not a test): 'Psi Volume' on 1, 2 and 4 ranks of pvbatch (MPI, ParaView's ordered
compositing) on one mesh: s/frame, the largest and the summed peak RSS of the ranks, and the
image against the 1-rank image.

pvpython Benchmarks/bench_ranks.py [--half 40] [--ranks 1 2 4] [--size 512] [--frames 3]
                                   [--mapper "Psi Volume" | "Projected tetra"]

--half is the half-extent of ParaView's Wavelet, tetrahedralized (5 tets per voxel): 40 gives
2,560,000 tetrahedra, split among the ranks by the Wavelet's own pieces. Each run is
`mpiexec -n N pvbatch --symmetric` (every rank runs the worker, so that every rank reports its
own peak RSS); the image compared is the composited one on rank 0. Image differences are in
1/255 units (mean, max, share of pixels off by more than 24/255, the MPI test's tolerance)."""
import argparse
import json
import os
import resource
import subprocess
import sys
import tempfile

from psivolume import data, process, testing, timing


def worker(args):
    import numpy as np
    from mpi4py import MPI
    from paraview import simple
    from vtkmodules.util.numpy_support import vtk_to_numpy

    comm = MPI.COMM_WORLD
    data.load_plugin(globals())
    src, array = data.wavelet(args.half)
    src.UpdatePipeline()
    view = simple.CreateRenderView()
    view.ViewSize = [args.size, args.size]
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [0.0, 0.0, 0.0]
    d = simple.Show(src, view)
    simple.ColorBy(d, ("POINTS", array))
    if args.mapper == "Psi Volume":
        d.SetRepresentationType("Psi Volume")
    else:
        d.SetRepresentationType("Volume")
        d.SelectMapper = args.mapper
    lut = simple.GetColorTransferFunction(array)
    pwf = simple.GetOpacityTransferFunction(array)
    lut.RescaleTransferFunction(37.35, 276.8)  # the Wavelet's range, the same for every run
    pwf.RescaleTransferFunction(37.35, 276.8)
    c = view.GetActiveCamera()
    c.SetFocalPoint(0, 0, 0)
    c.SetPosition(4 * args.half, 2.2 * args.half, 3 * args.half)
    c.SetViewUp(0, 0, 1)
    h = float(args.half)
    view.ResetCamera(-h, h, -h, h, -h, h)
    spf = timing.time_frames(view, args.frames, warmup=1, jitter=0.0)[0]
    im = view.SMProxy.CaptureWindow(1)
    rss = comm.gather(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0, root=0)
    if comm.Get_rank() == 0:
        dims = im.GetDimensions()
        a = vtk_to_numpy(im.GetPointData().GetScalars()).reshape(dims[1], dims[0], -1)
        np.save(args.out, a[:, :, :3].astype(np.float64))
        print("RESULT " + json.dumps({"spf": spf, "rss": rss}), flush=True)
    comm.Barrier()
    testing.exit_now(0)


def run(n, args, out):
    env = process.environment_without_mpi()
    cmd = ["mpiexec", "--allow-run-as-root", "--oversubscribe", "-n", str(n), "pvbatch",
           "--symmetric", "--force-offscreen-rendering", os.path.abspath(__file__), "--worker",
           "--half", str(args.half), "--size", str(args.size), "--frames", str(args.frames),
           "--mapper", args.mapper, "--out", out]
    p = subprocess.run(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       universal_newlines=True, timeout=args.timeout)
    for line in p.stdout.splitlines():
        if line.startswith("RESULT "):
            return json.loads(line[len("RESULT "):])
    sys.stderr.write("run with %d ranks failed:\n%s\n" % (n, p.stdout[-3000:]))
    return None


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--worker", action="store_true")
    p.add_argument("--half", type=int, default=40)
    p.add_argument("--ranks", nargs="*", type=int, default=[1, 2, 4])
    p.add_argument("--size", type=int, default=512)
    p.add_argument("--frames", type=int, default=3)
    p.add_argument("--mapper", default="Psi Volume")
    p.add_argument("--out", default="")
    p.add_argument("--timeout", type=float, default=3000)
    args = p.parse_args()
    if args.worker:
        worker(args)
        return
    import numpy as np
    tmp = tempfile.mkdtemp()
    print("%-6s %9s %16s %14s %10s %9s %12s" % ("ranks", "s/frame", "max rank RSS MB",
                                                 "sum RSS MB", "mean diff", "max diff",
                                                 "px > 24/255"))
    first = None
    for n in args.ranks:
        out = os.path.join(tmp, "ranks%d.npy" % n)
        r = run(n, args, out)
        if not r:
            continue
        img = np.load(out)
        first = img if first is None else first
        d = np.abs(img - first)
        print("%-6d %9.3f %16.0f %14.0f %10.3f %9.0f %11.2f%%" % (
            n, r["spf"], max(r["rss"]), sum(r["rss"]), d.mean(), d.max(),
            100.0 * (d.max(axis=2) > 24).mean()), flush=True)


if __name__ == "__main__":
    main()
