#!/usr/bin/env python3
"""Runs an MPI test command with a time limit; on a hang, says so and shows where every process
of the command waits before ending them all.

  python3 mpi_watchdog.py --timeout SECONDS -- COMMAND [ARG...]

The command starts in a session of its own. When it ends within SECONDS, this exits with its
exit code (a skip, 77, stays a skip; killed by signal N: 128 + N), after naming and ending what
it left running in that session (a process holding the test's output open would keep CTest
waiting). Otherwise it prints

  [mpi-watchdog] TIMEOUT after SECONDS s: COMMAND

then, for every process still running under the command (mpiexec's ranks, a pvpython client and
the pvserver ranks it started, their children; MPI launchers and daemons only listed), a header
line with its pid, its MPI rank and command line, and the native stack of each of its threads
(`gdb -p PID -batch -ex 'thread apply all bt'`); then ends them all and exits with TIMEOUT_CODE.

Why outside the test's own process: a rank that hangs waits inside a ParaView call that holds
Python's GIL, so no Python thread of the test can run, and faulthandler (which can) shows only
the Python frames of the one process that runs the script, not the ranks' native stacks.

Why the whole tree, not a process group: Open MPI puts each rank in a process group of its own,
and a test may start its server in a session of its own (test_pvserver.py). The processes are
found by parent pid under /proc, recursively, and the members of every session they lead are
added (an orphaned rank stays in its session).

Plain Python 3, no ParaView module: also imported by its test (Testing/Python/test_mpi_watchdog.py).
"""
import argparse
import os
import shutil
import signal
import subprocess
import sys
import time

TIMEOUT_CODE = 124  # as coreutils' timeout(1)
PREFIX = "[mpi-watchdog]"
# processes whose stacks say nothing about the hang (they wait for their ranks): listed only
LAUNCHERS = ("mpiexec", "mpirun", "orterun", "prterun", "orted", "prted", "hydra_pmi_proxy",
             "mpiexec.hydra", "mpiexec.openmpi", "mpirun.openmpi")
RANK_VARIABLES = ("OMPI_COMM_WORLD_RANK", "PMIX_RANK", "PMI_RANK")
GDB_SECONDS = 30.0  # one process's stacks (normally 1-3 s for a pvbatch rank)
STACKS_SECONDS = 60.0  # all the stacks; the CTest TIMEOUT leaves room for this and the end


def say(msg):
    sys.stdout.write("%s %s\n" % (PREFIX, msg))
    sys.stdout.flush()


def stat(pid):
    """(state, ppid, session) of a process, or None when it is gone."""
    try:
        with open("/proc/%d/stat" % pid) as f:
            fields = f.read().rsplit(")", 1)[1].split()
    except OSError:
        return None
    return fields[0], int(fields[1]), int(fields[3])  # fields: state ppid pgrp session ...


def processes():
    """{pid: (state, ppid, session)} of every process."""
    table = {}
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            s = stat(int(entry))
            if s:
                table[int(entry)] = s
    return table


def tree(root, sessions=()):
    """The live pids under `root` and `root` itself, parents before children, then the other
    members of the sessions they lead, of session `root` (the command's, see run()) and of
    `sessions` (ids seen earlier: a server's session outlives the client that started it).
    Never this process, nor the members of its own session."""
    table = processes()
    children = {}
    for pid, (_, ppid, _) in table.items():
        children.setdefault(ppid, []).append(pid)
    found, todo = [], [root]
    while todo:
        pid = todo.pop(0)
        if pid in table and pid not in found:
            found.append(pid)
        todo.extend(sorted(children.get(pid, [])))
    own = os.getsid(0)
    led = {root} | set(sessions) | {pid for pid in found if table[pid][2] == pid}
    led.discard(own)
    found += sorted(pid for pid, (_, _, sid) in table.items()
                    if sid in led and pid not in found)
    me = os.getpid()
    return [pid for pid in found if pid != me and table[pid][0] != "Z"]


def sessions_of(pids):
    """The ids of the sessions that processes `pids` lead."""
    return {pid for pid in pids if (stat(pid) or (0, 0, 0))[2] == pid}


def command_line(pid):
    try:
        with open("/proc/%d/cmdline" % pid, "rb") as f:
            return f.read().replace(b"\0", b" ").decode(errors="replace").strip()
    except OSError:
        return "?"


def rank(pid):
    """The MPI rank in a process's environment (Open MPI, PMIx or MPICH), or None."""
    try:
        with open("/proc/%d/environ" % pid, "rb") as f:
            env = dict(v.split(b"=", 1) for v in f.read().split(b"\0") if b"=" in v)
    except OSError:
        return None
    for name in RANK_VARIABLES:
        if name.encode() in env:
            return env[name.encode()].decode(errors="replace")
    return None


def is_launcher(pid):
    try:
        with open("/proc/%d/comm" % pid) as f:
            return f.read().strip() in LAUNCHERS
    except OSError:
        return False


def stacks(pid, seconds=GDB_SECONDS):
    """The native stack of every thread of process `pid` as gdb prints it (the process is
    stopped while gdb reads it, then detached), or a line saying why not."""
    gdb = shutil.which("gdb")
    if not gdb:
        return "(no stacks: gdb is not installed)"
    env = dict(os.environ, DEBUGINFOD_URLS="")  # never fetch debug info from the network
    env.pop("LD_PRELOAD", None)  # a test's preloaded runtime (ThreadSanitizer) is not gdb's
    cmd = [gdb, "-nx", "-batch", "-iex", "set debuginfod enabled off", "-ex", "set pagination off",
           "-ex", "thread apply all bt", "-p", str(pid)]
    try:
        r = subprocess.run(cmd, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, env=env, timeout=seconds)
    except subprocess.TimeoutExpired:
        return "(no stacks: gdb took more than %.0f s)" % seconds
    return r.stdout.decode(errors="replace").rstrip()


def report(pids, seconds=STACKS_SECONDS):
    """One header line per process, ranks by rank, and the stacks of those that are not MPI
    launchers, all within about `seconds`."""
    def order(pid):
        r = rank(pid)
        return (is_launcher(pid), r is None, int(r) if r and r.isdigit() else 0, pid)
    deadline = time.monotonic() + seconds
    for pid in sorted(pids, key=order):
        r = rank(pid)
        head = "pid %d%s: %s" % (pid, " (rank %s)" % r if r is not None else "",
                                 command_line(pid)[:300])
        if is_launcher(pid):
            say("%s [MPI launcher, stack not shown]" % head)
            continue
        say("stack of %s" % head)
        left = deadline - time.monotonic()
        text = stacks(pid, min(GDB_SECONDS, left)) if left > 1 else "(no stacks: out of time)"
        sys.stdout.write(text + "\n")
        say("end of stack of pid %d" % pid)


def end(root, grace=5.0):
    """SIGTERM to `root`'s tree (tree()), then SIGKILL to what is left after `grace` seconds,
    looked up again each time, with the sessions seen before (a rank whose parent died first
    is no longer under `root`). Returns the pids still alive afterwards."""
    sessions = sessions_of(tree(root))
    for sig in (signal.SIGTERM, signal.SIGKILL):
        for pid in tree(root, sessions):
            try:
                os.kill(pid, sig)
            except OSError:
                pass
        deadline = time.monotonic() + grace
        while time.monotonic() < deadline:
            pids = tree(root, sessions)
            if not pids:
                break
            sessions |= sessions_of(pids)
            time.sleep(0.1)
    return tree(root, sessions)


def run(cmd, seconds, grace=5.0):
    """Runs `cmd` as the module's docstring says; returns the exit code to exit with."""
    proc = subprocess.Popen(cmd, start_new_session=True)

    def interrupted(signum, _frame):  # CTest or a user ending the launcher: end the command too
        say("signal %d: ending %s" % (signum, " ".join(cmd)))
        end(proc.pid, grace)
        os._exit(128 + signum)
    for sig in (signal.SIGTERM, signal.SIGINT, signal.SIGHUP):
        signal.signal(sig, interrupted)

    try:
        code = proc.wait(timeout=seconds)
    except subprocess.TimeoutExpired:
        say("TIMEOUT after %g s: %s" % (seconds, " ".join(cmd)))
        pids = tree(proc.pid)
        say("%d processes still running; the stack of each thread of each follows" % len(pids))
        report(pids)
        left = end(proc.pid, grace)
        proc.wait()
        say("ended %d processes%s; exit %d" % (len(pids), " (%d would not end: %s)" % (
            len(left), left) if left else "", TIMEOUT_CODE))
        return TIMEOUT_CODE
    # a rank or child left behind by a command that ended (it would hold the test's output open)
    left_over = tree(proc.pid)
    if left_over:
        say("the command ended (exit %d) but left %d processes: %s; ending them"
            % (code, len(left_over), ", ".join("%d %s" % (p, command_line(p)[:80])
                                              for p in left_over)))
        end(proc.pid, grace)
    return code if code >= 0 else 128 - code


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--timeout", type=float, required=True, help="seconds")
    parser.add_argument("--grace", type=float, default=5.0,
                        help="seconds between SIGTERM and SIGKILL when ending")
    parser.add_argument("command", nargs=argparse.REMAINDER)
    args = parser.parse_args()
    cmd = args.command[1:] if args.command[:1] == ["--"] else args.command
    if not cmd:
        parser.error("no command")
    sys.exit(run(cmd, args.timeout, args.grace))


if __name__ == "__main__":
    main()
