"""The project's Python helpers for pvpython, pvbatch and the GUI's Python shell, one module each:

    data            datasets for 'Psi Volume': the literature's files, the embedded default
    images          a view's image as an array, the PNG writer
    testing         the tests' helpers: checks that count failures, image comparison
    timing          frame times: one frame, a view's frames, interleaved rounds of contenders
    process         the environment of child pvpython/pvbatch processes, leaving pvpython
    session         a server's session and its end (the whole session, every MPI rank)
    bench           the benchmarks' scene and exact reference
    accuracy        the accuracy report (also a command: pvpython -m psivolume.accuracy)
    accuracy_plots  the accuracy report's table and plots
    gui             the accuracy report inside ParaView: a spreadsheet view and a point chart
    progress        ParaView's progress (the GUI's progress bar) for long Python work
    moreland        Moreland's Table 6.4 beside the report's ratios

Installed by `cmake --install` beside ParaView's own Python modules, it imports as it is (and finds
the installed plugin). Loading the plugin (LoadPlugin, the GUI) puts the folder holding this
package on sys.path, from a build tree or an install (Plugin/PsiPluginPython.h). Before that, in a
checkout, the folder holding this package (Python/) goes on PYTHONPATH: the tests' CTest
registrations and the scripts set it; by hand, `PYTHONPATH=Python pvpython FILE.py`. Nothing here
imports from the rest of the checkout, and importing the package alone imports no module.

No module reads a setting from the environment: paths (the plugin, its build, the shared
datasets, the reference renderer, pvpython) are function arguments and command-line options,
with defaults for an install and for the checkout's build/. The one reader of the environment is
psivolume.process, which copies it for child processes (less the MPI launcher's variables).
The accuracy report (accuracy, accuracy_plots, gui) imports neither testing nor bench."""
