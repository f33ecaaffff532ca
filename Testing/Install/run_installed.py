#!/usr/bin/env python3
"""PsiPython.installed: `cmake --install BUILD --prefix TMP` into a temporary prefix, the files a
packager gets checked; then `import psivolume` after loading the installed plugin with no
PYTHONPATH (Testing/Python/test_gui_report.py --import-only), and Testing/Python/test_installed.py
run by pvpython against that tree with PYTHONPATH naming only the installed package (no checkout,
no PSI_* overrides)."""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    ap.add_argument("--cmake", required=True)
    ap.add_argument("--pvpython", required=True)
    ap.add_argument("--plugins-dir", required=True, help="relative to the prefix")
    ap.add_argument("--python-dir", required=True, help="relative to the prefix")
    args = ap.parse_args()
    prefix = tempfile.mkdtemp(prefix="psivolume-install-")
    try:
        return run(args, prefix)
    finally:
        shutil.rmtree(prefix, ignore_errors=True)


def run(args, prefix):
    subprocess.run([args.cmake, "--install", args.build, "--prefix", prefix], check=True,
                   stdout=subprocess.DEVNULL)
    expected = [os.path.join(args.plugins_dir, p) for p in (
        "PsiVolume.plugins.xml", "PsiVolume/PsiVolume.so", "PsiVolume/libPsiVolumeCore.so",
        "PsiVolume/psi_reference_render")]
    expected += [os.path.join(args.python_dir, "psivolume", p) for p in (
        "__init__.py", "accuracy.py", "timing.py", "installed_paths.py")]
    missing = [p for p in expected if not os.path.exists(os.path.join(prefix, p))]
    headers = os.path.exists(os.path.join(prefix, "include"))
    print("installed into %s; missing: %s; headers: %s" % (prefix, missing or "none", headers))
    if missing or headers:
        return 1
    env = {k: v for k, v in os.environ.items()
           if not k.startswith("PSI_") and k != "PYTHONPATH"}
    package_dir = os.path.join(prefix, args.python_dir)
    # `import psivolume` after LoadPlugin with no PYTHONPATH: the installed plugin puts the
    # installed package's folder on sys.path (this prefix's is not ParaView's)
    script = os.path.join(HERE, "..", "Python", "test_gui_report.py")
    plugin = os.path.join(prefix, args.plugins_dir, "PsiVolume", "PsiVolume.so")
    imported = subprocess.run([args.pvpython, "--force-offscreen-rendering", script, "--plugin",
                               plugin, "--package-dir", package_dir, "--import-only"],
                              env=env, cwd=prefix).returncode
    env["PYTHONPATH"] = package_dir
    script = os.path.join(HERE, "..", "Python", "test_installed.py")
    return subprocess.run([args.pvpython, "--force-offscreen-rendering", script,
                           "--prefix", prefix], env=env, cwd=prefix).returncode or imported


if __name__ == "__main__":
    sys.exit(main())
