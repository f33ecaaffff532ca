"""Run inside the paraview client (paraview --script=...), with sys.argv set to [this file,
READY, BUILD] by the script that runs it (paraview passes a script no arguments): sets up the
scene the README's panel screenshot shows with the plugin of the build BUILD, then writes the
file READY so that scripts/readme-images.sh knows the window is ready to be grabbed. The
project's package comes from PYTHONPATH (scripts/readme-images.sh sets it)."""
import sys

from paraview import simple

from psivolume import data

ready, build = sys.argv[1:3]
data.load_plugin(globals(), build_dir=build)
mesh, array = data.wavelet(10)
simple.RenameSource("Wavelet, tetrahedralized", mesh)
view = simple.GetActiveViewOrCreate("RenderView")
d = simple.Show(mesh, view)
simple.ColorBy(d, ("POINTS", array))
d.SetRepresentationType("Psi Volume")
d.RescaleTransferFunctionToDataRange(True, False)
d.IsosurfaceValues = [200.0]
d.IsosurfaceOpacity = 0.6
simple.SetActiveSource(mesh)
simple.Render(view)  # the client frames the view itself once the script is done
with open(ready, "w") as f:
    f.write("ready\n")
