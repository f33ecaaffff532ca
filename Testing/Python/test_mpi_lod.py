"""'Psi Volume''s interactive level of detail in parallel: the scene of test_mpi.py on 2 pvbatch
ranks, InteractionMode 'Volume LOD', one interactive render; the composited level of detail must
match the serial (1-rank) level of detail of the same view.

Run: mpiexec --allow-run-as-root -n 2 pvbatch --force-offscreen-rendering test_mpi_lod.py
As test_mpi.py: rank 0 first renders the serial reference in a separate serial pvbatch
(`test_mpi_lod.py --serial OUT.npy`), then the same pipeline on all ranks, for the Wavelet's own
pieces and after RedistributeDataSet. The interactive image is read from the render window (a
screenshot would be a still render); ParaView's interactive image reduction is set to 1 so that
both images have the full resolution.

Each rank probes its piece on ONE lattice spanned over the whole mesh (ParaView's
ordered-compositing cuts give its box to every rank) and draws only its piece's box (cropping): its
ray samples are then exactly the serial ray's samples that fall in that box. The pieces need not
end at the cuts: on ParaView 6.1 the slab, cut at x = 0, comes as [-16, -1] and [-1, 16] (cropped
to the cuts instead: mean 0.767/255, max 70/255, a slab a cell wide missing). Residual differences
against the serial image: the partial images are composited as 8-bit premultiplied colors (as for
the still frame, test_mpi.py: measured there 0.08/255 mean), and between the last lattice point
before the seam and the seam a rank interpolates towards a value it may not hold (the neighbour's
cells), then the nearest one inside its box; and at the silhouette, a ray that grazes the lattice's
box takes one sample more or fewer where the parallel box (spanned over the union of the cuts)
differs from the serial one by a rounding, one sample per lattice spacing being up to about 14/255
there. Measured: mean |diff| 0.071/255, max 7/255 on ParaView 5.11 (the pixels above 4/255 on the
box's silhouette edges), 0.075/255 and 9/255 on 6.1, for both data distributions; through pvserver
(test_pvserver.py) mean 0.11/255, max 10-14/255. Before the common lattice (each rank on its own
lattice over its piece's bounds): mean 0.196/255, the seam visible.

Tolerance: mean |diff| <= MEAN_TOL and no pixel differing by more than MAX_TOL."""
import os
import sys
import tempfile

import numpy as np
from paraview import simple

import test_mpi  # the scene, camera, capture, environment watch and serial run of the MPI test
from psivolume import data, testing

SIZE = test_mpi.SIZE
BG = test_mpi.BG
LOD = 1  # psi::InteractiveImages::VolumeLOD
# A slab, twice as long in x as across: ParaView cuts it in x at 0, into cubes; a lattice over each
# cube alone would be twice as fine as the serial one, and 0 is not a point of the serial lattice.
EXTENT = (-test_mpi.HALF, test_mpi.HALF, -test_mpi.HALF // 2, test_mpi.HALF // 2,
          -test_mpi.HALF // 2, test_mpi.HALF // 2)
MEAN_TOL = 0.1  # 1/255 units
MAX_TOL = 16.0  # 1/255 units, any pixel (a silhouette edge's sample, see above)


def lod_frame(src):
    """The still image, the interactive 'Volume LOD' image and what drew the interactive frame."""
    view, d = test_mpi.render(src)
    view.ImageReductionFactor = 1  # the interactive frame at full resolution
    still = testing.grab(view)
    d.InteractionMode = "Volume LOD"
    view.InteractiveRender()
    img = testing.grab(view)
    d.UpdatePropertyInformation()
    used = d.GetProperty("LastInteractiveImage").GetElement(0)
    simple.Delete(d)
    simple.Delete(view)
    return still, img, used


def serial_main(out):
    data.load_plugin(globals(), os.environ.get("PSI_PLUGIN"))
    src, _ = test_mpi.build(False, EXTENT)
    still, img, used = lod_frame(src)
    np.save(out, img)
    np.save(out + ".still.npy", still)
    print("serial: the interactive frame drew %d" % used)
    testing.exit_now(0 if used == LOD else 1)


def parallel_main():
    t, _ = test_mpi.start("test_mpi_lod")
    out = os.path.join(tempfile.mkdtemp(), "serial_lod.npy")
    ok = test_mpi.serial_reference(out, __file__)
    t.check(ok, "the serial level of detail rendered")
    if not ok:
        t.finish()
    ref, ref_still = np.load(out), np.load(out + ".still.npy")
    t.check(testing.covered(ref, BG) > 0.2 * SIZE * SIZE, "serial image not empty")
    # (0.49/255 apart on this scene since the level of detail reads the opacity as 'Psi Volume'
    # does: a still frame drawn instead would be 0)
    t.check(testing.mean_error(ref, ref_still) > 0.2 / 255,
            "the serial level of detail is not the still frame (mean |diff| %.3f/255)"
            % (255 * testing.mean_error(ref, ref_still)))

    data.load_plugin(globals(), os.environ.get("PSI_PLUGIN"))
    for redistribute in (False, True):
        label = "RedistributeDataSet" if redistribute else "Wavelet pieces"
        src, _ = test_mpi.build(redistribute, EXTENT)
        still, img, used = lod_frame(src)
        t.check(used == LOD, "%s: rank 0 drew the level of detail (%d)" % (label, used))
        d_abs = np.abs(img - ref)
        mean, mx = float(d_abs.mean()), float(d_abs.max())
        print("%s: 2-rank vs serial level of detail: mean |diff| %.3f/255, max %.0f/255; vs the "
              "2-rank still frame %.3f/255" % (label, mean, mx, 255 * testing.mean_error(img, still)))
        t.check(mean <= MEAN_TOL, "%s: mean |diff| %.3f/255 <= %.2f/255" % (label, mean, MEAN_TOL))
        t.check(mx <= MAX_TOL, "%s: max |diff| %.0f/255 <= %.0f/255" % (label, mx, MAX_TOL))
        if os.environ.get("PSI_TEST_OUTPUT"):
            save = os.environ["PSI_TEST_OUTPUT"]
            np.save(os.path.join(save, "lod_mpi_%d.npy" % redistribute), img)
            np.save(os.path.join(save, "lod_serial.npy"), ref)
    test_mpi.finish(t)


if __name__ == "__main__":
    if "--serial" in sys.argv:
        serial_main(sys.argv[sys.argv.index("--serial") + 1])
    else:
        parallel_main()
