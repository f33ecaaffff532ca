"""Loading datasets for 'Psi Volume' in pvpython: files of the unstructured-volume literature
(PLOT3D pairs, legacy/XML VTK, Exodus) and the embedded default (ParaView's Wavelet, split into
tetrahedra). Shared by the render command, the benchmarks and the tests."""
import glob
import os

from paraview import servermanager, simple

# The checkout's root: this file is <root>/Python/psivolume/data.py.
SOURCE_ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
SHARED_DATA = os.environ.get("PSI_DATA") or os.path.normpath(
    os.path.join(SOURCE_ROOT, "..", "shared", "data"))

# PLOT3D datasets of ../shared/data: grid file, solution file, IBLANK, array to render.
PLOT3D = {
    "bluntfin": ("bluntfinxyz.bin", "bluntfinq.bin", 0, "Density"),
    "post": ("postxyz.bin", "postq.bin", 1, "StagnationEnergy"),
    "comb": ("combxyz.bin", "combq.bin", 0, "Density"),
}

# Single-file datasets of ../shared/data by short name, and the point array to render.
NAMED_FILES = {"spx": ("spx.vtk", "scalars")}


def loaded_plugin():
    """The file of the PsiVolume plugin this process has loaded, or None. Resolved: ParaView
    reports the path as its plugin list spelled it (/usr/bin/../lib/..., or a link of the
    directory of other packages' plugins)."""
    info = servermanager.vtkSMProxyManager.GetProxyManager().GetPluginManager() \
        .GetLocalInformation()
    for i in range(info.GetNumberOfPlugins() if info else 0):
        if info.GetPluginName(i) == "PsiVolume" and info.GetPluginLoaded(i):
            return os.path.realpath(info.GetPluginFileName(i))
    return None


def find_plugin():
    """Path of the plugin (PSI_PLUGIN overrides): the one this process has loaded (the GUI's, say),
    else the installed one when this package is installed (`cmake --install` adds
    installed_paths.py), else the checkout's build."""
    if os.environ.get("PSI_PLUGIN"):
        return os.environ["PSI_PLUGIN"]
    if loaded_plugin():
        return loaded_plugin()
    try:
        from . import installed_paths
        return os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                             installed_paths.PLUGIN))
    except ImportError:
        pass
    build = os.environ.get("PSI_BUILD_DIR") or os.path.join(SOURCE_ROOT, "build")
    # The plugin directory is named for the ParaView it was built against (CMakeLists.txt):
    # only a build for the running ParaView can load.
    sm = servermanager.vtkSMProxyManager
    version = "paraview-%d.%d" % (sm.GetVersionMajor(), sm.GetVersionMinor())
    pattern = os.path.join(build, "lib*", version, "plugins", "PsiVolume", "PsiVolume.so")
    hits = glob.glob(pattern)
    if not hits:
        raise RuntimeError("PsiVolume plugin for %s not built in %s: run scripts/build.sh "
                           "(or set PSI_PLUGIN)" % (version, os.path.abspath(build)))
    return os.path.abspath(hits[0])


def load_plugin(ns):
    simple.LoadPlugin(find_plugin(), remote=False, ns=ns)


def wavelet(half=20):
    """The embedded default: ParaView's Wavelet source, tetrahedralized (8,000 * 5 tets at 20)."""
    w = simple.Wavelet(WholeExtent=[-half, half, -half, half, -half, half])
    return simple.Tetrahedralize(Input=w), "RTData"


def with_vector(src):
    """`src` (a Wavelet) with the point vector V = (x, RTData / 40, z + 10), whose components and
    magnitude all differ from each other."""
    return simple.Calculator(Input=src, ResultArrayName="V",
                             Function="coordsX*iHat + RTData/40*jHat + (coordsZ + 10)*kHat")


def plot3d(name, data_dir=SHARED_DATA):
    xyz, q, iblank, array = PLOT3D[name]
    reader = simple.PLOT3DReader(FileName=os.path.join(data_dir, xyz),
                                 QFileName=[os.path.join(data_dir, q)])
    reader.BinaryFile = 1
    reader.ByteOrder = "BigEndian"
    reader.MultiGrid = 0
    reader.HasByteCount = 0
    reader.IBlanking = iblank
    merged = simple.MergeBlocks(Input=reader)
    return simple.Tetrahedralize(Input=merged), array


def open_any(path, array=None):
    """A pipeline producing an unstructured grid from `path`, and the point array to render.

    `path` may be a PLOT3D grid file (its solution file is found by replacing 'xyz' with 'q'),
    one of the short names bluntfin/post/comb/spx, or anything ParaView reads."""
    base = os.path.basename(path)
    if path in PLOT3D:
        return plot3d(path)
    if path in NAMED_FILES:
        path, array = os.path.join(SHARED_DATA, NAMED_FILES[path][0]), array or NAMED_FILES[path][1]
    if base.endswith("xyz.bin"):
        key = base[: -len("xyz.bin")]
        if key in PLOT3D:
            return plot3d(key, os.path.dirname(os.path.abspath(path)))
    if not os.path.exists(path):
        raise SystemExit("no such file: %s" % path)
    reader = simple.OpenDataFile(path)
    if reader is None:
        raise SystemExit("ParaView cannot read %s" % path)
    reader.UpdatePipeline()
    src = reader
    if reader.GetDataInformation().DataInformation.IsCompositeDataSet():
        src = simple.MergeBlocks(Input=reader)
    if array is None:
        pd = src.PointData
        names = [pd.GetArray(i).Name for i in range(pd.GetNumberOfArrays())]
        if names:
            array = names[0]
        else:
            cd = src.CellData
            names = [cd.GetArray(i).Name for i in range(cd.GetNumberOfArrays())]
            array = names[0] if names else None
    return src, array


def open_or_wavelet(path=None, array=None, half=20):
    """open_any(`path`, `array`), or with no path the embedded default (wavelet(`half`)); ends
    the program with a message when there is no array to render."""
    src, array = open_any(path, array) if path else wavelet(half)
    if array is None:
        raise SystemExit("%s has no point or cell array to render" % path)
    return src, array


def association(src, array):
    """'POINTS' or 'CELLS' for the array name."""
    if src.PointData.GetArray(array) is not None:
        return "POINTS"
    return "CELLS"


def show_volume(src, array, view, representation="Psi Volume", unit_distance=None,
                assoc=None):
    """Shows `src` as a volume colored by `array` ('POINTS' or 'CELLS' as `assoc` says,
    else the association that has it, points first) with ParaView's default maps."""
    d = simple.Show(src, view)
    simple.ColorBy(d, (assoc or association(src, array), array))
    d.SetRepresentationType(representation)
    d.RescaleTransferFunctionToDataRange(True, False)
    if unit_distance is not None:
        d.ScalarOpacityUnitDistance = unit_distance
    return d


def volume_view(src, array, size, unit_distance=None):
    """The commands' scene (the render command, the accuracy report): `src` shown as a volume
    colored by `array` in a size x size view without orientation axes, the camera reset, turned
    30 degrees and raised 20. Returns (view, representation)."""
    view = simple.CreateRenderView()
    view.ViewSize = [size, size]
    view.OrientationAxesVisibility = 0
    d = show_volume(src, array, view, unit_distance=unit_distance)
    view.ResetCamera()
    cam = view.GetActiveCamera()
    cam.Azimuth(30)
    cam.Elevation(20)
    view.ResetCamera()
    return view, d
