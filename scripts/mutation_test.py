#!/usr/bin/env python3
"""Mutation testing of the fast test suite (run through scripts/mutation-test.sh).

Each mutation of scripts/mutations.py is applied, alone, to a scratch copy of the source tree
(WORKDIR/src, synchronized file by file so that unchanged files keep their time stamps), which has
its own build directory (WORKDIR/build): configured and built once, then rebuilt incrementally,
only the test executables the mutation names (the whole build for a test that runs none of
them, as PsiPython.installed installs the build). The named tests then run (each in an X server
of its own, scripts/lib/with-xvfb.sh, niced,
each with a timeout: a hang counts as caught). The mutated file is restored after each mutation.

Prints a table (mutation | caught by | seconds) and the score, and exits 1 when the score is below
95% (or when a test fails without any mutation); exits 2 when a mutation's original snippet is not
present exactly once, so the list cannot silently rot.

  --list          list the mutations and exit
  --check         only verify the snippets against the source tree and the test names of a
                  configured build (--build-dir, default build/; CTest `PsiProject.MutationList`
                  runs this), no build
  --only NAME...  run only these mutations
  --jobs N        build jobs (default 2)
  --timeout S     per-test timeout in seconds (default 300)
  --workdir DIR   scratch tree and build, kept between runs (default
                  ~/.cache/psivolume/mutation, or under $XDG_CACHE_HOME)
  --data-dir DIR  the shared datasets (CMake's PSI_DATA_DIR; default: ../shared/data beside the
                  checkout, which the scratch tree does not have beside it)
"""
import argparse
import os
import pathlib
import re
import shutil
import signal
import subprocess
import sys
import time

from mutations import MUTATIONS  # this folder's list of mutations

ROOT = pathlib.Path(__file__).resolve().parent.parent

THRESHOLD = 0.95
SKIP_DIRS = {".git", "__pycache__"}
XVFB = ["bash", str(ROOT / "scripts" / "lib" / "with-xvfb.sh"), "--new"]
NICE = ["nice", "-n", "15"]


def target_of(path, build):
    """The build target a path of `build` is the output of: an executable in bin/, or a module
    (the plugin PsiVolume.so); None for anything else (a directory a test writes to)."""
    p = pathlib.Path(path)
    try:
        rel = p.relative_to(build)
    except ValueError:
        return None
    if rel.parts[:1] == ("bin",):
        return p.name
    return p.name[:-3] if p.name.endswith(".so") else None


ADD_TEST = re.compile(r'^add_test\((?:\[=\[(.+?)\]=\]|(\S+))\s+"([^"]*)"', re.M)
TEST_PROPERTIES = re.compile(
    r'^set_tests_properties\((?:\[=\[(.+?)\]=\]|(\S+))\s+PROPERTIES\s+(.*)\)$', re.M)
ENVIRONMENT = re.compile(r'\bENVIRONMENT\s+"([^"]*)"')


def registered_tests(build):
    """CTest name -> the targets it runs, as the configured `build` registers them (the
    CTestTestfile.cmake files CMake writes: `ctest --show-only` leaves out the command of a test
    whose executable is not built yet): its executable, and the targets its environment names
    (the plugin of a pvpython test, the reference renderer)."""
    paths = {}
    for f in sorted(pathlib.Path(build).rglob("CTestTestfile.cmake")):
        text = f.read_text()
        for bracketed, bare, command in ADD_TEST.findall(text):
            paths.setdefault(bracketed or bare, []).append(command)
        for bracketed, bare, props in TEST_PROPERTIES.findall(text):
            env = ENVIRONMENT.search(props)
            if env:
                paths.setdefault(bracketed or bare, []).extend(
                    v.split("=", 1)[1] for v in env.group(1).split(";") if "=" in v)
    return {name: sorted({t for t in (target_of(p, build) for p in ps) if t})
            for name, ps in paths.items()}


def check(root, mutations, tests):
    """Problems with the list against the tree at `root` and the tests registered (`tests`):
    snippets not present exactly once, unknown tests, duplicate names."""
    problems, seen = [], set()
    for m in mutations:
        if m.name in seen:
            problems.append(f"{m.name}: duplicate name")
        seen.add(m.name)
        path = root / m.file
        if not path.is_file():
            problems.append(f"{m.name}: {m.file} does not exist")
            continue
        count = path.read_text().count(m.original)
        if count != 1:
            problems.append(f"{m.name}: original snippet found {count} times in {m.file} "
                            f"(must be exactly once):\n    {m.original!r}")
        if m.original == m.replacement:
            problems.append(f"{m.name}: replacement equals the original")
        for t in m.tests:
            if t not in tests:
                problems.append(f"{m.name}: test {t} is not registered")
    return problems


def matches_tree(tests):
    """Whether the whole list matches the source tree and `tests`; prints what does not."""
    problems = check(ROOT, MUTATIONS, tests)
    if problems:
        print("The mutation list does not match the tree:\n  " + "\n  ".join(problems))
    return not problems


def is_build_dir(rel):
    first = rel.parts[0] if rel.parts else ""
    return first.startswith("build") or first in SKIP_DIRS


def sync_tree(src, dst):
    """Copies src to dst, writing only files whose content differs; removes files gone from src."""
    wanted = set()
    for dirpath, dirnames, filenames in os.walk(src):
        rel_dir = pathlib.Path(dirpath).relative_to(src)
        dirnames[:] = [d for d in dirnames if not is_build_dir(rel_dir / d)]
        for f in filenames:
            rel = rel_dir / f
            wanted.add(rel)
            s, d = src / rel, dst / rel
            if d.is_file() and d.read_bytes() == s.read_bytes():
                continue
            d.parent.mkdir(parents=True, exist_ok=True)
            # a fresh time stamp: newer than anything built from a mutated copy, so it rebuilds
            shutil.copyfile(s, d)
            shutil.copymode(s, d)
    for dirpath, dirnames, filenames in os.walk(dst):
        rel_dir = pathlib.Path(dirpath).relative_to(dst)
        dirnames[:] = [d for d in dirnames if not is_build_dir(rel_dir / d)]
        for f in filenames:
            if rel_dir / f not in wanted:
                (dst / rel_dir / f).unlink()


def run(cmd, log, timeout=None):
    with open(log, "a") as out:
        out.write(f"\n$ {' '.join(cmd)}\n")
        out.flush()
        try:
            return subprocess.run(cmd, stdout=out, stderr=subprocess.STDOUT, timeout=timeout).returncode
        except subprocess.TimeoutExpired:
            return "timeout"


def configure(work, log, data_dir):
    """Configures the scratch build (again, so that CTest lists the tests of the tree as it is),
    its tests reading the shared datasets of `data_dir`."""
    src, bld = work / "src", work / "build"
    return run(NICE + ["cmake", "-S", str(src), "-B", str(bld), "-DCMAKE_BUILD_TYPE=Release",
                       f"-DPSI_DATA_DIR={data_dir.resolve()}"],
               log) == 0


def targets_of_tests(names, tests):
    """The build targets the CTests `names` run; None (the whole build) when one of them runs no
    executable of the build (PsiPython.installed installs the whole build)."""
    if any(not tests[t] for t in names):
        return None
    return {x for t in names for x in tests[t]}


def build(work, targets, jobs, log):
    """Builds `targets` in the scratch build; no target (a test that runs no executable of the
    build, as `PsiPython.installed` installs the build with cmake --install): the whole build."""
    bld = work / "build"
    chosen = ["--target"] + sorted(targets) if targets else []
    return run(NICE + ["cmake", "--build", str(bld), f"-j{jobs}"] + chosen, log) == 0


def run_test(work, name, timeout, log):
    """'pass', 'fail' or 'timeout' for CTest `name` in the scratch build."""
    cmd = NICE + XVFB + ["ctest", "--test-dir", str(work / "build"), "-R", f"^{re.escape(name)}$",
                         "--output-on-failure", "--timeout", str(timeout)]
    rc = run(cmd, log, timeout=timeout + 60)
    if rc == "timeout":
        return "timeout"
    text = pathlib.Path(log).read_text(errors="replace")
    tail = text[text.rfind("$ "):]
    if "Timeout" in tail and "***Timeout" in tail:
        return "timeout"
    if "No tests were found" in tail:
        return "missing"
    return "pass" if rc == 0 else "fail"


def main():
    # Interrupted (Ctrl-C, kill), the mutated file is still restored (the finally below); the
    # scratch tree is re-synchronized with the source tree at the next start anyway.
    signal.signal(signal.SIGINT, signal.default_int_handler)
    signal.signal(signal.SIGTERM, lambda *_: sys.exit(130))
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--list", action="store_true")
    ap.add_argument("--check", action="store_true")
    ap.add_argument("--build-dir", type=pathlib.Path, default=ROOT / "build",
                    help="with --check: the configured build whose tests are listed")
    ap.add_argument("--only", nargs="+", metavar="NAME")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--timeout", type=int, default=300)
    cache = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    ap.add_argument("--workdir", type=pathlib.Path,
                    default=pathlib.Path(cache) / "psivolume" / "mutation")
    ap.add_argument("--data-dir", type=pathlib.Path, default=ROOT.parent / "shared" / "data")
    args = ap.parse_args()

    mutations = MUTATIONS
    if args.only:
        unknown = set(args.only) - {m.name for m in MUTATIONS}
        if unknown:
            sys.exit(f"unknown mutation(s): {', '.join(sorted(unknown))} (see --list)")
        mutations = [m for m in MUTATIONS if m.name in args.only]
    if args.list:
        for m in mutations:
            print(f"{m.name:44s} {m.file:48s} {' '.join(m.tests)}")
        print(f"{len(mutations)} mutations")
        return 0
    if args.check:
        if not matches_tree(registered_tests(args.build_dir.resolve())):
            return 2
        print(f"{len(MUTATIONS)} mutations: every original snippet occurs exactly once, every "
              "test is registered")
        return 0

    work = args.workdir.resolve()
    (work / "src").mkdir(parents=True, exist_ok=True)
    sync_tree(ROOT, work / "src")
    log = work / "mutation.log"
    log.write_text("")
    if not configure(work, log, args.data_dir):
        print(f"the scratch tree does not configure: see {log}")
        return 1
    tests = registered_tests(work / "build")
    if not matches_tree(tests):
        return 2
    needed = sorted({t for m in mutations for t in m.tests})
    print(f"scratch tree {work / 'src'}, build {work / 'build'}, log {log}")
    t0 = time.time()
    if not build(work, targets_of_tests(needed, tests), args.jobs, log):
        print(f"the unmutated scratch tree does not build: see {log}")
        return 1
    for t in needed:
        status = run_test(work, t, args.timeout, log)
        if status != "pass":
            print(f"test {t} does not pass without mutation ({status}): see {log}")
            return 1
    print(f"baseline: {len(needed)} tests pass ({time.time() - t0:.0f} s)")

    rows = []
    for m in mutations:
        path = work / "src" / m.file
        original = path.read_text()
        start = time.time()
        caught = "survived"
        try:
            path.write_text(original.replace(m.original, m.replacement, 1))
            if not build(work, targets_of_tests(m.tests, tests), args.jobs, log):
                caught = "(build error)"
            else:
                for t in m.tests:
                    status = run_test(work, t, args.timeout, log)
                    if status in ("fail", "timeout"):
                        caught = t if status == "fail" else f"{t} (timeout)"
                        break
        finally:
            path.write_text(original)
        rows.append((m.name, caught, time.time() - start))
        print(f"  {m.name:44s} {caught:34s} {rows[-1][2]:6.0f} s", flush=True)

    killed = sum(1 for _, c, _ in rows if c not in ("survived", "(build error)"))
    invalid = [n for n, c, _ in rows if c == "(build error)"]
    score = killed / max(1, len(rows) - len(invalid))
    print("\n| mutation | caught by | seconds |\n|---|---|---|")
    for name, caught, secs in rows:
        print(f"| {name} | {caught} | {secs:.0f} |")
    print(f"\nscore: {killed}/{len(rows) - len(invalid)} caught ({100 * score:.1f}%), "
          f"{time.time() - t0:.0f} s in all")
    if invalid:
        print(f"mutations that do not build (fix them): {', '.join(invalid)}")
    return 0 if score >= THRESHOLD and not invalid else 1


if __name__ == "__main__":
    sys.exit(main())
