"""ParaView's progress for long Python work: the GUI's progress bar (its text and percentage, user
input held while it runs, as for a filter), pvpython's printed progress.

ParaView shows the progress of what its session's progress handler observes between the
session's PrepareProgress() and CleanupPendingProgress(). A vtkAlgorithm that draws nothing stands
for the Python work: registered with the handler, its UpdateProgress() is shown under its
progress text. Filters updated meanwhile show their own progress in between.

    with Progress("Accuracy report") as progress:
        progress(0.5, "timing rounds")   # "Accuracy report: timing rounds", 50%"""
from paraview import servermanager
from vtkmodules.vtkCommonExecutionModel import vtkAlgorithm

PROGRESS_ID = 0x9517  # the id the handler knows the stand-in by (any unused number)


class Progress:
    def __init__(self, title, session=None):
        self.title = title
        self.session = session or servermanager.ActiveConnection.Session
        self.standin = vtkAlgorithm()
        self.standin.SetProgressText(title)
        self.session.GetProgressHandler().RegisterProgressEvent(self.standin, PROGRESS_ID)

    def __enter__(self):
        self.session.PrepareProgress()
        return self

    def __call__(self, fraction, step=None):
        self.standin.SetProgressText("%s: %s" % (self.title, step) if step else self.title)
        self.standin.UpdateProgress(min(max(float(fraction), 0.0), 1.0))

    def __exit__(self, *exc):
        self.session.CleanupPendingProgress()
        return False
