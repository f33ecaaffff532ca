"""Several 'Psi Volume' displays in one view, intermixed (one visibility order, one pass): two
tetrahedralized Wavelets, the second moved by a Transform so that they overlap on screen but share
no space, give the same image in either show order (within 1/255; ParaView's 'Volume' pastes the
later over the earlier); the second colored by another array with its own color map and unit
distance, likewise; hiding one gives the other alone, deleting it too; a state file saved and
loaded in a new session draws the same image."""
import os
import tempfile

import numpy as np
from paraview import simple

from psivolume import data, testing

t = testing.Checks("test_intermixed")
data.load_plugin(globals(), os.environ.get("PSI_PLUGIN"))
simple._DisableFirstRenderCameraReset()  # every scene from the same camera
SIZE = 160


def set_camera(view):
    view.CameraFocalPoint = [4.0, 2.0, 6.0]
    view.CameraPosition = [30.0, 22.0, 60.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.CameraViewAngle = 30.0


def scene(order, representation="Psi Volume", other_array=False, function="400-%s"):
    """A new session's view of the two Wavelets shown in `order` (0: the first first)."""
    simple.ResetSession()
    view = testing.black_view(SIZE)
    a, array = data.wavelet(6)
    b = simple.Transform(Input=a)
    b.Transform.Translate = [8.0, 4.0, 12.0]
    arrays = {a: array, b: array}
    if other_array:
        b = simple.Calculator(Input=b, ResultArrayName="other", Function=function % array)
        arrays[b] = "other"
    displays = {}
    for src in ([a, b] if order == 0 else [b, a]):
        displays[src] = data.show_volume(src, arrays[src], view, representation=representation,
                                         unit_distance=2.0)
    if other_array:
        testing.apply_preset(simple.GetColorTransferFunction("other"), "Viridis (matplotlib)",
                             "Viridis")
        displays[b].ScalarOpacityUnitDistance = 0.7
    set_camera(view)
    simple.Render(view)
    return view, a, b, displays


def largest(x, y):
    return float(np.abs(x - y).max())


# --- either show order: the same image
for representation in ("Psi Volume", "Volume"):
    first = testing.grab(scene(0, representation)[0])
    second = testing.grab(scene(1, representation)[0])
    print("%s: the show order changes the image by up to %.0f/255" %
          (representation, largest(first, second)))
    if representation == "Psi Volume":
        psi_first = first
        t.check(largest(first, second) <= 1.0 and testing.covered(first, [0, 0, 0]) > SIZE * SIZE / 8,
                "'Psi Volume': the show order changes the image by %.0f/255 at most"
                % largest(first, second))
    else:
        volume_difference = largest(first, second)
t.check(volume_difference > 10, "(ParaView's 'Volume' pastes the later display over the earlier: "
        "%.0f/255; the scene tells them apart)" % volume_difference)

# --- another array, color map and unit distance: the same in either order, and its own
mixed = [testing.grab(scene(order, other_array=True)[0]) for order in (0, 1)]
t.check(largest(mixed[0], mixed[1]) <= 1.0 and largest(mixed[0], psi_first) > 40,
        "another array with its own color map and unit distance: the show order changes the image "
        "by %.0f/255 at most, and its own map shows (%.0f/255 from one map)"
        % (largest(mixed[0], mixed[1]), largest(mixed[0], psi_first)))

def readouts(display):
    display.UpdatePropertyInformation()
    return [display.GetProperty(name).GetElement(0) for name in (
        "NumberOfTetrahedra", "NumberOfIntermixedVolumes", "NumberOfIntermixedTetrahedra")]


# --- new values on the same mesh (a time step, an edited filter): the image of those values
view, a, b, displays = scene(0, other_array=True)
b.Function = "300-RTData+coordsX"
b.UpdatePipeline()
displays[b].RescaleTransferFunctionToDataRange(False, True)  # to the new range, as a new session
simple.Render(view)
changed = testing.grab(view)
fresh = testing.grab(scene(0, other_array=True, function="300-%s+coordsX")[0])
t.check(largest(changed, fresh) <= 1.0 and largest(changed, mixed[0]) > 10,
        "new values of one volume on the same mesh: their image (%.0f/255 from a new session "
        "showing them; %.0f/255 from the old values)"
        % (largest(changed, fresh), largest(changed, mixed[0])))

# --- the read-outs: each display its own tetrahedra, and the combined draw's
view, a, b, displays = scene(0)
own_a, own_b = readouts(displays[a]), readouts(displays[b])
t.check(own_a[1:] == own_b[1:] == [2, own_a[0] + own_b[0]] and own_a[0] > 0 and own_b[0] > 0,
        "the read-outs: each display its own tetrahedra (%d, %d), both drawn intermixed with the "
        "other (%d, %d volumes; %d, %d tetrahedra in all)" % (
            own_a[0], own_b[0], own_a[1], own_b[1], own_a[2], own_b[2]))

# --- hiding or deleting one gives the other alone
simple.Hide(b, view)
simple.Render(view)
hidden = testing.grab(view)
t.check(readouts(displays[a])[1:] == [0, 0],
        "one display hidden: the other drawn alone (read-outs %s)" % readouts(displays[a]))
alone_view, alone_a, _, alone_displays = scene(0)
simple.Delete(alone_displays[[s for s in alone_displays if s is not alone_a][0]])
simple.Render(alone_view)
deleted = testing.grab(alone_view)
simple.ResetSession()
view = testing.black_view(SIZE)
single, array = data.wavelet(6)
data.show_volume(single, array, view, unit_distance=2.0)
set_camera(view)
simple.Render(view)
reference = testing.grab(view)
t.check(largest(hidden, reference) <= 1.0 and largest(deleted, reference) <= 1.0,
        "one display hidden or deleted: the other alone (%.0f/255, %.0f/255)"
        % (largest(hidden, reference), largest(deleted, reference)))

# --- a state file: the same image in a new session
view, a, b, displays = scene(1)
before = testing.grab(view)
with tempfile.TemporaryDirectory() as tmp:
    state = os.path.join(tmp, "intermixed.pvsm")
    simple.SaveState(state)
    simple.ResetSession()
    simple.LoadState(state)
    loaded = simple.GetActiveView()
    loaded.ViewSize = [SIZE, SIZE]
    simple.Render(loaded)
    after = testing.grab(loaded)
t.check(largest(before, after) <= 1.0, "a state saved and loaded: the same image (%.0f/255)"
        % largest(before, after))
t.finish()
