"""A child process in a session of its own (a server under mpiexec), and its end.

The whole session is ended, not the child's process group: Open MPI puts each rank in a process
group of its own, so a SIGKILL to mpiexec's group leaves the ranks running, waiting for a client
that is gone, one of them busy-waiting in MPI at a full core. SIGTERM goes first (mpiexec passes
it on to its ranks), SIGKILL to whatever is left after a grace period.

The reaper (`python3 -m psivolume.session SID PARENT SECONDS`, started by reaper()) ends the
session when its parent is gone, whatever ended the parent (a crash, a watchdog, a timeout, a
SIGKILL), or after SECONDS. Plain Python: no ParaView module is imported."""
import os
import shutil
import signal
import subprocess
import sys
import time


def members(sid):
    """The pids of the live (not zombie) processes of session `sid`."""
    pids = []
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open("/proc/%s/stat" % entry) as f:
                fields = f.read().rsplit(")", 1)[1].split()
        except OSError:
            continue
        if int(fields[3]) == sid and fields[0] != "Z":  # fields: state, ppid, pgrp, session, ...
            pids.append(int(entry))
    return pids


def end(sid, grace=5.0):
    """SIGTERM to every process of session `sid`, then SIGKILL to those left after `grace`
    seconds. Returns the pids still there afterwards (none, unless a process is stuck in the
    kernel)."""
    for sig in (signal.SIGTERM, signal.SIGKILL):
        for pid in members(sid):
            try:
                os.kill(pid, sig)
            except OSError:
                pass
        deadline = time.monotonic() + grace
        while members(sid) and time.monotonic() < deadline:
            time.sleep(0.2)
    return members(sid)


def reaper(sid, seconds, env=None):
    """Starts the reaper of session `sid` for this process (in a session of its own, so that
    what ends this process's group does not end it)."""
    py = shutil.which("python3") or "/usr/bin/python3"
    return subprocess.Popen([py, "-m", "psivolume.session", str(sid), str(os.getpid()),
                             str(seconds)], env=env, stdin=subprocess.DEVNULL,
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                            start_new_session=True)


def _reap(sid, parent, seconds):
    deadline = time.monotonic() + seconds
    while os.getppid() == parent and time.monotonic() < deadline:
        time.sleep(0.5)
    end(sid)


if __name__ == "__main__":
    _reap(int(sys.argv[1]), int(sys.argv[2]), float(sys.argv[3]))
