"""Benchmark (not a test): 'Psi Volume' against ParaView's own unstructured volume mappers as the
mesh grows, each mapper in its own pvpython process so that peak memory is its own.

pvpython Benchmarks/bench_scale.py [--sizes 20 40 60] [--bluntfin] [--size 512] [--frames 4]
                                   [--mappers "Psi Volume GS" "Psi Volume GS fan" "Psi Volume CS"
                                              "Projected tetra"
                                              "Bunyk ray cast"]
                                   [--bunyk-max-tets 400000] [--threads 1 2]

--sizes are half-extents of ParaView's Wavelet, tetrahedralized (5 tets per voxel): 20 gives
320,000 tets, 40 gives 2,560,000 and 60 gives 8,640,000. For each mesh and mapper it prints:
  - first frame: seconds from the first Render to its completion (upload, sort, draw), the
    pipeline already updated;
  - s/frame: mean over an orbit of --frames frames, and the speed relative to 'Projected tetra';
  - peak RSS of the process (MB), and relative to 'Projected tetra';
  - thread scaling: s/frame with the first --threads value of LP_NUM_THREADS (Mesa llvmpipe's
    rendering threads) over s/frame with the last;
  - time step: a new time step of the same mesh (the scalars change, points and cells do not),
    rendered at a fixed view, over a plain frame at that view.
'Psi Volume' runs with its defaults (partial pre-integration, MPVONC), once with each projector:
"Psi Volume GS" the geometry shader, "Psi Volume CS" the compute shader ("Psi Volume": Auto).
"Psi Volume GS fan" draws the geometry shader's Shirley-Tuchman fan instead of the silhouettes
(the two give the same image). Bunyk runs only up to
--bunyk-max-tets. Ratios are taken within one run; absolute times vary with the machine."""
import argparse
import json
import os
import resource
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))

# Time steps on a fixed mesh: the output shares the input's points and cells (ShallowCopy), only
# the array "step" (the input's `array` scaled by 1 + 0.05 k) changes with time step k.
STEP_SCRIPT = """
import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk
inp = self.GetInput()
out = self.GetOutput()
out.ShallowCopy(inp)
rt = np.asarray(inp.GetPointData().GetArray("{array}"), dtype=np.float32)
a = numpy_to_vtk(rt * (1.0 + 0.05 * {k}), deep=1)
a.SetName("step")
out.GetPointData().AddArray(a)
"""


def worker(args):
    """One mapper on one mesh: prints one JSON line."""
    sys.path.insert(0, os.path.join(HERE, "..", "Python"))
    from paraview import simple
    import psi_bench
    import psi_data
    import psi_testing

    psi_data.load_plugin(globals())
    if args.data == "bluntfin":
        src, array = psi_bench.load("bluntfin")
    else:
        src, array = psi_data.wavelet(int(args.data))
    prog = simple.ProgrammableFilter(Input=src)
    prog.Script = STEP_SCRIPT.format(array=array, k=0)
    prog.CopyArrays = 0
    prog.UpdatePipeline()
    view, _ = psi_bench.scale_view(prog, "step", args.mapper, args.size)
    cells = prog.GetDataInformation().GetNumberOfCells()
    t = time.perf_counter()
    simple.Render(view)
    psi_data.wait(view)
    first = time.perf_counter() - t
    times = []
    for _ in range(args.frames):
        view.GetActiveCamera().Azimuth(360.0 / args.frames)
        t = time.perf_counter()
        simple.Render(view)
        psi_data.wait(view)
        times.append(time.perf_counter() - t)
    # fixed view: plain frames, then time steps (pipeline updated before the clock starts)
    plain, steps = [], []
    simple.Render(view)
    for k in range(1, args.frames + 1):
        t = time.perf_counter()
        simple.Render(view)
        psi_data.wait(view)
        plain.append(time.perf_counter() - t)
        prog.Script = STEP_SCRIPT.format(array=array, k=k)
        prog.UpdatePipeline()
        t = time.perf_counter()
        simple.Render(view)
        psi_data.wait(view)
        steps.append(time.perf_counter() - t)
    rss_mb = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
    print("RESULT " + json.dumps({
        "cells": cells, "first": first, "spf": sum(times) / len(times),
        "plain": min(plain), "step": min(steps), "rss": rss_mb}), flush=True)
    psi_testing.exit_now(0)


def run_worker(data, mapper, threads, args):
    sys.path.insert(0, os.path.join(HERE, "..", "Python"))
    import psi_process
    env = psi_process.environment_without_mpi()
    env["LP_NUM_THREADS"] = str(threads)
    cmd = [sys.executable, os.path.abspath(__file__), "--worker", "--data", str(data),
           "--mapper", mapper, "--size", str(args.size), "--frames", str(args.frames)]
    pvpython = os.environ.get("PVPYTHON", "pvpython")
    cmd = [pvpython, "--force-offscreen-rendering"] + cmd[1:]
    out = subprocess.run(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         universal_newlines=True, timeout=args.timeout)
    for line in out.stdout.splitlines():
        if line.startswith("RESULT "):
            return json.loads(line[len("RESULT "):])
    sys.stderr.write("worker failed (%s, %s):\n%s\n" % (data, mapper, out.stdout[-2000:]))
    return None


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--worker", action="store_true")
    p.add_argument("--data", default="20")
    p.add_argument("--mapper", default="Psi Volume")
    p.add_argument("--sizes", nargs="*", type=int, default=[20, 40, 60])
    p.add_argument("--bluntfin", action="store_true", help="also the Blunt Fin")
    p.add_argument("--size", type=int, default=512)
    p.add_argument("--frames", type=int, default=4)
    p.add_argument("--threads", nargs=2, type=int, default=[1, 2])
    p.add_argument("--mappers", nargs="*",
                   default=["Psi Volume GS", "Psi Volume GS fan", "Psi Volume CS",
                            "Projected tetra", "Bunyk ray cast"])
    p.add_argument("--bunyk-max-tets", type=int, default=400000)
    p.add_argument("--timeout", type=float, default=3000)
    args = p.parse_args()
    if args.worker:
        worker(args)
        return
    datasets = [str(s) for s in args.sizes] + (["bluntfin"] if args.bluntfin else [])
    print("%-10s %-20s %11s %9s %9s %9s %9s %8s %12s" % (
        "tets", "mapper", "first (s)", "s/frame", "speed/PT", "RSS (MB)", "RSS/PT",
        "%d->%d thr" % tuple(args.threads), "step/frame"))
    for data in datasets:
        rows = {}
        for mapper in args.mappers:
            if mapper == "Bunyk ray cast" and data != "bluntfin" and \
                    5 * (2 * int(data)) ** 3 > args.bunyk_max_tets:
                continue
            fast = run_worker(data, mapper, args.threads[1], args)
            slow = run_worker(data, mapper, args.threads[0], args) if fast else None
            if fast:
                rows[mapper] = (fast, slow)
        pt = rows.get("Projected tetra", (None, None))[0]
        for mapper, (r, slow) in rows.items():
            print("%-10d %-20s %11.3f %9.3f %8.2fx %9.0f %8.2fx %7.2fx %11.2fx" % (
                r["cells"], mapper, r["first"], r["spf"],
                pt["spf"] / r["spf"] if pt else float("nan"), r["rss"],
                r["rss"] / pt["rss"] if pt else float("nan"),
                slow["spf"] / r["spf"] if slow else float("nan"), r["step"] / r["plain"]),
                flush=True)


if __name__ == "__main__":
    main()
