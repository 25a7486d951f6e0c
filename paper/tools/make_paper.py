"""Builds the paper from the experiments: one command (scripts/make-paper.sh).

usage: make_paper.py [--quick|--full] [--out DIR] [--allow-mixed] [--status]
                     [--cache DIR] [--skip ID]... [--no-pdf] [--repose BIN] [--inputs FILE]

1. reads paper/inputs.yaml (what the paper uses);
2. says, per experiment, whether its cached run folder is fresh, stale (and
   which input changed) or missing, and what this mode will run, with the time
   it should take (the last manifest's wall time, or the entry's estimate);
3. runs what is stale or missing and belongs to the mode (--quick: the short
   runs and committed data; --full: every experiment), showing progress;
4. refuses, unless --allow-mixed, when the folders used were made by different
   versions of the same solver's code;
5. writes generated/macros.tex, generated/tables/*.tex, generated/figures/*.pdf
   and generated/provenance.tex under DIR, copies the LaTeX sources beside
   them and builds DIR/paper.pdf with latexmk; checks it (check_build.py).
Exit status: 0 built, 1 failed, 2 bad input, 3 refused (mixed code versions).
"""
import argparse
import os
import shutil
import subprocess
import sys
import time

from check_build import check, page_count
from code_version import cmake_libraries
from figures import write_figures
from fingerprint import engine_versions
from inputs import InputsError, load_inputs
from latex import escape
from macros import write_macros
from mixed_versions import describe, mixed_versions, remedies
from provenance import write_provenance
from run_cache import MISSING, STALE, previous_wall_s, run_entry, status_of
from staleness_report import report_lines, write_staleness
from tables import write_tables
from values import ValueMissing

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))


def parse_args(argv):
    p = argparse.ArgumentParser(prog="make-paper.sh", description=__doc__.split("\n\n")[0])
    mode = p.add_mutually_exclusive_group()
    mode.add_argument("--quick", dest="mode", action="store_const", const="quick", help="short runs and data/ (default)")
    mode.add_argument("--full", dest="mode", action="store_const", const="full", help="every experiment")
    p.add_argument("--out", default=os.path.join(ROOT, "paper", "out"), help="build folder (default paper/out)")
    p.add_argument("--allow-mixed", action="store_true", help="build although runs of different code versions mix")
    p.add_argument("--status", action="store_true", help="only say what is fresh, stale and missing")
    p.add_argument("--cache", help="run folders (default: cache_dir of inputs.yaml, runs/paper)")
    p.add_argument("--skip", action="append", default=[], metavar="ID", help="do not run this experiment")
    p.add_argument("--no-pdf", action="store_true", help="write generated/ but do not run latexmk")
    p.add_argument("--repose", default=os.path.join(ROOT, "build", "bin", "repose"))
    p.add_argument("--inputs", default=os.path.join(ROOT, "paper", "inputs.yaml"))
    args = p.parse_args(argv)
    args.mode = args.mode or "quick"
    return args


def plan(statuses, mode, skip):
    """The statuses this mode (re)runs: stale or missing, run by the mode, not skipped."""
    return [s for s in statuses if s.entry.command != "data" and s.state in (STALE, MISSING)
            and mode in s.entry.modes and s.entry.id not in skip]


def run_plan(todo, cache, repose_bin):
    estimates = [previous_wall_s(s) for s in todo]
    print(f"make-paper: running {len(todo)} experiment(s), about {sum(estimates) / 60:.1f} min in all "
          "(each one's last manifest wall time, or its estimate in inputs.yaml)", flush=True)
    for k, (status, estimate) in enumerate(zip(todo, estimates), start=1):
        print(f"[{k}/{len(todo)}] {status.entry.id}: about {estimate:.0f} s", flush=True)
        start = time.monotonic()
        try:
            run_entry(ROOT, cache, repose_bin, status)
        except RuntimeError as e:
            if not status.entry.optional:
                raise
            # an optional experiment (a model being written) that does not run yet reads "not yet run"
            print(f"[{k}/{len(todo)}] {status.entry.id}: failed, optional: its numbers print 'not yet run' ({e})",
                  flush=True)
            status.state, status.reasons = MISSING, [f"failed to run: {e}"]
            continue
        print(f"[{k}/{len(todo)}] {status.entry.id}: done in {time.monotonic() - start:.0f} s", flush=True)


def copy_sources(out):
    paper = os.path.join(ROOT, "paper")
    shutil.copyfile(os.path.join(paper, "paper.tex"), os.path.join(out, "paper.tex"))
    shutil.copytree(os.path.join(paper, "sections"), os.path.join(out, "sections"), dirs_exist_ok=True)


def head_commit():
    def git(*a):
        return subprocess.run(["git", "-C", ROOT, *a], capture_output=True, text=True).stdout.strip()
    return git("rev-parse", "--short=10", "HEAD") + ("+dirty" if git("status", "--porcelain", "--untracked-files=no") else "")


def generate(inputs, statuses, mode, out):
    gen = os.path.join(out, "generated")
    os.makedirs(gen, exist_ok=True)
    by_id = {s.entry.id: s for s in statuses}
    used = [s for s in statuses if s.usable]
    stale = [s for s in used if s.state == STALE]
    extra = [("PaperMode", mode), ("PaperCommit", r"\texttt{" + escape(head_commit()) + "}"),
             ("PaperRunCount", str(len(used))), ("PaperStaleCount", str(len(stale)))]
    # the plot scripts first: the CSV files they derive (table1.csv, testbed.csv) feed macros and tables
    write_figures(ROOT, os.path.join(gen, "figures"), inputs, by_id)
    write_macros(os.path.join(gen, "macros.tex"), inputs, by_id, extra)
    write_tables(os.path.join(gen, "tables"), inputs, by_id)
    write_provenance(os.path.join(gen, "provenance.tex"), ROOT, used)
    write_staleness(os.path.join(gen, "staleness.tex"), statuses)
    copy_sources(out)


def build_pdf(out):
    command = ["latexmk", "-pdf", "-interaction=nonstopmode", "-halt-on-error", "-file-line-error", "paper.tex"]
    result = subprocess.run(command, cwd=out, capture_output=True, text=True)
    if result.returncode != 0:
        sys.stderr.write(result.stdout[-4000:])
        raise RuntimeError(f"latexmk failed in {out} (see paper.log there)")
    pdf = os.path.join(out, "paper.pdf")
    problems = check(out, pdf)
    if problems:
        raise RuntimeError("the built paper does not check:\n  " + "\n  ".join(problems))
    print(f"make-paper: {pdf}: {page_count(pdf)} pages", flush=True)


def main(argv):
    args = parse_args(argv)
    start = time.monotonic()
    try:
        inputs = load_inputs(args.inputs)
    except InputsError as e:
        print(f"make-paper: {e}", file=sys.stderr)
        return 2
    cache = os.path.abspath(args.cache or os.path.join(ROOT, inputs.cache_dir))
    libraries, engines = cmake_libraries(ROOT), engine_versions(args.repose)
    statuses = [status_of(ROOT, cache, libraries, e, engines) for e in inputs.experiments]
    todo = plan(statuses, args.mode, set(args.skip))
    for line in report_lines(statuses, todo, args.mode):
        print(line, flush=True)
    if args.status:
        print(f"make-paper: {len(todo)} experiment(s) would run, about "
              f"{sum(previous_wall_s(s) for s in todo) / 60:.1f} min", flush=True)
        return 0
    run_plan(todo, cache, args.repose)
    mixed = mixed_versions([s for s in statuses if s.usable])
    if mixed and not args.allow_mixed:
        print("make-paper: refused: the run folders were made by different code versions:", file=sys.stderr)
        print("\n".join(describe(mixed) + remedies(mixed, statuses)), file=sys.stderr)
        return 3
    os.makedirs(args.out, exist_ok=True)
    try:
        generate(inputs, statuses, args.mode, os.path.abspath(args.out))
    except ValueMissing as e:
        print(f"make-paper: {e}", file=sys.stderr)
        return 2
    if not args.no_pdf:
        build_pdf(os.path.abspath(args.out))
    print(f"make-paper: done in {time.monotonic() - start:.0f} s", flush=True)
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv[1:]))
    except (RuntimeError, subprocess.CalledProcessError, OSError) as e:
        print(f"make-paper: {e}", file=sys.stderr)
        sys.exit(1)
