"""Benchmark (not a test): 'Psi Volume' with every setting 'Auto' (the ways that draw the same
image timed on the first frames, the fastest kept: psi::MeasuredChoice) against each of those
ways fixed, the raster floor and ParaView's 'Projected tetra', in interleaved rounds.

pvpython Benchmarks/bench_ways.py [--scenes bluntfin 20 40] [--budget 300] [--frames 4]

Scenes:
  bluntfin  the Blunt Fin (Density) at 384x384, opacity 0 -> 0.3 -> 1 over the range, unit
            distance 0.2, the camera reset, turned 30 degrees and raised 20
  20, 40    ParaView's Wavelet [-h, h]^3 tetrahedralized (320,000 and 2,560,000 tets) in
            bench_scale.py's view at 512x512 (default maps, camera raised 25 degrees)
Contenders, each in its own pvpython that stays up (psivolume.timing: interleaved rounds, the
order rotating; each round an orbit-free turn of --frames frames, the camera turned by half a
degree between frames so that every frame sorts, as while the camera moves):
  "Psi Volume"                    every 'Auto' (the default), its measurement over before the
                                  rounds; the way it chose and the frames it took are printed
  "Psi Volume GS|CS [fan] front to back|back to front"   one way fixed
  "Psi Volume floor"              the raster floor: the fixed way's triangles, geometry shader,
                                  silhouettes, back to front, every fragment one constant color
  "Projected tetra", "Outline"    ParaView's ('Outline': a frame's fixed cost)
Prints, per scene, s/frame (median over rounds), speed relative to 'Projected tetra', the
frame over the raster floor, and 'Auto' against the fastest fixed way (>= 1: as fast)."""
import argparse
import json
import os
import sys

from paraview import simple

from psivolume import bench, data, testing, timing

FIXED = ["Psi Volume GS front to back", "Psi Volume GS back to front",
         "Psi Volume CS front to back", "Psi Volume CS back to front",
         "Psi Volume GS fan front to back", "Psi Volume GS fan back to front"]
FLOOR = "Psi Volume floor"


def scene(name, mapper):
    """(view, rep, tetrahedra) of scene `name` drawn by `mapper`."""
    data.load_plugin(globals())
    drawn = "Psi Volume GS back to front" if mapper == FLOOR else mapper
    if name != "bluntfin":
        src, array = data.wavelet(int(name))
        view, rep = bench.scale_view(src, array, drawn, 512)
    else:
        src, array = bench.load("bluntfin")  # SKIP when the data is absent
        src.UpdatePipeline()
        view, rep = bench.scale_view(src, array, drawn, 384)
        lo, hi = src.PointData[array].GetRange()
        otf = simple.GetOpacityTransferFunction(array)
        otf.Points = [lo, 0.0, 0.5, 0.0, 0.5 * (lo + hi), 0.3, 0.5, 0.0, hi, 1.0, 0.5, 0.0]
        rep.ScalarOpacityUnitDistance = 0.2
        cam = view.GetActiveCamera()
        cam.Elevation(-25)
        view.ResetCamera()
        cam.Azimuth(30)
        cam.Elevation(20)
        view.ResetCamera()
    if mapper == FLOOR:
        set_raster_floor(rep)
    return view, rep, src.GetDataInformation().GetNumberOfCells()


def set_raster_floor(rep):
    """RasterFloor on: a mapper-only switch with no property, called on the 'Psi Volume'
    representation through a ClientServer stream (the representation is not Python-wrapped)."""
    from paraview.modules.vtkRemotingClientServerStream import vtkClientServerStream
    from paraview.modules.vtkRemotingCore import vtkPVSession

    owner = rep.GetProperty("LastDrawWay").SMProperty.GetParent()  # the 'Psi Volume' sub-proxy
    stream = vtkClientServerStream()
    stream.StreamFromString("Invoke id_value(1) GetVTKObject uint32_value(%d)\n"
                            "Assign id_value(5050601) LastResult()\n"
                            "Invoke id_value(5050601) SetRasterFloor int32_value(1)\n"
                            "Delete id_value(5050601)" % owner.GetGlobalID())
    owner.GetSession().ExecuteStream(vtkPVSession.RENDER_SERVER, stream, False)


def draw_way(rep):
    rep.UpdatePropertyInformation()
    prop = rep.GetProperty("LastDrawWay")
    return prop.SMProperty.GetElement(0) if prop else ""


def worker(args):
    """One contender on one scene: measures the first frames, prints a RESULT line, serves rounds."""
    view, rep, cells = scene(args.scene, args.mapper)
    frames, seconds = 0, 0.0
    while frames < 40:
        seconds += timing.frame(view)[0]
        frames += 1
        if "(measuring" not in draw_way(rep):
            break
    print("RESULT " + json.dumps({"cells": cells, "way": draw_way(rep), "frames": frames,
                                  "seconds": seconds}), flush=True)
    timing.serve_rounds(view)
    testing.exit_now(0)


def run_scene(name, mappers, args):
    procs = {}
    for m in mappers:
        cmd = [timing.pvpython(), "--force-offscreen-rendering", os.path.abspath(__file__),
               "--worker", "--scene", name, "--mapper", m]
        proc = timing.ChildProcess(cmd, env=timing.child_environment(), timeout=args.timeout)
        result = proc.line("RESULT ")
        if not proc.ready or result is None:
            sys.stderr.write("%s failed: %s\n%s\n" % (m, proc.note, "\n".join(proc.output[-10:])))
            continue
        procs[m] = (proc, json.loads(result))
    live = [timing.Child(m, p) for m, (p, _) in procs.items()]
    res = timing.interleaved(live, "Projected tetra", frames=args.frames, budget=args.budget,
                             min_rounds=args.rounds, max_rounds=max(args.rounds, 30))
    return res, {m: r for m, (_, r) in procs.items()}


def report(name, res, first):
    rows = {m: res.row(m) for m in first}
    floor = rows.get(FLOOR, {}).get("spf")
    fixed = [m for m in FIXED if m in rows and rows[m]["spf"]]
    best = min(fixed, key=lambda m: rows[m]["spf"]) if fixed else None
    cells = next(iter(first.values()))["cells"]
    print("\n## %s: %d tetrahedra; %s" % (name, cells, res.summary()))
    print("| contender | s/frame | speed/PT | over the floor | way |")
    print("|---|---|---|---|---|")
    for m, r in rows.items():
        speed = 1.0 / r["ratio"] if r.get("ratio") else float("nan")
        over = r["spf"] / floor if floor else float("nan")
        print("| %s | %.4f | %.2fx | %.2fx | %s |" % (m, r["spf"], speed, over, first[m]["way"]))
    auto = rows.get("Psi Volume")
    if auto and best:
        print("\n'Auto' at %.2fx the speed of the fastest fixed way (%s); its measurement took %d "
              "frames, %.2f s (the fastest fixed way's %d frames: %.2f s)" % (
                  rows[best]["spf"] / auto["spf"], best, first["Psi Volume"]["frames"],
                  first["Psi Volume"]["seconds"], first["Psi Volume"]["frames"],
                  first["Psi Volume"]["frames"] * rows[best]["spf"]), flush=True)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--worker", action="store_true")
    p.add_argument("--scene", default="bluntfin")
    p.add_argument("--mapper", default="Psi Volume")
    p.add_argument("--scenes", nargs="*", default=["bluntfin", "20", "40"])
    p.add_argument("--mappers", nargs="*",
                   default=["Projected tetra", "Psi Volume"] + FIXED + [FLOOR, "Outline"])
    p.add_argument("--frames", type=int, default=4)
    p.add_argument("--rounds", type=int, default=10)
    p.add_argument("--budget", type=float, default=300)
    p.add_argument("--timeout", type=float, default=1200)
    args = p.parse_args()
    if args.worker:
        worker(args)
        return
    for name in args.scenes:
        res, first = run_scene(name, args.mappers, args)
        report(name, res, first)


main()
