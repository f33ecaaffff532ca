"""Benchmark (not a test): Moreland's Table 6.4 side by side with 'Psi Volume'. The six methods
of his table, each as a frame rate relative to Average, on the Blunt Fin and the Oxygen Post,
with Mesa's llvmpipe on 1 thread and on all threads (LP_NUM_THREADS, fixed per process: each
thread count runs in its own child pvpython, its methods in interleaved rounds, psivolume.timing).

pvpython Benchmarks/bench_moreland_table.py [--size 512] [--frames 3] [--budget 240]
                                            [--models bluntfin post] [--out FILE.md]
Prints the Markdown table (and writes it to --out)."""
import argparse
import os
import tempfile

from paraview import simple

from psivolume import accuracy, data, moreland, testing, timing

MODELS = {"bluntfin": "Blunt Fin", "post": "Oxygen Post"}


def scene(model, size):
    """The model in a size x size view, the accuracy report's camera and transfer function."""
    args = argparse.Namespace(file=model, array=None, size=size, wavelet_half=20,
                              unit_distance=None)
    view, rep, src, _ = accuracy.command_scene(args)
    simple.Render(view)
    return view, rep, src


def ratios(cap, work, threads, frames, budget):
    """{method: (time ratio to Average, spread)} for one llvmpipe thread count, and the summary."""
    scene_file = os.path.join(work, "scene.json")
    cap.write_child_scene(scene_file)
    cmd = accuracy.child_command("Psi Volume|Average", scene_file,
                                 os.path.join(work, "image_%s.npy" % threads))
    proc = timing.ChildProcess(cmd, env=timing.child_environment(threads), timeout=600)
    contenders = [timing.Child(m, proc, {"IntegrationMethod": m, "AdaptiveSampling": "Off"})
                  for m in moreland.METHODS]
    res = timing.interleaved(contenders, "Average", frames=frames, budget=budget,
                             log=lambda m: print("    %s" % m, flush=True))
    out = {}
    for m in moreland.METHODS:
        row = res.row(m)
        out[m] = (row["ratio"], row["ratio_spread"] or 0.0)
    return out, res.summary()


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--size", type=int, default=512)
    p.add_argument("--frames", type=int, default=3)
    p.add_argument("--budget", type=float, default=240)
    p.add_argument("--models", nargs="*", default=list(MODELS))
    p.add_argument("--out")
    args = p.parse_args()
    data.load_plugin(globals())
    threads = sorted({1, os.cpu_count() or 1})
    columns, notes = [], []
    for model in args.models:
        view, rep, src = scene(model, args.size)
        with tempfile.TemporaryDirectory(prefix="psi_table64_") as work:
            cap = accuracy.Capture(view, rep, src, work)
            for t in threads:
                print("%s, %d llvmpipe thread%s:" % (MODELS[model], t, "s" * (t > 1)), flush=True)
                ours, summary = ratios(cap, work, t, args.frames, args.budget)
                columns.append(("%s, ours, %d thread%s" % (MODELS[model], t, "s" * (t > 1)), ours))
                notes.append("%s, %d thread%s: %s." % (MODELS[model], t, "s" * (t > 1), summary))
        simple.Delete(rep)
        simple.Delete(view)
    text = ("Frame rate relative to Average (Moreland's 'Average Luminance and Attenuation'): "
            "Moreland's Table 6.4 (Quadro FX 3000, 800x800) and 'Psi Volume' (%dx%d, llvmpipe), "
            "ours with half the interquartile range of the ratio over the rounds.\n\n%s\n\n%s\n"
            % (args.size, args.size, moreland.side_by_side(columns), "\n".join(notes)))
    print(text)
    if args.out:
        with open(args.out, "w") as f:
            f.write(text)
    testing.exit_now(0)


if __name__ == "__main__":
    main()
