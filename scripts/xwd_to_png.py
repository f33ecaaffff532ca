"""Converts an X window dump (XWD, as Xvfb -fbdir keeps its screen) of 32 bits per pixel to PNG,
with the project's PNG writer (psivolume.images.write_png, VTK's): pvpython
scripts/xwd_to_png.py SCREEN.xwd OUT.png [WIDTH HEIGHT] (crops to the top-left WIDTH x HEIGHT when
given)."""
import struct
import sys

import numpy as np

from psivolume.images import write_png


def read_xwd(path):
    data = open(path, "rb").read()
    # XWDFileHeader: 25 CARD32, big-endian (X11/XWDFile.h)
    h = struct.unpack(">25I", data[:100])
    header_size, version, width, height = h[0], h[1], h[4], h[5]
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


if __name__ == "__main__":
    rgb = read_xwd(sys.argv[1])
    if len(sys.argv) >= 5:
        rgb = rgb[:int(sys.argv[4]), :int(sys.argv[3])]
    write_png(rgb[::-1], sys.argv[2])  # the screen's top row first; VTK's bottom row first
