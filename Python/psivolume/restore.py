"""The user's scene as it was after work that changes it meanwhile, also when that work fails:
the accuracy report switches the display to 'Psi Volume', sets its integration method, adaptive
sampling and interaction mode for each image, turns the camera between timed frames and makes a
merging filter the active source.

    with restore.scene(view, rep, ...):
        ...   # anything of each rep, its color and opacity maps, the view, its camera

Every setting of those proxies (each property but the information-only ones) is put back where
it differs, the camera with the view's properties (ParaView keeps them in step with it)."""
import contextlib

from paraview import simple

# Not put back: the window sets it (the GUI resizes the view with its window meanwhile).
NOT_SETTINGS = {"ViewSize"}


def settings(proxy):
    """{name: value} of `proxy`'s settings: its value and proxy properties, not the
    information-only ones."""
    values = {}
    for name in proxy.ListProperties():
        p = proxy.GetProperty(name)
        sm = p.SMProperty
        if name in NOT_SETTINGS or sm.GetInformationOnly():
            continue
        if sm.IsA("vtkSMVectorProperty") or sm.IsA("vtkSMProxyProperty"):
            values[name] = p.GetData()
    return values


def put_back(proxy, saved):
    """Sets each of `saved` (settings(proxy) as they were) that differs now."""
    now = settings(proxy)
    for name, value in saved.items():
        if now.get(name) != value:
            proxy.GetProperty(name).SetData(value)
    proxy.UpdateVTKObjects()


def proxies(view, reps):
    """The displays, their color and opacity maps and the view (what a display lacks left out),
    each once."""
    found = []
    for rep in reps:
        maps = [rep.GetPropertyValue(n) for n in ("LookupTable", "ScalarOpacityFunction")
                if rep.GetProperty(n) is not None]
        found += [p for p in [rep] + maps if p is not None and p not in found]
    return found + [view]


@contextlib.contextmanager
def scene(view, *reps):
    """The settings of each of `reps`, their maps and `view` (its camera too) and the active
    source put back when the block ends, however it ends; the view rendered as it was."""
    saved = [(p, settings(p)) for p in proxies(view, reps)]
    active = simple.GetActiveSource()
    try:
        yield
    finally:
        for p, values in saved:
            put_back(p, values)
        if simple.GetActiveSource() != active:
            simple.SetActiveSource(active)
        simple.Render(view)
