"""Benchmark (not a test): how much of 'Psi Volume''s work lies behind the point where a pixel is
already opaque, i.e. what front-to-back compositing with early ray termination could skip, on the
benchmarks' own scenes. Each scene is written by psivolume.accuracy.Capture (the exact reference's
mesh.vtu and scene file) in a child pvpython, then build/bin/bench_saturation walks every pixel's
ray front to back with the reference's rays and prints the shares (bench_saturation.cxx).

PYTHONPATH=Python pvpython Benchmarks/bench_saturation.py [--size 256] [--scenes wavelet20 ...] [--program FILE]
                                                           [--no-check] [--out FILE.md]
Scenes:
  wavelet20, wavelet40  ParaView's Wavelet [-h, h]^3 tetrahedralized (320,000 and 2,560,000
                        tets), bench_scale.py's view (bench.scale_view: default maps over the data
                        range, default unit distance, camera reset, Elevation(25), reset)
  bluntfin              the Blunt Fin (Density) in the same view (bench_scale.py --bluntfin)
  post                  the Oxygen Post (StagnationEnergy) in bench_moreland_table.py's view
                        (data.volume_view: Azimuth(30), Elevation(20))
A suffix changes the opacity: ':opaque' opacity 1 over the whole range, ':unitX' the unit distance
times X (tau = opacity / unit distance: X < 1 is denser), e.g. wavelet20:opaque:unit0.1.
Prints a Markdown table (and writes it to --out)."""
import argparse
import os
import subprocess
import sys
import tempfile

SCRIPT = os.path.abspath(__file__)
DEFAULT_SCENES = ["wavelet20", "wavelet40", "bluntfin", "post", "wavelet20:opaque",
                  "wavelet20:unit0.1", "wavelet20:opaque:unit0.1"]


def capture(scene, size, work):
    """Child: the scene as its benchmark shows it, written to work/mesh.vtu and work/scene.txt."""
    from paraview import simple

    from psivolume import accuracy, bench, data, testing

    data.load_plugin(globals())
    name, *changes = scene.split(":")
    if name.startswith("wavelet"):
        src, array = data.wavelet(int(name[len("wavelet"):]))
        view, rep = bench.scale_view(src, array, "Psi Volume", size)
    elif name == "bluntfin":
        src, array = bench.load("bluntfin")
        view, rep = bench.scale_view(src, array, "Psi Volume", size)
    elif name == "post":
        src, array = bench.load("post")
        view, rep = data.volume_view(src, array, size)
    else:
        raise SystemExit("unknown scene %s" % scene)
    for change in changes:
        if change == "opaque":
            pwf = rep.ScalarOpacityFunction
            lo, hi = pwf.Points[0], pwf.Points[-4]
            pwf.Points = [lo, 1.0, 0.5, 0.0, hi, 1.0, 0.5, 0.0]
        elif change.startswith("unit"):
            rep.ScalarOpacityUnitDistance = rep.ScalarOpacityUnitDistance * float(change[4:])
        else:
            raise SystemExit("unknown change %s" % change)
    simple.Render(view)  # the benchmark's first frame: ParaView's first Render resets the camera
    cap = accuracy.Capture(view, rep, src, work)
    cap.write_reference_scene(os.path.join(work, "scene.txt"))
    testing.exit_now(0)


def find_program(program=None):
    """`program` (--program) when given, else bench_saturation beside the reference renderer."""
    from psivolume import accuracy

    return program or os.path.join(os.path.dirname(accuracy.find_reference_renderer()),
                                   "bench_saturation")


def measure(scene, args):
    """The program's "key value" lines for `scene`, as a dict; None when its data is absent."""
    from psivolume import timing

    with tempfile.TemporaryDirectory(prefix="psi_saturation_") as work:
        subprocess.run([timing.pvpython(), "--force-offscreen-rendering", SCRIPT, "--capture",
                        scene, "--size", str(args.size), "--work", work],
                       env=timing.child_environment(), check=True)
        if not os.path.exists(os.path.join(work, "scene.txt")):
            print("# %s: SKIP (its data is absent)" % scene, flush=True)
            return None
        argv = [find_program(args.program), os.path.join(work, "mesh.vtu"), os.path.join(work, "scene.txt")]
        out = subprocess.run(argv + (["--no-check"] if args.no_check else []),
                             capture_output=True, text=True)
    sys.stdout.write("# %s\n%s" % (scene, out.stdout))
    sys.stdout.flush()
    if out.returncode != 0:
        raise SystemExit("%s failed on %s: %s" % (argv[0], scene, out.stderr.strip()))
    values = {}
    for line in out.stdout.splitlines():
        if line.startswith("threshold "):
            words = line.replace(":", "").split()
            for key, value in zip(words[2::2], words[3::2]):
                values["%s %s" % (key, words[1])] = float(value)
        else:
            key, _, value = line.partition(" ")
            values[key] = value
    return values


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--capture", help=argparse.SUPPRESS)
    p.add_argument("--work", help=argparse.SUPPRESS)
    p.add_argument("--size", type=int, default=256)
    p.add_argument("--scenes", nargs="*", default=DEFAULT_SCENES)
    p.add_argument("--no-check", action="store_true",
                   help="skip the comparison with psi::RenderReference (halves the time)")
    p.add_argument("--out")
    p.add_argument("--program", help="bench_saturation (default: beside psi_reference_render)")
    args = p.parse_args()
    if args.capture:
        capture(args.capture, args.size, args.work)
        return
    rows = ["| scene | tets | unit distance | image | fragments / hit pixel | mean opacity "
            "| % hit pixels reaching 0.99 / 0.999 | % fragments behind 0.99 / 0.999 "
            "| % ray length behind 0.99 / 0.999 |",
            "|---|---|---|---|---|---|---|---|---|"]
    for scene in args.scenes:
        v = measure(scene, args)
        if v is None:
            continue
        rows.append("| %s | %s | %.4g | %s | %s | %.3f | %.1f / %.1f | %.1f / %.1f "
                    "| %.1f / %.1f |" % (
            scene, "{:,}".format(int(v["tetrahedra"])), float(v["unit"]),
            "x".join(v["size"].split()), v["fragments_per_hit_pixel"],
            float(v["mean_alpha_hit_pixels"]),
            v["pixels_saturated_pct 0.99"], v["pixels_saturated_pct 0.999"],
            v["fragments_behind_pct 0.99"], v["fragments_behind_pct 0.999"],
            v["length_behind_pct 0.99"], v["length_behind_pct 0.999"]))
    text = "\n".join(rows) + "\n"
    print(text)
    if args.out:
        with open(args.out, "w") as f:
            f.write(text)


if __name__ == "__main__":
    main()
