"""Child processes of pvpython/pvbatch scripts (benchmarks, accuracy report, tests), and leaving
pvpython.

pvpython and pvbatch initialize MPI as a singleton, which puts the launcher's variables
(OMPI_*, PMIX_*, ...) in their environment. A child pvpython, pvbatch or mpiexec that inherits
them tries to join that singleton and exits at once, printing nothing (seen with Open MPI 5 under
ParaView 6.1; mpiexec under 5.11). Children get the environment without them.

Children also get PYTHONUNBUFFERED=1: under ParaView 5.13 and 6.1 a pvpython whose stdout is a
pipe lost what it printed (even with print(flush=True)) when it left through os._exit, as the
scripts do (exit_now); unbuffered, the lines reach the parent.

And children find this package: its folder is put first on their PYTHONPATH (the parent may
have found it some other way, say the GUI's Python shell).

The package's one reader of the environment: environment_without_mpi() copies this process's
environment for a child, since a child must run as this process does (its PATH, DISPLAY, Mesa's
settings) less the variables ParaView's MPI singleton put there. It reads no setting of the
package from it; every path and option of psivolume is a function argument."""
import os
import sys

MPI_PREFIXES = ("OMPI_", "PMIX_", "PMI_", "OPAL_", "ORTE_", "HYDRA_", "MPI_")


def environment_without_mpi(base=None, **extra):
    """A copy of `base` (default: this process's environment) without MPI launcher variables,
    unbuffered, with this package on PYTHONPATH, and the variables of `extra` set."""
    base = os.environ if base is None else base
    env = {k: v for k, v in base.items() if not k.startswith(MPI_PREFIXES)}
    env["PYTHONUNBUFFERED"] = "1"
    env["PYTHONPATH"] = python_path(env.get("PYTHONPATH", ""))
    env.update({k: str(v) for k, v in extra.items()})
    return env


def python_path(rest=""):
    """A PYTHONPATH with the folder holding this package first, then the entries of `rest`."""
    here = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    others = [p for p in rest.split(os.pathsep) if p and os.path.abspath(p) != here]
    return os.pathsep.join([here] + others)


def exit_now(code):
    """Leaves pvpython with `code`. sys.exit() from a pvpython script under Xvfb makes the
    teardown fail with GLXBadContext and exit 1 even with ParaView's own mappers (measured with
    the built-in 'Volume' representation), which would turn every passing test into a failure."""
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(code)
