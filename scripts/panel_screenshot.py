"""Run inside the paraview client (paraview --script=...): sets up the scene the README's panel
screenshot shows, then writes the file named by PSI_SCREENSHOT_READY so that
scripts/readme-images.sh knows the window is ready to be grabbed. The project's package comes
from PYTHONPATH (scripts/readme-images.sh sets it)."""
import os

from paraview import simple

from psivolume import data

data.load_plugin(globals())
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
with open(os.environ["PSI_SCREENSHOT_READY"], "w") as f:
    f.write("ready\n")
