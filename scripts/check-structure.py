#!/usr/bin/env python3
"""Checks the size limits of the code layout (docs/architecture.md):
  - no C++ function in Core/, Rendering/, Representations/, Filters/ or Readers/ longer than
    150 lines;
  - no C++ file there longer than 600 lines, and vtkPsiVolumeMapper.cxx at most 500;
  - the same two limits for the test code (Testing/Cxx, Reference, Testing/Fuzz): a test is
    one named function per check, and a test file past 600 lines holds more than one concept
    (its mesh builders or checkers belong in a header of their own);
  - no shader file (Shaders/*.glsl) longer than 300 lines;
  - every C++ file of the project formatted as .clang-format says (VTK's style), by clang-format
    14 (Debian 12's: other versions break some lines differently; with another version, or
    none, the format is not checked and the output says so);
  - the README, a user's manual, at most 400 lines, and no table row of it repeated in docs/*.md
    (a table is kept in one place);
  - the modules' dependencies along VTK's line: Core, Rendering and Filters depend on no ParaView
    module (Rendering renders from plain VTK), Core on neither Rendering nor Representations, and
    Rendering and Filters not on Representations;
  - the shipped Python package (Python/psivolume) reads no environment variable, but for
    psivolume.process, which passes the environment on to child processes;
  - every XML file of the source (server-manager XML, GUI test scripts, templates) is well-formed:
    ParaView's readers of test scripts stop, or crash, where Python's parser reports the error;
  - no stale reference (stale_references): every path of the tree that the README, docs/*.md or
    a comment names exists, every Psi*.h named exists, every header of a module is in its
    module's CMakeLists.txt, and (with --build-dir, as CTest runs it) every CTest test named is
    registered, or names a group of registered tests.
Function bodies are found by brace matching on the source with comments and strings removed:
a body is the braces that follow a line ending a signature `)` (or `) const`, `override`).
Prints every violation and exits 1 when there is one."""
import pathlib
import re
import shutil
import subprocess
import sys
import xml.dom.minidom
from xml.parsers.expat import ExpatError

ROOT = pathlib.Path(__file__).resolve().parent.parent
FOLDERS = ["Core", "Rendering", "Representations", "Filters", "Readers",
           "Testing/Cxx", "Reference", "Testing/Fuzz"]
MAX_FUNCTION, MAX_FILE, MAX_MAPPER, MAX_SHADER, MAX_README = 150, 600, 500, 300, 400


def strip(src):
    """Removes comments, string and character literals, keeping line breaks."""
    out, i, n = [], 0, len(src)
    while i < n:
        c = src[i]
        if src.startswith("//", i):
            j = src.find("\n", i)
            i = n if j < 0 else j
        elif src.startswith("/*", i):
            j = src.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append("\n" * src.count("\n", i, j))
            i = j
        elif c in "\"'":
            j = i + 1
            while j < n and src[j] != c:
                j += 2 if src[j] == "\\" else 1
            out.append(c + c)
            i = j + 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


SIGNATURE_END = re.compile(r"\)\s*(const)?\s*(override)?\s*(noexcept)?\s*$")


def functions(path):
    """(name line, length) of each function body that starts after a signature line."""
    lines = strip(path.read_text()).split("\n")
    found, depth, start = [], 0, None
    for k, line in enumerate(lines):
        for ch in line:
            if ch == "{":
                # a body opens after a signature line, or on a line of its own below one
                head = lines[k - 1] if line.strip() == "{" and k > 0 else line
                if start is None and SIGNATURE_END.search(head.split("{")[0].strip()):
                    start = (k, depth)
                depth += 1
            elif ch == "}":
                depth -= 1
                if start is not None and depth == start[1]:
                    found.append((start[0] + 1, k - start[0] + 1))
                    start = None
    return found


def malformed_xml():
    """The XML files of the source tree (not of build trees) that do not parse."""
    errors = []
    for path in sorted(ROOT.rglob("*.xml")):
        rel = path.relative_to(ROOT)
        if rel.parts[0].startswith(("build", ".", "dist")):
            continue
        try:
            xml.dom.minidom.parse(str(path))
        except ExpatError as e:
            errors.append("%s: not well-formed XML: %s" % (rel, e))
    return errors


# Paths of the tree as text names them: a top folder (not within a longer path), then a name.
PATH = re.compile(r"(?<![\w/.$-])((?:Core|Rendering|Representations|Filters|Readers|Reference|"
                  r"Shaders|Testing|Python|scripts|docs|cmake|XML|Qt|Benchmarks|Plugin)/"
                  r"[A-Za-z0-9_./-]*[A-Za-z0-9_])")
HEADER = re.compile(r"(?<![\w/])((?:vtk)?Psi[A-Za-z0-9]+\.h)\b")
TEST = re.compile(r"\b(Psi(?:Core|Rendering|Representations|Python|Installed|GUI|Headless|Project|"
                  r"Filters|Readers)\.[A-Za-z0-9_]+(?:\.[A-Za-z0-9_]+)*)")
MODULES = ["Core", "Rendering", "Representations", "Filters", "Readers"]
# Where a build writes (named in comments, not in the source tree).
GENERATED = ("Testing/Images", "Testing/Temporary")


def texts():
    """(path, text) of what names the tree: the README, docs/*.md and the sources' files."""
    paths = [ROOT / "README.md"] + sorted((ROOT / "docs").glob("*.md"))
    for folder in MODULES + ["Reference", "Shaders", "Testing", "Python", "scripts", "cmake", "XML",
                             "Qt", "Benchmarks", "Plugin"]:
        paths += sorted(p for p in (ROOT / folder).rglob("*") if p.is_file() and p.suffix in
                        (".h", ".cxx", ".glsl", ".py", ".cmake", ".txt", ".xml", ".sh", ".md"))
    paths.append(ROOT / "CMakeLists.txt")
    # not the mutation list: its replacements are wrong on purpose
    return [(p, p.read_text(errors="replace")) for p in paths
            if "__pycache__" not in p.parts and p.name != "mutations.py"]


def tree_paths():
    """Every file and folder of the source tree, relative to it."""
    found = set()
    for p in ROOT.rglob("*"):
        rel = p.relative_to(ROOT)
        if not rel.parts[0].startswith(("build", ".", "dist")) and "__pycache__" not in rel.parts:
            found.add(rel.as_posix())
    return found


def names_path(name, where, paths):
    """Whether `name`, as the file at `where` writes it, is a path of the tree: from the top or
    from a folder above that file, with or without its extension, or as the start of a name
    (a family: Shaders/PsiIntegrate for Shaders/PsiIntegrate*.glsl); placeholders (NAME) and
    what a build writes pass."""
    if "*" in name or any(part.isupper() and part != "XML" for part in re.split(r"[/._-]", name)) \
            or name.startswith(GENERATED):
        return True
    bases = [""] + ["/".join(where.parts[:k]) + "/" for k in range(1, len(where.parts))]
    return any(any(p.startswith(base + name) for p in paths) for base in bases)


def known_tests(build):
    """The CTest names the build registers, and those the Testing/*.cmake files register only
    under conditions (another ParaView, a fuzzer): add_test(NAME ...) and psi_add_python_test."""
    from mutation_test import registered_tests  # this folder's reader of a build's CTest files
    names = set(registered_tests(pathlib.Path(build).resolve()))
    for f in (ROOT / "Testing").glob("*.cmake"):
        text = f.read_text()
        names |= set(re.findall(r"add_test\(NAME (Psi[\w.]+)", text))
        names |= {"PsiPython." + n for n in re.findall(r"psi_add_python_test\((\w+)", text)}
    return names


def stale_references(build=None):
    """Names of the tree that do not exist (see the module's docstring)."""
    errors = []
    paths = tree_paths()
    # and those the build generates: the modules' export headers, the embedded shaders
    headers = {pathlib.PurePath(p).name for p in paths if p.endswith(".h")} | \
        {pathlib.PurePath(p).stem + ".h" for p in paths if p.endswith(".glsl")}
    tests = known_tests(build) if build else None
    for path, text in texts():
        rel = path.relative_to(ROOT)
        for number, line in enumerate(text.splitlines(), 1):
            for name in PATH.findall(line):
                if not names_path(name, rel, paths):
                    errors.append("%s:%d: names %s, which does not exist" % (rel, number, name))
            for name in HEADER.findall(line):
                if name not in headers and not name.endswith("Module.h"):
                    errors.append("%s:%d: names %s, which does not exist" % (rel, number, name))
            for name in TEST.findall(line) if tests is not None else []:
                if not name.split(".")[-1].isupper() and not any(t.startswith(name) for t in tests):
                    errors.append("%s:%d: names the test %s, which is not registered"
                                  % (rel, number, name))
    for module in MODULES:
        listed = (ROOT / module / "CMakeLists.txt").read_text()
        for header in sorted((ROOT / module).glob("*.h")):
            if header.stem not in listed:
                errors.append("%s/%s: not in %s/CMakeLists.txt" % (module, header.name, module))
    return errors


CLANG_FORMAT_MAJOR = 14


def unformatted():
    """The C++ files clang-format (of the pinned major version) would change."""
    tool = shutil.which("clang-format-%d" % CLANG_FORMAT_MAJOR) or shutil.which("clang-format")
    version = subprocess.run([tool, "--version"], capture_output=True, text=True).stdout \
        if tool else ""
    major = re.search(r"version (\d+)", version)
    if not major or int(major.group(1)) != CLANG_FORMAT_MAJOR:
        print("format: not checked (clang-format %d wanted, %s found)"
              % (CLANG_FORMAT_MAJOR, major.group(0) if major else "none"))
        return []
    files = [str(p.relative_to(ROOT)) for folder in FOLDERS + ["Qt", "Benchmarks", "Plugin",
                                                                "Readers/SurfaceOFF"]
             for pattern in ("*.cxx", "*.h") for p in sorted((ROOT / folder).glob(pattern))]
    errors = []
    for name in files:
        done = subprocess.run([tool, "--style=file", "--dry-run", "--Werror", name], cwd=ROOT,
                              capture_output=True, text=True)
        if done.returncode != 0:
            errors.append("%s: not formatted (clang-format -i %s)" % (name, name))
    return errors


def readme():
    """The README's length, and its table rows (bar the header separators) found again in a
    page of docs/."""
    text = (ROOT / "README.md").read_text()
    errors = []
    if text.count("\n") > MAX_README:
        errors.append("README.md: %d lines (limit %d)" % (text.count("\n"), MAX_README))
    rows = {line.strip() for line in text.splitlines()
            if line.startswith("|") and not re.match(r"^\|[-| :]+\|$", line.strip())}
    for page in sorted((ROOT / "docs").glob("*.md")):
        twice = rows & {line.strip() for line in page.read_text().splitlines()}
        if twice:
            errors.append("README.md: %d table row(s) also in %s, e.g. %s"
                          % (len(twice), page.relative_to(ROOT), sorted(twice)[0][:60]))
    return errors


def main():
    build = sys.argv[sys.argv.index("--build-dir") + 1] if "--build-dir" in sys.argv else None
    errors = malformed_xml() + stale_references(build) + readme() + unformatted()
    for folder in FOLDERS:
        for path in sorted((ROOT / folder).glob("*.[ch]xx")) + sorted((ROOT / folder).glob("*.h")):
            rel = path.relative_to(ROOT)
            n = path.read_text().count("\n")
            limit = MAX_MAPPER if path.name == "vtkPsiVolumeMapper.cxx" else MAX_FILE
            if n > limit:
                errors.append("%s: %d lines (limit %d)" % (rel, n, limit))
            for line, length in functions(path):
                if length > MAX_FUNCTION:
                    errors.append("%s:%d: function of %d lines (limit %d)"
                                  % (rel, line, length, MAX_FUNCTION))
    for path in sorted((ROOT / "Shaders").glob("*.glsl")):
        n = path.read_text().count("\n")
        if n > MAX_SHADER:
            errors.append("%s: %d lines (limit %d)" % (path.relative_to(ROOT), n, MAX_SHADER))
    forbidden = {"Core": ["ParaView::", "PsiVolume::Rendering", "PsiVolume::Representations"],
                 "Rendering": ["ParaView::", "PsiVolume::Representations"],
                 "Filters": ["ParaView::", "PsiVolume::Rendering", "PsiVolume::Representations"]}
    for module, names in forbidden.items():
        text = (ROOT / module / "vtk.module").read_text()
        for name in names:
            if name in text:
                errors.append("%s/vtk.module depends on %s" % (module, name.rstrip(":")))
    # the shipped Python package reads no environment variable (arguments instead); the one
    # exception, psivolume.process, copies the environment for the child processes it starts
    for path in sorted((ROOT / "Python" / "psivolume").glob("*.py")):
        if path.name == "process.py":
            continue
        for number, line in enumerate(path.read_text().splitlines(), 1):
            if re.search(r"\bos\.environ\b|\bgetenv\b", line.split("#")[0]):
                errors.append("%s:%d: reads the environment" % (path.relative_to(ROOT), number))
    for e in errors:
        print(e)
    print("structure: %d violation(s)" % len(errors))
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
