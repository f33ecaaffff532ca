"""The README's picture of two volumes in one view (docs/intermixed.png): two tetrahedralized
Wavelets, the second moved by a Transform and colored by another array with its own color map,
overlapping on screen without sharing space; drawn as 'Psi Volume' and as ParaView's 'Volume',
each in both show orders. 'Psi Volume' draws the same image in either order; 'Volume' pastes the
display shown later over the other, whatever the depth.
    pvpython scripts/intermixed_picture.py PLUGIN OUT.png   (scripts/readme-images.sh runs it)"""
import os
import sys

import numpy as np
from paraview import simple

from psivolume import data, testing

plugin, out = sys.argv[1], sys.argv[2]
data.load_plugin(globals(), plugin)
simple._DisableFirstRenderCameraReset()
SIZE = 320


def draw(representation, order):
    simple.ResetSession()
    view = testing.black_view(SIZE)
    a, array = data.wavelet(10)
    moved = simple.Transform(Input=a)
    moved.Transform.Translate = [13.0, 5.0, 18.0]
    b = simple.Calculator(Input=moved, ResultArrayName="other", Function="400-%s" % array)
    shown = [(a, array), (b, "other")]
    for src, name in (shown if order == 0 else shown[::-1]):
        data.show_volume(src, name, view, representation=representation, unit_distance=8.0)
    testing.apply_preset(simple.GetColorTransferFunction("other"), "Viridis (matplotlib)", "Viridis")
    view.CameraFocalPoint = [6.5, 2.5, 9.0]
    view.CameraPosition = [40.0, 30.0, 95.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.CameraViewAngle = 30.0
    simple.Render(view)
    image = testing.grab(view)
    del view
    return image


images = [draw(rep, order) for rep in ("Psi Volume", "Volume") for order in (0, 1)]
for rep, i in (("Psi Volume", 0), ("Volume", 2)):
    print("%s: the show order changes the image by up to %.0f/255"
          % (rep, np.abs(images[i] - images[i + 1]).max()))

import matplotlib  # noqa: E402 (after ParaView's own imports)
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

titles = ["'Psi Volume', first shown first", "'Psi Volume', second shown first",
          "'Volume', first shown first", "'Volume', second shown first"]
fig, axes = plt.subplots(1, 4, figsize=(12, 3.3))
for ax, image, title in zip(axes, images, titles):
    ax.imshow(np.clip(image, 0, 255).astype(np.uint8)[::-1])
    ax.set_title(title, fontsize=9)
    ax.axis("off")
fig.tight_layout()
fig.savefig(out, dpi=100)
print("wrote %s" % out)
testing.exit_now(0)  # no teardown under Xvfb
