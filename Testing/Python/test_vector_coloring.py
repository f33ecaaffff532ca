"""Coloring 'Psi Volume' by a vector array follows the color map's vector mode, as 'Volume'
does: by ('POINTS', 'V', 'Magnitude') the image equals coloring by the magnitude computed as its
own array, by component Z it equals coloring by the Z array, and the two differ (the X component,
which a mapper reading component 0 would draw, differs from both). The same for cell data, and
'Volume' reacts the same way."""

import os

from paraview import simple

from psivolume import data, testing

t = testing.Checks("test_vector_coloring")
data.load_plugin(globals(), os.environ.get("PSI_PLUGIN"))
src, _ = data.wavelet(8)
calc = data.with_vector(src)
mag = simple.Calculator(Input=calc, ResultArrayName="Vmag", Function="mag(V)")
vz = simple.Calculator(Input=mag, ResultArrayName="Vz", Function="V_Z")
vx = simple.Calculator(Input=vz, ResultArrayName="Vx", Function="V_X")
cells = simple.PointDatatoCellData(Input=vx)
view = testing.black_view(160)


def image(source, assoc, array, component=None, rng=None, representation="Psi Volume"):
    """`representation` colored by `array` (and vector `component`), over the scalar range
    `rng`."""
    d = simple.Show(source, view)
    d.SetRepresentationType(representation)
    simple.ColorBy(d, (assoc, array) if component is None else (assoc, array, component))
    lut = simple.GetColorTransferFunction(array)
    pwf = simple.GetOpacityTransferFunction(array)
    lut.RescaleTransferFunction(rng[0], rng[1])
    pwf.RescaleTransferFunction(rng[0], rng[1])
    d.ScalarOpacityUnitDistance = 3.0
    view.ResetCamera()
    simple.Render(view)
    img = testing.grab(view)
    simple.Hide(source, view)
    return img


for assoc, source in (("POINTS", vx), ("CELLS", cells)):
    arrays = source.PointData if assoc == "POINTS" else source.CellData
    rmag, rz, rx = (arrays[a].GetRange() for a in ("Vmag", "Vz", "Vx"))
    by_mag = image(source, assoc, "V", "Magnitude", rmag)
    ref_mag = image(source, assoc, "Vmag", None, rmag)
    by_z = image(source, assoc, "V", "Z", rz)
    ref_z = image(source, assoc, "Vz", None, rz)
    ref_x = image(source, assoc, "Vx", None, rz)
    e_mag, e_z = testing.mean_error(by_mag, ref_mag), testing.mean_error(by_z, ref_z)
    t.check(testing.covered(ref_mag, [0, 0, 0]) > 2000, "%s: images are not empty" % assoc)
    t.check(e_mag < 0.5 / 255, "%s: V Magnitude equals |V| as its own array (%.2e)"
            % (assoc, e_mag))
    t.check(e_z < 0.5 / 255, "%s: V component Z equals V_Z as its own array (%.2e)" % (assoc, e_z))
    t.check(testing.mean_error(by_z, ref_x) > 5.0 / 255,
            "%s: component Z differs from component X (%.2e)"
            % (assoc, testing.mean_error(by_z, ref_x)))
    t.check(testing.mean_error(by_mag, ref_z) > 5.0 / 255,
            "%s: magnitude differs from component Z" % assoc)
    # parity: ParaView's own 'Volume' reacts the same way to the vector mode
    vol_z = image(source, assoc, "V", "Z", rz, "Volume")
    vol_ref_z = image(source, assoc, "Vz", None, rz, "Volume")
    t.check(testing.mean_error(vol_z, vol_ref_z) < 0.5 / 255,
            "%s: 'Volume' too draws V component Z as V_Z (%.2e)"
            % (assoc, testing.mean_error(vol_z, vol_ref_z)))
t.finish()
