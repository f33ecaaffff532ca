"""'Psi Volume' in parallel: a tetrahedralized Wavelet rendered on 2 ranks with ParaView's
ordered compositing must match the serial render of the same view.

Run: mpiexec --allow-run-as-root -n 2 pvbatch --force-offscreen-rendering test_mpi.py
The script runs on rank 0 (pvbatch's client). It first renders the serial reference in a separate
serial pvbatch (`test_mpi.py --serial OUT.npy`, with the MPI launcher's environment removed so
that it is a singleton), then the same pipeline and camera on all ranks, and compares the two
images as numbers: mean and max absolute difference per channel, in 1/255 units.

Tolerance: mean |diff| <= 1.0/255 and at most 1% of the pixels differing by more than 24/255. The
parallel image is composited from two 8-bit premultiplied partial images (IceT), so pixels along
the seam between the ranks' regions differ by quantization (a few 1/255); a wrong compositing
order, a missing part or a black frame changes a large share of the pixels by much more."""
import faulthandler
import os
import subprocess
import sys
import tempfile
import time

import numpy as np
from paraview import servermanager, simple
from vtkmodules.util.numpy_support import vtk_to_numpy

from psivolume import data, process, testing

SIZE = 240
HALF = 16  # Wavelet extent [-16, 16]^3: 32^3 voxels, 163,840 tetrahedra
BG = [0.0, 0.0, 0.0]
MEAN_TOL = 1.0  # 1/255 units
OUTLIER = 24.0  # 1/255 units
OUTLIER_FRACTION = 0.01
WATCHDOG = 200  # seconds
# the rank array: ProcessIdScalars' "ProcessId" up to ParaView 5.13, ProcessIds' in ParaView 6
PROCESS_ID_ARRAY = "ProcessId" if hasattr(simple, "ProcessIdScalars") else "PointProcessIds"


def capture(view):
    """The composited image of the view (what SaveScreenshot writes) as float RGB in [0, 255]."""
    im = view.SMProxy.CaptureWindow(1)
    dims = im.GetDimensions()
    a = vtk_to_numpy(im.GetPointData().GetScalars()).reshape(dims[1], dims[0], -1)
    return a[:, :, :3].astype(np.float64)


def build(redistribute, extent=(-HALF, HALF, -HALF, HALF, -HALF, HALF)):
    w = simple.Wavelet(WholeExtent=list(extent))
    src = simple.Tetrahedralize(Input=w)
    if redistribute:
        src = simple.RedistributeDataSet(Input=src)
    # a point array of the rank: where the mesh lives (PROCESS_ID_ARRAY)
    if hasattr(simple, "ProcessIdScalars"):
        ids = simple.ProcessIdScalars(Input=src)
    else:  # ParaView 6
        ids = simple.ProcessIds(Input=src, GeneratePointData=1)
    ids.UpdatePipeline()
    return src, ids


def render(src, view_size=SIZE):
    view = simple.CreateRenderView()
    view.ViewSize = [view_size, view_size]
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = BG
    d = simple.Show(src, view)
    simple.ColorBy(d, ("POINTS", "RTData"))
    d.SetRepresentationType("Psi Volume")
    lut = simple.GetColorTransferFunction("RTData")
    pwf = simple.GetOpacityTransferFunction("RTData")
    lut.RescaleTransferFunction(37.35, 276.8)  # the Wavelet's range, fixed for both runs
    pwf.RescaleTransferFunction(37.35, 276.8)
    lut.ColorSpace = "RGB"
    d.ScalarOpacityUnitDistance = 3.0
    c = view.GetActiveCamera()
    c.SetFocalPoint(0, 0, 0)
    c.SetPosition(60, 35, 45)
    c.SetViewUp(0, 0, 1)
    # the data's bounds, as the first simple.Render of a session resets the camera to them
    view.ResetCamera(*src.GetDataInformation().GetBounds())
    simple.Render(view)
    simple.Render(view)
    return view, d


def serial_main(out):
    data.load_plugin(globals(), os.environ.get("PSI_PLUGIN"))
    src, _ = build(False)
    view, d = render(src)
    np.save(out, capture(view))
    d.UpdatePropertyInformation()
    print("serial: %d tetrahedra drawn" % d.GetProperty("NumberOfTetrahedra").GetElement(0))
    testing.exit_now(0)


def serial_reference(out, script=__file__):
    """Runs `script` (this one by default) with `--serial OUT` serially in a clean environment (no
    MPI launcher variables)."""
    env = process.environment_without_mpi()
    exe = os.environ.get("PSI_PVBATCH") or "pvbatch"
    cmd = [exe, "--force-offscreen-rendering", os.path.abspath(script), "--serial", out]
    t0 = time.time()
    r = subprocess.run(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       timeout=240)
    text = r.stdout.decode(errors="replace")
    print("serial reference (%s, %.1f s, exit %d):" % (" ".join(cmd[:1]), time.time() - t0,
                                                       r.returncode))
    for line in text.splitlines():
        if "serial:" in line or "rror" in line:
            print("    " + line.strip())
    return r.returncode == 0 and os.path.exists(out)


def watch_environment():
    """Fails fast, with the reason, instead of deadlocking: when a rank cannot open its render
    window (X connection refused under load, seen on this machine before any plugin code runs),
    ParaView reports that remote rendering is unavailable and the ranks' renders then wait on
    each other forever. A watchdog also ends a hang after WATCHDOG seconds."""
    from vtkmodules.util.misc import calldata_type
    from vtkmodules.util.vtkConstants import VTK_STRING
    from vtkmodules.vtkCommonCore import vtkCommand, vtkOutputWindow

    @calldata_type(VTK_STRING)
    def on_error(obj, event, text):
        if text and "require remote rendering" in text:
            msg = ("FAILED  environment: a rank could not create its render window (ParaView: "
                   "'%s'); the parallel render would deadlock. Not a Psi Volume result: rerun.\n"
                   % " ".join(text.split())[-120:])
            (sys.__stdout__ or sys.stdout).write(msg)
            testing.exit_now(1)

    vtkOutputWindow.GetInstance().AddObserver(vtkCommand.ErrorEvent, on_error)
    err = open("/dev/stderr", "w")
    faulthandler.dump_traceback_later(WATCHDOG, exit=True, file=err)


def start(name):
    """The checks of a parallel test named `name`, with the environment watched; skips a run on
    fewer than 2 ranks. Returns the checks and the number of ranks."""
    t = testing.Checks(name)
    watch_environment()
    nranks = servermanager.ActiveConnection.GetNumberOfDataPartitions()
    print("ranks: %d" % nranks)
    if nranks < 2:
        print("SKIP: run with mpiexec -n 2 pvbatch (this run has %d rank)" % nranks)
        testing.exit_now(testing.SKIP)
    return t, nranks


def parallel_main():
    t, nranks = start("test_mpi")
    out = os.path.join(tempfile.mkdtemp(), "serial.npy")
    ok = serial_reference(out)
    t.check(ok, "the serial reference rendered")
    if not ok:
        t.finish()
    ref = np.load(out)
    cov_ref = testing.covered(ref, BG)
    t.check(cov_ref > 0.2 * SIZE * SIZE, "serial image not empty (%d pixels)" % cov_ref)

    data.load_plugin(globals(), os.environ.get("PSI_PLUGIN"))
    for redistribute in (False, True):
        label = "RedistributeDataSet" if redistribute else "Wavelet pieces"
        src, ids = build(redistribute)
        ntotal = src.GetDataInformation().GetNumberOfCells()
        prange = ids.PointData[PROCESS_ID_ARRAY].GetRange()
        t.check(prange[0] == 0 and prange[1] == nranks - 1,
                "%s: the mesh is spread over the ranks (ProcessId range %s, %d tetrahedra in all)"
                % (label, prange, ntotal))
        view, d = render(src)
        img = capture(view)
        d.UpdatePropertyInformation()
        n0 = d.GetProperty("NumberOfTetrahedra").GetElement(0)
        print("%s: rank 0 drew %d of %d tetrahedra" % (label, n0, ntotal))
        t.check(0 < n0 < ntotal, "%s: rank 0 drew only its part (%d of %d)" % (label, n0, ntotal))
        cov = testing.covered(img, BG)
        t.check(cov > 0.2 * SIZE * SIZE, "%s: parallel image not black (%d pixels covered, "
                "serial %d)" % (label, cov, cov_ref))
        d_abs = np.abs(img - ref)
        mean, mx = float(d_abs.mean()), float(d_abs.max())
        frac = float((d_abs.max(axis=2) > OUTLIER).mean())
        print("%s: 2 ranks vs serial: mean |diff| %.3f/255, max %.0f/255, %.3f%% of pixels "
              "> %.0f/255" % (label, mean, mx, 100 * frac, OUTLIER))
        t.check(mean <= MEAN_TOL, "%s: mean |diff| vs serial %.3f/255 <= %.1f/255"
                % (label, mean, MEAN_TOL))
        t.check(frac <= OUTLIER_FRACTION, "%s: %.3f%% of pixels differ by more than %.0f/255 "
                "(<= %.0f%%)" % (label, 100 * frac, OUTLIER, 100 * OUTLIER_FRACTION))
        if os.environ.get("PSI_TEST_OUTPUT"):
            np.save(os.path.join(os.environ["PSI_TEST_OUTPUT"], "mpi_%d.npy" % redistribute), img)
            np.save(os.path.join(os.environ["PSI_TEST_OUTPUT"], "mpi_serial.npy"), ref)
        simple.Delete(d)
        simple.Delete(view)
    finish(t)


def finish(t):
    """Ends a parallel test. Not Checks.finish(): os._exit on rank 0 skips MPI_Finalize, and
    mpiexec then reports the job as failed whatever the code. Ending the script lets pvbatch
    finalize all ranks; an exception makes pvbatch (and mpiexec) exit non-zero."""
    faulthandler.cancel_dump_traceback_later()
    print("%s: %s" % (t.name, "FAILED (%d)" % t.failures if t.failures else "passed"))
    sys.stdout.flush()
    if t.failures:
        raise RuntimeError("%s: %d check(s) failed" % (t.name, t.failures))


if __name__ == "__main__":
    if "--serial" in sys.argv:
        serial_main(sys.argv[sys.argv.index("--serial") + 1])
    else:
        parallel_main()
