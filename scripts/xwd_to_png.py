"""Converts an X window dump (XWD, as Xvfb -fbdir keeps its screen) of depth 24/32 to PNG, with
VTK's PNG writer: pvpython scripts/xwd_to_png.py SCREEN.xwd OUT.png [WIDTH HEIGHT] (crops to the
top-left WIDTH x HEIGHT when given)."""
import struct
import sys

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOImage import vtkPNGWriter


def read_xwd(path):
    data = open(path, "rb").read()
    # XWDFileHeader: 25 CARD32, big-endian (X11/XWDFile.h)
    h = struct.unpack(">25I", data[:100])
    header_size, version, depth, width, height = h[0], h[1], h[3], h[4], h[5]
    byte_order, bits_per_pixel, bytes_per_line, ncolors = h[7], h[11], h[12], h[19]
    if version != 7 or bits_per_pixel != 32:
        raise SystemExit("xwd_to_png: only 32-bit XWD version 7 (got version %d, %d bpp)" %
                         (version, bits_per_pixel))
    start = header_size + 12 * ncolors
    rows = np.frombuffer(data, dtype=np.uint8, count=bytes_per_line * height, offset=start)
    pixels = rows.reshape(height, bytes_per_line)[:, :4 * width].reshape(height, width, 4)
    # LSBFirst (0): bytes B, G, R, X; MSBFirst: X, R, G, B
    rgb = pixels[:, :, [2, 1, 0]] if byte_order == 0 else pixels[:, :, [1, 2, 3]]
    return rgb


def write_png(rgb, path):
    height, width, _ = rgb.shape
    image = vtkImageData()
    image.SetDimensions(width, height, 1)
    flat = np.ascontiguousarray(rgb[::-1]).reshape(-1, 3)  # VTK's rows go bottom-up
    image.GetPointData().SetScalars(numpy_to_vtk(flat, deep=1))
    w = vtkPNGWriter()
    w.SetFileName(path)
    w.SetInputData(image)
    w.Write()


if __name__ == "__main__":
    rgb = read_xwd(sys.argv[1])
    if len(sys.argv) >= 5:
        rgb = rgb[:int(sys.argv[4]), :int(sys.argv[3])]
    write_png(rgb, sys.argv[2])
