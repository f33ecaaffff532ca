"""Benchmark (not a test): 'Psi Volume' against ParaView's own unstructured volume mappers as the
mesh grows, each mapper in its own pvpython process so that peak memory is its own.

pvpython Benchmarks/bench_scale.py [--sizes 20 40 60] [--bluntfin] [--size 512] [--frames 4]
                                   [--mappers "Psi Volume GS" "Psi Volume GS fan" "Psi Volume CS"
                                              "Psi Volume GS back to front"
                                              "Projected tetra"
                                              "Bunyk ray cast" "Outline"]
                                   [--bunyk-max-tets 400000] [--threads 1 2] [--budget 300]
                                   [--plot scale.png]

--sizes are half-extents of ParaView's Wavelet, tetrahedralized (5 tets per voxel): 20 gives
320,000 tets, 40 gives 2,560,000 and 60 gives 8,640,000. For each mesh and mapper it prints:
  - first frame: seconds from the first Render to its completion (upload, sort, draw), the
    pipeline already updated;
  - s/frame: the median over interleaved rounds of all the mappers' workers (psivolume.timing:
    each worker stays up, draws its turn of --frames frames after a warm-up one, the order
    rotating), and the speed relative to 'Projected tetra' taken round by round;
  - peak RSS of the process (MB), and relative to 'Projected tetra';
  - thread scaling: s/frame with the first --threads value of LP_NUM_THREADS (Mesa llvmpipe's
    rendering threads) over s/frame with the last (a second pass of rounds);
  - time step: a new time step of the same mesh (the scalars change, points and cells do not),
    rendered at a fixed view, over a plain frame at that view;
  - own/PT: the speed relative to 'Projected tetra' on the volume's own time, each s/frame minus
    the 'Outline' representation's (ParaView's fixed cost of a frame), when "Outline" is among
    the --mappers.
'Psi Volume' runs with its defaults (partial pre-integration, MPVONC), once with each projector:
"Psi Volume GS" the geometry shader, "Psi Volume CS" the compute shader ("Psi Volume": Auto).
"Psi Volume GS fan" draws the geometry shader's Shirley-Tuchman fan instead of the silhouettes
(the two give the same image); " back to front" after a 'Psi Volume' name turns
EarlyRayTermination off (within 1/255 of the same image). Bunyk runs only up to
--bunyk-max-tets. Ratios are taken within one run; absolute times vary with the machine. --plot draws s/frame
against tetrahedra (log-log, with each median's range over the rounds) for each mapper: the
Wavelet sizes as lines, the Blunt Fin as separate points."""
import argparse
import json
import os
import resource
import sys

from paraview import simple

from psivolume import bench, data, testing, timing

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
    data.load_plugin(globals())
    if args.data == "bluntfin":
        src, array = bench.load("bluntfin")
    else:
        src, array = data.wavelet(int(args.data))
    prog = simple.ProgrammableFilter(Input=src)
    prog.Script = STEP_SCRIPT.format(array=array, k=0)
    prog.CopyArrays = 0
    prog.UpdatePipeline()
    view, _ = bench.scale_view(prog, "step", args.mapper, args.size)
    cells = prog.GetDataInformation().GetNumberOfCells()
    first = timing.frame(view)[0]
    # an orbit, its times unused: every view's sort and buffers have been made
    timing.time_frames(view, args.frames, warmup=0, orbit=True)
    # fixed view: plain frames, then time steps (pipeline updated before the clock starts)
    plain, steps = [], []
    simple.Render(view)
    for k in range(1, args.frames + 1):
        plain.append(timing.frame(view)[0])
        prog.Script = STEP_SCRIPT.format(array=array, k=k)
        prog.UpdatePipeline()
        steps.append(timing.frame(view)[0])
    rss_mb = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
    print("RESULT " + json.dumps({
        "cells": cells, "first": first, "plain": timing.frame_time(plain),
        "step": timing.frame_time(steps), "rss": rss_mb}), flush=True)
    timing.serve_rounds(view)  # s/frame: interleaved rounds with the other mappers
    testing.exit_now(0)


def start_worker(dataset, mapper, threads, args):
    """A worker for one mapper on one mesh, with llvmpipe on `threads` threads, that stays up
    for the timing rounds (timing.ChildProcess)."""
    cmd = [timing.pvpython(), "--force-offscreen-rendering", os.path.abspath(__file__),
           "--worker", "--data", str(dataset), "--mapper", mapper, "--size", str(args.size),
           "--frames", str(args.frames)]
    proc = timing.ChildProcess(cmd, env=timing.child_environment(threads), timeout=args.timeout)
    result = proc.line("RESULT ")
    if not proc.ready or result is None:
        sys.stderr.write("worker failed (%s, %s): %s\n%s\n" % (
            dataset, mapper, proc.note, "\n".join(proc.output[-20:])))
    return proc, (json.loads(result) if result else None)


def measure(dataset, mappers, threads, args):
    """For each mapper that ran: its worker's figures (first frame, time step, RSS) and, from
    interleaved rounds with the others, s/frame and the ratio to 'Projected tetra'."""
    workers = {m: start_worker(dataset, m, threads, args) for m in mappers}
    live = [timing.Child(m, proc) for m, (proc, r) in workers.items() if r is not None]
    baseline = "Projected tetra" if "Projected tetra" in [c.name for c in live] else \
        (live[0].name if live else None)
    rows = {}
    if live:
        timed = timing.interleaved(live, baseline, frames=args.frames, budget=args.budget,
                                   min_rounds=5)
        print("# %s, %d llvmpipe thread%s: %s" % (dataset, threads, "s" * (threads > 1),
                                                 timed.summary()), flush=True)
        for c in live:
            rows[c.name] = dict(workers[c.name][1], **timed.row(c.name))
    for proc, _ in workers.values():
        proc.close()
    return rows


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
    p.add_argument("--budget", type=float, default=300,
                   help="seconds of interleaved timing rounds per mesh and thread count")
    p.add_argument("--plot", help="PNG of s/frame against tetrahedra")
    args = p.parse_args()
    if args.worker:
        worker(args)
        return
    datasets = [str(s) for s in args.sizes] + (["bluntfin"] if args.bluntfin else [])
    print("%-10s %-27s %11s %9s %9s %9s %9s %8s %12s %9s" % (
        "tets", "mapper", "first (s)", "s/frame", "speed/PT", "RSS (MB)", "RSS/PT",
        "%d->%d thr" % tuple(args.threads), "step/frame", "own/PT"))
    measured = []
    for dataset in datasets:
        mappers = [m for m in args.mappers if not (
            m == "Bunyk ray cast" and dataset != "bluntfin" and
            5 * (2 * int(dataset)) ** 3 > args.bunyk_max_tets)]
        # all threads first, then one: each pass its own interleaved rounds (halves the memory)
        fast = measure(dataset, mappers, args.threads[1], args)
        slow = measure(dataset, list(fast), args.threads[0], args)
        pt, outline = fast.get("Projected tetra"), fast.get("Outline")
        for mapper, r in fast.items():
            s1 = slow.get(mapper)
            print("%-10d %-27s %11.3f %9.3f %8.2fx %9.0f %8.2fx %7.2fx %11.2fx %8.2fx" % (
                r["cells"], mapper, r["first"], r["spf"],
                1.0 / r["ratio"] if pt and r["ratio"] else float("nan"), r["rss"],
                r["rss"] / pt["rss"] if pt else float("nan"),
                s1["spf"] / r["spf"] if s1 and s1["spf"] else float("nan"),
                r["step"] / r["plain"], own_speed(r, pt, outline)), flush=True)
            measured.append(dict(r, data=dataset, mapper=mapper))
    if args.plot and measured:
        plot(measured, args)


def own_speed(r, pt, outline):
    """The speed relative to 'Projected tetra' on the volume's own time: each s/frame minus the
    'Outline' frame's (ParaView's fixed cost), when both ran (else nan)."""
    if not pt or not outline or r is outline:
        return float("nan")
    own, pt_own = r["spf"] - outline["spf"], pt["spf"] - outline["spf"]
    return pt_own / own if own > 0 else float("nan")


def plot(rows, args):
    """s/frame against tetrahedra for each mapper, from this run's rows."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.4, 4.2), dpi=100)
    for i, mapper in enumerate(dict.fromkeys(r["mapper"] for r in rows)):
        color = "C%d" % i
        mine = [r for r in rows if r["mapper"] == mapper]
        for wavelet, style in ((True, "o-"), (False, "D")):
            pts = sorted((r for r in mine if (r["data"] != "bluntfin") == wavelet),
                         key=lambda r: r["cells"])
            if not pts:
                continue
            x = [r["cells"] for r in pts]
            y = [r["spf"] for r in pts]
            err = [[r["spf"] - r.get("spf_min", r["spf"]) for r in pts],
                   [r.get("spf_max", r["spf"]) - r["spf"] for r in pts]]
            ax.errorbar(x, y, yerr=err, fmt=style, color=color, capsize=3,
                        label=mapper + ("" if wavelet else " (Blunt Fin)"),
                        fillstyle="full" if wavelet else "none")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("tetrahedra")
    ax.set_ylabel("s/frame (median over rounds, %d llvmpipe threads)" % args.threads[1])
    ax.set_title("%d x %d, ParaView's Wavelet tetrahedralized, and the Blunt Fin" % (
        args.size, args.size), fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(args.plot)
    print("plot: %s" % args.plot)


if __name__ == "__main__":
    main()
