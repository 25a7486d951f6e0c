"""Checks a built paper folder: the PDF exists, every \\input and \\includegraphics
of the sources resolves to a file, and page 1 renders to PNG (pdftoppm).

usage: check_build.py BUILD_DIR [PDF]   (exit 1 and one line per problem)
"""
import os
import re
import subprocess
import sys
import tempfile

INPUT = re.compile(r"\\(?:input|include)\{([^}]+)\}")
GRAPHICS = re.compile(r"\\includegraphics(?:\[[^\]]*\])?\{([^}]+)\}")
COMMENT = re.compile(r"(?<!\\)%.*")
GRAPHIC_SUFFIXES = ("", ".pdf", ".png", ".jpg")


def _resolves(folder, name, suffixes):
    return any(os.path.isfile(os.path.join(folder, name + s)) for s in suffixes)


def unresolved(folder, tex="paper.tex"):
    """Problems with the \\input/\\includegraphics reachable from `tex` (paths relative to folder)."""
    problems, pending, seen = [], [tex], set()
    while pending:
        name = pending.pop()
        if name in seen:
            continue
        seen.add(name)
        path = os.path.join(folder, name if name.endswith(".tex") else name + ".tex")
        with open(path, encoding="utf-8") as f:
            text = "\n".join(COMMENT.sub("", line) for line in f)
        for target in INPUT.findall(text):
            if _resolves(folder, target, ("", ".tex")):
                pending.append(target if target.endswith(".tex") else target + ".tex")
            else:
                problems.append(f"{name}: \\input{{{target}}} does not resolve")
        for target in GRAPHICS.findall(text):
            if not _resolves(folder, target, GRAPHIC_SUFFIXES):
                problems.append(f"{name}: \\includegraphics{{{target}}} does not resolve")
    return problems


def page_count(pdf):
    out = subprocess.run(["pdfinfo", pdf], capture_output=True, text=True).stdout
    m = re.search(r"^Pages:\s+(\d+)", out, re.M)
    return int(m.group(1)) if m else 0


def renders_page_one(pdf):
    with tempfile.TemporaryDirectory() as scratch:
        prefix = os.path.join(scratch, "page")
        result = subprocess.run(["pdftoppm", "-png", "-r", "40", "-f", "1", "-l", "1", pdf, prefix],
                                capture_output=True, text=True)
        pngs = [n for n in os.listdir(scratch) if n.endswith(".png")]
        return result.returncode == 0 and len(pngs) == 1 and os.path.getsize(os.path.join(scratch, pngs[0])) > 0


def check(folder, pdf):
    problems = []
    if not os.path.isfile(pdf) or os.path.getsize(pdf) == 0:
        return [f"{pdf}: no PDF"]
    problems += unresolved(folder)
    if not renders_page_one(pdf):
        problems.append(f"{pdf}: pdftoppm could not render page 1")
    return problems


def main(argv):
    if len(argv) not in (2, 3):
        sys.exit(__doc__)
    pdf = argv[2] if len(argv) == 3 else os.path.join(argv[1], "paper.pdf")
    problems = check(argv[1], pdf)
    for p in problems:
        print(p)
    if not problems:
        print(f"{pdf}: {page_count(pdf)} pages; inputs and graphics resolve; page 1 renders")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
