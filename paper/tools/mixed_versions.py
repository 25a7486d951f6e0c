"""Whether the run folders a paper would use were made by different versions of
the same code (a solver, or the command that ran them): such a paper describes
no one version of the model, so it is refused unless --allow-mixed.
"""
import os


def mixed_versions(statuses):
    """{component: {version: [entry ids]}} for every component with two or more versions."""
    seen = {}
    for status in statuses:
        for component, version in status.code.items():
            if version == "absent":
                continue
            seen.setdefault(component, {}).setdefault(version, []).append(status.entry.id)
    return {c: v for c, v in seen.items() if len(v) > 1}


def describe(mixed):
    """Lines for the refusal: each component, each version (shortened) and its runs."""
    lines = []
    for component, versions in sorted(mixed.items()):
        lines.append(f"  {component} has {len(versions)} versions among the runs used:")
        for version, ids in sorted(versions.items()):
            lines.append(f"    {version[:16]}: {', '.join(sorted(ids))}")
    return lines


def remedies(mixed, statuses):
    """What would make the versions agree: the committed data folders among the
    mixed runs are remade by scripts/make-canonical-data.sh (the paper never
    runs them), the rest by rerunning the paper in full mode."""
    ids = {i for versions in mixed.values() for run_ids in versions.values() for i in run_ids}
    data = sorted(os.path.relpath(s.entry.path, "data") for s in statuses
                  if s.entry.id in ids and s.entry.command == "data")
    lines = []
    if data:
        lines.append(f"remake the committed data with the current code: scripts/make-canonical-data.sh {' '.join(data)}")
    lines.append("rerun what the paper runs: scripts/make-paper.sh --full; or build anyway with --allow-mixed")
    return lines
