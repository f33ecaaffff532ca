"""The project's Python helpers for pvpython, pvbatch and the GUI's Python shell, one module each:

    data            datasets for 'Psi Volume': the literature's files, the embedded default
    testing         checks that count failures, image capture and comparison, the PNG writer
    timing          frame times: one frame, a view's frames, interleaved rounds of contenders
    process         the environment of child pvpython/pvbatch processes
    session         a server's session and its end (the whole session, every MPI rank)
    bench           the benchmarks' scene, mapper switching and exact reference
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
imports from the rest of the checkout, and importing the package alone imports no module."""
