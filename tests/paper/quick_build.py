"""The paper's quick build as a test (ctest -L paper_build): builds the paper from
data/ and the short runs into WORK (run folders cached in WORK/cache, so a
second run reuses them), then checks that the PDF exists, that every \\input
and \\includegraphics resolves, that page 1 renders to PNG, and that the LaTeX
sources hold no typed number. The tearing experiment, the calibration
with the drag compaction ratio (about two minutes each) and the height-span
scoop's calibration (about four) are skipped to keep the test short; their
numbers print "not yet run".

usage: quick_build.py REPOSE_BINARY WORK_DIR
"""
import os
import subprocess
import sys

import tools_path
from check_build import check, page_count
from check_typed_numbers import check_file, tex_files


def main(argv):
    if len(argv) != 3:
        sys.exit(__doc__)
    repose, work = argv[1], os.path.abspath(argv[2])
    out = os.path.join(work, "out")
    command = [sys.executable, os.path.join(tools_path.TOOLS, "make_paper.py"), "--quick", "--out", out,
               "--cache", os.path.join(work, "cache"), "--repose", repose, "--skip", "tearing_grain",
               "--skip", "calibration_one_alpha", "--skip", "heightspan_scoop_fit"]
    if subprocess.run(command).returncode != 0:
        print("quick build: make_paper.py failed")
        return 1
    problems = check(out, os.path.join(out, "paper.pdf"))
    sources = [os.path.join(tools_path.REPOSITORY, "paper", "paper.tex"),
               os.path.join(tools_path.REPOSITORY, "paper", "sections")]
    problems += [f"{p}:{line}: typed number {n}" for p, line, n, _ in
                 (x for path in tex_files(sources) for x in check_file(path))]
    for p in problems:
        print(f"quick build: {p}")
    if not problems:
        print(f"quick build: {page_count(os.path.join(out, 'paper.pdf'))} pages, every input resolves, "
              "page 1 renders, no typed number")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
