"""The timing harness (psivolume.timing) with contenders whose times are known, no GL: the
order rotates from round to round; a drift of the whole machine between rounds cancels in the
ratios (the point of interleaving); steady contenders converge after the minimum rounds, a noisy
one runs the rounds to the budget and the summary says so; a contender that fails gets its note
and the others go on."""

from psivolume import testing, timing

t = testing.Checks("timing")


class Fake:
    """A contender taking `base` seconds per frame times the machine's slowness, which grows by
    1.3 from round to round (the same for every contender of a round)."""

    def __init__(self, name, base, machine, log, noise=None, fail_at=None):
        self.name, self.base, self.machine, self.log = name, base, machine, log
        self.noise, self.fail_at, self.note, self.calls = noise, fail_at, "", 0

    def measure(self, frames, warmup, jitter):
        self.calls += 1
        self.log.append(self.name)
        if self.fail_at is not None and self.calls >= self.fail_at:
            self.note = "failed (crashed)"
            return None
        f = self.noise[self.calls % len(self.noise)] if self.noise else 1.0
        wall = self.base * 1.3 ** (self.calls - 1) * f
        return wall, 0.5 * wall

    def close(self):
        pass


machine, log = [1.0], []
steady = [Fake("A", 1.0, machine, log), Fake("B", 2.0, machine, log), Fake("C", 0.5, machine, log)]
r = timing.interleaved(steady, "A", min_rounds=3, budget=1e9, min_turn=0)
t.check(log[:9] == ["A", "B", "C", "B", "C", "A", "C", "A", "B"],
        "the order rotates from round to round: %s" % log[:9])
t.check(r.converged and r.rounds == 3, "steady ratios converge after 3 rounds (%d, %s)"
        % (r.rounds, r.summary()))
# the machine slows by 1.3 per round, 2.2x over the run: the ratios, taken round by round, do
# not see it, while the median times do
ratio_b, ratio_c = r.row("B")["ratio"], r.row("C")["ratio"]
t.check(abs(ratio_b - 2.0) < 1e-9 and abs(ratio_c - 0.5) < 1e-9 and r.row("A")["ratio"] == 1.0
        and r.row("A")["spf_max"] > 1.6 * r.row("A")["spf_min"],
        "ratios from the same rounds: B/A %.3f, C/A %.3f, though A's time went from %.2f to %.2f"
        % (ratio_b, ratio_c, r.row("A")["spf_min"], r.row("A")["spf_max"]))
t.check(abs(r.row("B")["cpu"] / r.row("B")["spf"] - 0.5) < 1e-9, "CPU seconds kept beside wall")

machine, log = [1.0], []
noisy = [Fake("A", 1.0, [1.0], log), Fake("N", 1.0, [1.0], log, noise=[1.0, 1.5, 0.7, 1.2])]
r = timing.interleaved(noisy, "A", min_rounds=3, max_rounds=8, budget=1e9, min_turn=0)
t.check(not r.converged and r.rounds == 8 and "8 rounds allowed spent" in r.summary() and
        "N" in r.summary(),
        "a noisy ratio keeps the rounds going and is named: %s" % r.summary())

log = []
failing = [Fake("A", 1.0, [1.0], log), Fake("F", 1.0, [1.0], log, fail_at=2),
           Fake("G", 2.0, [1.0], log)]
r = timing.interleaved(failing, "A", min_rounds=3, budget=1e9, min_turn=0)
t.check(r.notes["F"] == "failed (crashed)" and r.row("F")["rounds"] == 1 and r.converged and
        r.row("G")["rounds"] == 3, "a failing contender keeps its note, the others go on: %s, %s"
        % (r.notes, r.summary()))
t.finish()
