"""The interactive level of detail of several 'Psi Volume' displays in one view: two
tetrahedralized Wavelets, the second moved by a Transform so that they overlap on screen but share
no space (test_intermixed's scene), forced into the volume level of detail ('Volume LOD', and
'Auto' past a budget of 0). The interactive frame is the same in either show order (within 1/255:
the same draws in the same order), and as close to the intermixed still frame as one display's
level of detail is to its own (twice its mean and largest error: two images meet along the rays
that cross both); 'Auto' chooses the level of detail for both displays. Drawing each display's
level of detail on its own (VTK's order of props, the later pasted over the earlier) gives 62/255
between the orders and 61/255 from the still frame; 'Auto' then drew only the first display's.
Where the two displays' modes differ, the one drawing its level of detail is not drawn again in
the other's intermixed full frame."""
import os

import numpy as np
from paraview import simple

from psivolume import data, testing

t = testing.Checks("test_lod_several")
data.load_plugin(globals(), os.environ.get("PSI_PLUGIN"))
simple._DisableFirstRenderCameraReset()  # every scene from the same camera
SIZE = 160
FULL, LOD = 0, 1  # LastInteractiveImage: the full frame, the volume level of detail


def set_camera(view):
    view.CameraFocalPoint = [4.0, 2.0, 6.0]
    view.CameraPosition = [30.0, 22.0, 60.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.CameraViewAngle = 30.0


def scene(order, mode, two=True, near_mode=None):
    """A new session's view of the Wavelets (`two`: both, in `order`; else the first alone) in
    interaction `mode` (the near one, the moved Wavelet, in `near_mode` if given) with a budget of
    0: the still frame, the interactive frame, and what drew each display in it."""
    simple.ResetSession()
    view = testing.black_view(SIZE)
    a, array = data.wavelet(6)
    b = simple.Transform(Input=a)
    b.Transform.Translate = [8.0, 4.0, 12.0]
    sources = ([a, b] if order == 0 else [b, a]) if two else [a]
    displays = [data.show_volume(s, array, view, unit_distance=2.0) for s in sources]
    for src, d in zip(sources, displays):
        d.InteractionMode = near_mode if near_mode and src is b else mode
        d.InteractiveBudget = 0.0
    set_camera(view)
    simple.Render(view)
    still = testing.grab(view)
    view.InteractiveRender()
    lod = testing.grab(view)
    used = []
    for d in displays:
        d.UpdatePropertyInformation()
        used.append(d.GetProperty("LastInteractiveImage").GetElement(0))
    return still, lod, used


def errors(x, y):
    """The mean (/255) and largest (0-255) difference of two images."""
    return testing.mean_error(x, y), float(np.abs(x - y).max())


alone_still, alone_lod, _ = scene(0, "Volume LOD", two=False)
alone_mean, alone_max = errors(alone_lod, alone_still)
print("one display: its level of detail from its still frame: mean %.4f, max %.0f/255"
      % (alone_mean, alone_max))

for mode in ("Volume LOD", "Auto"):
    (still0, lod0, used0), (still1, lod1, used1) = scene(0, mode), scene(1, mode)
    t.check(used0 == [LOD, LOD] and used1 == [LOD, LOD],
            "'%s': both displays draw the level of detail in either order (%s, %s)"
            % (mode, used0, used1))
    t.check(testing.covered(lod0, [0, 0, 0]) > SIZE * SIZE / 8 and errors(lod0, lod1)[1] <= 1.0,
            "'%s': the show order changes the level of detail by %.0f/255 at most"
            % (mode, errors(lod0, lod1)[1]))
    for order, lod in ((0, lod0), (1, lod1)):
        mean, largest = errors(lod, still0)
        t.check(mean <= 2 * alone_mean and largest <= 2 * alone_max,
                "'%s', order %d: the level of detail close to the intermixed still frame (mean "
                "%.4f, max %.0f/255; bounds %.4f, %.0f)"
                % (mode, order, mean, largest, 2 * alone_mean, 2 * alone_max))
# --- Modes that differ: the far display's level of detail, the near one's full frame (shown
# later, so drawn later: the right order here). The far display is drawn once, as its level of
# detail: the frame is no further from the still frame than one display's level of detail is from
# its own (drawn twice, also in the near display's intermixed full frame: 0.0034).
still, mixed, used = scene(0, "Volume LOD", near_mode="Full frame")
mean, largest = errors(mixed, still)
t.check(used == [LOD, FULL] and mean <= alone_mean,
        "one display's level of detail beside the other's full frame: drawn once (mean %.4f, "
        "bound %.4f; drew %s)" % (mean, alone_mean, used))
t.finish()
