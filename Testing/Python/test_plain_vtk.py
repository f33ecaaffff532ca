"""vtkPsiVolumeMapper from plain VTK Python: the Rendering module on VTK alone, no ParaView.

Run with the Python interpreter VTK was built for (not pvpython), the wrapped modules' folder as
the argument:  python3 test_plain_vtk.py BUILD/lib/python3/dist-packages

A tetrahedral Wavelet drawn by vtkPsiVolumeMapper and by VTK's own vtkProjectedTetrahedraMapper
in the same window, camera and volume property:
  - no ParaView module is imported and no ParaView library is loaded into the process;
  - the mapper draws every tetrahedron (its read-out) with the geometry-shader projector;
  - both images cover the same footprint, and agree within a few 8-bit levels on average (VTK's
    projected tetrahedra approximate each segment, so they are not equal);
  - the opacity function scaled to zero draws the background only, and restored draws the
    image again (the mapper follows the property's modifications).
Exits 1 with a line per failed check.
"""
import sys

sys.path.insert(0, sys.argv[1])

from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkFiltersGeneral import vtkDataSetTriangleFilter
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkRenderer, vtkRenderWindow,
                                         vtkVolume, vtkVolumeProperty, vtkWindowToImageFilter)
from vtkmodules.vtkRenderingVolumeOpenGL2 import vtkOpenGLProjectedTetrahedraMapper
from vtkmodules.util.numpy_support import vtk_to_numpy
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL factory overrides)
import vtkmodules.vtkRenderingVolumeOpenGL2  # noqa: F401

from psivolume_vtk.PsiVolumeRendering import vtkPsiVolumeMapper

FAILURES = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        FAILURES.append(what)


def mesh():
    source = vtkRTAnalyticSource()
    source.SetWholeExtent(-10, 10, -10, 10, -10, 10)
    tets = vtkDataSetTriangleFilter()
    tets.SetInputConnection(source.GetOutputPort())
    tets.Update()
    return tets.GetOutput()


def opacity_ramp(opacity, rng, top):
    """The opacity function: 0 at the scalar range's low end, `top` at its high end."""
    opacity.RemoveAllPoints()
    opacity.AddPoint(rng[0], 0.0)
    opacity.AddPoint(rng[1], top)


def volume_property(rng):
    color = vtkColorTransferFunction()
    color.AddRGBPoint(rng[0], 0.2, 0.3, 1.0)
    color.AddRGBPoint(rng[1], 1.0, 0.4, 0.1)
    opacity = vtkPiecewiseFunction()
    opacity_ramp(opacity, rng, 0.6)
    prop = vtkVolumeProperty()
    prop.SetColor(color)
    prop.SetScalarOpacity(opacity)
    prop.SetScalarOpacityUnitDistance(4.0)
    return prop, opacity


def grab(window):
    window.Render()
    capture = vtkWindowToImageFilter()
    capture.SetInput(window)
    capture.SetInputBufferTypeToRGB()
    capture.ReadFrontBufferOff()
    capture.Update()
    image = capture.GetOutput()
    w, h, _ = image.GetDimensions()
    return vtk_to_numpy(image.GetPointData().GetScalars()).reshape(h, w, 3).astype(float)


def paraview_libraries():
    with open("/proc/self/maps") as maps:
        return sorted({line.split()[-1] for line in maps
                       if "libvtkRemoting" in line or "libvtkPV" in line or "ParaView" in line})


def main():
    data = mesh()
    rng = data.GetPointData().GetScalars().GetRange()
    prop, opacity = volume_property(rng)
    renderer = vtkRenderer()
    renderer.SetBackground(0, 0, 0)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(200, 200)
    window.AddRenderer(renderer)
    volume = vtkVolume()
    volume.SetProperty(prop)
    renderer.AddVolume(volume)
    renderer.GetActiveCamera().Azimuth(30)
    renderer.GetActiveCamera().Elevation(20)

    psi = vtkPsiVolumeMapper()
    psi.SetInputData(data)
    psi.SetProjector(0)
    volume.SetMapper(psi)
    renderer.ResetCamera()
    ours = grab(window)
    check(psi.GetNumberOfTetrahedra() == data.GetNumberOfCells(),
          "all %d tetrahedra drawn (read-out %d)" % (data.GetNumberOfCells(),
                                                   psi.GetNumberOfTetrahedra()))
    check(psi.GetLastUsedProjector() == 0, "the geometry-shader projector drew the frame")

    vtk_pt = vtkOpenGLProjectedTetrahedraMapper()
    vtk_pt.SetInputData(data)
    volume.SetMapper(vtk_pt)
    theirs = grab(window)

    drawn_ours, drawn_theirs = ours.sum(axis=2) > 3, theirs.sum(axis=2) > 3
    overlap = (drawn_ours & drawn_theirs).sum() / max(1, (drawn_ours | drawn_theirs).sum())
    check(drawn_ours.sum() > 0.1 * drawn_ours.size, "the volume covers %.0f%% of the window"
          % (100.0 * drawn_ours.sum() / drawn_ours.size))
    check(overlap > 0.97, "the footprint is VTK's projected tetrahedra's (overlap %.3f)" % overlap)
    mean = abs(ours - theirs).mean()
    check(mean < 4.0, "the image is VTK's projected tetrahedra's within %.2f/255 on average"
          % mean)

    volume.SetMapper(psi)
    opacity_ramp(opacity, rng, 0.0)
    check(grab(window).max() == 0, "a zero opacity function draws the background only")
    opacity_ramp(opacity, rng, 0.6)
    check(abs(grab(window) - ours).max() == 0, "the opacity restored draws the first image again")

    loaded = [name for name in sys.modules if name.split(".")[0] in ("paraview", "paraview_")]
    check(not loaded, "no ParaView Python module imported (%s)" % ", ".join(loaded))
    libraries = paraview_libraries()
    check(not libraries, "no ParaView library loaded (%s)" % ", ".join(libraries))
    return 1 if FAILURES else 0


if __name__ == "__main__":
    sys.exit(main())
