"""A translucent surface in the view of a 'Psi Volume', with depth peeling for volumes on
(ParaView's default DepthPeelingForVolumes) and off.

VTK's dual depth peeling renders a volume once per stage of each frame; 'Psi Volume' integrates
in each only the depth intervals the stage asks for (Rendering/PsiDepthPeelingCalls.h).
Once it was blended in whole at every stage: a stipple of lines over the whole volume, also
where no surface covers it (mean 127/255 off in check 1). The exact intermixing of surfaces in
front of, behind and inside the volume is measured against the reference ray caster in
Testing/Cxx/TestPsiTranslucentGeometry.cxx; here ParaView's view checks the same compositing.

1. A translucent sphere beside the volume: the volume's pixels are those of the volume alone.
2. A translucent sphere behind the volume: the volume over the sphere's own image S,
   V + (1 - A_V) S, the volume's transparency read from its image over a white background.
3. A translucent sphere in front of the volume (unlit, color (1, 0.5, 0.25), opacity 0.5): the
   image is the sphere's own image S over the volume's V, S + (1 - A) V, with the sphere's
   coverage A read from its red channel (color 1)."""

import os

import numpy as np
from paraview import simple

from psivolume import data, testing

t = testing.Checks("test_translucent_geometry")
data.load_plugin(globals(), os.environ.get("PSI_PLUGIN"))
src, array = data.wavelet(8)
view = testing.black_view(160)
d = simple.Show(src, view)
d.SetRepresentationType("Psi Volume")
testing.apply_requested(d)
simple.ColorBy(d, ("POINTS", array))
d.ScalarOpacityUnitDistance = 3.0
view.CameraPosition = [0.0, 0.0, 60.0]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 1.0, 0.0]
simple.Render(view)
volume = testing.grab(view)
t.check(testing.covered(volume, [0, 0, 0]) > 5000, "the volume alone is drawn")


def with_sphere(center, peel, show_volume=True, radius=3.0):
    """The view with a translucent unlit sphere at `center` (and the volume unless hidden)."""
    s = simple.Sphere(Center=center, Radius=radius, ThetaResolution=32, PhiResolution=32)
    sd = simple.Show(s, view)
    sd.ColorArrayName = ["POINTS", ""]
    sd.AmbientColor = sd.DiffuseColor = [1.0, 0.5, 0.25]
    sd.Ambient, sd.Diffuse, sd.Opacity = 1.0, 0.0, 0.5
    view.DepthPeelingForVolumes = peel
    if not show_volume:
        simple.Hide(src, view)
    simple.Render(view)
    img = testing.grab(view)
    simple.Hide(s, view)
    simple.Delete(s)
    simple.Show(src, view)
    return img


for peel in (1, 0):
    mode = "DepthPeelingForVolumes %d" % peel
    beside = with_sphere([14.0, 10.0, 0.0], peel)
    alone = with_sphere([14.0, 10.0, 0.0], peel, show_volume=False)
    mask = (alone.sum(axis=2) < 1) & (volume.sum(axis=2) > 3)
    off = np.abs(beside - volume)[mask]
    print("%s, sphere beside: volume pixels mean %.3f max %.0f" % (mode, off.mean(), off.max()))
    t.check(mask.sum() > 5000 and off.mean() < 0.5 and np.percentile(off, 99) <= 8,
            "%s, sphere beside: the volume's pixels are unchanged (mean %.3f/255)"
            % (mode, off.mean()))
    if peel:
        # Behind the volume: V + (1 - A_V) S, with the volume's transparency 1 - A_V read from
        # the volume over a white background.
        view.Background = [1.0, 1.0, 1.0]
        simple.Render(view)
        transparency = np.clip(testing.grab(view) - volume, 0.0, 255.0) / 255.0
        view.Background = [0.0, 0.0, 0.0]
        behind = with_sphere([0.0, 0.0, -20.0], peel, radius=6.0)
        sphere = with_sphere([0.0, 0.0, -20.0], peel, show_volume=False, radius=6.0)
        expected = volume + transparency * sphere
        err = np.abs(behind - expected)
        print("%s, sphere behind: against V + (1 - A_V) S mean %.3f, 99th percentile %.0f"
              % (mode, err.mean(), np.percentile(err, 99)))
        t.check(testing.covered(sphere, [0, 0, 0]) > 1000 and err.mean() < 0.5 and
                np.percentile(err, 99) <= 8,
                "%s, sphere behind: seen through the volume (mean %.3f/255)" % (mode, err.mean()))
        front = with_sphere([0.0, 0.0, 20.0], peel)
        sphere = with_sphere([0.0, 0.0, 20.0], peel, show_volume=False)
        cover = sphere[..., 0:1] / 255.0
        expected = sphere + (1.0 - cover) * volume
        err = np.abs(front - expected)
        print("%s, sphere in front: against S + (1 - A) V mean %.3f, 99th percentile %.0f"
              % (mode, err.mean(), np.percentile(err, 99)))
        t.check(testing.covered(sphere, [0, 0, 0]) > 1000 and err.mean() < 0.5 and
                np.percentile(err, 99) <= 8,
                "%s, sphere in front: composited over the volume (mean %.3f/255)"
                % (mode, err.mean()))
t.finish()
