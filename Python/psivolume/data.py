"""Loading datasets for 'Psi Volume' in pvpython: files of the unstructured-volume literature
(PLOT3D pairs, legacy/XML VTK, Exodus) and the embedded default (ParaView's Wavelet, split into
tetrahedra). Shared by the render command, the benchmarks and the tests.

Where things are is given by the caller, never read from the environment: `data_dir` (the shared
datasets; default: ../shared/data beside the checkout), `plugin` (the plugin's file) and
`build_dir` (the build tree to find it in; default: the checkout's build/)."""
import glob
import os

from paraview import servermanager, simple

# The checkout's root: this file is <root>/Python/psivolume/data.py.
SOURCE_ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
# The shared datasets when no folder is given: ../shared/data beside the checkout.
DATA_DIR = os.path.normpath(os.path.join(SOURCE_ROOT, "..", "shared", "data"))

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


def find_plugin(plugin=None, build_dir=None):
    """Path of the plugin: `plugin` when given, else the one this process has loaded (the GUI's,
    say), else the installed one when this package is installed (`cmake --install` adds
    installed_paths.py), else the one in `build_dir` (default: the checkout's build/)."""
    if plugin:
        return plugin
    if loaded_plugin():
        return loaded_plugin()
    try:
        from . import installed_paths
        return os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                             installed_paths.PLUGIN))
    except ImportError:
        pass
    build = build_dir or os.path.join(SOURCE_ROOT, "build")
    # The plugin directory is named for the ParaView it was built against (CMakeLists.txt):
    # only a build for the running ParaView can load.
    sm = servermanager.vtkSMProxyManager
    version = "paraview-%d.%d" % (sm.GetVersionMajor(), sm.GetVersionMinor())
    pattern = os.path.join(build, "lib*", version, "plugins", "PsiVolume", "PsiVolume.so")
    hits = glob.glob(pattern)
    if not hits:
        raise RuntimeError("PsiVolume plugin for %s not built in %s: run scripts/build.sh "
                           "(or give the plugin's path)" % (version, os.path.abspath(build)))
    return os.path.abspath(hits[0])


def load_plugin(ns, plugin=None, build_dir=None):
    """Loads the plugin (find_plugin(`plugin`, `build_dir`)) into the namespace `ns`."""
    simple.LoadPlugin(find_plugin(plugin, build_dir), remote=False, ns=ns)


def wavelet(half=20):
    """The embedded default: ParaView's Wavelet source, tetrahedralized (8,000 * 5 tets at 20)."""
    w = simple.Wavelet(WholeExtent=[-half, half, -half, half, -half, half])
    return simple.Tetrahedralize(Input=w), "RTData"


def with_vector(src):
    """`src` (a Wavelet) with the point vector V = (x, RTData / 40, z + 10), whose components and
    magnitude all differ from each other."""
    return simple.Calculator(Input=src, ResultArrayName="V",
                             Function="coordsX*iHat + RTData/40*jHat + (coordsZ + 10)*kHat")


def shared_file(name, data_dir=None):
    """The first file of the shared dataset `name` (a key of PLOT3D or NAMED_FILES) in
    `data_dir` (default DATA_DIR), whether it exists or not."""
    entry = PLOT3D.get(name) or NAMED_FILES[name]
    return os.path.join(data_dir or DATA_DIR, entry[0])


def plot3d(name, data_dir=None):
    """The PLOT3D dataset `name` of `data_dir` (default DATA_DIR), tetrahedralized, and its
    array."""
    data_dir = data_dir or DATA_DIR
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


def open_any(path, array=None, data_dir=None):
    """A pipeline producing an unstructured grid from `path`, and the point array to render.

    `path` may be a PLOT3D grid file (its solution file is found by replacing 'xyz' with 'q'),
    one of the short names bluntfin/post/comb/spx (files of `data_dir`, default DATA_DIR), or
    anything ParaView reads."""
    base = os.path.basename(path)
    if path in PLOT3D:
        return plot3d(path, data_dir)
    if path in NAMED_FILES:
        path, array = shared_file(path, data_dir), array or NAMED_FILES[path][1]
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


def open_or_wavelet(path=None, array=None, half=20, data_dir=None):
    """open_any(`path`, `array`, `data_dir`), or with no path the embedded default
    (wavelet(`half`)); ends the program with a message when there is no array to render."""
    src, array = open_any(path, array, data_dir) if path else wavelet(half)
    if array is None:
        raise SystemExit("%s has no point or cell array to render" % path)
    return src, array


def association(src, array):
    """'POINTS' or 'CELLS' for the array name."""
    if src.PointData.GetArray(array) is not None:
        return "POINTS"
    return "CELLS"


def display_translation(rep):
    """The property that moves display `rep` (its actor's position): 'Position' up to ParaView
    5.12, 'Translation' from 5.13 on (where 'Position' is refused as obsolete)."""
    return rep.GetProperty("Translation") or rep.GetProperty("Position")


def set_mapper(rep, name):
    """Puts `rep` on 'Psi Volume|<IntegrationMethod>' or on 'Volume' with one of ParaView's
    SelectMapper values ('Projected tetra', 'Z sweep', 'Bunyk ray cast', 'Resample To Image')."""
    if name.startswith("Psi Volume"):
        rep.SetRepresentationType("Psi Volume")
        rep.IntegrationMethod = name.split("|")[1]
    else:
        rep.SetRepresentationType("Volume")
        rep.SelectMapper = name


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
