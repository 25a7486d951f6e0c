"""What is fresh, stale (and why) or missing, said before anything runs, and
written into the paper's appendix (generated/staleness.tex)."""
from latex import GENERATED_HEADER, escape
from run_cache import ABSENT, FRESH, MISSING, STALE

MAX_REASONS = 6


def _action(status, todo, mode):
    if status in todo:
        return "will run"
    if status.entry.command == "data":
        return "committed data: remake with scripts/make-canonical-data.sh" if status.state == STALE else "used"
    if status.state == ABSENT:
        return "optional, not there: its numbers print 'not yet run'"
    if status.state == MISSING:
        return f"not run in {mode} mode: its numbers print 'not yet run'"
    return "used as it is (stale)" if status.state == STALE else "used"


def report_lines(statuses, todo, mode):
    lines = [f"make-paper: {mode} mode; {len(statuses)} experiment(s) in inputs.yaml"]
    for s in statuses:
        lines.append(f"  {s.entry.id:24s} {s.state:8s} {_action(s, todo, mode)}")
        for reason in s.reasons[:MAX_REASONS]:
            lines.append(f"      {reason}")
        if len(s.reasons) > MAX_REASONS:
            lines.append(f"      ... and {len(s.reasons) - MAX_REASONS} more")
    return lines


def write_staleness(path, statuses):
    """An itemised list of the folders that were stale or missing when the paper was built."""
    out = [GENERATED_HEADER]
    flagged = [s for s in statuses if s.state != FRESH]
    if not flagged:
        out.append("Every run folder was fresh when this paper was built.\n")
    else:
        out.append("\\begin{itemize}\n")
        for s in flagged:
            reasons = "; ".join(escape(r) for r in s.reasons[:MAX_REASONS]) or "--"
            out.append(f"\\item \\texttt{{{escape(s.entry.id)}}} ({s.state}): {reasons}\n")
        out.append("\\end{itemize}\n")
    with open(path, "w", encoding="utf-8") as f:
        f.writelines(out)
