#!/usr/bin/env python3
"""Counts how often a 2-rank pvbatch with ordered compositing hangs (docs/testing.md, "MPI tests
and hangs"): runs one scene N times, each under scripts/lib/mpi_watchdog.py, and prints one line
per run (ended, hung, failed; for a hang the innermost VTK/ParaView frame of each rank's main
thread) and the count.

  bash scripts/lib/with-xvfb.sh python3 scripts/mpi_hang_rate.py \\
      [--runs 10] [--timeout 60] [--symmetric] [--out DIR] -- [scene options]

Scene options (the scene runs on rank 0, or on every rank with --symmetric):
  --data bluntfin|wavelet   the Blunt Fin from ../shared/data (239,382 tetrahedra) or the
                            Wavelet at half-extent 20 (40,000 x 5 tetrahedra)
  --mapper volume|psi       'Volume' with 'Projected tetra', or 'Psi Volume' (the plugin loaded)
  --frames N                still frames, orbiting the camera by 360/N degrees (default 8)
  --interactive             frames after the first are interactive renders
  --passes N                N views in turn, each shown, rendered, captured and deleted
  --redistribute            RedistributeDataSet before the view
  --barrier                 an MPI barrier before the first render (mpi4py; --symmetric only)
The ranks' output and the watchdog's stacks of each run go to DIR (default: a new temporary
folder), one file per run."""
import argparse
import os
import re
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
WATCHDOG = os.path.join(HERE, "lib", "mpi_watchdog.py")


def scene(argv):
    """The scene, inside pvbatch."""
    from paraview import servermanager, simple
    from psivolume import data

    p = argparse.ArgumentParser()
    p.add_argument("--data", default="bluntfin")
    p.add_argument("--mapper", default="volume")
    p.add_argument("--frames", type=int, default=8)
    p.add_argument("--interactive", action="store_true")
    p.add_argument("--passes", type=int, default=1)
    p.add_argument("--redistribute", action="store_true")
    p.add_argument("--barrier", action="store_true")
    args = p.parse_args(argv)
    pm = servermanager.vtkProcessModule.GetProcessModule()
    t0 = time.time()

    def log(msg):
        print("[rank %d %.1f s] %s" % (pm.GetPartitionId(), time.time() - t0, msg), flush=True)

    if args.mapper == "psi":
        data.load_plugin(globals())
    src, array = data.wavelet(20) if args.data == "wavelet" else data.plot3d(args.data)
    if args.redistribute:
        src = simple.RedistributeDataSet(Input=src)
    src.UpdatePipeline()
    log("%d cells" % src.GetDataInformation().GetNumberOfCells())
    for _ in range(args.passes):
        view = simple.CreateRenderView()
        view.ViewSize = [400, 400]
        view.OrientationAxesVisibility = 0
        d = data.show_volume(src, array, view,
                             "Psi Volume" if args.mapper == "psi" else "Volume")
        if args.mapper != "psi":
            d.SelectMapper = "Projected tetra"
        view.ResetCamera()
        if args.barrier:
            from mpi4py import MPI  # every rank runs this only with --symmetric
            MPI.COMM_WORLD.Barrier()
        for i in range(args.frames):
            if args.interactive and i > 0:
                view.InteractiveRender()
            else:
                simple.Render(view)
            log("frame %d" % i)
            view.GetActiveCamera().Azimuth(360.0 / args.frames)
        if args.passes > 1:
            view.SMProxy.CaptureWindow(1)
            simple.Delete(d)
            simple.Delete(view)
    log("done")


def waits(text):
    """{rank: the innermost MPI or VTK/ParaView frame of its main thread, and the innermost
    VTK/ParaView one} from the watchdog's stacks."""
    found = {}
    for m in re.finditer(r"\[mpi-watchdog\] stack of pid \d+ \(rank (\d+)\).*?\n(.*?)"
                         r"\[mpi-watchdog\] end of stack", text, re.S):
        main = m.group(2).split("\nThread 1 ", 1)[-1]
        frame = re.search(r"^#\d+ .*? in (vtk[A-Z]\w*::\w+|PMPI_\w+)", main, re.M)
        names = re.findall(r"^#\d+ .*? in (vtk[A-Z]\w*::\w+)", main, re.M)
        found[int(m.group(1))] = "%s (in %s)" % (frame.group(1) if frame else "?",
                                                 names[0] if names else "?")
    return found


def main():
    if "--scene" in sys.argv:
        scene(sys.argv[sys.argv.index("--scene") + 1:])
        return
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--runs", type=int, default=10)
    p.add_argument("--timeout", type=float, default=60)
    p.add_argument("--symmetric", action="store_true")
    p.add_argument("--out", default="")
    p.add_argument("scene", nargs=argparse.REMAINDER)
    args = p.parse_args()
    scene_args = args.scene[1:] if args.scene[:1] == ["--"] else args.scene
    out = args.out or tempfile.mkdtemp(prefix="psi_hang_rate_")
    os.makedirs(out, exist_ok=True)
    env = {k: v for k, v in os.environ.items()
           if not k.startswith(("OMPI_", "PMIX_", "PMI_", "OPAL_", "ORTE_", "HYDRA_"))}
    env["OMPI_MCA_rmaps_base_oversubscribe"] = "1"
    env["PYTHONPATH"] = os.pathsep.join(
        [os.path.join(HERE, "..", "Python")] + [x for x in [env.get("PYTHONPATH")] if x])
    pvbatch = ["pvbatch"] + (["--symmetric"] if args.symmetric else [])
    cmd = [sys.executable, WATCHDOG, "--timeout", str(args.timeout), "--", "mpiexec",
           "--allow-run-as-root", "-n", "2"] + pvbatch + [
           "--force-offscreen-rendering", os.path.abspath(__file__), "--scene"] + scene_args
    print("%d runs of: %s\noutput: %s" % (args.runs, " ".join(cmd[5:]), out), flush=True)
    hangs = failures = 0
    for i in range(1, args.runs + 1):
        t0 = time.time()
        path = os.path.join(out, "run%d.txt" % i)
        with open(path, "w") as f:
            code = subprocess.call(cmd, stdin=subprocess.DEVNULL, stdout=f,
                                   stderr=subprocess.STDOUT, env=env)
        with open(path, errors="replace") as f:
            text = f.read()
        if code == 124:
            hangs += 1
            where = "; ".join("rank %d in %s" % kv for kv in sorted(waits(text).items()))
            what = "HUNG (%s)" % where
        elif code == 0:
            what = "ended"
        else:
            failures += 1
            what = "FAILED (exit %d)" % code
        print("run %d: %s, %.0f s" % (i, what, time.time() - t0), flush=True)
    print("%d runs: %d hung, %d failed" % (args.runs, hangs, failures))


if __name__ == "__main__":
    main()
