"""Benchmark (not a test): where a frame's time goes, thread by thread. One mapper renders an orbit
in its own pvpython process while this script reads every thread's CPU time from
/proc/<pid>/task/<tid>/schedstat every few milliseconds.

pvpython Benchmarks/bench_threads.py [--data 40] [--mapper "Psi Volume GS"] [--frames 4]
                                     [--size 512] [--bin 0.05]

--data: a Wavelet half-extent (20: 320,000 tets, 40: 2,560,000, 60: 8,640,000) or bluntfin.
--mapper: as in bench_scale.py ("Psi Volume GS", "Psi Volume CS", "Projected tetra", ...).
Threads are grouped as: main (the process's first thread: ParaView, the draw calls and, in Mesa's
llvmpipe, the vertex and geometry shaders, clipping, triangle setup and binning), raster (the
llvmpipe-N threads: rasterization and fragment shading) and other (the visibility sort's worker
and helper threads). It prints CPU seconds per frame of each group, the share of the cores in
use, and the last frame as a timeline of --bin seconds: the busy fraction of each group per bin
(1.00 is one core). docs/benchmarks.md has its latest output."""
import argparse
import os
import subprocess
import sys
import time

from psivolume import bench, data, process, testing, timing


def worker(args):
    """Renders the scene, printing READY before the orbit and DONE after it."""
    from paraview import simple

    data.load_plugin(globals())
    src, array = (bench.load("bluntfin") if args.data == "bluntfin"
                  else data.wavelet(int(args.data)))
    src.UpdatePipeline()
    view, _ = bench.scale_view(src, array, args.mapper, args.size)
    for _ in range(2):
        simple.Render(view)
        timing.wait(view)
    print("READY", flush=True)
    for _ in range(args.frames):
        view.GetActiveCamera().Azimuth(360.0 / args.frames)
        print("FRAME %.6f" % time.monotonic(), flush=True)
        simple.Render(view)
        timing.wait(view)
    print("DONE %.6f" % time.monotonic(), flush=True)
    testing.exit_now(0)


def group_of(pid, tid, name):
    if name.startswith("llvmpipe"):
        return "raster"
    return "main" if tid == str(pid) else "other"


def sample(pid, seen):
    """(monotonic time, {group: CPU seconds so far}). `seen` keeps each thread's last reading, so
    that a thread that ended (the sort's worker is joined every frame) still counts."""
    for tid in os.listdir("/proc/%d/task" % pid):
        try:
            with open("/proc/%d/task/%s/comm" % (pid, tid)) as f:
                name = f.read().strip()
            with open("/proc/%d/task/%s/schedstat" % (pid, tid)) as f:
                ns = int(f.read().split()[0])
        except (OSError, ValueError):
            continue  # the thread ended
        seen[tid] = (group_of(pid, tid, name), ns * 1e-9)
    totals = {"main": 0.0, "raster": 0.0, "other": 0.0}
    for group, seconds in seen.values():
        totals[group] += seconds
    return time.monotonic(), totals


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--worker", action="store_true")
    p.add_argument("--data", default="40")
    p.add_argument("--mapper", default="Psi Volume GS")
    p.add_argument("--frames", type=int, default=4)
    p.add_argument("--size", type=int, default=512)
    p.add_argument("--bin", type=float, default=0.05)
    p.add_argument("--pvpython", help="the worker's pvpython (default: PATH's)")
    args = p.parse_args()
    if args.worker:
        worker(args)
        return
    cmd = [timing.pvpython(args.pvpython), "--force-offscreen-rendering", os.path.abspath(__file__), "--worker",
           "--data", args.data, "--mapper", args.mapper, "--frames", str(args.frames),
           "--size", str(args.size)]
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, text=True,
                            env=process.environment_without_mpi())
    for line in proc.stdout:
        if line.startswith("READY"):
            break
        print(line, end="")  # the worker's own messages (SKIP when a dataset is absent)
    os.set_blocking(proc.stdout.fileno(), False)
    samples, marks, seen = [], [], {}
    while proc.poll() is None:
        samples.append(sample(proc.pid, seen))
        for line in iter(proc.stdout.readline, ""):
            marks.append(line.split())
        if marks and marks[-1][0] == "DONE":
            break
        time.sleep(0.004)
    proc.wait()
    frames = [float(m[1]) for m in marks if m[0] == "FRAME"]
    done = [float(m[1]) for m in marks if m[0] == "DONE"]
    if not frames or not done or len(samples) < 2:
        print("no frames measured")
        sys.exit(1)
    report(args, samples, frames, done[0])


def cpu_at(samples, t):
    """Group CPU seconds at time t, from the nearest sample at or before it."""
    best = samples[0]
    for s in samples:
        if s[0] > t:
            break
        best = s
    return best[1]


def report(args, samples, frames, end):
    groups = ("main", "raster", "other")
    wall = (end - frames[0]) / len(frames)
    c0, c1 = cpu_at(samples, frames[0]), cpu_at(samples, end)
    cpu = {g: (c1[g] - c0[g]) / len(frames) for g in groups}
    cores = os.cpu_count() or 1
    print("%s on %s, %d frames: %.3f s/frame" % (args.mapper, args.data, len(frames), wall))
    print("CPU s/frame: " + ", ".join("%s %.3f" % (g, cpu[g]) for g in groups) +
          "; %.0f%% of %d cores busy" % (100.0 * sum(cpu.values()) / (wall * cores), cores))
    print("last frame, busy cores per %.3f s:" % args.bin)
    print("%7s %6s %6s %6s" % (("t (s)",) + groups))
    t = frames[-1]
    while t < end - 1e-9:
        a, b = cpu_at(samples, t), cpu_at(samples, min(t + args.bin, end))
        width = min(args.bin, end - t)
        print("%7.3f " % (t - frames[-1]) +
              " ".join("%6.2f" % ((b[g] - a[g]) / width) for g in groups))
        t += args.bin


if __name__ == "__main__":
    main()
