#!/usr/bin/env python3
"""Checks the size limits of the code layout (docs/architecture.md):
  - no C++ function in Core/, Rendering/, Representations/, Filters/ or Readers/ longer than
    150 lines;
  - no C++ file there longer than 600 lines, and vtkPsiVolumeMapper.cxx at most 500;
  - the same two limits for the test code (Testing/Cxx, Reference, Testing/Fuzz): a test is
    one named function per check, and a test file past 600 lines holds more than one concept
    (its mesh builders or checkers belong in a header of their own);
  - no shader file (Shaders/*.glsl) longer than 300 lines;
  - the modules' dependencies along VTK's line: Core, Rendering and Filters depend on no ParaView
    module (Rendering renders from plain VTK), Core on neither Rendering nor Representations, and
    Rendering and Filters not on Representations;
  - the shipped Python package (Python/psivolume) reads no environment variable, but for
    psivolume.process, which passes the environment on to child processes;
  - every XML file of the source (server-manager XML, GUI test scripts, templates) is well-formed:
    ParaView's readers of test scripts stop, or crash, where Python's parser reports the error.
Function bodies are found by brace matching on the source with comments and strings removed:
a body is the braces that follow a line ending a signature `)` (or `) const`, `override`).
Prints every violation and exits 1 when there is one."""
import pathlib
import re
import sys
import xml.dom.minidom
from xml.parsers.expat import ExpatError

ROOT = pathlib.Path(__file__).resolve().parent.parent
FOLDERS = ["Core", "Rendering", "Representations", "Filters", "Readers",
           "Testing/Cxx", "Reference", "Testing/Fuzz"]
MAX_FUNCTION, MAX_FILE, MAX_MAPPER, MAX_SHADER = 150, 600, 500, 300


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


def main():
    errors = malformed_xml()
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
