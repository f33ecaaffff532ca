"""The main command (scripts/psi_render.py) as a user runs it: the embedded default, and an
Exodus multiblock file of hexahedra from ../shared/data (skipped when the folder is absent): it
prints the tetrahedra drawn and writes a non-empty PNG."""
import os
import re
import subprocess
import sys
import tempfile

from vtkmodules.vtkIOImage import vtkPNGReader

from psivolume import data, testing

here = os.path.dirname(os.path.abspath(__file__))

t = testing.Checks("test_render_command")
script = os.path.join(here, "..", "..", "scripts", "psi_render.py")
pvpython = sys.executable if "pvpython" in os.path.basename(sys.executable) else "pvpython"
cases = [("default", [], 320000)]
exodus = os.path.join(os.environ.get("PSI_DATA_DIR") or data.DATA_DIR, "disk_out_ref.ex2")
if os.path.exists(exodus):
    cases.append(("exodus multiblock hexahedra", [exodus], None))
else:
    print("skipping the Exodus case: %s not found" % exodus)
for name, args, expected in cases:
    out = os.path.join(tempfile.mkdtemp(), "image.png")
    if os.environ.get("PSI_PLUGIN"):
        args = args + ["--plugin", os.environ["PSI_PLUGIN"]]
    r = subprocess.run([pvpython, "--force-offscreen-rendering", script] + args +
                       ["--out", out, "--size", "128", "--frames", "2"],
                       capture_output=True, text=True, timeout=300)
    m = re.search(r"tetrahedra: (\d+) drawn", r.stdout)
    ntets = int(m.group(1)) if m else 0
    t.check(r.returncode == 0 and m is not None,
            "%s: the command runs and reports its tetrahedra (%s)" % (name, r.stdout[-300:] + r.stderr[-300:]
                                                                     if not m else ntets))
    if expected is not None:
        t.check(ntets == expected, "%s: %d tetrahedra drawn (expected %d)" % (name, ntets, expected))
    else:
        t.check(ntets > 0, "%s: tetrahedra drawn (%d)" % (name, ntets))
    t.check(re.search(r"frame time: [0-9.]+ s", r.stdout) is not None, "%s: frame time printed" % name)
    ok = os.path.exists(out)
    if ok:
        reader = vtkPNGReader()
        reader.SetFileName(out)
        reader.Update()
        rng = reader.GetOutput().GetPointData().GetScalars().GetRange(0)
        ok = rng[1] > rng[0]
    t.check(ok, "%s: a non-uniform PNG was written" % name)
t.finish()
