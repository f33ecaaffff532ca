"""Child processes of pvpython/pvbatch scripts (benchmarks, accuracy report, tests).

pvpython and pvbatch initialize MPI as a singleton, which puts the launcher's variables
(OMPI_*, PMIX_*, ...) in their environment. A child pvpython, pvbatch or mpiexec that inherits
them tries to join that singleton and exits at once, printing nothing (seen with Open MPI 5 under
ParaView 6.1; mpiexec under 5.11). Children get the environment without them.

Children also get PYTHONUNBUFFERED=1: under ParaView 5.13 and 6.1 a pvpython whose stdout is a
pipe lost what it printed (even with print(flush=True)) when it left through os._exit, as the
scripts do (testing.exit_now); unbuffered, the lines reach the parent.

And children find this package: its folder is put first on their PYTHONPATH (the parent may
have found it some other way, say the GUI's Python shell)."""
import os

MPI_PREFIXES = ("OMPI_", "PMIX_", "PMI_", "OPAL_", "ORTE_", "HYDRA_", "MPI_")


def environment_without_mpi(base=None):
    """A copy of `base` (default: this process's environment) without MPI launcher variables,
    unbuffered, with this package on PYTHONPATH."""
    base = os.environ if base is None else base
    env = {k: v for k, v in base.items() if not k.startswith(MPI_PREFIXES)}
    env["PYTHONUNBUFFERED"] = "1"
    env["PYTHONPATH"] = python_path(env.get("PYTHONPATH", ""))
    return env


def python_path(rest=""):
    """A PYTHONPATH with the folder holding this package first, then the entries of `rest`."""
    here = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    others = [p for p in rest.split(os.pathsep) if p and os.path.abspath(p) != here]
    return os.pathsep.join([here] + others)
