"""Fails on a number typed into the paper's LaTeX sources (a result must be a
generated macro, paper/inputs.yaml).

usage: check_typed_numbers.py FILE.tex|FOLDER...   (exit 1 and one line per digit found)

A digit is allowed only where it is not a result: inside \\stated{...} (a
method's setting, a published value, a year, which the author vouches for),
in labels, references, citations, file names of \\input/\\includegraphics,
package and class options, environment arguments (column specs) and lengths.
Files under a folder named `generated` are skipped: they are written from the
runs. Comments and the bibliography (thebibliography) are ignored.
"""
import os
import re
import sys

# commands whose every [..] and {..} argument is structure, not text
STRUCTURAL = ("label", "ref", "eqref", "pageref", "cite", "citep", "citet", "input", "include", "includegraphics",
              "documentclass", "usepackage", "setlength", "addtolength", "hspace", "vspace", "stated",
              "begin", "end", "newcommand", "renewcommand", "setcounter", "bibliographystyle", "bibliography",
              "path", "url", "href", "hypersetup", "cline", "multicolumn")
ARGUMENTS = r"(?:\s*\[[^\]]*\]|\s*\{(?:[^{}]|\{[^{}]*\})*\})*"
STRUCTURE = re.compile(r"\\(?:" + "|".join(STRUCTURAL) + r")(?![A-Za-z])\*?" + ARGUMENTS)
LENGTH = re.compile(r"-?\d*\.?\d+\s*(?:pt|em|ex|cm|mm|in|bp)\b|-?\d*\.?\d+\s*\\(?:text|line|column|paper)width")
COMMENT = re.compile(r"(?<!\\)%.*")
PARAMETER = re.compile(r"#\d")  # a macro's parameter (#1) in a definition
DIGITS = re.compile(r"\d[\d.,]*")


def typed_numbers_in_line(line):
    """The digit runs left in one line once comments and structure are removed."""
    text = COMMENT.sub("", line)
    text = STRUCTURE.sub(" ", text)
    text = LENGTH.sub(" ", text)
    text = PARAMETER.sub(" ", text)
    return DIGITS.findall(text)


def check_file(path):
    """[(path, line number, number, line)] for every typed number in the file."""
    problems, in_bibliography = [], False
    with open(path, encoding="utf-8") as f:
        for k, line in enumerate(f, start=1):
            code = COMMENT.sub("", line)
            if "\\begin{thebibliography}" in code:
                in_bibliography = True
            if "\\end{thebibliography}" in code:
                in_bibliography = False
                continue
            if in_bibliography:
                continue
            for number in typed_numbers_in_line(line):
                problems.append((path, k, number, line.rstrip()))
    return problems


def tex_files(paths):
    for path in paths:
        if os.path.isfile(path):
            yield path
            continue
        for folder, dirs, names in os.walk(path):
            dirs[:] = sorted(d for d in dirs if d != "generated")
            for name in sorted(names):
                if name.endswith(".tex"):
                    yield os.path.join(folder, name)


def main(argv):
    if len(argv) < 2:
        sys.exit(__doc__)
    problems = [p for path in tex_files(argv[1:]) for p in check_file(path)]
    for path, line, number, text in problems:
        print(f"{path}:{line}: typed number '{number}' (make it a generated macro, or \\stated{{}} "
              f"if it is a method's setting): {text.strip()}")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
