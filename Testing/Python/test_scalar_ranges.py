"""Scalar ranges that float arithmetic on the GPU cannot hold: 'Psi Volume' draws them as
ParaView's own mappers and the exact reference do.

1. Constant fields (0, -2, 1, 1e-30, 1e30) with a flat opacity: ParaView widens a constant's
   range (a field of zeros to [0, 1.18e-38], narrower than the smallest normal float, which a
   GPU flushes to 0). Every path that maps scalars (the sampled table, adaptive nodes, full
   pre-integration, separate opacity; both projectors) draws the color the map gives the
   constant, as 'Projected tetra' does and as the exact reference (the project's CPU ray caster)
   does.
2. Scale invariance: the field g = c + w f, with its color map and opacity rescaled to g's range,
   is the field f with the map over f's range: the same image, whatever c and w, for ranges of
   denormal width (w = 1e-39), far from 0 beside their width (c = 1e30, w = 1e24) and tiny
   negative ones. Checked for each path above and for isosurfaces at the same fraction of the
   range (marching tetrahedra and per fragment).
"""
import os
import tempfile

import numpy as np
from paraview import simple

from psivolume import accuracy, data, testing

t = testing.Checks("test_scalar_ranges")
data.load_plugin(globals(), os.environ.get("PSI_PLUGIN"))
src, rt = data.wavelet(4)
src.UpdatePipeline()
lo, hi = src.PointData[rt].GetRange()
view = testing.black_view(120)
BG = [0.0, 0.0, 0.0]
SAME = 0.1       # mean |difference| on 0..255: the same image up to float rounding ...
SAME_MAX = 2.0   # ... and no pixel off by more than two 8-bit steps
PT_CHANGED = 5.0  # 'Projected tetra' drawing a scaled field with another opacity function
NEAR_REF = 1.0   # mean |difference| against the exact reference
NEAR_PT = 1.0    # and from 'Projected tetra', beyond that mapper's own error

# Each path: (name, settings of the 'Psi Volume' display).
PATHS = [
    ("sampled table", dict(IntegrationMethod="Partial Pre-Integration", AdaptiveSampling="Off")),
    ("adaptive nodes", dict(IntegrationMethod="Partial Pre-Integration", AdaptiveSampling="On")),
    ("full pre-integration", dict(IntegrationMethod="Full Pre-Integration", AdaptiveSampling="Off")),
    ("linear exact, nodes", dict(IntegrationMethod="Linear Exact", AdaptiveSampling="On")),
]
PROJECTORS = ["Geometry Shader", "Compute Shader"]


def field(name, expression):
    calc = simple.Calculator(Input=src, ResultArrayName=name, Function=expression)
    calc.ResultArrayType = "Double"
    calc.UpdatePipeline()
    return calc


def show(source, array, rng, flat_opacity, representation="Psi Volume"):
    d = simple.Show(source, view)
    simple.ColorBy(d, ("POINTS", array))
    d.SetRepresentationType(representation)
    if rng is None:
        d.RescaleTransferFunctionToDataRange(True, False)  # as ParaView does for a new array
    lut = simple.GetColorTransferFunction(array)
    testing.apply_preset(lut, "Cool to Warm")
    lut.ColorSpace = "RGB"
    pwf = simple.GetOpacityTransferFunction(array)
    if rng is not None:
        lut.RescaleTransferFunction(rng[0], rng[1])
        pwf.RescaleTransferFunction(rng[0], rng[1])
    p0, p1 = lut.RGBPoints[0], lut.RGBPoints[-4]
    pwf.Points = [p0, 0.4, 0.5, 0.0, p1, 0.4, 0.5, 0.0] if flat_opacity else \
        [p0, 0.0, 0.5, 0.0, p0 + 0.6 * (p1 - p0), 0.3, 0.5, 0.0, p1, 0.9, 0.5, 0.0]
    d.ScalarOpacityUnitDistance = 2.0
    return d


def render(d, **settings):
    for k, v in settings.items():
        setattr(d, k, v)
    simple.Render(view)
    return testing.grab(view)


def settled_render(d):
    """'Projected tetra's image once its settings have reached it: its first frame after a
    change of representation can still use the previous opacity (seen: 161 instead of 170/255
    in blue on a constant field, whose second frame matches the reference)."""
    render(d)
    return render(d)


def diff(a, b):
    return float(np.abs(a - b).mean()), float(np.abs(a - b).max())


def aim():
    view.CameraPosition = [11.0, 8.0, 15.0]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.CameraViewAngle = 30.0


def reference(source, d):
    """The exact reference's image of the display's scene (psivolume.accuracy's capture)."""
    with tempfile.TemporaryDirectory() as work:
        cap = accuracy.Capture(view, d, source, work)
        images, _ = accuracy.reference_image(cap, os.environ.get("PSI_REFERENCE_RENDER"), runs=1)
    return images[0]


def constant_fields():
    for k, c in enumerate((0.0, -2.0, 1.0, 1e-30, 1e30)):
        name = "c%d" % k
        source = field(name, "RTData*0 + %r" % c)
        d = show(source, name, None, True)
        lut = simple.GetColorTransferFunction(name)
        print("constant %g: ParaView's color map range [%r, %r]" % (c, lut.RGBPoints[0],
                                                                    lut.RGBPoints[-4]))
        d.SetRepresentationType("Volume")
        d.SelectMapper = "Projected tetra"
        pt = settled_render(d)
        d.SetRepresentationType("Psi Volume")
        ref = reference(source, d)
        t.check(testing.covered(ref, BG) > 2000, "constant %g: the reference is not empty" % c)
        mr, _ = diff(pt, ref)
        print("constant %g: 'Projected tetra' vs the reference: mean %.3f/255" % (c, mr))
        # With a separate opacity array ParaView's 'Projected tetra' may draw another opacity
        # (its range made anew for the opacity array): that path is held to its image.
        pt_sep = projected_tetra_separate(d, name)
        print("constant %g: 'Projected tetra' with the field as separate opacity array vs "
              "without: mean %.3f/255" % (c, diff(pt_sep, pt)[0]))
        for pname, settings in PATHS + [SEPARATE]:
            for projector in PROJECTORS:
                img = render_feature(d, name, pname, c, 0.0, projector, settings)
                if pname == SEPARATE[0]:
                    mp, mx = diff(img, pt_sep)
                    t.check(mp < mr + NEAR_PT, "constant %g, %s, %s: 'Projected tetra's color "
                            "with the same separate array (mean |diff| %.3f/255, max %.0f), within "
                            "its own error %.3f/255 + %.0f" % (c, pname, projector, mp, mx, mr,
                                                               NEAR_PT))
                    continue
                m, mx = diff(img, ref)
                mp, _ = diff(img, pt)
                t.check(m < NEAR_REF and mp < mr + NEAR_PT,
                        "constant %g, %s, %s: the reference's color (mean |diff| %.3f/255, max "
                        "%.0f); from 'Projected tetra' %.3f/255, within its own error %.3f/255 "
                        "+ %.0f" % (c, pname, projector, m, mx, mp, mr, NEAR_PT))
        simple.Hide(source, view)


def projected_tetra_separate(d, array):
    d.SetRepresentationType("Volume")
    d.SelectMapper = "Projected tetra"
    d.UseSeparateOpacityArray = 1
    d.OpacityArrayName = ["POINTS", array]
    img = settled_render(d)
    d.UseSeparateOpacityArray = 0
    d.SetRepresentationType("Psi Volume")
    return img


def scaled_fields():
    f = "(RTData - %r) / %r" % (lo, hi - lo)  # in [0, 1]
    base_src = field("f", f)
    scales = [(-1e-300, 1e-302, "tiny negative"), (0.0, 1e-39, "denormal width"),
              (1e30, 1e24, "far from 0"), (-2.0, 1e-6, "narrow")]
    features = PATHS + ISOSURFACES + [SEPARATE]
    base = show(base_src, "f", (0.0, 1.0), False)
    images = {}
    for fname, settings in features:
        for projector in PROJECTORS:
            images[(fname, projector)] = render_feature(base, "f", fname, 0.0, 1.0, projector,
                                                        settings)
            n = testing.covered(images[(fname, projector)], BG)
            t.check(n > 2000, "f: %s, %s: the image is not empty (%d pixels)"
                    % (fname, projector, n))
    pt_base = projected_tetra_separate(base, "f")
    simple.Hide(base_src, view)
    for k, (c, w, what) in enumerate(scales):
        name = "g%d" % k
        g = field(name, "%r + %r * %s" % (c, w, f))
        d = show(g, name, (c, c + w), False)
        # ParaView's own separate-opacity path is not scale invariant everywhere: where
        # 'Projected tetra' changes, 'Psi Volume' is held to its image instead
        pt = projected_tetra_separate(d, name)
        pt_invariant = diff(pt, pt_base)[0] < PT_CHANGED
        for fname, settings in features:
            for projector in PROJECTORS:
                img = render_feature(d, name, fname, c, w, projector, settings)
                if fname == SEPARATE[0] and not pt_invariant:
                    m, mx = diff(img, pt)
                    m0, _ = diff(images[(fname, projector)], pt_base)
                    t.check(m < m0 + 1.0, "%r + %r f (%s): %s, %s: 'Projected tetra' changes "
                            "with the scale (%.3f/255), and 'Psi Volume' is as near it as for f "
                            "(mean |diff| %.3f/255, f: %.3f/255)" % (
                                c, w, what, fname, projector, diff(pt, pt_base)[0], m, m0))
                    continue
                m, mx = diff(img, images[(fname, projector)])
                t.check(m < SAME and mx <= SAME_MAX,
                        "%r + %r f (%s): %s, %s draws the image of f (mean |diff| %.3f/255, max "
                        "%.0f)" % (c, w, what, fname, projector, m, mx))
        simple.Hide(g, view)


ISOSURFACES = [
    ("isosurfaces, marching tetrahedra", dict(
        IntegrationMethod="Partial Pre-Integration", AdaptiveSampling="Off",
        IsosurfaceMethod="Marching Tetrahedra", IsosurfaceOpacity=0.5)),
    ("isosurfaces, per fragment", dict(
        IntegrationMethod="Partial Pre-Integration", AdaptiveSampling="On",
        IsosurfaceMethod="Per Fragment", IsosurfaceOpacity=0.5))]
SEPARATE = ("separate opacity", dict(IntegrationMethod="Partial Pre-Integration",
                                     AdaptiveSampling="On"))


def render_feature(d, array, fname, c, w, projector, settings):
    iso = fname.startswith("isosurfaces")
    d.IsosurfaceValues = [c + 0.45 * w] if iso else []
    d.UseSeparateOpacityArray = 1 if fname == SEPARATE[0] else 0
    if fname == SEPARATE[0]:
        # the opacity from the field itself through the separate path: its own buffer and range
        d.OpacityArrayName = ["POINTS", array]
    img = render(d, Projector=projector, **settings)
    d.IsosurfaceValues = []
    d.UseSeparateOpacityArray = 0
    return img


simple.Render(view)  # the first render resets the camera: take it before aiming
aim()
constant_fields()
scaled_fields()
t.finish()
