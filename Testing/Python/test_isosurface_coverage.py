"""Isosurface coverage on the Blunt Fin: 'Psi Volume' isosurfaces (ParaView's Tetrahedralize, two
isovalues at 35% and 60% of the Density range, volume opacity 0, unlit) cover exactly the pixels
of ParaView's Contour filter of the same values and tetrahedra rendered without antialiasing:
the same triangles rasterized. With the view's FXAA on (ParaView's default), FXAA blurs the
Contour surface's silhouettes into a rim of dim pixels one pixel wide, which looks like coverage
that 'Psi Volume' lacks; FXAA does not touch volumes ('Volume' is unchanged by it too), so that
rim is not missing from the isosurfaces. Skips (77) without ../shared/data."""
import os

from paraview import simple

from psivolume import data, testing

DATA_DIR = os.environ.get("PSI_DATA_DIR") or data.DATA_DIR
if not os.path.exists(data.shared_file("bluntfin", DATA_DIR)):
    print("SKIP: the Blunt Fin is not in %s" % DATA_DIR)
    testing.exit_now(testing.SKIP)

t = testing.Checks("test_isosurface_coverage")
data.load_plugin(globals(), os.environ.get("PSI_PLUGIN"))
src, array = data.plot3d("bluntfin", DATA_DIR)
tets = simple.Tetrahedralize(Input=src)
tets.UpdatePipeline()
lo, hi = tets.PointData[array].GetRange()
values = [lo + 0.35 * (hi - lo), lo + 0.60 * (hi - lo)]
view = testing.black_view(400)
contour = simple.Contour(Input=tets, ContourBy=["POINTS", array], Isosurfaces=values,
                         ComputeScalars=1)
cd = simple.Show(contour, view)
simple.ColorBy(cd, ("POINTS", array))
cd.Ambient, cd.Diffuse = 1.0, 0.0  # unlit, as the isosurfaces
simple.Render(view)
view.ResetCamera()
view.GetActiveCamera().Elevation(25)
view.ResetCamera()
simple.Hide(contour, view)
d = simple.Show(tets, view)
simple.ColorBy(d, ("POINTS", array))
d.SetRepresentationType("Psi Volume")
simple.GetOpacityTransferFunction(array).Points = [lo, 0.0, 0.5, 0.0, hi, 0.0, 0.5, 0.0]
d.IsosurfaceValues = values
d.IsosurfaceShading = "Unlit"


def masks(fxaa):
    """Covered pixels of the isosurfaces and of the Contour filter, with the view's FXAA."""
    view.UseFXAA = fxaa
    simple.Show(tets, view)
    simple.Render(view)
    psi = testing.grab(view)
    simple.Hide(tets, view)
    simple.Show(contour, view)
    simple.Render(view)
    ref = testing.grab(view)
    simple.Hide(contour, view)
    return psi.sum(axis=2) > 2, ref.sum(axis=2) > 2, ref.sum(axis=2)


m_psi, m_ref, _ = masks(0)
print("FXAA off: isosurfaces %d pixels, Contour %d, only Contour %d, only isosurfaces %d"
      % (m_psi.sum(), m_ref.sum(), (m_ref & ~m_psi).sum(), (m_psi & ~m_ref).sum()))
t.check(m_ref.sum() > 10000, "the contour covers the view (%d pixels)" % m_ref.sum())
t.check((m_psi ^ m_ref).sum() <= 0.001 * m_ref.sum(),
        "without antialiasing the same pixels are covered (%d differ)" % (m_psi ^ m_ref).sum())
a_psi, a_ref, gray = masks(1)
rim = a_ref & ~a_psi
print("FXAA on: isosurfaces %d pixels, Contour %d, rim %d pixels of mean gray %.0f (inside %.0f)"
      % (a_psi.sum(), a_ref.sum(), rim.sum(), gray[rim].mean() if rim.any() else 0,
         gray[a_ref & a_psi].mean()))
t.check((a_psi ^ m_psi).sum() == 0, "FXAA does not change the isosurfaces (a volume)")
t.check(((a_psi & ~a_ref).sum() == 0) and gray[rim].mean() < 0.5 * gray[a_ref & a_psi].mean(),
        "with FXAA the Contour's extra pixels are a dim antialiasing rim")
t.finish()
