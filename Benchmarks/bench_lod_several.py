"""Benchmark (not a test): the interactive level of detail of two 'Psi Volume' displays in one
view. Two tetrahedralized Wavelets, the second moved by a Transform so that they overlap on
screen but share no space (test_intermixed's scene, scaled with --half), both in 'Volume LOD':
the interactive frame in both show orders against each other and against the intermixed still
frame (largest and mean difference, /255), beside one display's level of detail against its own
still frame; and the interactive frame's seconds (median of --frames) for two displays and for
one.

pvpython Benchmarks/bench_lod_several.py [--size 400] [--half 12] [--frames 5]

Absolute times vary with the machine (and on a shared one from run to run); compare within a
run."""
import argparse
import time

import numpy as np
from paraview import simple

from psivolume import data, testing


def scene(order, half, size, frames, two=True):
    simple.ResetSession()
    view = testing.black_view(size)
    a, array = data.wavelet(half)
    b = simple.Transform(Input=a)
    s = half / 6.0
    b.Transform.Translate = [8.0 * s, 4.0 * s, 12.0 * s]
    sources = ([a, b] if order == 0 else [b, a]) if two else [a]
    for src in sources:
        d = data.show_volume(src, array, view, unit_distance=2.0)
        d.InteractionMode = "Volume LOD"
    view.CameraFocalPoint = [4.0 * s, 2.0 * s, 6.0 * s]
    view.CameraPosition = [30.0 * s, 22.0 * s, 60.0 * s]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.CameraViewAngle = 30.0
    simple.Render(view)
    still = testing.grab(view)
    view.InteractiveRender()
    lod = testing.grab(view)
    seconds = []
    for _ in range(frames):
        start = time.perf_counter()
        view.InteractiveRender()
        seconds.append(time.perf_counter() - start)
    return still, lod, float(np.median(seconds))


def differences(x, y):
    return "max %.0f, mean %.4f" % (np.abs(x - y).max(), np.abs(x - y).mean() / 255)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--size", type=int, default=400)
    parser.add_argument("--half", type=int, default=12)
    parser.add_argument("--frames", type=int, default=5)
    parser.add_argument("--plugin")
    args = parser.parse_args()
    data.load_plugin(globals(), args.plugin)
    simple._DisableFirstRenderCameraReset()
    s0, l0, t0 = scene(0, args.half, args.size, args.frames)
    s1, l1, t1 = scene(1, args.half, args.size, args.frames)
    sa, la, ta = scene(0, args.half, args.size, args.frames, two=False)
    print("still frame, order 0 against order 1: %s" % differences(s0, s1))
    print("level of detail, order 0 against order 1: %s" % differences(l0, l1))
    print("level of detail against the still frame: order 0 %s; order 1 %s"
          % (differences(l0, s0), differences(l1, s0)))
    print("one display's level of detail against its still frame: %s" % differences(la, sa))
    print("interactive frame: two displays %.4f s (order 0), %.4f s (order 1); one %.4f s"
          % (t0, t1, ta))


if __name__ == "__main__":
    main()
    from psivolume.process import exit_now
    exit_now(0)
