"""Ends every process a test run started, found by a tag in its environment.

scripts/test.sh starts each test (all its attempts) with PSI_TEST_RUN=<run>:<n> in its environment,
which every process the test starts inherits, wherever it goes: a child that makes its own
session or process group (test_pvserver.py's server and reaper, Open MPI's singleton daemon),
each MPI rank (Open MPI puts every rank in a process group of its own), and an orphan whose
parent died (a pvserver rank left by a killed smTestDriver waits for its client forever, one
rank busy-waiting in MPI at a full core). Neither a process group nor ctest's own kill of the
test's process tree reaches all of these; the tag does.

  python3 end_tagged.py PREFIX              ends the processes whose PSI_TEST_RUN starts with
                                            PREFIX (SIGTERM, then SIGKILL after --grace
                                            seconds) and prints one line per process
  python3 end_tagged.py PREFIX --watch PID  first waits until process PID is gone (a sentinel
                                            outliving a test.sh killed by SIGKILL)
"""
import argparse
import os
import signal
import sys
import time

TAG = "PSI_TEST_RUN"


def tagged(prefix):
    """{pid: command line} of the processes whose environment has TAG=<prefix...>. A process's
    environment is the one it was started with; other users' processes are not readable and
    not ours."""
    key = ("%s=%s" % (TAG, prefix)).encode()
    found = {}
    for entry in os.listdir("/proc"):
        if not entry.isdigit() or int(entry) == os.getpid():
            continue
        try:
            with open("/proc/%s/environ" % entry, "rb") as f:
                env = f.read().split(b"\0")
            with open("/proc/%s/cmdline" % entry, "rb") as f:
                cmd = f.read().replace(b"\0", b" ").decode(errors="replace").strip()
            with open("/proc/%s/stat" % entry) as f:
                state = f.read().rsplit(")", 1)[1].split()[0]
        except OSError:
            continue
        if state != "Z" and any(v.startswith(key) for v in env):
            found[int(entry)] = cmd
    return found


def alive(pid):
    try:
        with open("/proc/%d/stat" % pid) as f:
            return f.read().rsplit(")", 1)[1].split()[0] != "Z"
    except OSError:
        return False


def signal_all(pids, sig):
    for pid in pids:
        try:
            os.kill(pid, sig)
        except OSError:
            pass


def end(prefix, grace):
    """SIGTERM to every tagged process (mpiexec passes it on to its ranks, Xvfb removes its
    lock), SIGKILL to those still there after `grace` seconds. Returns {pid: command}."""
    found = tagged(prefix)
    if not found:
        return found
    signal_all(found, signal.SIGTERM)
    deadline = time.monotonic() + grace
    while time.monotonic() < deadline and tagged(prefix):
        time.sleep(0.2)
    signal_all(tagged(prefix), signal.SIGKILL)
    return found


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("prefix")
    p.add_argument("--watch", type=int, help="wait until this process is gone first")
    p.add_argument("--grace", type=float, default=5.0)
    a = p.parse_args()
    if not a.prefix:
        sys.exit("end_tagged.py: an empty prefix would match every test run")
    while a.watch and alive(a.watch):
        time.sleep(1)
    for pid, cmd in sorted(end(a.prefix, a.grace).items()):
        print("%d %s" % (pid, cmd[:160]))


if __name__ == "__main__":
    main()
