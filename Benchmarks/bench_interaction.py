"""Benchmark (not a test): what a camera move costs with 'Psi Volume', beside ParaView's fixed
cost per frame ('Outline') and the mapper users pick for speed ('Resample To Image', 128^3).

pvpython Benchmarks/bench_interaction.py [--sizes 8 20 40] [--bluntfin] [--size 512]
                                         [--orbit 12] [--plot interaction.png]

--sizes are half-extents of ParaView's Wavelet, tetrahedralized (5 tets per voxel: 8 gives
20,480 tets, 20 gives 320,000, 40 gives 2,560,000). For each mesh, in one process, it prints
seconds (wall, the GL work waited for):
  - still: a still frame of 'Psi Volume' (the median of 3, each after a small camera turn);
  - first drag: the first interactive frame after it, the level of detail's build included;
  - drag: the median interactive frame over an orbit of --orbit frames, and what drew them
    (LastInteractiveImage: 0 the full frame, 1 the volume level of detail);
  - outline: a still frame of the 'Outline' representation, ParaView's fixed cost per frame;
  - RTI first / RTI: 'Volume' with 'Resample To Image' (128^3): its first frame (the resampling)
    and the median of its later frames;
  - peak RSS of the process after the 'Psi Volume' frames (MB);
and the ratios drag / outline and drag / still. Absolute times vary with the machine; the ratios
are taken within one run. --plot draws still and drag against tetrahedra."""
import argparse
import resource
import time

from paraview import simple

from psivolume import bench, data, timing


def interactive_frame(view):
    t0 = time.perf_counter()
    view.InteractiveRender()
    timing.wait(view)
    return time.perf_counter() - t0


def measure(src, array, size, orbit):
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
    cam = view.GetActiveCamera()
    cam.Azimuth(5)
    first = interactive_frame(view)
    drags = []
    for _ in range(orbit):
        cam.Azimuth(360.0 / orbit)
        drags.append(interactive_frame(view))
    rep.UpdatePropertyInformation()
    drew = rep.GetProperty("LastInteractiveImage").GetElement(0)
    build = rep.GetProperty("LODBuildSeconds").GetElement(0)
    rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
    rep.SetRepresentationType("Outline")
    outline = timing.time_frames(view, 5)[0]
    rep.SetRepresentationType("Volume")
    rep.SelectMapper = "Resample To Image"
    rti_first = timing.frame(view)[0]
    rti = timing.time_frames(view, 3, warmup=0)[0]
    simple.Delete(view)
    drag = timing.frame_time(drags)
    return {"tets": tets, "still": still, "first": first, "drag": drag, "drew": drew,
            "build": build, "outline": outline, "rti_first": rti_first, "rti": rti, "rss": rss}


def print_table(rows):
    print("| mesh | tets | still s | first drag s (LOD build) | drag s (drew) | outline s | "
          "RTI first s | RTI s | peak RSS MB | drag/outline | drag/still |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for name, r in rows:
        print("| %s | %d | %.3f | %.3f (%.3f) | %.3f (%s) | %.3f | %.3f | %.3f | %.0f | %.2f | %.3f |"
              % (name, r["tets"], r["still"], r["first"], r["build"], r["drag"],
                 "LOD" if r["drew"] == 1 else "full", r["outline"], r["rti_first"], r["rti"],
                 r["rss"], r["drag"] / r["outline"], r["drag"] / r["still"]))


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
    p.add_argument("--sizes", type=int, nargs="*", default=[8, 20, 40])
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
    if args.bluntfin:
        src, array = bench.load("bluntfin")
        rows.append(("Blunt Fin", measure(src, array, args.size, args.orbit)))
    print_table(rows)
    if args.plot:
        plot(rows, args.plot)


main()
