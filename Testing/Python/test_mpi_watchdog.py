"""The MPI tests' watchdog (scripts/lib/mpi_watchdog.py) on jobs whose outcome is known.

Run: python3 test_mpi_watchdog.py   (plain Python 3, no ParaView; PSI_MPIEXEC names mpiexec)

1. A 2-rank job that hangs on purpose, as ParaView's ordered compositing can: rank 0 waits in
   MPI_Barrier, which rank 1 never reaches, waiting in MPI_Recv for a message rank 0 never sends.
   Under a short timeout the watchdog must exit with its timeout code, print its TIMEOUT line,
   the stacks of both ranks (gdb's "Thread" and "#0" lines, rank 0's showing the barrier and
   rank 1's the receive) and leave no process of the job running.
2. A 2-rank job that ends by itself with exit code 77 (CTest's skip): the same code, no TIMEOUT.
3. A command that ends leaving a process behind: the launcher ends it.
4. A hung command whose child runs in a session of its own (test_pvserver.py's server): ended.

The ranks run a Python that has mpi4py (python3-mpi4py: Debian's /usr/bin/python3). Without gdb
the stacks cannot be checked: the other checks still run and must pass, then the test reports a
skip (77)."""
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
LAUNCHER = os.path.join(HERE, "..", "..", "scripts", "lib", "mpi_watchdog.py")
sys.path.insert(0, os.path.dirname(LAUNCHER))
import mpi_watchdog  # noqa: E402

SKIP = 77
TIMEOUT_CODE = 124  # the launcher's exit code after a timeout, as coreutils' timeout(1)
TIMEOUT = 15  # seconds: the ranks start within a few seconds, then wait forever
HANG = """
import sys
import numpy as np
from mpi4py import MPI
comm = MPI.COMM_WORLD
print("rank %d waiting" % comm.rank, flush=True)
if comm.rank == 0:
    comm.Barrier()  # rank 1 never comes
else:
    comm.Recv(np.zeros(1), source=0)  # rank 0 never sends
"""
failures = []


def check(ok, msg):
    print("%s  %s" % ("ok    " if ok else "FAILED", msg))
    sys.stdout.flush()
    if not ok:
        failures.append(msg)
    return ok


def mpi_python():
    """A Python 3 interpreter that imports mpi4py, or None."""
    for exe in (sys.executable, "/usr/bin/python3", shutil.which("python3")):
        if exe and subprocess.run([exe, "-c", "import mpi4py"], stdout=subprocess.DEVNULL,
                                  stderr=subprocess.DEVNULL).returncode == 0:
            return exe
    return None


def environment():
    """This environment without the variables of an MPI launcher (a job started from inside
    another would try to join it), and with oversubscription allowed (2 ranks, any core count)."""
    env = {k: v for k, v in os.environ.items()
           if not k.startswith(("OMPI_", "PMIX_", "PMI_", "OPAL_", "ORTE_", "HYDRA_"))}
    env["OMPI_MCA_rmaps_base_oversubscribe"] = "1"
    return env


def watch(seconds, cmd, marker):
    """The launcher's exit code and output (stdout and stderr together). A launcher that has not
    ended 150 s after its timeout fails the test: it is killed, and so is every process whose
    command line holds `marker` (a path made for this job alone)."""
    with tempfile.TemporaryFile() as out:
        launcher = subprocess.Popen([sys.executable, LAUNCHER, "--timeout", str(seconds), "--"]
                                    + cmd, stdin=subprocess.DEVNULL, stdout=out,
                                    stderr=subprocess.STDOUT, env=environment())
        try:
            code = launcher.wait(timeout=seconds + 150)
        except subprocess.TimeoutExpired:
            launcher.kill()
            code = launcher.wait()
            left = kill_marked(marker)
            check(False, "the launcher ended by itself (killed after %d s; then %d processes "
                  "of its job killed)" % (seconds + 150, len(left)))
        out.seek(0)
        return code, out.read().decode(errors="replace")


def kill_marked(marker):
    """SIGKILL to the processes whose command line holds `marker`; their pids."""
    pids = []
    for entry in os.listdir("/proc"):
        if entry.isdigit() and int(entry) != os.getpid() \
                and marker in mpi_watchdog.command_line(int(entry)):
            pids.append(int(entry))
            try:
                os.kill(int(entry), signal.SIGKILL)
            except OSError:
                pass
    return pids


def end_pid(pid):
    """Ends process `pid` that a check found running (a launcher that failed to end it)."""
    if pid > 0 and alive(pid):
        os.kill(pid, signal.SIGKILL)


def alive(pid):
    """Whether process `pid` still runs (a zombie does not)."""
    s = mpi_watchdog.stat(pid)
    return s is not None and s[0] != "Z"


def hung_job(mpiexec, python):
    tmp = tempfile.mkdtemp(prefix="psi_watchdog_")
    script = os.path.join(tmp, "hang.py")
    with open(script, "w") as f:
        f.write(HANG)
    cmd = [mpiexec, "--allow-run-as-root", "-n", "2", python, script]
    code, text = watch(TIMEOUT, cmd, tmp)
    print("---- launcher output ----\n%s\n---- end of launcher output ----" % text.rstrip())
    check(code == TIMEOUT_CODE, "hung job: exit code %d (the timeout's: %d)"
          % (code, TIMEOUT_CODE))
    line = "[mpi-watchdog] TIMEOUT after %d s: %s" % (TIMEOUT, " ".join(cmd))
    check(line in text.splitlines(), "hung job: the line '%s'" % line)
    before = text.split(line)[0]
    check("rank 0 waiting" in before and "rank 1 waiting" in before,
          "hung job: both ranks were waiting before the timeout")
    ranks = dict((int(r), int(p)) for p, r in
                 re.findall(r"\[mpi-watchdog\] stack of pid (\d+) \(rank (\d+)\)", text))
    check(sorted(ranks) == [0, 1], "hung job: a stack for each rank (ranks %s, pids %s)"
          % (sorted(ranks), [ranks[r] for r in sorted(ranks)]))
    launchers = [int(p) for p in re.findall(r"\[mpi-watchdog\] pid (\d+)[^\n]*MPI launcher", text)]
    check(len(launchers) == 1, "hung job: mpiexec listed (pids %s)" % launchers)
    have_gdb = "(no stacks: gdb is not installed)" not in text
    for r, want in ((0, "Barrier"), (1, "Recv")):
        if r not in ranks:
            continue
        pid = ranks[r]
        start = text.find("[mpi-watchdog] stack of pid %d " % pid)
        stop = text.find("[mpi-watchdog] end of stack of pid %d\n" % pid)
        stack = text[start:stop] if 0 <= start < stop else ""
        if have_gdb:
            frames = [ln for ln in stack.splitlines() if re.match(r"#\d+ ", ln)]
            check(re.search(r"^Thread \d+ ", stack, re.M) is not None
                  and any(ln.startswith("#0 ") for ln in frames),
                  "rank %d (pid %d): gdb's stacks ('Thread N' and '#0'; %d frames)"
                  % (r, pid, len(frames)))
            check(any(want in ln for ln in frames), "rank %d: its stack shows where it waits "
                  "(a frame naming '%s')" % (r, want))
    for pid in list(ranks.values()) + launchers:
        check(not alive(pid), "hung job: pid %d no longer running" % pid)
    shutil.rmtree(tmp, ignore_errors=True)
    return have_gdb


def ended_job(mpiexec, python):
    marker = "psi_watchdog_%d" % os.getpid()  # names this job's processes
    cmd = [mpiexec, "--allow-run-as-root", "-n", "2", python, "-c",
           "import sys; sys.exit(77)  # %s" % marker]
    code, text = watch(120, cmd, marker)
    check(code == SKIP and "TIMEOUT" not in text,
          "job that ends by itself: exit code %d (its own: %d), no timeout" % (code, SKIP))


def left_behind():
    tmp = tempfile.mkdtemp(prefix="psi_watchdog_")
    pidfile = os.path.join(tmp, "pid")
    code, text = watch(60, ["sh", "-c", "sleep 300 & echo $! > %s; exit 3" % pidfile], tmp)
    with open(pidfile) as f:
        pid = int(f.read())
    check(code == 3 and "left 1 processes" in text and not alive(pid),
          "command that leaves a process: exit code %d (its own: 3), the process (pid %d) "
          "named and ended" % (code, pid))
    end_pid(pid)
    shutil.rmtree(tmp, ignore_errors=True)


def own_session():
    tmp = tempfile.mkdtemp(prefix="psi_watchdog_")
    pidfile = os.path.join(tmp, "pid")
    child = ("import subprocess, time\n"
             "p = subprocess.Popen(['sleep', '300'], start_new_session=True)\n"
             "open(%r, 'w').write(str(p.pid))\n"
             "time.sleep(300)\n" % pidfile)
    code, text = watch(5, [sys.executable, "-c", child], tmp)
    pid = int(open(pidfile).read()) if os.path.exists(pidfile) else -1
    check(code == TIMEOUT_CODE and pid > 0 and not alive(pid),
          "hung command with a child in a session of its own: exit code %d, the child (pid %d) "
          "ended" % (code, pid))
    end_pid(pid)
    shutil.rmtree(tmp, ignore_errors=True)


def main():
    mpiexec = os.environ.get("PSI_MPIEXEC") or shutil.which("mpiexec")
    python = mpi_python()
    if not check(mpiexec is not None and python is not None,
                 "mpiexec (%s) and a Python with mpi4py (%s)" % (mpiexec, python)):
        sys.exit(1)
    have_gdb = hung_job(mpiexec, python)
    ended_job(mpiexec, python)
    left_behind()
    own_session()
    if failures:
        print("test_mpi_watchdog: FAILED (%d)" % len(failures))
        sys.exit(1)
    if not have_gdb:
        print("SKIP: gdb is not installed, so the ranks' stacks were not checked (the rest "
              "passed)")
        sys.exit(SKIP)
    print("test_mpi_watchdog: passed")


if __name__ == "__main__":
    main()
