"""Frame timing that holds on a noisy machine, shared by the accuracy report and the benchmarks.

Contenders (a mapper, a method, a setting) are measured in interleaved rounds: each contender
once per round, the order rotating from round to round, so that whatever else the machine does
(another process, a frequency change) falls on all of them alike. In its turn a contender draws
`warmup` frames that are not counted (tables, shaders, the first sort), then `frames` timed
frames, the camera turning by +-`jitter` degrees between them so that view-dependent work is
counted (or around an orbit); its round time is the frame_time (median) of those frames, in wall
seconds and in CPU seconds of the process that drew them (all its threads: Mesa's llvmpipe
renders inside the process). A single frame is timed by frame(), a view's frames by
time_frames(): the benchmarks, the render command and the accuracy report time frames that way.

Each contender's ratio to the baseline is taken round by round, against the baseline measured in
the same round, and summarized by its median and interquartile range. Rounds go on until every
ratio's interquartile range is within `target` of its median (after at least `min_rounds`), or
until the time budget is spent; the result says which.

A contender can run in this process (InProcess) or in a child pvpython that stays up for all the
rounds (Child: its crash is a note in the table, not the end of the run)."""
import json
import math
import os
import queue
import subprocess
import sys
import threading
import time

import numpy as np

from . import process

ROUND_PREFIX = "PSI_ROUND "
CHILD_READY = "PSI_CHILD_READY"


def wait(view):
    """Blocks until the GL work of the last render of `view` is done (for wall-clock frame
    times)."""
    view.GetRenderWindow().WaitForCompletion()


def frame(view, interactive=False):
    """(wall, cpu) seconds of one frame of `view`: its Render (InteractiveRender with
    `interactive`, the frame drawn while the camera moves) and the GL work it started."""
    from paraview import simple

    wall0, cpu0 = time.perf_counter(), time.process_time()
    if interactive:
        view.InteractiveRender()
    else:
        simple.Render(view)
    wait(view)
    return time.perf_counter() - wall0, time.process_time() - cpu0


def frame_time(seconds):
    """The frame time of frames timed one by one (a list of seconds): their median, so that a
    frame that met a hiccup of the machine does not move it. Every frame time of the project is
    summarized by this function."""
    return float(np.median(seconds))


def time_frames(view, frames, warmup=1, jitter=0.5, orbit=False, interactive=False):
    """(wall, cpu) seconds per frame of `view`: `warmup` frames untimed, then the frame_time of
    `frames` timed ones (interactive frames with `interactive`). The camera turns by +-`jitter`
    degrees between frames, or with `orbit` by 360/`frames` degrees before each (an orbit), and
    is put back."""
    cam = view.GetActiveCamera()
    saved = (list(view.CameraPosition), list(view.CameraFocalPoint), list(view.CameraViewUp))
    for _ in range(warmup):
        frame(view, interactive)
    frames = max(frames, 1)
    walls, cpus = [], []
    for k in range(frames):
        cam.Azimuth(360.0 / frames if orbit else (jitter if k % 2 == 0 else -jitter))
        wall, cpu = frame(view, interactive)
        walls.append(wall)
        cpus.append(cpu)
    view.CameraPosition, view.CameraFocalPoint, view.CameraViewUp = saved
    return frame_time(walls), frame_time(cpus)


class InProcess:
    """A contender drawn in this process: `prepare()` puts the view in its state (a
    representation, a method), then its frames are timed (time_frames; over an orbit with
    `orbit`; interactive frames with `interactive`)."""

    def __init__(self, name, view, prepare=None, orbit=False, interactive=False):
        self.name, self.view, self.prepare, self.orbit, self.note = name, view, prepare, orbit, ""
        self.interactive = interactive

    def measure(self, frames, warmup, jitter):
        if self.prepare:
            self.prepare()
        return time_frames(self.view, frames, warmup, jitter, self.orbit, self.interactive)

    def close(self):
        pass


class ChildProcess:
    """A child pvpython that stays up for all the rounds: it runs `argv`, prints a line starting
    with CHILD_READY once its scene is drawn, then answers rounds (serve_rounds). A crash or a
    silence of `timeout` seconds ends it; `note` then says why."""

    def __init__(self, argv, env=None, timeout=300):
        self.note, self.timeout, self.tail, self.output = "", timeout, [], []
        self.proc = subprocess.Popen(argv, stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                     stderr=subprocess.STDOUT, text=True, env=env, bufsize=1)
        self.lines = queue.Queue()
        threading.Thread(target=self._read, daemon=True).start()
        self.ready = self._answer(CHILD_READY) is not None

    def _read(self):
        for line in self.proc.stdout:
            self.lines.put(line)
        self.lines.put(None)  # end of output: the child is gone

    def _answer(self, prefix):
        """The rest of the child's next line starting with `prefix`, or None (note set)."""
        deadline = time.monotonic() + self.timeout
        while not self.note:
            try:
                line = self.lines.get(timeout=max(deadline - time.monotonic(), 0.01))
            except queue.Empty:
                self.proc.kill()
                self.note = "timed out after %d s" % self.timeout
                break
            if line is None:
                code = self.proc.wait()
                self.note = "failed (exit code %s: %s)" % (
                    code, (self.tail or ["no output"])[-1][:80])
                break
            if line.startswith(prefix):
                return line[len(prefix):].strip()
            self.output.append(line.rstrip())
            self.tail = self.output[-5:]
        return None

    def line(self, prefix):
        """The rest of the child's output line starting with `prefix` (printed before it became
        ready, say a figure measured once), or None."""
        hits = [l[len(prefix):].strip() for l in self.output if l.startswith(prefix)]
        return hits[-1] if hits else None

    def measure(self, frames, warmup, jitter, settings):
        if self.note:
            return None
        try:
            self.proc.stdin.write("round %d %d %r %s\n" % (frames, warmup, jitter,
                                                          json.dumps(settings)))
            self.proc.stdin.flush()
        except OSError:
            return self._answer(ROUND_PREFIX)  # gone: says why
        r = self._answer(ROUND_PREFIX)
        return None if r is None else tuple(json.loads(r))

    def close(self):
        if self.proc.poll() is None:
            try:
                self.proc.stdin.write("quit\n")
                self.proc.stdin.flush()
                self.proc.wait(timeout=30)
            except (OSError, subprocess.TimeoutExpired):
                self.proc.kill()


class Child:
    """A contender drawn in a ChildProcess (several may share one), with the representation
    settings it needs (for example {"IntegrationMethod": "Average"})."""

    def __init__(self, name, proc, settings=None):
        self.name, self.process, self.settings = name, proc, settings or {}

    @property
    def note(self):
        return self.process.note

    def measure(self, frames, warmup, jitter):
        return self.process.measure(frames, warmup, jitter, self.settings)

    def close(self):
        self.process.close()


def serve_rounds(view, rep=None):
    """The child's side of ChildProcess: prints CHILD_READY, then answers each
    'round FRAMES WARMUP JITTER {settings}' line on stdin with one PSI_ROUND line (the settings
    put on `rep` first), until 'quit' or the end of stdin."""
    print(CHILD_READY, flush=True)
    # pvpython replaces sys.stdin with its own capture helper: read the process's own stdin
    for line in iter(sys.__stdin__.readline, ""):
        words = line.split(None, 4)
        if not words or words[0] == "quit":
            break
        for k, v in json.loads(words[4] if len(words) > 4 else "{}").items():
            setattr(rep, k, v)
        t = time_frames(view, int(words[1]), int(words[2]), float(words[3]))
        print(ROUND_PREFIX + json.dumps(list(t)), flush=True)


def _iqr(values):
    q1, q3 = np.percentile(values, [25, 75])
    return float(q3 - q1)


class Result:
    """Per contender: round times (wall, cpu) and ratios to the baseline; and how the rounds
    ended (converged, or the budget spent)."""

    def __init__(self, names, baseline, target):
        self.names, self.baseline, self.target = names, baseline, target
        self.wall = {n: [] for n in names}
        self.cpu = {n: [] for n in names}
        self.ratio = {n: [] for n in names}
        self.notes = {n: "" for n in names}
        self.rounds, self.seconds, self.converged = 0, 0.0, False
        self.stopped = "the time budget spent"  # or why else the rounds ended unconverged

    def add_round(self, times):
        base = times.get(self.baseline)
        for n, t in times.items():
            if t is None:
                continue
            self.wall[n].append(t[0])
            self.cpu[n].append(t[1])
            if base is not None:
                self.ratio[n].append(t[0] / base[0])
        self.rounds += 1

    def spread(self, name):
        """The ratio's interquartile range over its median (inf with fewer than 2 rounds)."""
        r = self.ratio[name]
        return _iqr(r) / float(np.median(r)) if len(r) >= 2 else float("inf")

    def widest(self):
        """The contender whose ratio spreads most, among those with two rounds or more."""
        seen = [n for n in self.names if len(self.ratio[n]) >= 2]
        return max(seen, key=self.spread) if seen else None

    def row(self, name):
        """s/frame (median, min, max over the rounds), CPU s/frame, ratio to the baseline
        (median, spread), as a dict; None entries for a contender without a round."""
        w, c, r = self.wall[name], self.cpu[name], self.ratio[name]
        if not w:
            return dict(spf=None, spf_min=None, spf_max=None, cpu=None, ratio=None,
                        ratio_spread=None, rounds=0)
        return dict(spf=frame_time(w), spf_min=min(w), spf_max=max(w), cpu=frame_time(c),
                    ratio=float(np.median(r)) if r else None,
                    ratio_spread=self.spread(name) if r else None, rounds=len(w))

    def summary(self):
        w = self.widest()
        if self.converged:
            return ("%d interleaved rounds in %.0f s: every ratio to %s within %.0f%% "
                    "(interquartile range over median; widest %s, %.1f%%)"
                    % (self.rounds, self.seconds, self.baseline, 100 * self.target, w,
                       100 * self.spread(w)))
        return ("%d interleaved rounds in %.0f s, %s: the widest ratio to %s, "
                "%s, spreads %.1f%% (target %.0f%%)" % (
                    self.rounds, self.seconds, self.stopped, self.baseline, w,
                    self.spread(w) * 100 if w else float("nan"), 100 * self.target))


def interleaved(contenders, baseline, frames=3, warmup=1, jitter=0.5, min_rounds=3,
                max_rounds=30, budget=300.0, target=0.05, min_turn=0.5, log=None):
    """Measures `contenders` (InProcess or Child) in interleaved rounds, ratios to the one named
    `baseline`. After the first round a contender faster than `min_turn` seconds per turn draws
    more frames (a short turn is mostly noise). Returns a Result."""
    names = [c.name for c in contenders]
    res = Result(names, baseline, target)
    live = list(contenders)
    count = {n: frames for n in names}
    t0 = time.perf_counter()
    for k in range(max_rounds):
        order = live[k % len(live):] + live[:k % len(live)] if live else []
        times = {}
        for c in order:
            times[c.name] = c.measure(count[c.name], warmup, jitter)
            if times[c.name] is None:
                res.notes[c.name] = c.note
            elif k == 0:
                count[c.name] = max(frames, int(math.ceil(min_turn / max(times[c.name][0], 1e-6))))
        live = [c for c in live if times.get(c.name) is not None]
        res.add_round(times)
        res.seconds = time.perf_counter() - t0
        if log and res.widest():
            log("round %d (%.0f s): widest ratio %s %.1f%%" % (
                res.rounds, res.seconds, res.widest(), 100 * res.spread(res.widest())))
        if baseline not in [c.name for c in live]:
            res.stopped = "the baseline failed"
            break
        if res.rounds >= min_rounds and all(res.spread(c.name) <= target for c in live):
            res.converged = True
            break
        if res.seconds > budget:
            break
        if k == max_rounds - 1:
            res.stopped = "the %d rounds allowed spent" % max_rounds
    for c in contenders:
        c.close()
    return res


def child_environment(threads=None):
    """The environment of a child pvpython: no MPI-singleton variables, unbuffered, and
    optionally llvmpipe's thread count."""
    if threads is None:
        return process.environment_without_mpi()
    return process.environment_without_mpi(LP_NUM_THREADS=threads)


def pvpython(path=None):
    """The pvpython to start children with: `path` when given, else the one on PATH."""
    import shutil

    return path or shutil.which("pvpython") or "pvpython"
