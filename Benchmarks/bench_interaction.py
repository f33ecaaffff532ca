"""Benchmark (not a test): what a camera move costs with 'Psi Volume', beside ParaView's fixed
cost per frame ('Outline') and the mapper users pick for speed ('Resample To Image', 128^3).

pvpython Benchmarks/bench_interaction.py [--sizes 10 20 30 40] [--bluntfin] [--size 512]
                                         [--orbit 12] [--plot interaction.png]

--sizes are half-extents of ParaView's Wavelet, tetrahedralized (5 tets per voxel: 10 gives
40,000 tets, 20 gives 320,000, 30 gives 1,080,000, 40 gives 2,560,000, 60 gives 8,640,000).
For each mesh, in one process, 'Psi Volume' with its defaults (InteractionMode 'Auto', budget
0.1 s), it prints seconds (wall, the GL work waited for):
  - still: a still frame (the median of 3, each after a small camera turn);
  - first drag: the first interactive frame after it, and what drew it. Past the budget 'Auto'
    builds the level of detail in that frame and draws it;
  - first move -> LOD: seconds from the start of the first interactive render until the level of
    detail has drawn a frame (the first frame's, or with later frames the sum), and the same in
    still frames (the target: at most one);
  - build: the level of detail's build (s) and per million tetrahedra;
  - drag: the median interactive frame over an orbit of --orbit frames after that, and what drew
    them (LOD: the volume level of detail, full: the full frame);
  - outline: a still frame of the 'Outline' representation, ParaView's fixed cost per frame;
  - RTI first / RTI: 'Volume' with 'Resample To Image' (128^3): its first frame (the resampling)
    and the median of its later frames;
  - memory: the process's resident memory after the still frames and its peak after the orbit
    (MB; the peak includes the level of detail's build);
and the ratios drag / outline and drag / still. With --bluntfin, on the Blunt Fin, the mean
error (/255) against the exact reference at the bench's view of the level of detail, of
'Projected tetra''s still frame and of 'Resample To Image' 128^3's. Absolute times vary with
the machine; the ratios are taken within one run. --plot draws still and drag against tets."""
import argparse
import tempfile
import time

import numpy as np
from paraview import simple

from psivolume import accuracy, bench, data, testing, timing

LOD = 1


def interactive_frame(view):
    t0 = time.perf_counter()
    view.InteractiveRender()
    timing.wait(view)
    return time.perf_counter() - t0


def memory_mb():
    """(resident, peak resident) memory of this process, MB."""
    fields = {}
    with open("/proc/self/status") as f:
        for line in f:
            key, _, value = line.partition(":")
            fields[key] = value
    return tuple(float(fields[k].split()[0]) / 1024.0 for k in ("VmRSS", "VmHWM"))


def drew(rep):
    rep.UpdatePropertyInformation()
    return rep.GetProperty("LastInteractiveImage").GetElement(0)


def until_lod(view, rep, timeout=600):
    """Interactive frames, the camera turning a little, until the level of detail draws one or
    `timeout` seconds pass: (frames, seconds)."""
    t0, frames = time.perf_counter(), 0
    while drew(rep) != LOD and time.perf_counter() - t0 < timeout:
        view.GetActiveCamera().Azimuth(1)
        interactive_frame(view)
        frames += 1
    return frames, time.perf_counter() - t0


def errors(view, rep, src, lod_image):
    """Mean errors (/255) against the exact reference at this view: of `lod_image`, of
    'Projected tetra''s still frame and of 'Resample To Image' 128^3's."""
    with tempfile.TemporaryDirectory(prefix="psi_bench_") as work:
        cap = accuracy.Capture(view, rep, src, work)
        ref = accuracy.reference_image(cap, runs=1)[0][0]
    out = {"err_lod": accuracy.errors(lod_image, ref)[0]}
    for key, mapper in (("err_pt", "Projected tetra"), ("err_rti", "Resample To Image")):
        bench.set_mapper(rep, mapper)
        simple.Render(view)
        out[key] = accuracy.errors(testing.grab(view), ref)[0]
    return out


def measure(src, array, size, orbit, with_errors=False):
    """One mesh: the row of the table, as a dict."""
    src.UpdatePipeline()
    tets = src.GetDataInformation().GetNumberOfCells()
    view = simple.CreateRenderView()
    view.ViewSize = [size, size]
    view.OrientationAxesVisibility = 0
    rep = data.show_volume(src, array, view)
    view.ResetCamera()
    view.GetActiveCamera().Elevation(25)
    view.ResetCamera()
    timing.frame(view)  # first frame: upload and first sort, not a still frame of the orbit
    still = timing.time_frames(view, 3, warmup=0)[0]
    rss_still = memory_mb()[0]
    cam = view.GetActiveCamera()
    cam.Azimuth(5)
    first = interactive_frame(view)
    first_drew = drew(rep)
    later = until_lod(view, rep) if first_drew != LOD and still > rep.InteractiveBudget else (0, 0)
    to_lod = (later[0] + 1, first + later[1]) if drew(rep) == LOD else (0, 0)
    drags, kinds = [], []
    for _ in range(orbit):
        cam.Azimuth(360.0 / orbit)
        drags.append(interactive_frame(view))
        kinds.append(drew(rep))
    lod_image = testing.grab(view)
    rep.UpdatePropertyInformation()
    build = rep.GetProperty("LODBuildSeconds").GetElement(0)
    peak = memory_mb()[1]
    row = {"tets": tets, "still": still, "first": first, "first_drew": first_drew,
           "to_lod": to_lod, "drag": timing.frame_time(drags), "drew": kinds, "build": build,
           "rss_still": rss_still, "peak": peak}
    if with_errors:
        row.update(errors(view, rep, src, lod_image) if set(kinds) == {LOD} else {})
    rep.SetRepresentationType("Outline")
    row["outline"] = timing.time_frames(view, 5)[0]
    bench.set_mapper(rep, "Resample To Image")
    row["rti_first"] = timing.frame(view)[0]
    row["rti"] = timing.time_frames(view, 3, warmup=0)[0]
    simple.Delete(view)
    return row


def kind(codes):
    names = {0: "full", LOD: "LOD"}
    return "/".join(sorted({names.get(c, str(c)) for c in codes}))


def print_table(rows):
    print("| mesh | tets | still s | first drag s (drew) | first move -> LOD: frames, s "
          "(still frames) | build s (s per M tets) | drag s (drew) | outline s | RTI first s | "
          "RTI s | RSS MB still / peak | drag/outline | drag/still |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for name, r in rows:
        frames, secs = r["to_lod"]
        print("| %s | %d | %.3f | %.3f (%s) | %s | %s | %.3f (%s) | %.3f | %.3f | %.3f | "
              "%.0f / %.0f | %.1f | %.3f |"
              % (name, r["tets"], r["still"], r["first"], kind([r["first_drew"]]),
                 "%d, %.3f (%.2f)" % (frames, secs, secs / r["still"]) if frames else "–",
                 "%.3f (%.3f)" % (r["build"], r["build"] / (r["tets"] / 1e6)) if r["build"]
                 else "–",
                 r["drag"], kind(r["drew"]), r["outline"], r["rti_first"], r["rti"],
                 r["rss_still"], r["peak"], r["drag"] / r["outline"], r["drag"] / r["still"]))
    for name, r in rows:
        if "err_lod" in r:
            print("\n%s, mean error against the exact reference (/255): level of detail %.3f, "
                  "'Projected tetra' still frame %.3f, 'Resample To Image' 128^3 %.3f"
                  % (name, r["err_lod"], r["err_pt"], r["err_rti"]))


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 4))
    wavelet = [r for name, r in rows if name.startswith("Wavelet")]
    others = [(name, r) for name, r in rows if not name.startswith("Wavelet")]
    for key, label in (("still", "still frame"), ("drag", "interactive frame"),
                       ("outline", "'Outline' frame"), ("rti", "'Resample To Image' frame")):
        line = ax.loglog([r["tets"] for r in wavelet], [r[key] for r in wavelet], "o-",
                         label=label + " (Wavelet)")
        for name, r in others:  # other meshes as points of the same color
            ax.loglog([r["tets"]], [r[key]], "s", color=line[0].get_color())
    if others:
        ax.set_title("squares: " + ", ".join(name for name, _ in others))
    ax.set_xlabel("tetrahedra")
    ax.set_ylabel("seconds per frame")
    ax.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=100)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--sizes", type=int, nargs="*", default=[10, 20, 30, 40])
    p.add_argument("--bluntfin", action="store_true")
    p.add_argument("--size", type=int, default=512)
    p.add_argument("--orbit", type=int, default=12)
    p.add_argument("--plot")
    args = p.parse_args()
    data.load_plugin(globals())
    rows = []
    for half in args.sizes:
        src, array = data.wavelet(half)
        rows.append(("Wavelet %d" % half, measure(src, array, args.size, args.orbit)))
        simple.Delete(src)
    if args.bluntfin:
        src, array = bench.load("bluntfin")
        rows.append(("Blunt Fin", measure(src, array, args.size, args.orbit, with_errors=True)))
    print_table(rows)
    if args.plot:
        plot(rows, args.plot)


main()
