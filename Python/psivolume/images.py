"""Images of a render view and the project's PNG writer (VTK's): the accuracy report's images and
plots, the tests' images, the GUI tests' strict check, the README's screenshot."""
import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter


def grab(view):
    """The view's current image as float RGB in [0, 255], rows from the bottom."""
    w2i = vtkWindowToImageFilter()
    w2i.SetInput(view.GetRenderWindow())
    w2i.ReadFrontBufferOff()
    w2i.ShouldRerenderOff()
    w2i.Update()
    im = w2i.GetOutput()
    dims = im.GetDimensions()
    a = vtk_to_numpy(im.GetPointData().GetScalars()).reshape(dims[1], dims[0], -1)
    return a[:, :, :3].astype(np.float64)


def write_png(rgb, path):
    """Writes `rgb` (rows x columns x 3, bottom row first, as VTK orders images; values 0..255,
    clipped) to a PNG."""
    from vtkmodules.util.numpy_support import numpy_to_vtk
    from vtkmodules.vtkCommonDataModel import vtkImageData
    from vtkmodules.vtkIOImage import vtkPNGWriter

    h, w, _ = rgb.shape
    img = vtkImageData()
    img.SetDimensions(w, h, 1)
    arr = numpy_to_vtk(np.clip(rgb.reshape(-1, 3), 0, 255).astype(np.uint8), deep=1)
    img.GetPointData().SetScalars(arr)
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputData(img)
    writer.Write()
