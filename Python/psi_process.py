"""Child processes of pvpython/pvbatch scripts (benchmarks, accuracy report, tests).

pvpython and pvbatch initialize MPI as a singleton, which puts the launcher's variables
(OMPI_*, PMIX_*, ...) in their environment. A child pvpython, pvbatch or mpiexec that inherits
them tries to join that singleton and exits at once, printing nothing (seen with Open MPI 5 under
ParaView 6.1; mpiexec under 5.11). Children get the environment without them.

Children also get PYTHONUNBUFFERED=1: under ParaView 5.13 and 6.1 a pvpython whose stdout is a
pipe lost what it printed (even with print(flush=True)) when it left through os._exit, as the
scripts do (psi_testing.exit_now); unbuffered, the lines reach the parent."""
import os

MPI_PREFIXES = ("OMPI_", "PMIX_", "PMI_", "OPAL_", "ORTE_", "HYDRA_", "MPI_")


def environment_without_mpi(base=None):
    """A copy of `base` (default: this process's environment) without MPI launcher variables."""
    base = os.environ if base is None else base
    env = {k: v for k, v in base.items() if not k.startswith(MPI_PREFIXES)}
    env["PYTHONUNBUFFERED"] = "1"
    return env
